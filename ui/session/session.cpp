// Session JSON: writing, and reading with a full validation that names the offending field.
#include "session/session.h"

#include "core/json_fields.h"
#include "core/light_math.h"
#include "core/pipeline_fields.h"
#include "model/viewer_fields.h"
#include "session/atomic_file.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <optional>
#include <span>
#include <sstream>
#include <stdexcept>

namespace gbl::ui {

using nlohmann::json;

namespace {

using namespace json_fields;  // the field readers, FieldError and joinNames

// --- writing ------------------------------------------------------------------------------

// Written in a fixed, readable order (format and version first); reading does not care.
using ojson = nlohmann::ordered_json;

ojson vec(glm::vec3 v) {
    return {v.x, v.y, v.z};
}

// One viewer's settings, field by field from model/viewer_fields.h: a vector's components in one
// array, the tool fields in their own object.
ojson viewerJson(ViewerState const& v) {
    ojson out = ojson::object();
    ojson tools = ojson::object();
    for (ViewerField const& f : viewerFields()) {
        ojson& into = f.inTools ? tools : out;
        std::string const key(f.key);
        double const x = f.get(v);
        switch (f.kind) {
            case ViewerFieldKind::Mask:
                into[key] = unsigned(x);
                break;
            case ViewerFieldKind::Number:
                if (f.component < 0)
                    into[key] = float(x);
                else
                    into[key][std::size_t(f.component)] = float(x);
                break;
            case ViewerFieldKind::Toggle:
                into[key] = x != 0.0;
                break;
            case ViewerFieldKind::Choice:
                into[key] = f.names[std::size_t(x)];
                break;
            case ViewerFieldKind::Flags: {
                ojson names = ojson::array();
                for (std::size_t i = 0; i < f.names.size(); ++i)
                    if (unsigned(x) & (1u << i)) names.push_back(f.names[i]);
                into[key] = names;
                break;
            }
        }
    }
    out["tools"] = tools;
    return out;
}

ojson pipelineJson(PipelineSettings const& p) {
    ojson out = ojson::object();
    for (PipelineField const& f : pipelineFields()) {
        std::string const name(f.name);
        if (f.rgb)
            out[name] = vec(p.*f.rgb);
        else if (f.kind == SettingKind::Choice)
            out[name] = fieldScriptText(f, p);
        else if (f.kind == SettingKind::Toggle)
            out[name] = f.get(p) != 0.0;
        else
            out[name] = float(f.get(p));
    }
    return out;
}

ojson sessionJson(Session const& s) {
    ojson lights = ojson::array();
    for (auto const& l : s.lights) lights.push_back(lightJson<ojson>(l));
    ojson viewers = ojson::object();
    for (std::size_t i = 0; i < s.viewers.size(); ++i) viewers[std::string(kViewerNames[i])] = viewerJson(s.viewers[i]);
    ojson out = {
        {"format", kSessionFormat},
        {"version", kSessionVersion},
        {"scene", {{"source", s.scene}, {"default_scene_lights", s.defaultSceneLights}}},
        {"camera",
         {{"position", vec(s.camera.position)},
          {"yaw_degrees", s.camera.yawDegrees},
          {"pitch_degrees", s.camera.pitchDegrees},
          {"fov_y_degrees", s.camera.fovYDegrees},
          {"near", s.camera.nearPlane},
          {"far", s.camera.farPlane}}},
        {"lights", lights},
        {"pipeline", pipelineJson(s.pipeline)},
        {"viewers", viewers},
        {"animation", {{"enabled", s.animation.enabled}, {"speed", s.animation.speed}, {"time", s.animation.time}}},
        {"viewer_tools",
         {{"sync", s.syncViews},
          {"viewport", {{"open", s.viewportToolsOpen}, {"viewer", viewerJson(s.viewportViewer)}}}}},
    };
    if (s.defaultSceneGlass) out["scene"]["default_scene_glass"] = true;
    return out;
}

// --- reading ------------------------------------------------------------------------------

Camera readCamera(json const& j) {
    Object o(j, "camera", {"position", "yaw_degrees", "pitch_degrees", "fov_y_degrees", "near", "far"});
    Camera c;
    c.position = vector<3>(o.required("position"), o.field("position"));
    c.yawDegrees = number(o.required("yaw_degrees"), o.field("yaw_degrees"));
    // The editor's camera rig keeps pitch within 89 degrees; at 90 the view matrix degenerates.
    c.pitchDegrees = numberIn(o.required("pitch_degrees"), o.field("pitch_degrees"), -89.0f, 89.0f);
    c.fovYDegrees = numberIn(o.required("fov_y_degrees"), o.field("fov_y_degrees"), 1.0f, 179.0f);
    c.nearPlane = number(o.required("near"), o.field("near"), Bound::Positive);
    c.farPlane = number(o.required("far"), o.field("far"), Bound::Positive);
    if (c.farPlane <= c.nearPlane) fail(o.field("far"), "must be greater than camera.near");
    return c;
}

std::vector<PointLight> readLights(json const& j) {
    if (!j.is_array()) fail("lights", "must be an array (got " + typeName(j) + ")");
    if (j.size() > std::size_t(kMaxLights))
        fail("lights", "holds " + std::to_string(j.size()) + " lights; the limit is " + std::to_string(kMaxLights));
    std::vector<PointLight> lights;
    lights.reserve(j.size());
    for (std::size_t i = 0; i < j.size(); ++i) lights.push_back(readLight(j[i], "lights[" + std::to_string(i) + "]"));
    return lights;
}

// Every field of core/pipeline_fields.h, by its kind and within its range; the optional ones (added
// after the format's first version) keep their default when absent.
PipelineSettings readPipeline(json const& j) {
    std::vector<std::string_view> known;
    for (PipelineField const& f : pipelineFields()) {
        known.push_back(f.name);
        if (!f.oldName.empty()) known.push_back(f.oldName);
    }
    Object o(j, "pipeline", known);
    PipelineSettings p;
    for (PipelineField const& f : pipelineFields()) {
        // Files written before a field was renamed ("blit") keep loading under its old name.
        json const* v = o.optional(f.name);
        std::string_view key = f.name;
        if (!f.oldName.empty() && o.optional(f.oldName)) {
            if (v) fail(o.field(f.oldName), "is the old name of " + o.field(f.name) + ": give only one of them");
            v = o.optional(f.oldName);
            key = f.oldName;
        }
        if (!v && !f.optionalInFiles) o.required(f.name);
        if (!v) continue;
        std::string const path = o.field(key);
        if (f.rgb) {
            if (!v->is_array() || v->size() != 3) fail(path, "must be an array of 3 numbers");
            for (std::size_t i = 0; i < 3; ++i)
                (p.*f.rgb)[int(i)] = numberIn((*v)[i], path + "[" + std::to_string(i) + "]", f.min, f.max);
            continue;
        }
        switch (f.kind) {
            case SettingKind::Choice:
                f.set(p, double(choiceIndex(*v, path, f.choices)));
                break;
            case SettingKind::Toggle:
                f.set(p, boolean(*v, path) ? 1.0 : 0.0);
                break;
            case SettingKind::Number:
                f.set(p, numberIn(*v, path, f.min, f.max));
                break;
        }
    }
    return p;
}

// One field of a viewer from its file value `j` at `path`, checked against the field's range.
void readViewerField(ViewerField const& f, json const& j, std::string const& path, ViewerState& v) {
    switch (f.kind) {
        case ViewerFieldKind::Mask:
            f.set(v, double(integer(j, path, int(f.min), int(f.max))));
            return;
        case ViewerFieldKind::Number: {
            float const x = f.positive ? number(j, path, Bound::Positive) : numberIn(j, path, f.min, f.max);
            f.set(v, double(x));
            return;
        }
        case ViewerFieldKind::Toggle:
            f.set(v, boolean(j, path) ? 1.0 : 0.0);
            return;
        case ViewerFieldKind::Choice:
            f.set(v, double(choiceIndex(j, path, f.names)));
            return;
        case ViewerFieldKind::Flags: {
            if (!j.is_array())
                fail(path, "must be an array of names out of " + joinNames(f.names) + " (got " + typeName(j) + ")");
            unsigned bits = 0;
            for (std::size_t i = 0; i < j.size(); ++i)
                bits |= 1u << unsigned(choiceIndex(j[i], path + "[" + std::to_string(i) + "]", f.names));
            f.set(v, double(bits));
            return;
        }
    }
}

// A viewer's settings, field by field from model/viewer_fields.h: the viewer's own fields are
// required, the tool fields optional (files from before the tools lack them). Then what relates two
// fields: range_max above range_min, far above near, the stencil on the depth viewer only.
ViewerState readViewer(json const& j, std::string const& path, ViewerState v) {
    Object o(j, path, {viewerFileKeys().begin(), viewerFileKeys().end()});
    json const* toolsJson = o.optional("tools");
    std::optional<Object> tools;
    if (toolsJson)
        tools.emplace(*toolsJson, o.field("tools"),
                      std::vector<std::string_view>(viewerToolKeys().begin(), viewerToolKeys().end()));
    for (ViewerField const& f : viewerFields()) {
        json const* value = nullptr;
        std::string at;
        if (f.inTools) {
            if (!tools) continue;
            value = tools->optional(f.key);
            at = tools->field(f.key);
        } else {
            value = &o.required(f.key);
            at = o.field(f.key);
        }
        if (!value) continue;
        if (f.component >= 0) {
            if (!value->is_array() || value->size() != 2) fail(at, "must be an array of 2 numbers");
            at += '[';  // appended: "[" + string trips GCC 12 -O3's -Wrestrict
            at += std::to_string(f.component) + "]";
            value = &(*value)[std::size_t(f.component)];
        }
        readViewerField(f, *value, at, v);
    }
    if (v.rangeMax <= v.rangeMin) fail(o.field("range_max"), "must be greater than " + o.field("range_min"));
    if (v.farPlane <= v.nearPlane) fail(o.field("far"), "must be greater than " + o.field("near"));
    if (v.showStencil && v.kind != ViewerKind::Depth)
        fail(tools->field("stencil"), "must be false: only the depth viewer shows the stencil");
    return v;
}

Session readSession(json const& j) {
    if (!j.is_object()) fail("the file", "must hold a JSON object (got " + typeName(j) + ")");
    // Format and version first: a newer file should say so, not trip over its new fields.
    auto const formatIt = j.find("format");
    if (formatIt == j.end()) fail("format", "is missing");
    json const& format = *formatIt;
    if (!format.is_string() || format.get<std::string>() != kSessionFormat)
        fail("format", "must be \"" + std::string(kSessionFormat) + "\" (got " + format.dump() +
                           "); this is not a gbuffer-lab session");
    auto const versionIt = j.find("version");
    if (versionIt == j.end()) fail("version", "is missing");
    json const& version = *versionIt;
    if (!version.is_number_integer()) fail("version", "must be a whole number (got " + version.dump() + ")");
    if (version.get<long long>() != kSessionVersion)
        fail("version",
             std::to_string(version.get<long long>()) + " is not supported; this program reads version " +
                 std::to_string(kSessionVersion) +
                 (version.get<long long>() > kSessionVersion ? " (the file comes from a newer gbuffer-lab)" : ""));

    Object const root(
        j, "", {"format", "version", "scene", "camera", "lights", "pipeline", "viewers", "animation", "viewer_tools"});
    Session s;
    {
        Object scene(root.required("scene"), "scene", {"source", "default_scene_lights", "default_scene_glass"});
        s.scene = string(scene.required("source"), scene.field("source"));
        if (s.scene.empty()) fail(scene.field("source"), "must be \"default\" or the path of a glTF file (got \"\")");
        s.defaultSceneLights =
            integer(scene.required("default_scene_lights"), scene.field("default_scene_lights"), 0, kMaxLights);
        if (json const* glass = scene.optional("default_scene_glass"))
            s.defaultSceneGlass = boolean(*glass, scene.field("default_scene_glass"));
    }
    s.camera = readCamera(root.required("camera"));
    s.lights = readLights(root.required("lights"));
    s.pipeline = readPipeline(root.required("pipeline"));
    {
        static_assert(kViewerNames.size() == 5, "list every viewer in the known fields below");
        Object viewers(root.required("viewers"), "viewers",
                       {kViewerNames[0], kViewerNames[1], kViewerNames[2], kViewerNames[3], kViewerNames[4]});
        for (std::size_t i = 0; i < s.viewers.size(); ++i)
            s.viewers[i] = readViewer(viewers.required(kViewerNames[i]), viewers.field(kViewerNames[i]), s.viewers[i]);
    }
    {
        Object anim(root.required("animation"), "animation", {"enabled", "speed", "time"});
        s.animation.enabled = boolean(anim.required("enabled"), anim.field("enabled"));
        s.animation.speed = number(anim.required("speed"), anim.field("speed"));
        s.animation.time = number(anim.required("time"), anim.field("time"));
    }
    if (json const* toolsJ = root.optional("viewer_tools")) {
        Object tools(*toolsJ, "viewer_tools", {"sync", "viewport"});
        if (json const* sync = tools.optional("sync")) s.syncViews = boolean(*sync, tools.field("sync"));
        if (json const* viewportJ = tools.optional("viewport")) {
            Object viewport(*viewportJ, tools.field("viewport"), {"open", "viewer"});
            if (json const* open = viewport.optional("open"))
                s.viewportToolsOpen = boolean(*open, viewport.field("open"));
            if (json const* viewer = viewport.optional("viewer"))
                s.viewportViewer = readViewer(*viewer, viewport.field("viewer"), s.viewportViewer);
        }
    }
    return s;
}

}  // namespace

std::string sessionToJson(Session const& session) {
    return sessionJson(session).dump(2) + "\n";
}

SessionLoad parseSession(std::string_view text, std::string const& fileLabel) {
    SessionLoad out;
    json j;
    try {
        j = json::parse(text.begin(), text.end());
    } catch (json::exception const& e) {
        // nlohmann's message carries the line and column; drop its "[json.exception...]" prefix.
        std::string what = e.what();
        if (auto const close = what.find("] "); what.rfind("[json.exception", 0) == 0 && close != std::string::npos)
            what = what.substr(close + 2);
        out.error = fileLabel + ": not valid JSON: " + what;
        return out;
    }
    try {
        out.session = readSession(j);
    } catch (FieldError const& e) {
        out.error = fileLabel + ": " + e.what();
    } catch (json::exception const& e) {
        // Only reachable through a bug above (every access is checked first); still no crash.
        out.error = fileLabel + ": " + e.what();
    }
    return out;
}

SessionLoad loadSession(std::string const& path) {
    std::string error;
    auto text = readWholeFile(path, &error);
    if (!text) return {std::nullopt, "cannot read session: " + error};
    return parseSession(*text, path);
}

std::optional<std::string> saveSession(std::string const& path, Session const& session) {
    return writeFileAtomically(path, sessionToJson(session));
}

}  // namespace gbl::ui
