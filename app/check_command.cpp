// The check command: manifest, images, checks; findings as text or JSON.
#include "check_command.h"

#include "import/gbuffer_checks.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>

namespace gbl {

void addCheckOptions(CLI::App& sub, CheckOptions& o) {
    sub.add_option("manifest", o.manifest, "A G-buffer manifest (docs/import.md), or a folder")->required();
    sub.add_flag("--json", o.json, "Print the findings as JSON");
    sub.add_flag("--time", o.time, "Print the seconds spent opening the G-buffer and checking it (stderr)");
}

int runCheck(CheckOptions const& o) {
    using Clock = std::chrono::steady_clock;
    auto const start = Clock::now();
    ManifestLoad m = loadManifest(o.manifest);
    if (!m.manifest) {
        std::fprintf(stderr, "gbuffer-lab check: %s\n", m.error.c_str());
        return 2;
    }
    GBufferLoad g = loadGBuffer(*m.manifest);
    if (!g.gbuffer) {
        std::fprintf(stderr, "gbuffer-lab check: %s\n", g.error.c_str());
        return 2;
    }
    auto const loaded = Clock::now();
    GBufferCheckReport const r = checkGBuffer(*g.gbuffer);
    auto const checked = Clock::now();
    if (o.json) {
        nlohmann::ordered_json j = {{"width", r.width},
                                    {"height", r.height},
                                    {"geometry_pixels", r.geometryPixels},
                                    {"background_pixels", r.backgroundPixels}};
        j["findings"] = nlohmann::ordered_json::array();
        for (auto const& f : r.findings)
            j["findings"].push_back({{"check", f.check},
                                     {"attachment", f.attachment},
                                     {"pixels", f.pixels},
                                     {"share", f.share},
                                     {"heuristic", f.heuristic},
                                     {"cause", f.cause}});
        j["precision"] = nlohmann::ordered_json::array();
        for (auto const& p : r.precision)
            j["precision"].push_back({{"attachment", p.attachment},
                                      {"storage", p.storage},
                                      {"step", p.step},
                                      {"highlight_error", p.highlightError}});
        std::printf("%s\n", j.dump(2).c_str());
    } else {
        std::printf("%s: %dx%d, %zu geometry pixels, %zu background\n", o.manifest.c_str(), r.width, r.height,
                    r.geometryPixels, r.backgroundPixels);
        for (auto const& f : r.findings)
            std::printf("%s (%s): %zu pixels, %.2f%%%s\n  %s\n", f.check.c_str(), f.attachment.c_str(), f.pixels,
                        f.share * 100.0, f.heuristic ? ", heuristic" : "", f.cause.c_str());
        if (r.findings.empty()) std::printf("no findings\n");
        std::printf("precision (what each attachment's storage can hold):\n");
        for (auto const& p : r.precision) std::printf("  %s\n", precisionLine(p).c_str());
    }
    if (o.time)
        std::fprintf(stderr, "check: open %.3f s, checks %.3f s\n",
                     std::chrono::duration<double>(loaded - start).count(),
                     std::chrono::duration<double>(checked - loaded).count());
    return r.findings.empty() ? 0 : 1;
}

}  // namespace gbl
