// UI test script interpreter.
#include "script/ui_script.h"

#include "gl/gl_object.h"
#include "model/light_list.h"
#include "core/light_math.h"

#include <unistd.h>

#include <glm/gtc/matrix_transform.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace gbl::ui {

namespace {

struct Arity {
    char const* name;
    int args;  // -1: one or more words (free text)
};
constexpr Arity kCommands[] = {
    {"frames", 1}, {"set", 2}, {"light", 3}, {"select", 1}, {"click-light", 1}, {"frame-scene", 0},
    {"resize", 2}, {"capture", 1}, {"screenshot", 1}, {"measure", 1}, {"expect-windows", 0},
    {"expect-different", 3}, {"expect-pixels-differ", 3}, {"expect-same", 3}, {"expect-message", -1}, {"expect-no-message", 0},
    {"expect-selected", 1}, {"expect-lights", 1}, {"expect-no-gl-errors", 0}, {"expect-mode-used", 1}, {"inspect", 2}, {"expect-breakdown-sums", 1}, {"expect-smaller", 2}, {"expect-log", -1}, {"print", -1}, {"save-session", 1}, {"open-session", 1}, {"open-bad-session", 1},
    {"undo", 0}, {"redo", 0}, {"expect-recovery-offered", 0}, {"recover", 0},
    {"wait-autosave", 1}, {"expect-light", 3}, {"expect-setting", 2}, {"export-all", 1}, {"export-viewer", 3},
    {"expect-file", 1}, {"wait-log", -1}, {"wait", 1}, {"shader-break", 1}, {"shader-fix", 1}, {"soak-baseline", 0}, {"expect-soak-stable", 2},
};

double nowSeconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// Resident set size of this process in MiB (Linux /proc; 0 where it does not exist).
double residentMb() {
    std::ifstream statm("/proc/self/statm");
    long pages = 0, resident = 0;
    if (!(statm >> pages >> resident)) return 0.0;
    return double(resident) * double(::sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

// Reads one field of a light the way the `light` command writes it; nullopt for unknown names.
std::optional<float> lightField(PointLight const& l, std::string const& f) {
    if (f == "x") return l.position.x;
    if (f == "y") return l.position.y;
    if (f == "z") return l.position.z;
    if (f == "r") return l.color.r;
    if (f == "g") return l.color.g;
    if (f == "b") return l.color.b;
    if (f == "intensity") return l.intensity;
    if (f == "kc") return l.kc;
    if (f == "kl") return l.kl;
    if (f == "kq") return l.kq;
    if (f == "threshold") return l.threshold;
    return std::nullopt;
}

// Replaces each ${NAME} in `word` by the environment variable; false (and a sentence) when unset.
bool expandEnvironment(std::string const& word, std::string& out, std::string* error) {
    out.clear();
    for (std::size_t i = 0; i < word.size();) {
        std::size_t const open = word.find("${", i);
        std::size_t const close = open == std::string::npos ? open : word.find('}', open);
        if (close == std::string::npos) {
            out += word.substr(i);
            break;
        }
        std::string const name = word.substr(open + 2, close - open - 2);
        char const* value = std::getenv(name.c_str());
        if (!value) {
            *error = "the environment variable " + name + " is not set";
            return false;
        }
        out += word.substr(i, open - i) + value;
        i = close + 1;
    }
    return true;
}

std::string rest(std::vector<std::string> const& words, std::size_t from) {
    std::string s;
    for (std::size_t i = from; i < words.size(); ++i) s += (i > from ? " " : "") + words[i];
    return s;
}

float number(std::string const& s) {
    // strtof accepts "nan" and "inf": scripts use them to test that bad input is refused.
    return std::strtof(s.c_str(), nullptr);
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

template <std::size_t N>
bool setEnum(auto& field, std::array<std::string_view, N> const& names, std::string const& value) {
    using Enum = std::remove_reference_t<decltype(field)>;
    auto const e = enumFromName<Enum>(names, value);
    if (!e) return false;
    field = *e;
    return true;
}

}  // namespace

std::optional<UiScript> UiScript::load(std::string const& path, std::string* error) {
    std::ifstream in(path);
    if (!in) {
        *error = "cannot read UI test script " + path;
        return std::nullopt;
    }
    UiScript script;
    script.path_ = path;
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
        ++number;
        if (auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
        std::istringstream words(line);
        Command c{number, {}};
        for (std::string w; words >> w;) {
            std::string expanded;
            if (!expandEnvironment(w, expanded, error)) {
                *error = path + ":" + std::to_string(number) + ": " + *error;
                return std::nullopt;
            }
            c.words.push_back(std::move(expanded));
        }
        if (c.words.empty()) continue;
        Arity const* arity = nullptr;
        for (auto const& a : kCommands)
            if (c.words[0] == a.name) arity = &a;
        Arity const scene{"", sceneCommandArity(c.words[0])};
        if (!arity && scene.args != -2) arity = &scene;
        int const given = int(c.words.size()) - 1;
        if (!arity || (arity->args >= 0 && given != arity->args) || (arity->args < 0 && given < 1)) {
            *error = path + ":" + std::to_string(number) + ": " +
                     (arity ? "wrong number of arguments for " + c.words[0] : "unknown command " + c.words[0]);
            return std::nullopt;
        }
        script.commands_.push_back(std::move(c));
    }
    return script;
}

void UiScript::check(bool ok, Command const& c, std::string const& detail) {
    std::printf("ui-test %s %s:%d %s%s%s\n", ok ? "PASS" : "FAIL", path_.c_str(), c.line, rest(c.words, 0).c_str(),
                detail.empty() ? "" : ": ", detail.c_str());
    std::fflush(stdout);
    if (!ok) ++failures_;
}

void UiScript::step(ScriptHost& host) {
    if (wait_ > 0) {
        --wait_;
        return;
    }
    if (until_) {
        if (until_()) {
            check(true, *untilCommand_, "done");
        } else if (nowSeconds() > untilDeadline_) {
            check(false, *untilCommand_, "timed out");
        } else {
            return;
        }
        until_ = nullptr;
        untilCommand_.reset();
    }
    while (next_ < commands_.size() && wait_ == 0 && !until_) run(commands_[next_++], host);
}

void UiScript::run(Command const& c, ScriptHost& host) {
    if (sceneCommandArity(c.words[0]) != -2) return runSceneCommand(c, host);
    auto const& w = c.words;
    // Session commands need the editor's session support; without it they fail, never crash.
    bool const sessionCommand = w[0] == "save-session" || w[0] == "open-session" || w[0] == "open-bad-session" ||
                                w[0] == "undo" || w[0] == "redo" || w[0] == "expect-recovery-offered" ||
                                w[0] == "recover";
    if (sessionCommand && !(host.openSession && host.saveSession && host.undo && host.redo && host.recoveryOffered &&
                            host.acceptRecovery))
        return check(false, c, "this editor build has no session support wired in");
    EditorState& s = host.state;
    std::string const& cmd = w[0];

    if (cmd == "frames") {
        wait_ = std::max(std::atoi(w[1].c_str()), 1);
    } else if (cmd == "set") {
        std::string const& key = w[1];
        std::string const& value = w[2];
        bool ok = true;
        if (key == "mode") ok = setEnum(s.pipeline.mode, kLightingModeNames, value);
        else if (key == "cull") ok = setEnum(s.pipeline.cull, kCullModeNames, value);
        else if (key == "blit") ok = setEnum(s.pipeline.depthCopy, kDepthCopyNames, value);
        else if (key == "view") ok = setEnum(s.pipeline.view, kDebugViewNames, value);
        else if (key == "tonemap") ok = setEnum(s.pipeline.tonemap, kTonemapNames, value);
        else if (key == "exposure") s.pipeline.exposure = number(value);
        else if (key == "cubes") s.pipeline.lightCubes = value != "0";
        else if (key == "wireframes") s.pipeline.volumeWireframes = value != "0";
        else if (key == "animate") s.animation.enabled = value != "0";
        else if (key == "time") s.animation.time = number(value);
        else if (key == "lights") {
            ok = bool(host.defaultLights);
            if (ok) s.lights = host.defaultLights(std::atoi(value.c_str()));
        } else ok = false;
        if (!ok) check(false, c, "unknown setting or value");
    } else if (cmd == "light") {
        int const i = std::atoi(w[1].c_str());
        if (i < 0 || i >= int(s.lights.size())) return check(false, c, "no such light");
        PointLight edited = s.lights[std::size_t(i)];
        float const v = number(w[3]);
        std::string const& f = w[2];
        if (f == "x") edited.position.x = v;
        else if (f == "y") edited.position.y = v;
        else if (f == "z") edited.position.z = v;
        else if (f == "r") edited.color.r = v;
        else if (f == "g") edited.color.g = v;
        else if (f == "b") edited.color.b = v;
        else if (f == "intensity") edited.intensity = v;
        else if (f == "kc") edited.kc = v;
        else if (f == "kl") edited.kl = v;
        else if (f == "kq") edited.kq = v;
        else if (f == "threshold") edited.threshold = v;
        else return check(false, c, "unknown light field");
        auto const error = applyLightEdit(s.lights, i, edited);
        s.lightsPanel.message = error ? *error : std::string();
    } else if (cmd == "select") {
        s.lightsPanel.selected = std::atoi(w[1].c_str());
    } else if (cmd == "click-light") {
        int const i = std::atoi(w[1].c_str());
        if (i < 0 || i >= int(s.lights.size())) return check(false, c, "no such light");
        glm::ivec2 const size(host.renderer.width(), host.renderer.height());
        if (size.x <= 0 || size.y <= 0) return check(false, c, "the viewport has no pixels");
        // The pixel whose centre sees the light's centre: project it as the renderer does.
        glm::vec4 const clip = s.camera.projection(float(size.x) / float(size.y)) * s.camera.view() *
                               glm::vec4(s.lights[std::size_t(i)].position, 1.0f);
        if (clip.w <= 0.0f) return check(false, c, "the light is behind the camera");
        glm::vec2 const ndc = glm::vec2(clip) / clip.w;
        glm::ivec2 const px(int((ndc.x * 0.5f + 0.5f) * float(size.x)), int((0.5f - ndc.y * 0.5f) * float(size.y)));
        host.clickViewport(px);
    } else if (cmd == "frame-scene") {
        host.frameScene();
    } else if (cmd == "resize") {
        host.resizeWindow(std::atoi(w[1].c_str()), std::atoi(w[2].c_str()));
    } else if (cmd == "capture") {
        captures_[w[1]] = host.renderer.readAttachment(Attachment::Final);
        if (captures_[w[1]].pixels.empty()) check(false, c, "the final image is empty (0x0 viewport?)");
    } else if (cmd == "screenshot") {
        auto const error = writePng(host.readWindow(), w[1]);
        check(!error, c, error ? *error : std::string());
    } else if (cmd == "measure") {
        s.measurement = CostMeasurement{};
        s.measurement.remaining = std::max(std::atoi(w[1].c_str()), 1);
        wait_ = s.measurement.remaining + 1;
    } else if (cmd == "expect-windows") {
        for (std::size_t i = 0; i < kEditorWindowNames.size(); ++i) {
            std::string const problem = host.windowProblem(EditorWindow(i));
            check(problem.empty(), c, std::string(kEditorWindowNames[i]) + (problem.empty() ? " visible" : ": " + problem));
        }
    } else if (cmd == "expect-different" || cmd == "expect-same") {
        auto a = captures_.find(w[1]), b = captures_.find(w[2]);
        if (a == captures_.end() || b == captures_.end()) return check(false, c, "capture missing");
        double const d = meanDifference(a->second, b->second);
        double const limit = number(w[3]);
        bool const ok = cmd == "expect-same" ? d <= limit : d >= limit;
        char detail[96];
        std::snprintf(detail, sizeof detail, "mean difference %.6f", d);
        check(ok, c, detail);
    } else if (cmd == "expect-pixels-differ") {
        auto a = captures_.find(w[1]), b = captures_.find(w[2]);
        if (a == captures_.end() || b == captures_.end()) return check(false, c, "capture missing");
        long const n = pixelsDiffering(a->second, b->second);
        check(n >= std::atol(w[3].c_str()), c, std::to_string(n) + " pixels differ");
    } else if (cmd == "expect-message") {
        std::string const text = rest(w, 1);
        check(s.lightsPanel.message.find(text) != std::string::npos, c, "message is \"" + s.lightsPanel.message + "\"");
    } else if (cmd == "expect-no-message") {
        check(s.lightsPanel.message.empty(), c, s.lightsPanel.message);
    } else if (cmd == "expect-selected") {
        check(s.lightsPanel.selected == std::atoi(w[1].c_str()), c,
              "selected is " + std::to_string(s.lightsPanel.selected));
    } else if (cmd == "expect-lights") {
        check(int(s.lights.size()) == std::atoi(w[1].c_str()), c, "there are " + std::to_string(s.lights.size()));
    } else if (cmd == "expect-no-gl-errors") {
        auto const n = host.renderer.glErrorCount();
        check(n == 0, c, std::to_string(n) + " GL errors");
    } else if (cmd == "inspect") {
        s.inspector.pixel = glm::ivec2(std::atoi(w[1].c_str()), std::atoi(w[2].c_str()));
        s.inspector.locked = true;
        s.inspector.source = "script";
    } else if (cmd == "expect-breakdown-sums") {
        auto const& in = s.inspector;
        if (!in.sample || !in.breakdown) return check(false, c, "no inspected pixel with geometry");
        glm::vec3 const stored(in.sample->lighting);
        float const tol = number(w[1]);
        bool ok = true;
        for (int k = 0; k < 3; ++k)
            ok &= std::abs(in.breakdown->total[k] - stored[k]) <= tol + 0.01f * std::abs(stored[k]);
        char detail[160];
        std::snprintf(detail, sizeof detail, "sum (%.5f %.5f %.5f) stored (%.5f %.5f %.5f), %d lights reach it",
                      in.breakdown->total.r, in.breakdown->total.g, in.breakdown->total.b, stored.r, stored.g, stored.b,
                      int(in.breakdown->lights.size()));
        check(ok, c, detail);
    } else if (cmd == "expect-mode-used") {
        FrameStats const& f = s.stats.last;
        std::string const used(enumName(kLightingModeNames, f.modeUsed));
        check(used == w[1], c, "ran " + used + (f.fallbackReason.empty() ? "" : " (" + f.fallbackReason + ")"));
    } else if (cmd == "expect-smaller") {
        auto a = captures_.find(w[1]), b = captures_.find(w[2]);
        if (a == captures_.end() || b == captures_.end()) return check(false, c, "capture missing");
        check(a->second.width < b->second.width && a->second.height < b->second.height, c,
              std::to_string(a->second.width) + "x" + std::to_string(a->second.height) + " vs " +
                  std::to_string(b->second.width) + "x" + std::to_string(b->second.height));
    } else if (cmd == "expect-log") {
        std::string const text = rest(w, 1);
        bool found = false;
        for (auto const& line : s.log.lines) found |= line.find(text) != std::string::npos;
        check(found, c, found ? std::string() : "no log line contains it");
    } else if (cmd == "save-session") {
        auto const error = host.saveSession(w[1]);
        check(!error, c, error.value_or(""));
    } else if (cmd == "open-session") {
        auto const error = host.openSession(w[1]);
        check(!error, c, error.value_or(""));
    } else if (cmd == "open-bad-session") {
        auto const error = host.openSession(w[1]);
        check(bool(error), c, error ? "refused: " + *error : "the file was accepted");
    } else if (cmd == "undo") {
        host.undo();
    } else if (cmd == "redo") {
        host.redo();
    } else if (cmd == "expect-recovery-offered") {
        check(host.recoveryOffered(), c, "");
    } else if (cmd == "recover") {
        host.acceptRecovery();
    } else if (cmd == "wait-autosave") {
        if (!host.autosaves) return check(false, c, "this editor run has no autosave (set GBL_RECOVERY_DIR)");
        int const before = host.autosaves();
        until_ = [&host, before] { return host.autosaves() > before; };
        untilCommand_ = c;
        untilDeadline_ = nowSeconds() + number(w[1]);
    } else if (cmd == "wait") {
        // Wall-clock time, for what is defined in seconds (undo merging, autosave delays).
        double const until = nowSeconds() + number(w[1]);
        until_ = [until] { return nowSeconds() >= until; };
        untilCommand_ = c;
        untilDeadline_ = until + 3600.0;
    } else if (cmd == "wait-log") {
        if (w.size() < 3) return check(false, c, "expected SECONDS TEXT");
        std::string const text = rest(w, 2);
        LogState const* log = &s.log;
        until_ = [log, text] {
            for (auto const& line : log->lines)
                if (line.find(text) != std::string::npos) return true;
            return false;
        };
        untilCommand_ = c;
        untilDeadline_ = nowSeconds() + number(w[1]);
    } else if (cmd == "expect-light") {
        int const i = std::atoi(w[1].c_str());
        if (i < 0 || i >= int(s.lights.size())) return check(false, c, "no such light");
        auto const v = lightField(s.lights[std::size_t(i)], w[2]);
        if (!v) return check(false, c, "unknown light field");
        check(*v == number(w[3]), c, "it is " + std::to_string(*v));
    } else if (cmd == "expect-setting") {
        std::string const& key = w[1];
        std::string now;
        if (key == "mode") now = enumName(kLightingModeNames, s.pipeline.mode);
        else if (key == "cull") now = enumName(kCullModeNames, s.pipeline.cull);
        else if (key == "blit") now = enumName(kDepthCopyNames, s.pipeline.depthCopy);
        else if (key == "view") now = enumName(kDebugViewNames, s.pipeline.view);
        else if (key == "tonemap") now = enumName(kTonemapNames, s.pipeline.tonemap);
        else return check(false, c, "unknown setting");
        check(now == w[2], c, "it is " + now);
    } else if (cmd == "export-all") {
        if (!host.exportAll) return check(false, c, "no export in this editor build");
        auto const error = host.exportAll(w[1]);
        check(!error, c, error.value_or(""));
    } else if (cmd == "export-viewer") {
        if (!host.exportViewer) return check(false, c, "no export in this editor build");
        int viewer = -1;
        for (std::size_t i = 0; i < kViewerNames.size(); ++i)
            if (kViewerNames[i] == w[1]) viewer = int(i);
        if (viewer < 0 || (w[2] != "png" && w[2] != "exr")) return check(false, c, "expected a viewer name and png or exr");
        auto const error = host.exportViewer(viewer, w[2] == "exr", w[3]);
        check(!error, c, error.value_or(""));
    } else if (cmd == "expect-file") {
        std::error_code ec;
        auto const size = std::filesystem::file_size(w[1], ec);
        check(!ec && size > 0, c, ec ? ec.message() : std::to_string(size) + " bytes");
    } else if (cmd == "shader-break" || cmd == "shader-fix") {
        // Only ever a copy of the shaders: editing the source tree would disturb everyone else.
        char const* dir = std::getenv("GBL_SHADER_DIR");
        if (!dir || !*dir) return check(false, c, "GBL_SHADER_DIR is not set; refusing to edit the source tree");
        std::string const path = (std::filesystem::path(dir) / w[1]).string();
        if (cmd == "shader-break") {
            std::ifstream in(path);
            if (!in) return check(false, c, "cannot read " + path);
            std::string const text((std::istreambuf_iterator<char>(in)), {});
            brokenShaders_[w[1]] = text;
            std::ofstream(path) << text << "\n#error broken on purpose by a UI test script\n";
        } else {
            auto const it = brokenShaders_.find(w[1]);
            if (it == brokenShaders_.end()) return check(false, c, "not broken by shader-break");
            std::ofstream(path) << it->second;
            brokenShaders_.erase(it);
        }
    } else if (cmd == "soak-baseline") {
        baselineObjects_ = gl::liveObjectCount();
        baselineRssMb_ = residentMb();
        std::printf("ui-test: baseline %ld live GL objects, %.1f MB resident\n", baselineObjects_, baselineRssMb_);
        std::fflush(stdout);
    } else if (cmd == "expect-soak-stable") {
        if (baselineObjects_ < 0) return check(false, c, "no soak-baseline before");
        long const objects = gl::liveObjectCount();
        double const rss = residentMb();
        bool const ok = std::abs(objects - baselineObjects_) <= std::atol(w[1].c_str()) &&
                        rss - baselineRssMb_ <= number(w[2]);
        char detail[160];
        std::snprintf(detail, sizeof detail, "GL objects %ld (baseline %ld), resident %.1f MB (baseline %.1f MB)",
                      objects, baselineObjects_, rss, baselineRssMb_);
        check(ok, c, detail);
    } else if (cmd == "print") {
        std::printf("ui-test: %s\n", rest(w, 1).c_str());
    }
}

}  // namespace gbl::ui
