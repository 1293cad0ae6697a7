// Reading the G-buffer manifest: presets merged under the file's fields, then every field checked
// with a message naming it (the same phrasing as session files, docs/sessions.md).
#include "import/gbuffer_manifest.h"

#include "core/json_fields.h"
#include "core/light_math.h"

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace gbl {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

using namespace json_fields;  // the field readers and FieldError, shared with session files

// "rgb", "a", "xy": channel letters, each naming an index of the file's channels.
std::vector<int> channelList(json const& j, std::string const& field, std::size_t count) {
    std::string const text = string(j, field);
    std::string const want = "must be " + std::to_string(count) + " of the letters r, g, b, a (or x, y, z, w)";
    if (text.size() != count) fail(field, want + " (got " + j.dump() + ")");
    std::vector<int> channels;
    for (char c : text) {
        std::size_t const rgba = std::string_view("rgba").find(c), xyzw = std::string_view("xyzw").find(c);
        if (rgba == std::string_view::npos && xyzw == std::string_view::npos)
            fail(field, want + " (got " + j.dump() + ")");
        channels.push_back(int(rgba != std::string_view::npos ? rgba : xyzw));
    }
    return channels;
}

// --- attachments --------------------------------------------------------------------------

struct Reader {
    std::string dir;

    std::vector<std::string_view> withImageFields(std::vector<std::string_view> fields) const {
        fields.insert(fields.end(), {"file", "raw"});
        return fields;
    }

    ImageRef image(Object const& o, std::string const& name, std::string_view channelsKey,
                   std::string_view defaultChannels) const {
        ImageRef ref;
        ref.field = name;
        std::string const file = string(o.required("file"), o.field("file"));
        if (file.empty()) fail(o.field("file"), "must name a file");
        ref.path = fs::path(file).is_absolute() ? file : (fs::path(dir) / file).string();
        json const def = std::string(defaultChannels);
        json const* ch = o.optional(channelsKey);
        ref.channels = channelList(ch ? *ch : def, o.field(channelsKey), defaultChannels.size());
        if (json const* r = o.optional("raw")) {
            Object ro(*r, o.field("raw"), {"type", "width", "height", "channels"});
            RawFormat f;
            f.type = enumeration<RawType>(ro.required("type"), ro.field("type"), kRawTypeNames);
            f.width = integer(ro.required("width"), ro.field("width"), 1, 65536);
            f.height = integer(ro.required("height"), ro.field("height"), 1, 65536);
            f.channels = integer(ro.required("channels"), ro.field("channels"), 1, 4);
            ref.raw = f;
        }
        return ref;
    }
};

CameraMatrices readMatrixCamera(Object const& o) {
    // Every matrix is given as 4 arrays of 4 numbers or 16 numbers; matrix_layout says whether the
    // arrays (or runs of 4) are rows or columns. It is never guessed.
    std::string const layoutField = o.field("matrix_layout");
    std::string const layout = string(o.required("matrix_layout"), layoutField);
    if (layout != "row-major" && layout != "column-major")
        fail(layoutField, "must be one of row-major or column-major (got \"" + layout + "\")");
    bool const rowMajor = layout == "row-major";
    auto matrix = [&](std::string_view key) {
        json const& j = o.required(key);
        std::string const field = o.field(key);
        std::vector<float> v;
        if (j.is_array() && j.size() == 4) {
            for (std::size_t i = 0; i < 4; ++i) {
                std::string const f = field + "[" + std::to_string(i) + "]";
                if (!j[i].is_array() || j[i].size() != 4) fail(f, "must be an array of 4 numbers");
                for (std::size_t k = 0; k < 4; ++k) v.push_back(number(j[i][k], f + "[" + std::to_string(k) + "]"));
            }
        } else if (j.is_array() && j.size() == 16) {
            for (std::size_t i = 0; i < 16; ++i) v.push_back(number(j[i], field + "[" + std::to_string(i) + "]"));
        } else {
            fail(field, "must be 4 arrays of 4 numbers or an array of 16 numbers");
        }
        glm::mat4 m;
        for (int a = 0; a < 4; ++a)
            for (int b = 0; b < 4; ++b) {
                float const x = v[std::size_t(a * 4 + b)];
                if (rowMajor)
                    m[b][a] = x;  // row a, column b (glm indexes columns first)
                else
                    m[a][b] = x;
            }
        double const det = glm::determinant(glm::dmat4(m));
        if (!std::isfinite(det) || std::abs(det) < 1e-12)
            fail(field, "is singular (determinant " + std::to_string(det) +
                            "): it has no inverse, so no pixel can be placed in the world");
        return m;
    };
    CameraMatrices c;
    c.view = matrix("view");
    c.projection = matrix("projection");
    c.position = glm::vec3(glm::inverse(c.view)[3]);
    // A perspective projection of OpenGL's form: P[2][2] = -(f+n)/(f-n), P[3][2] = -2fn/(f-n).
    float const a = c.projection[2][2], b = c.projection[3][2];
    if (c.projection[2][3] == -1.0f && std::abs(a + 1.0f) > 1e-9f && std::abs(a - 1.0f) > 1e-9f) {
        float const n = b / (a - 1.0f), f = b / (a + 1.0f);
        if (n > 0.0f && f > n) {
            c.nearPlane = n;
            c.farPlane = f;
        }
    }
    return c;
}

CameraMatrices readCamera(json const& j) {
    Object o(j, "camera",
             {"position", "target", "up", "fov_y_degrees", "near", "far", "view", "projection", "matrix_layout"});
    if (o.optional("view") || o.optional("projection") || o.optional("matrix_layout")) {
        for (char const* k : {"position", "target", "up", "fov_y_degrees", "near", "far"})
            if (o.optional(k)) fail(o.field(k), "cannot be given with camera.view and camera.projection");
        return readMatrixCamera(o);
    }
    CameraMatrices c;
    c.position = vector<3>(o.required("position"), o.field("position"));
    glm::vec3 const target = vector<3>(o.required("target"), o.field("target"));
    glm::vec3 up(0.0f, 1.0f, 0.0f);
    if (json const* u = o.optional("up")) up = vector<3>(*u, o.field("up"));
    glm::vec3 const forward = target - c.position;
    if (glm::dot(forward, forward) <= 0.0f) fail(o.field("target"), "must differ from camera.position");
    glm::vec3 const side = glm::cross(forward, up);
    if (glm::dot(side, side) <= 1e-12f * glm::dot(forward, forward) * glm::dot(up, up))
        fail(o.field("up"), "must not be zero or parallel to the viewing direction (the view matrix is singular)");
    float const fov = number(o.required("fov_y_degrees"), o.field("fov_y_degrees"));
    if (fov < 1.0f || fov > 179.0f)
        fail(o.field("fov_y_degrees"), "must be between 1 and 179 (got " + std::to_string(fov) + ")");
    c.fovYDegrees = fov;
    c.nearPlane = number(o.required("near"), o.field("near"), Bound::Positive);
    c.farPlane = number(o.required("far"), o.field("far"), Bound::Positive);
    if (*c.farPlane <= *c.nearPlane) fail(o.field("far"), "must be greater than camera.near");
    c.view = glm::lookAt(c.position, target, up);
    return c;
}

// The arrays a LearnOpenGL-style program uploads: lightPositions, lightColors and per light (or
// one for all) Linear, Quadratic and an optional Radius, with Constant 1.
std::vector<PointLight> readArrayLights(json const& j) {
    Object o(j, "lights", {"positions", "colors", "linear", "quadratic", "radius"});
    json const& positions = o.required("positions");
    if (!positions.is_array())
        fail(o.field("positions"), "must be an array of [x, y, z] (got " + typeName(positions) + ")");
    std::size_t const n = positions.size();
    if (n > std::size_t(kMaxLights))
        fail(o.field("positions"),
             "holds " + std::to_string(n) + " lights; the limit is " + std::to_string(kMaxLights));
    json const& colors = o.required("colors");
    if (!colors.is_array() || colors.size() != n)
        fail(o.field("colors"),
             "must be an array of " + std::to_string(n) + " [r, g, b], one per lights.positions entry");
    // One number for every light, or one per light.
    auto perLight = [&](json const& v, std::string const& field, std::size_t i, Bound bound) {
        if (v.is_array()) {
            if (v.size() != n) fail(field, "must be a number or an array of " + std::to_string(n) + " numbers");
            return number(v[i], field + "[" + std::to_string(i) + "]", bound);
        }
        return number(v, field, bound);
    };
    json const& linear = o.required("linear");
    json const& quadratic = o.required("quadratic");
    std::vector<PointLight> lights;
    for (std::size_t i = 0; i < n; ++i) {
        std::string const idx = "[" + std::to_string(i) + "]";
        PointLight l;
        l.name = "light " + std::to_string(i);
        l.position = vector<3>(positions[i], o.field("positions") + idx);
        l.color = vector<3>(colors[i], o.field("colors") + idx, Bound::NonNegative);
        l.kc = 1.0f;
        l.kl = perLight(linear, o.field("linear"), i, Bound::NonNegative);
        l.kq = perLight(quadratic, o.field("quadratic"), i, Bound::NonNegative);
        if (json const* r = o.optional("radius")) perLight(*r, o.field("radius"), i, Bound::NonNegative);
        if (auto err = validateLight(l)) fail("lights" + idx + ":", *err);
        lights.push_back(l);
    }
    return lights;
}

// --- presets ------------------------------------------------------------------------------

json presetJson(std::string const& name) {
    if (name == "learnopengl")
        // LearnOpenGL's deferred chapter: gPosition RGB16F and gNormal RGB16F in world space,
        // gAlbedoSpec RGBA8 with the specular intensity in alpha; its lighting shader's exponent 16.
        return json::parse(R"({
          "position": {"file": "gPosition.exr", "channels": "rgb", "space": "world"},
          "normal": {"file": "gNormal.exr", "channels": "rgb", "encoding": "float", "space": "world"},
          "albedo": {"file": "gAlbedoSpec.png", "channels": "rgb", "encoding": "linear"},
          "specular": {"file": "gAlbedoSpec.png", "channel": "a"},
          "shininess": 16, "shading": "learnopengl"})");
    if (name == "newcastle")
        // Newcastle University's deferred tutorial: depth, RGB8 normals stored as 0.5 n + 0.5,
        // colour; position comes back from depth through the inverse view-projection.
        return json::parse(R"({
          "position": {"from_depth": true},
          "depth": {"file": "depth.exr", "channel": "r", "convention": "window"},
          "normal": {"file": "normal.png", "channels": "rgb", "encoding": "biased", "space": "world"},
          "albedo": {"file": "colour.png", "channels": "rgb", "encoding": "linear"}})");
    // gbuffer-lab's own `render --out` folder (frame_export.h): decoded position (w = 1 where drawn)
    // and normal, 8-bit albedo and specular, emission and occlusion decoded (emissive.exr: rgb and
    // a; 0 and 1 from a layout that stores neither), window-space depth, the lit HDR image.
    return json::parse(R"({
      "position": {"file": "position.exr", "channels": "rgb", "space": "world", "coverage": "a"},
      "normal": {"file": "normal.exr", "channels": "rgb", "encoding": "float", "space": "world"},
      "albedo": {"file": "albedo.png", "channels": "rgb", "encoding": "linear"},
      "specular": {"file": "specular.png", "channel": "r"},
      "emissive": {"file": "emissive.exr", "channels": "rgb", "encoding": "linear"},
      "occlusion": {"file": "emissive.exr", "channel": "a"},
      "depth": {"file": "depth.exr", "channel": "r", "convention": "window"},
      "lit": {"file": "lighting.exr", "channels": "rgb"}})");
}

std::optional<json> exportFolderJson(fs::path const& dir, std::string* error);

GBufferManifest readManifest(json j, std::string const& dir) {
    if (!j.is_object()) fail("the manifest", "must be a JSON object (got " + typeName(j) + ")");
    // Format and version first, so a newer file is reported as newer rather than as unknown fields.
    auto const fmt = j.find("format");
    if (fmt == j.end())
        fail("format", "is missing (a G-buffer manifest starts with \"format\": \"gbuffer-lab-gbuffer\")");
    if (string(*fmt, "format") != kManifestFormat)
        fail("format", "must be \"" + std::string(kManifestFormat) + "\" (got " + fmt->dump() + ")");
    auto const ver = j.find("version");
    if (ver == j.end()) fail("version", "is missing");
    int const version = integer(*ver, "version", 1, 1 << 20);
    if (version != kManifestVersion)
        fail("version", std::to_string(version) + " is not supported; this program reads version " +
                            std::to_string(kManifestVersion));
    GBufferManifest m;
    if (auto p = j.find("preset"); p != j.end()) {
        m.preset = std::string(kManifestPresetNames[std::size_t(enumeration<int>(*p, "preset", kManifestPresetNames))]);
        // The file's fields patch the preset's: "normal": {"space": "view"} changes that alone.
        json merged = presetJson(m.preset);
        // Position is a file or rebuilt from depth: naming either replaces the preset's whole entry.
        if (auto pos = j.find("position");
            pos != j.end() && pos->is_object() && (pos->contains("file") || pos->contains("from_depth")))
            merged.erase("position");
        merged.merge_patch(j);
        j = std::move(merged);
        // The gbuffer-lab preset is a `render --out` folder: its camera.json and lights.json come with it,
        // unless the manifest gives its own.
        std::string ignored;
        if (m.preset == "gbuffer-lab" && (!j.contains("camera") || !j.contains("lights")))
            if (auto folder = exportFolderJson(fs::path(dir), &ignored))
                for (char const* key : {"camera", "lights"})
                    if (!j.contains(key)) j[key] = (*folder)[key];
    }
    // A captured manifest (gbuffer-lab capture) says per field why it was chosen, and keeps what it
    // found in "capture": notes for the reader, not read here.
    for (auto& [key, value] : j.items())
        if (value.is_object()) value.erase("guessed_from");
    Object top(j, "",
               {"format", "version", "preset", "flip_y", "shininess", "shading", "position", "normal", "albedo",
                "specular", "emissive", "occlusion", "depth", "lit", "camera", "lights", "capture"});
    Reader reader{dir};
    if (json const* f = top.optional("flip_y")) m.flipY = boolean(*f, "flip_y");
    if (json const* s = top.optional("shading"))
        m.shading = enumeration<ShadingModel>(*s, "shading", kShadingModelNames);
    if (json const* s = top.optional("shininess"))
        m.shininess = number(*s, "shininess", Bound::Positive);
    else if (m.shading == ShadingModel::LearnOpenGl)
        m.shininess = kLearnOpenGlShininess;  // that text's lighting shader's exponent

    json const& pj = top.required("position");
    if (pj.is_object() && pj.contains("from_depth")) {
        Object o(pj, "position", {"from_depth"});
        if (!boolean(o.required("from_depth"), "position.from_depth"))
            fail("position.from_depth", "must be true, or left out and position.file given");
        m.positionFromDepth = true;
    } else {
        Object o(pj, "position", reader.withImageFields({"channels", "space", "coverage"}));
        PositionSpec p;
        p.image = reader.image(o, "position", "channels", "rgb");
        if (json const* s = o.optional("space")) p.space = enumeration<Space>(*s, o.field("space"), kSpaceNames);
        if (json const* c = o.optional("coverage")) {
            p.coverageChannel = channelList(*c, o.field("coverage"), 1)[0];
            p.image.channels.push_back(*p.coverageChannel);  // read along as a fourth channel
        }
        m.position = p;
    }
    {
        Object o(top.required("normal"), "normal", reader.withImageFields({"channels", "encoding", "space"}));
        NormalSpec& n = m.normal;
        n.encoding = enumeration<NormalEncoding>(o.required("encoding"), o.field("encoding"), kNormalEncodingNames);
        n.image = reader.image(o, "normal", "channels", n.encoding == NormalEncoding::Octahedral ? "rg" : "rgb");
        if (json const* s = o.optional("space")) n.space = enumeration<Space>(*s, o.field("space"), kSpaceNames);
    }
    if (json const* a = top.optional("albedo"); a && !a->is_null()) {
        Object o(*a, "albedo", reader.withImageFields({"channels", "encoding"}));
        AlbedoSpec s;
        s.image = reader.image(o, "albedo", "channels", "rgb");
        if (json const* e = o.optional("encoding"))
            s.encoding = enumeration<ColorEncoding>(*e, o.field("encoding"), kColorEncodingNames);
        m.albedo = s;
    }
    if (json const* s = top.optional("specular"); s && !s->is_null()) {
        Object o(*s, "specular", reader.withImageFields({"channel"}));
        m.specular = reader.image(o, "specular", "channel", "r");
    }
    if (json const* e = top.optional("emissive"); e && !e->is_null()) {
        Object o(*e, "emissive", reader.withImageFields({"channels", "encoding", "scale"}));
        EmissiveSpec s;
        s.image = reader.image(o, "emissive", "channels", "rgb");
        if (json const* c = o.optional("encoding"))
            s.encoding = enumeration<ColorEncoding>(*c, o.field("encoding"), kColorEncodingNames);
        if (json const* k = o.optional("scale")) s.scale = number(*k, o.field("scale"), Bound::NonNegative);
        m.emissive = s;
    }
    if (json const* a = top.optional("occlusion"); a && !a->is_null()) {
        Object o(*a, "occlusion", reader.withImageFields({"channel"}));
        m.occlusion = reader.image(o, "occlusion", "channel", "r");
    }
    if (json const* l = top.optional("lit"); l && !l->is_null()) {
        Object o(*l, "lit", reader.withImageFields({"channels"}));
        m.lit = reader.image(o, "lit", "channels", "rgb");
    }
    if (json const* c = top.optional("camera"); c && !c->is_null()) m.camera = readCamera(*c);
    if (json const* d = top.optional("depth"); d && !d->is_null()) {
        Object o(*d, "depth", reader.withImageFields({"channel", "convention", "near", "far"}));
        DepthSpec s;
        s.image = reader.image(o, "depth", "channel", "r");
        s.convention =
            enumeration<DepthConvention>(o.required("convention"), o.field("convention"), kDepthConventionNames);
        json const* n = o.optional("near");
        json const* f = o.optional("far");
        if (n)
            s.nearPlane = number(*n, o.field("near"), Bound::Positive);
        else if (m.camera && m.camera->nearPlane)
            s.nearPlane = *m.camera->nearPlane;
        else
            fail(o.field("near"), "is missing, and the camera gives none (a perspective projection or camera.near)");
        if (f)
            s.farPlane = number(*f, o.field("far"), Bound::Positive);
        else if (m.camera && m.camera->farPlane)
            s.farPlane = *m.camera->farPlane;
        else
            fail(o.field("far"), "is missing, and the camera gives none (a perspective projection or camera.far)");
        if (s.farPlane <= s.nearPlane) fail(o.field("far"), "must be greater than depth.near");
        m.depth = s;
    }
    if (m.positionFromDepth) {
        if (!m.depth) fail("position.from_depth", "needs a depth attachment (depth.file)");
        if (!m.camera) fail("position.from_depth", "needs the camera (its inverse view-projection places each pixel)");
    }
    if (json const* l = top.optional("lights"); l && !l->is_null()) {
        if (l->is_object()) {
            m.lights = readArrayLights(*l);
        } else if (l->is_array()) {
            if (l->size() > std::size_t(kMaxLights))
                fail("lights",
                     "holds " + std::to_string(l->size()) + " lights; the limit is " + std::to_string(kMaxLights));
            for (std::size_t i = 0; i < l->size(); ++i)
                m.lights.push_back(readLight((*l)[i], "lights[" + std::to_string(i) + "]"));
        } else {
            fail("lights", "must be a session light list (an array) or LearnOpenGL-style arrays (an object) (got " +
                               typeName(*l) + ")");
        }
    }
    return m;
}

// gbuffer-lab's own export folder as a manifest: the preset plus camera.json and lights.json.
std::optional<json> exportFolderJson(fs::path const& dir, std::string* error) {
    auto readJson = [&](fs::path const& p) -> std::optional<json> {
        std::ifstream f(p);
        if (!f) {
            *error = dir.string() + ": no manifest.json, and not a `render --out` folder (" + p.filename().string() +
                     " is missing)";
            return std::nullopt;
        }
        json j = json::parse(f, nullptr, false);
        if (j.is_discarded()) {
            *error = p.string() + ": not valid JSON";
            return std::nullopt;
        }
        return j;
    };
    auto camera = readJson(dir / "camera.json");
    if (!camera) return std::nullopt;
    auto lights = readJson(dir / "lights.json");
    if (!lights) return std::nullopt;
    json m = {{"format", kManifestFormat}, {"version", kManifestVersion}, {"preset", "gbuffer-lab"}};
    json cam = json::object();
    for (char const* k : {"view", "projection"})
        if (camera->contains(k)) cam[k] = (*camera)[k];
    cam["matrix_layout"] = "row-major";  // camera.json's "matrix_layout": "row-major: view[r][c]"
    m["camera"] = cam;
    // lights.json is a session light list plus the derived radius, which a manifest does not take.
    if (lights->is_array())
        for (json& l : *lights)
            if (l.is_object()) {
                l.erase("radius");
                l.erase("radius_kind");
            }
    m["lights"] = *lights;
    return m;
}

}  // namespace

CameraMatrices cameraForSize(CameraMatrices camera, int width, int height) {
    if (camera.fovYDegrees > 0.0f && width > 0 && height > 0)
        camera.projection = glm::perspective(glm::radians(camera.fovYDegrees), float(width) / float(height),
                                             *camera.nearPlane, *camera.farPlane);
    return camera;
}

ManifestLoad parseManifest(std::string_view text, std::string const& label, std::string const& dir) {
    ManifestLoad out;
    json j;
    try {
        j = json::parse(text);
    } catch (json::exception const& e) {  // parse_error, and out_of_range for a number like 1e400
        // nlohmann's message carries the line and column; its "[json.exception...] " prefix goes.
        std::string what = e.what();
        if (auto const close = what.find("] "); what.rfind("[json.exception", 0) == 0 && close != std::string::npos)
            what = what.substr(close + 2);
        out.error = label + ": not valid JSON: " + what;
        return out;
    }
    try {
        GBufferManifest m = readManifest(std::move(j), dir);
        m.label = label;
        out.manifest = std::move(m);
    } catch (FieldError const& e) {
        out.error = label + ": " + e.what();
    } catch (json::exception const& e) {
        out.error = label + ": " + e.what();
    }
    return out;
}

ManifestLoad loadManifest(std::string const& path) {
    fs::path const p(path);
    std::error_code ec;
    if (fs::is_directory(p, ec)) {
        if (fs::exists(p / "manifest.json")) return loadManifest((p / "manifest.json").string());
        ManifestLoad out;
        auto j = exportFolderJson(p, &out.error);
        if (!j) return out;
        return parseManifest(j->dump(), p.filename().empty() ? path : p.filename().string() + "/", path);
    }
    std::ifstream f(p, std::ios::binary);
    if (!f) return {std::nullopt, path + ": cannot read the manifest (no such file, or no permission)"};
    std::ostringstream s;
    s << f.rdbuf();
    return parseManifest(s.str(), p.filename().string(), p.parent_path().string());
}

void applyManifestShading(float shininess, ShadingModel shading, PipelineSettings& settings) {
    settings.shininess = shininess;
    settings.shading = shading;
    if (shading == ShadingModel::LearnOpenGl) settings.ambient = glm::vec3(kLearnOpenGlAmbient);
}

}  // namespace gbl
