// UI script commands that capture images and check the editor's state, images and resources.
#include "script/script_run.h"

#include "core/pipeline_fields.h"

#include "gl/gl_object.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace gbl::ui {

namespace {

// Resident set size of this process in MiB (Linux /proc; 0 where it does not exist).
double residentMb() {
    std::ifstream statm("/proc/self/statm");
    long pages = 0, resident = 0;
    if (!(statm >> pages >> resident)) return 0.0;
    return double(resident) * double(::sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

long pixelsDiffering(FloatImage const& a, FloatImage const& b) {
    if (a.width != b.width || a.height != b.height || a.channels != b.channels) return long(a.width) * a.height;
    long n = 0;
    for (std::size_t p = 0; p < a.pixels.size(); p += std::size_t(a.channels)) {
        bool differs = false;
        for (int c = 0; c < a.channels; ++c)
            differs |= std::abs(a.pixels[p + std::size_t(c)] - b.pixels[p + std::size_t(c)]) > 1.5f / 255.0f;
        n += differs ? 1 : 0;
    }
    return n;
}

double meanDifference(FloatImage const& a, FloatImage const& b) {
    if (a.width != b.width || a.height != b.height || a.channels != b.channels || a.pixels.empty()) return 1.0;
    double sum = 0.0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) sum += std::abs(double(a.pixels[i]) - double(b.pixels[i]));
    return sum / double(a.pixels.size());
}

// The captures named by words 1 and 2, or nullptr after a failed check.
std::pair<FloatImage const*, FloatImage const*> capturePair(CommandCall const& c) {
    auto a = c.run.captures.find(c.w[1]), b = c.run.captures.find(c.w[2]);
    if (a == c.run.captures.end() || b == c.run.captures.end()) {
        c.check(false, "capture missing");
        return {nullptr, nullptr};
    }
    return {&a->second, &b->second};
}

void compareMeans(CommandCall const& c, bool same) {
    auto const [a, b] = capturePair(c);
    if (!a) return;
    double const d = meanDifference(*a, *b);
    double const limit = number(c.w[3]);
    char detail[96];
    std::snprintf(detail, sizeof detail, "mean difference %.6f", d);
    c.check(same ? d <= limit : d >= limit, detail);
}

void breakdownSumsCommand(CommandCall const& c) {
    auto const& in = c.host.state.inspector;
    if (!in.sample || !in.breakdown) return c.check(false, "no inspected pixel with geometry");
    glm::vec3 const stored(in.sample->lighting);
    float const tol = number(c.w[1]);
    bool ok = true;
    for (int k = 0; k < 3; ++k) ok &= std::abs(in.breakdown->total[k] - stored[k]) <= tol + 0.01f * std::abs(stored[k]);
    char detail[160];
    std::snprintf(detail, sizeof detail, "sum (%.5f %.5f %.5f) stored (%.5f %.5f %.5f), %d lights reach it",
                  in.breakdown->total.r, in.breakdown->total.g, in.breakdown->total.b, stored.r, stored.g, stored.b,
                  int(in.breakdown->lights.size()));
    c.check(ok, detail);
}

void expectLightCommand(CommandCall const& c) {
    EditorState const& s = c.host.state;
    int const i = std::atoi(c.w[1].c_str());
    if (i < 0 || i >= int(s.lights.size())) return c.check(false, "no such light");
    if (c.w[2] == "kind") {
        std::string const now(lightKindName(s.lights[std::size_t(i)].kind));
        return c.check(now == c.w[3], "it is " + now);
    }
    LightField const* field = findLightField(c.w[2]);
    if (!field) return c.check(false, "unknown light field");
    float const v = field->of(s.lights[std::size_t(i)]);
    c.check(v == number(c.w[3]), "it is " + std::to_string(v));
}

void expectSettingCommand(CommandCall const& c) {
    PipelineField const* field = findPipelineField(c.w[1]);
    if (!field) return c.check(false, "unknown setting");
    std::string const now = fieldScriptText(*field, c.host.state.pipeline);
    c.check(now == c.w[2], "it is " + now);
}

void soakStableCommand(CommandCall const& c) {
    ScriptRun const& r = c.run;
    if (r.baselineObjects < 0) return c.check(false, "no soak-baseline before");
    long const objects = gl::liveObjectCount();
    double const rss = residentMb();
    bool const ok =
        std::abs(objects - r.baselineObjects) <= std::atol(c.w[1].c_str()) && rss - r.baselineRssMb <= number(c.w[2]);
    char detail[160];
    std::snprintf(detail, sizeof detail, "GL objects %ld (baseline %ld), resident %.1f MB (baseline %.1f MB)", objects,
                  r.baselineObjects, rss, r.baselineRssMb);
    c.check(ok, detail);
}

// What the current mode evaluated at the inspected pixel (ambient plus each verdict's share)
// against the stored lit value: the "why this value" answer checked against the GPU.
void whySumsCommand(CommandCall const& c) {
    auto const& in = c.host.state.inspector;
    if (!in.sample || !in.breakdown || in.breakdown->verdicts.empty())
        return c.check(false, "no verdicts at the inspected pixel");
    glm::vec3 sum = in.breakdown->ambient;
    int evaluated = 0;
    for (LightVerdict const& v : in.breakdown->verdicts) {
        sum += v.added;
        evaluated += v.evaluated ? 1 : 0;
    }
    glm::vec3 const stored(in.sample->lighting);
    float const tol = number(c.w[1]);
    bool ok = true;
    for (int k = 0; k < 3; ++k) ok &= std::abs(sum[k] - stored[k]) <= tol + 0.01f * std::abs(stored[k]);
    char detail[200];
    std::snprintf(detail, sizeof detail, "by mode (%.5f %.5f %.5f) stored (%.5f %.5f %.5f), %d of %d lights evaluated",
                  sum.r, sum.g, sum.b, stored.r, stored.g, stored.b, evaluated, int(in.breakdown->verdicts.size()));
    c.check(ok, detail);
}

constexpr ScriptCommandSpec kCheckCommands[] = {
    {"capture", "NAME", "keep the renderer's final image under NAME",
     [](CommandCall const& c) {
         FloatImage& image = c.run.captures[c.w[1]] = c.host.renderer.readAttachment(Attachment::Final);
         if (image.pixels.empty()) c.check(false, "the final image is empty (0x0 viewport?)");
     }},
    {"screenshot", "FILE", "write the whole window as PNG",
     [](CommandCall const& c) {
         auto const error = writePng(c.host.readWindow(), c.w[1]);
         c.check(!error, error ? *error : std::string());
     }},
    {"expect-windows", "", "every editor window exists, is visible and has a size",
     [](CommandCall const& c) {
         for (std::size_t i = 0; i < kEditorWindowNames.size(); ++i) {
             std::string const problem = c.host.windowProblem(EditorWindow(i));
             std::string const name(kEditorWindowNames[i]);
             c.check(problem.empty(), name + (problem.empty() ? " visible" : ": " + problem));
         }
     }},
    {"expect-different", "A B MIN", "mean |A - B| per channel (0..1) at least MIN",
     [](CommandCall const& c) { compareMeans(c, false); }},
    {"expect-same", "A B MAX", "mean |A - B| per channel at most MAX",
     [](CommandCall const& c) { compareMeans(c, true); }},
    {"expect-pixels-differ", "A B N", "at least N pixels differ by more than one 8-bit step",
     [](CommandCall const& c) {
         auto const [a, b] = capturePair(c);
         if (!a) return;
         long const n = pixelsDiffering(*a, *b);
         c.check(n >= std::atol(c.w[3].c_str()), std::to_string(n) + " pixels differ");
     }},
    {"expect-smaller", "A B", "capture A is narrower and lower than capture B",
     [](CommandCall const& c) {
         auto const [a, b] = capturePair(c);
         if (!a) return;
         auto const size = [](FloatImage const* i) {
             return std::to_string(i->width) + "x" + std::to_string(i->height);
         };
         c.check(a->width < b->width && a->height < b->height, size(a) + " vs " + size(b));
     }},
    {"expect-message", "TEXT...", "the Lights panel's refusal message contains TEXT",
     [](CommandCall const& c) {
         std::string const& message = c.host.state.lightsPanel.message;
         c.check(message.find(joinWords(c.w, 1)) != std::string::npos, "message is \"" + message + "\"");
     }},
    {"expect-no-message", "", "... and is empty",
     [](CommandCall const& c) { c.check(c.host.state.lightsPanel.message.empty(), c.host.state.lightsPanel.message); }},
    {"expect-selected", "I", "light I is selected",
     [](CommandCall const& c) {
         int const selected = c.host.state.lightsPanel.selected;
         c.check(selected == std::atoi(c.w[1].c_str()), "selected is " + std::to_string(selected));
     }},
    {"expect-lights", "N", "the list holds N lights",
     [](CommandCall const& c) {
         std::size_t const n = c.host.state.lights.size();
         c.check(int(n) == std::atoi(c.w[1].c_str()), "there are " + std::to_string(n));
     }},
    {"expect-light", "I FIELD VALUE", "light I's FIELD (as for `light`) equals VALUE", expectLightCommand},
    {"expect-setting", "KEY NAME", "pipeline field KEY (as for `set`) is NAME, 0|1 or the number",
     expectSettingCommand},
    {"wait-setting", "KEY NAME SECONDS",
     "run frames until the setting (as for expect-setting) is NAME: a real click may change it",
     [](CommandCall const& c) {
         PipelineField const* field = findPipelineField(c.w[1]);
         if (!field) return c.check(false, "unknown setting");
         PipelineSettings const& p = c.host.state.pipeline;
         std::string const want = c.w[2];
         c.waitUntil([field, &p, want] { return fieldScriptText(*field, p) == want; }, number(c.w[3]));
     }},
    {"expect-no-gl-errors", "", "the renderer counted no GL errors so far",
     [](CommandCall const& c) {
         auto const n = c.host.renderer.glErrorCount();
         c.check(n == 0, std::to_string(n) + " GL errors");
     }},
    {"expect-mode-used", "NAME", "the last frame ran this lighting mode (no silent fallback)",
     [](CommandCall const& c) {
         FrameStats const& f = c.host.state.stats.last;
         std::string const used(enumName(kLightingModeNames, f.modeUsed));
         c.check(used == c.w[1], "ran " + used + (f.fallbackReason.empty() ? "" : " (" + f.fallbackReason + ")"));
     }},
    {"expect-breakdown-sums", "TOL",
     "the inspector's per-light sum equals the stored lit value\n"
     "within TOL + 1% (16-bit float storage, CPU vs GPU float math)",
     breakdownSumsCommand},
    {"expect-why-sums", "TOL",
     "ambient plus what each light added by the current mode's verdict (why this value)\n"
     "equals the stored lit value within TOL + 1%",
     whySumsCommand},
    {"expect-log", "TEXT...", "some log line contains TEXT",
     [](CommandCall const& c) {
         std::string const text = joinWords(c.w, 1);
         auto const& lines = c.host.state.log.lines;
         bool const found = std::any_of(lines.begin(), lines.end(),
                                        [&](std::string const& line) { return line.find(text) != std::string::npos; });
         c.check(found, found ? std::string() : "no log line contains it");
     }},
    {"expect-file", "PATH", "a file exists and is not empty",
     [](CommandCall const& c) {
         std::error_code ec;
         auto const size = std::filesystem::file_size(c.w[1], ec);
         c.check(!ec && size > 0, ec ? ec.message() : std::to_string(size) + " bytes");
     }},
    {"soak-baseline", "", "remember the live GL object count and the process RSS",
     [](CommandCall const& c) {
         c.run.baselineObjects = gl::liveObjectCount();
         c.run.baselineRssMb = residentMb();
         std::printf("ui-test: baseline %ld live GL objects, %.1f MB resident\n", c.run.baselineObjects,
                     c.run.baselineRssMb);
         std::fflush(stdout);
     }},
    {"expect-soak-stable", "N MB", "live GL objects within N of the baseline, RSS grown by at most MB",
     soakStableCommand},
};

}  // namespace

std::span<ScriptCommandSpec const> checkCommands() {
    return kCheckCommands;
}

}  // namespace gbl::ui
