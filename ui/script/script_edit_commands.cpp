// UI script commands that edit the editor's state, drive its input and wait.
#include "script/script_run.h"

#include "core/light_math.h"
#include "core/pipeline_fields.h"
#include "model/light_list.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace gbl::ui {

namespace {

void setCommand(CommandCall const& c) {
    EditorState& s = c.host.state;
    std::string const& key = c.w[1];
    std::string const& value = c.w[2];
    bool ok = true;
    if (PipelineField const* field = findPipelineField(key)) {  // core/pipeline_fields.h: names, ranges
        std::optional<double> const v = parseFieldValue(*field, value);
        ok = bool(v);
        if (ok) field->set(s.pipeline, *v);
    } else if (key == "animate")
        s.animation.enabled = value != "0";
    else if (key == "time")
        s.animation.time = number(value);
    else if (key == "accumulate") {  // K lights, or -1: off
        int const k = std::atoi(value.c_str());
        s.accumulate.enabled = k >= 0;
        s.accumulate.count = std::max(k, 0);
    } else if (key == "contribution")
        s.accumulate.contribution = value != "0";
    else if (key == "ab") {  // off, split or diff
        ok = value == "off" || value == "split" || value == "diff";
        if (ok && value != "off" && !s.ab.enabled) startAb(s.ab, s.pipeline);
        s.ab.enabled = ok && value != "off";
        s.ab.view = value == "diff" ? AbView::Diff : AbView::Split;
    } else if (key == "ab-metric") {  // lit or normal-angle (the latter needs B's layout ticked)
        ok = value == "lit" || (value == "normal-angle" && abComparesLayout(s.ab));
        if (ok) s.ab.metric = value == "lit" ? AbMetric::Lit : AbMetric::NormalAngle;
    } else if (key == "ab-threshold")
        s.ab.threshold = std::max(number(value), 0.0f);
    else if (key == "ab-angle-threshold")
        s.ab.angleThreshold = std::max(number(value), 0.0f);
    else if (key == "ab-divider")
        s.ab.divider = std::clamp(number(value), 0.02f, 0.98f);
    else if (key.rfind("b.", 0) == 0)  // side B's FIELD, as the A/B table names it
        ok = setAbField(s.ab, key.substr(2), value);
    else if (key == "lights") {
        ok = bool(c.host.defaultLights);
        if (ok) s.lights = c.host.defaultLights(std::atoi(value.c_str()));
    } else
        ok = false;
    if (!ok) c.check(false, "unknown setting or value");
}

void lightCommand(CommandCall const& c) {
    EditorState& s = c.host.state;
    int const i = std::atoi(c.w[1].c_str());
    if (i < 0 || i >= int(s.lights.size())) return c.check(false, "no such light");
    PointLight edited = s.lights[std::size_t(i)];
    if (c.w[2] == "kind") {  // not a number: point, spot or directional
        auto const kind = findLightKind(c.w[3]);
        if (!kind) return c.check(false, "unknown light kind (point, spot or directional)");
        edited.kind = *kind;
    } else {
        LightField const* field = findLightField(c.w[2]);
        if (!field) return c.check(false, "unknown light field");
        field->of(edited) = number(c.w[3]);
    }
    auto const error = applyLightEdit(s.lights, i, edited);
    s.lightsPanel.message = error ? *error : std::string();
}

void clickLightCommand(CommandCall const& c) {
    EditorState& s = c.host.state;
    int const i = std::atoi(c.w[1].c_str());
    if (i < 0 || i >= int(s.lights.size())) return c.check(false, "no such light");
    glm::ivec2 const size(c.host.renderer.width(), c.host.renderer.height());
    if (size.x <= 0 || size.y <= 0) return c.check(false, "the viewport has no pixels");
    // The pixel whose centre sees the light's centre: project it as the renderer does.
    glm::vec4 const clip = s.camera.projection(float(size.x) / float(size.y)) * s.camera.view() *
                           glm::vec4(s.lights[std::size_t(i)].position, 1.0f);
    if (clip.w <= 0.0f) return c.check(false, "the light is behind the camera");
    glm::vec2 const ndc = glm::vec2(clip) / clip.w;
    glm::ivec2 const px(int((ndc.x * 0.5f + 0.5f) * float(size.x)), int((0.5f - ndc.y * 0.5f) * float(size.y)));
    c.host.clickViewport(px);
}

// shader-break and shader-fix edit only a copy of the shaders: editing the source tree would
// disturb everyone else working in it.
std::optional<std::string> shaderCopyPath(CommandCall const& c) {
    char const* dir = std::getenv("GBL_SHADER_DIR");
    if (!dir || !*dir) {
        c.check(false, "GBL_SHADER_DIR is not set; refusing to edit the source tree");
        return std::nullopt;
    }
    return (std::filesystem::path(dir) / c.w[1]).string();
}

void shaderBreakCommand(CommandCall const& c) {
    auto const path = shaderCopyPath(c);
    if (!path) return;
    std::ifstream in(*path);
    if (!in) return c.check(false, "cannot read " + *path);
    std::string const text((std::istreambuf_iterator<char>(in)), {});
    c.run.brokenShaders[c.w[1]] = text;
    std::ofstream(*path) << text << "\n#error broken on purpose by a UI test script\n";
}

void shaderFixCommand(CommandCall const& c) {
    auto const path = shaderCopyPath(c);
    if (!path) return;
    auto const it = c.run.brokenShaders.find(c.w[1]);
    if (it == c.run.brokenShaders.end()) return c.check(false, "not broken by shader-break");
    std::ofstream(*path) << it->second;
    c.run.brokenShaders.erase(it);
}

constexpr ScriptCommandSpec kEditCommands[] = {
    {"frames", "N", "run N frames before the next command",
     [](CommandCall const& c) { c.run.wait = std::max(std::atoi(c.w[1].c_str()), 1); }},
    {"set", "KEY VALUE",
     "FIELD VALUE for every pipeline field (listed under Pipeline fields below), animate 0|1,\n"
     "time SECONDS (light animation), lights N (default scene lights),\n"
     "accumulate K (-1: off), contribution 0|1, ab off|split|diff, ab-divider X,\n"
     "ab-metric lit|normal-angle, ab-threshold X, ab-angle-threshold DEGREES,\n"
     "b.FIELD VALUE (side B of A/B: the fields marked B below, as the Pipeline window's table)",
     setCommand},
    {"light", "I FIELD VALUE",
     "edit light I through the validated path the Lights panel uses;\n"
     "FIELD = x y z r g b kc kl kq intensity threshold dx dy dz inner outer (kLightFields),\n"
     "or kind point|spot|directional",
     lightCommand},
    {"select", "I", "select light I (as a click in the list does)",
     [](CommandCall const& c) { c.host.state.lightsPanel.selected = std::atoi(c.w[1].c_str()); }},
    {"click-light", "I", "click the pixel where light I's cube is drawn (ray pick)", clickLightCommand},
    {"frame-scene", "", "the F key", [](CommandCall const& c) { c.host.frameScene(); }},
    {"inspect", "X Y", "lock the pixel inspector on viewport pixel (X, Y)",
     [](CommandCall const& c) {
         auto& in = c.host.state.inspector;
         in.pixel = glm::ivec2(std::atoi(c.w[1].c_str()), std::atoi(c.w[2].c_str()));
         in.locked = true;
         in.source = "script";
     }},
    {"resize", "W H", "resize the window (0 0 minimises the viewport)",
     [](CommandCall const& c) { c.host.resizeWindow(std::atoi(c.w[1].c_str()), std::atoi(c.w[2].c_str())); }},
    {"measure", "N", "measure the editor's own cost over N frames and print it",
     [](CommandCall const& c) {
         CostMeasurement& m = c.host.state.measurement;
         m = CostMeasurement{};
         m.remaining = std::max(std::atoi(c.w[1].c_str()), 1);
         c.run.wait = m.remaining + 1;
     }},
    {"wait", "SECONDS", "run frames for SECONDS of wall-clock time",
     [](CommandCall const& c) {
         // Wall-clock time, for what is defined in seconds (undo merging, autosave delays).
         double const until = nowSeconds() + number(c.w[1]);
         c.waitUntil([until] { return nowSeconds() >= until; }, number(c.w[1]) + 3600.0);
     }},
    {"wait-log", "SECONDS TEXT...", "run frames until a log line contains TEXT (fails after SECONDS)",
     [](CommandCall const& c) {
         std::string const text = joinWords(c.w, 2);
         LogState const* log = &c.host.state.log;
         c.waitUntil(
             [log, text] {
                 return std::any_of(log->lines.begin(), log->lines.end(),
                                    [&](std::string const& line) { return line.find(text) != std::string::npos; });
             },
             number(c.w[1]));
     }},
    {"shader-break", "FILE", "append a compile error to FILE in $GBL_SHADER_DIR (never the source tree)",
     shaderBreakCommand},
    {"shader-fix", "FILE", "put FILE back as it was before shader-break", shaderFixCommand},
    {"frame-window", "on|off", "open or close the Frame window",
     [](CommandCall const& c) { c.host.state.frame.open = c.w[1] != "off"; }},
    {"frame-pass", "PASS", "select PASS in the Frame window (as a click on its box)",
     [](CommandCall const& c) {
         std::optional<PassId> const pass = passFromName(c.w[1]);
         c.check(bool(pass), pass ? std::string() : "no pass called " + c.w[1]);
         if (pass) c.host.state.frame.selected = pass;
     }},
    {"frame-stop", "PASS|off", "stop the editor's frames after PASS (the Frame window's Stop here), or not",
     [](CommandCall const& c) {
         std::optional<PassId> const pass = passFromName(c.w[1]);
         if (!pass && c.w[1] != "off") return c.check(false, "no pass called " + c.w[1]);
         c.host.state.frame.stopAfter = pass;
     }},
    {"print", "TEXT...", "print TEXT",
     [](CommandCall const& c) { std::printf("ui-test: %s\n", joinWords(c.w, 1).c_str()); }},
};

}  // namespace

std::span<ScriptCommandSpec const> editCommands() {
    return kEditCommands;
}

}  // namespace gbl::ui
