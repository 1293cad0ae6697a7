// Roles from the lighting program's sampler names (else from the data), camera from the geometry
// program's matrices, lights from the lighting program's uniform arrays.
#include "capture/capture_mapping.h"

#include "capture/camera_solve.h"
#include "image/image_io.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>

namespace gbl::capture {

namespace fs = std::filesystem;
using ojson = nlohmann::ordered_json;

namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}
bool has(std::string const& s, char const* part) {
    return s.find(part) != std::string::npos;
}

enum class Role { Position, Normal, Albedo, AlbedoSpecular, Specular, Emissive, Unknown };

Role roleFromName(std::string const& name) {
    std::string const n = lower(name);
    if (has(n, "pos")) return Role::Position;
    if (has(n, "norm")) return Role::Normal;
    bool const spec = has(n, "spec");
    if (has(n, "albedo") || has(n, "diffuse") || has(n, "colo") || has(n, "base"))
        return spec ? Role::AlbedoSpecular : Role::Albedo;
    if (spec) return Role::Specular;
    if (has(n, "emiss")) return Role::Emissive;
    return Role::Unknown;
}

// What the values say: unit-length vectors on most non-zero pixels are normals; other floats positions;
// an 8-bit colour target albedo, its alpha a specular candidate.
Role roleFromData(DumpedImage const& d, std::string* why) {
    if (!d.isFloat) {
        *why = "an 8-bit colour target (" + d.format + "): albedo, its alpha a specular candidate";
        return Role::AlbedoSpecular;
    }
    FloatImage const img = d.decode();
    std::size_t unit = 0, drawn = 0;
    for (std::size_t i = 0; i + 2 < img.pixels.size(); i += std::size_t(img.channels)) {
        glm::vec3 const v(img.pixels[i], img.pixels[i + 1], img.pixels[i + 2]);
        float const len = glm::length(v);
        if (len == 0.0f) continue;
        ++drawn;
        if (std::abs(len - 1.0f) < 0.01f) ++unit;
    }
    if (drawn > 0 && unit > drawn * 9 / 10) {
        *why = "its values are unit length on " + std::to_string(unit * 100 / drawn) + " % of the drawn pixels";
        return Role::Normal;
    }
    *why = "a float target whose values are not unit length";
    return Role::Position;
}

std::string uniformFor(StateDump const& lighting, int unit) {
    for (auto const& [name, value] : lighting.uniforms.items())
        if (value.is_number_integer() && value.get<int>() == unit) return name;
    return {};
}

std::optional<glm::mat4> matrixOf(nlohmann::json const& j) {
    if (!j.is_array() || j.size() != 4) return std::nullopt;
    for (auto const& c : j)
        if (!c.is_array() || c.size() != 4) return std::nullopt;
    glm::mat4 m;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) m[c][r] = j[std::size_t(c)][std::size_t(r)].get<float>();
    return m;
}
ojson columns(glm::mat4 const& m) {
    ojson a = ojson::array();
    for (int c = 0; c < 4; ++c) a.push_back({m[c][0], m[c][1], m[c][2], m[c][3]});
    return a;
}

// Camera from the geometry program's mat4 uniforms named as view / projection / view-projection.
// *noUniforms: there are none of them at all (the camera can then be solved from the positions).
std::optional<ojson> cameraFrom(StateDump const& geometry, std::string* missing, bool* noUniforms) {
    std::string viewName, projName, vpName;
    for (auto const& [name, value] : geometry.uniforms.items()) {
        if (!matrixOf(value)) continue;
        std::string const n = lower(name);
        if ((has(n, "viewproj") || has(n, "view_proj") || n == "vp" || n == "uvp"))
            vpName = name;
        else if (has(n, "proj"))
            projName = name;
        else if (has(n, "view") && !has(n, "model"))
            viewName = name;
    }
    if (!viewName.empty() && !projName.empty())
        return ojson{{"view", columns(*matrixOf(geometry.uniforms[viewName]))},
                     {"projection", columns(*matrixOf(geometry.uniforms[projName]))},
                     {"matrix_layout", "column-major"},
                     {"guessed_from", "the geometry program's uniforms " + viewName + " and " + projName}};
    if (!vpName.empty()) {
        if (auto split = splitViewProjection(*matrixOf(geometry.uniforms[vpName])))
            return ojson{{"view", columns(split->view)},
                         {"projection", columns(split->projection)},
                         {"matrix_layout", "column-major"},
                         {"guessed_from", "the geometry program's uniform " + vpName +
                                              ", split into a rigid view and a perspective projection"}};
        *missing = "the camera (" + vpName + " is not a perspective view-projection)";
        return std::nullopt;
    }
    *missing = "the camera (the geometry program has no view/projection mat4 uniforms";
    *noUniforms = true;
    return std::nullopt;
}

// The camera solved from the position attachment (and the depth attachment's depth rows, if any).
std::optional<ojson> solvedCamera(DumpedImage const& position, std::string const& positionName,
                                  DumpedImage const* depth, std::string* missing) {
    FloatImage const img = position.decode();
    FloatImage const depthImg = depth ? depth->decode() : FloatImage{};
    std::string why;
    auto const solved = solveCameraFromPositions(img, depthImg.pixels.empty() ? nullptr : &depthImg, &why);
    if (!solved) {
        *missing += ", and solving it from the positions failed: " + why + ")";
        return std::nullopt;
    }
    // Half a pixel: the positions are the surface at each pixel's centre, so a true camera fits far closer.
    if (solved->rmsPixels > 0.5) {
        char text[160];
        std::snprintf(text, sizeof text,
                      ", and the positions fit no perspective camera: %.2f px rms off their pixels after solving "
                      "(view-space positions, or not a pinhole camera?))",
                      solved->rmsPixels);
        *missing += text;
        return std::nullopt;
    }
    char text[320];
    std::snprintf(text, sizeof text,
                  "solved from the position attachment %s: %zu world positions and their pixel centres give the "
                  "view-projection by least squares (normalised direct linear transform), reprojection error "
                  "%.3f px rms, %.3f px at most; near and far %s",
                  positionName.c_str(), solved->samples, solved->rmsPixels, solved->maxPixels,
                  solved->depthFitted ? "fitted to the depth attachment" : "bracket the positions (no usable depth)");
    return ojson{{"view", columns(solved->view)},
                 {"projection", columns(solved->projection)},
                 {"matrix_layout", "column-major"},
                 {"guessed_from", text}};
}

// Lights: uniform arrays of the lighting program, "lights[2].Position" or "uLightPos" = [[...], ...].
ojson lightsFrom(StateDump const& lighting, std::vector<std::string>* unmapped) {
    std::map<std::string, std::map<int, nlohmann::json>> members;  // member -> index -> value
    std::set<std::string> names;
    static std::regex const structMember(R"(^(\w+)\[(\d+)\]\.(\w+)$)");
    for (auto const& [name, value] : lighting.uniforms.items()) {
        std::smatch m;
        if (std::regex_match(name, m, structMember) && has(lower(m[1].str()), "light")) {
            members[m[3].str()][std::stoi(m[2].str())] = value;
            names.insert(m[1].str() + "[i]." + m[3].str());
        } else if (has(lower(name), "light") && value.is_array() && !value.empty() &&
                   (value[0].is_array() || value[0].is_number())) {
            for (std::size_t i = 0; i < value.size(); ++i) members[name][int(i)] = value[i];
            names.insert(name);
        }
    }
    ojson l = ojson::object();
    std::string from;
    std::map<std::string, std::string> keyOf;  // member -> manifest key
    for (auto const& [member, values] : members) {
        std::string const n = lower(member);
        char const* key = has(n, "pos")                                               ? "positions"
                          : (has(n, "col") || has(n, "intens") || has(n, "radiance")) ? "colors"
                          : has(n, "lin")                                             ? "linear"
                          : has(n, "quad")                                            ? "quadratic"
                          : has(n, "radius")                                          ? "radius"
                                                                                      : nullptr;
        if (!key || l.contains(key)) {
            unmapped->push_back(member);
            continue;
        }
        ojson arr = ojson::array();
        for (auto const& [i, v] : values) arr.push_back(ojson::parse(v.dump()));
        l[key] = arr;
        from += (from.empty() ? "" : ", ") + member + " -> " + key;
    }
    if (!l.contains("positions")) return ojson();
    if (!l.contains("colors")) {
        unmapped->push_back("a light colour (every light is taken as white)");
        l["colors"] = ojson::array();
        for (std::size_t i = 0; i < l["positions"].size(); ++i) l["colors"].push_back({1, 1, 1});
    }
    for (char const* k : {"linear", "quadratic"})
        if (!l.contains(k)) {
            unmapped->push_back(std::string("the attenuation's ") + k +
                                " term (no uniform holds it: the shader may hard-code it; set lights." + k +
                                " by hand, 0 is taken)");
            l[k] = 0;
        }
    l["guessed_from"] = "the lighting program's uniforms: " + from;
    return l;
}

std::string safeName(std::string s) {
    for (char& c : s)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') c = '_';
    return s;
}

std::optional<std::string> writeImage(DumpedImage const& d, std::string const& base, std::string const& dir) {
    if (!d.isFloat) {
        std::ofstream(dir + "/" + base + ".png", std::ios::binary) << d.encoded;
        return base + ".png";
    }
    FloatImage const img = d.decode();
    if (img.pixels.empty()) return std::nullopt;
    if (writeExr(dir + "/" + base + ".exr", img)) return std::nullopt;
    return base + ".exr";
}

}  // namespace

std::optional<ViewProjection> splitViewProjection(glm::mat4 const& vp) {
    auto row = [&](int r) { return glm::vec4(vp[0][r], vp[1][r], vp[2][r], vp[3][r]); };
    glm::vec4 const r0 = row(0), r1 = row(1), r2 = row(2), r3 = row(3);
    float const s = glm::length(glm::vec3(r3));
    if (s < 1e-6f) return std::nullopt;
    glm::vec4 const v2 = -r3 / s;  // clip w = -z in view space, up to the scale s
    float const p02 = glm::dot(glm::vec3(r0), glm::vec3(v2)), p12 = glm::dot(glm::vec3(r1), glm::vec3(v2));
    glm::vec4 v0 = r0 - p02 * v2, v1 = r1 - p12 * v2;
    float p00 = glm::length(glm::vec3(v0)), p11 = glm::length(glm::vec3(v1));
    if (p00 < 1e-6f || p11 < 1e-6f) return std::nullopt;
    v0 /= p00;
    v1 /= p11;
    if (glm::dot(glm::cross(glm::vec3(v0), glm::vec3(v1)), glm::vec3(v2)) < 0.0f) return std::nullopt;
    float const p22 = glm::dot(glm::vec3(r2), glm::vec3(v2)), p23 = r2.w - p22 * v2.w;
    ViewProjection out;
    out.view = glm::mat4(1.0f);
    for (int c = 0; c < 4; ++c) {
        out.view[c][0] = v0[c];
        out.view[c][1] = v1[c];
        out.view[c][2] = v2[c];
    }
    out.projection = glm::mat4(0.0f);
    out.projection[0][0] = p00 / s;
    out.projection[2][0] = p02 / s;
    out.projection[1][1] = p11 / s;
    out.projection[2][1] = p12 / s;
    out.projection[2][2] = p22 / s;
    out.projection[3][2] = p23 / s;
    out.projection[2][3] = -1.0f;
    glm::mat4 const back = out.projection * out.view;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (std::abs(back[c][r] - vp[c][r]) > 1e-3f * (1.0f + std::abs(vp[c][r]))) return std::nullopt;
    return out;
}

std::optional<CaptureResult> writeCapture(TraceScan const& scan, StateDump const& geometry, StateDump const& lighting,
                                          CaptureSource const& source, std::string const& dir, std::string* error) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    ojson m{{"format", "gbuffer-lab-gbuffer"}, {"version", 1}, {"flip_y", false}};
    std::vector<std::string> unmapped;
    std::set<Role> taken;
    DumpedImage const* positionImage = nullptr;  // for a camera solved from it
    std::string positionName;
    // The sampled attachments first, by the lighting program's sampler names, then the data.
    for (auto const& [attachment, unit] : scan.sampledAttachments) {
        auto const img = geometry.framebuffer.find(attachment);
        if (img == geometry.framebuffer.end()) continue;
        std::string const sampler = uniformFor(lighting, unit);
        Role role = roleFromName(sampler);
        std::string why = "the lighting program samples it as " + sampler;
        if (role == Role::Unknown || taken.count(role)) {
            std::string dataWhy;
            role = roleFromData(img->second, &dataWhy);
            why = (sampler.empty() ? "no sampler name" : "the sampler name " + sampler + " says nothing") +
                  std::string("; ") + dataWhy;
        }
        if (taken.count(role)) {
            unmapped.push_back(attachment + " (" + sampler + ")");
            continue;
        }
        taken.insert(role);
        auto const file = writeImage(img->second, safeName(sampler.empty() ? attachment : sampler), dir);
        if (!file) {
            *error = "the " + attachment + " image of the dump could not be written into " + dir;
            return std::nullopt;
        }
        switch (role) {
            case Role::Position:
                positionImage = &img->second;
                positionName = sampler.empty() ? attachment : sampler;
                m["position"] = {{"file", *file}, {"channels", "rgb"}, {"space", "world"}, {"guessed_from", why}};
                break;
            case Role::Normal:
                m["normal"] = {{"file", *file},
                               {"channels", "rgb"},
                               {"encoding", img->second.isFloat ? "float" : "biased"},
                               {"space", "world"},
                               {"guessed_from", why + (img->second.isFloat ? "; float storage" : "; 8-bit storage")}};
                break;
            case Role::Albedo:
            case Role::AlbedoSpecular:
                m["albedo"] = {{"file", *file}, {"channels", "rgb"}, {"encoding", "linear"}, {"guessed_from", why}};
                if (role == Role::AlbedoSpecular && img->second.format.find("RGBA") != std::string::npos) {
                    m["specular"] = {{"file", *file}, {"channel", "a"}, {"guessed_from", why + ", its alpha"}};
                    taken.insert(Role::Specular);
                }
                break;
            case Role::Specular:
                m["specular"] = {{"file", *file}, {"channel", "r"}, {"guessed_from", why}};
                break;
            case Role::Emissive:
                m["emissive"] = {{"file", *file}, {"channels", "rgb"}, {"guessed_from", why}};
                break;
            case Role::Unknown:
                break;
        }
    }
    if (!m.contains("position") || !m.contains("normal")) {
        *error = std::string("the lighting pass samples no ") + (m.contains("position") ? "normal" : "position") +
                 " attachment that could be told apart (it samples " + std::to_string(scan.sampledAttachments.size()) +
                 " of the G-buffer's targets)";
        return std::nullopt;
    }
    DumpedImage const* depthImage = nullptr;
    char const* depthKey = nullptr;
    for (char const* key : {"GL_DEPTH_ATTACHMENT", "GL_DEPTH_STENCIL_ATTACHMENT"})
        if (auto d = geometry.framebuffer.find(key); d != geometry.framebuffer.end() && d->second.isFloat) {
            depthImage = &d->second;
            depthKey = key;
            break;
        }
    std::string cameraMissing;
    bool noCameraUniforms = false;
    auto camera = cameraFrom(geometry, &cameraMissing, &noCameraUniforms);
    if (!camera && noCameraUniforms) {
        if (positionImage && positionImage->isFloat)
            camera = solvedCamera(*positionImage, positionName, depthImage, &cameraMissing);
        else
            cameraMissing += ", and no float position attachment to solve it from)";
    }
    if (camera) {
        m["camera"] = *camera;
        if (depthImage)
            if (auto file = writeImage(*depthImage, "depth", dir))
                m["depth"] = {{"file", *file},
                              {"channel", "r"},
                              {"convention", "window"},
                              {"guessed_from", std::string("the G-buffer's ") + depthKey}};
    } else {
        unmapped.push_back(cameraMissing);
    }
    ojson lights = lightsFrom(lighting, &unmapped);
    if (!lights.is_null())
        m["lights"] = lights;
    else
        unmapped.push_back("the lights (no uniform array of the lighting program names a light position)");

    for (char const* litKey : {"GL_BACK", "GL_COLOR_ATTACHMENT0"})
        if (auto lit = lighting.framebuffer.find(litKey); lit != lighting.framebuffer.end()) {
            if (auto file = writeImage(lit->second, "lit", dir))
                m["lit"] = {{"file", *file},
                            {"channels", "rgb"},
                            {"guessed_from", std::string("the lighting draw's target ") + litKey + " after the draw"}};
            break;
        }
    // The equation: LearnOpenGL's unless told otherwise; its exponent read from a pow(…, N) if there is one.
    std::string const shader =
        lighting.shaders.count("GL_FRAGMENT_SHADER") ? lighting.shaders.at("GL_FRAGMENT_SHADER") : "";
    std::ofstream(dir + "/lighting.frag") << shader;
    m["shading"] = "learnopengl";
    std::smatch pw;
    static std::regex const powLiteral(R"(pow\s*\([^;]*,\s*([0-9]+(\.[0-9]*)?)\s*\))");
    std::string shininessFrom = "LearnOpenGL's 16 (no pow(..., N) with a literal exponent in lighting.frag)";
    if (std::regex_search(shader, pw, powLiteral)) {
        m["shininess"] = std::stod(pw[1].str());
        shininessFrom = "the literal exponent of pow() in lighting.frag";
    }
    std::string const unmappedText = unmapped.empty() ? std::string() : [&] {
        std::string s = "not mapped: ";
        for (std::size_t i = 0; i < unmapped.size(); ++i) s += (i ? "; " : "") + unmapped[i];
        return s;
    }();
    m["capture"] = {
        {"trace", source.trace},
        {"frame", source.frame},
        {"geometry_call", scan.lastGeometryDraw.value_or(0)},
        {"lighting_call", scan.lightingDraw.value_or(0)},
        {"gbuffer_framebuffer", scan.gbufferFramebuffer},
        {"lighting_shader", "lighting.frag"},
        {"notes",
         {{"flip_y", "false: the retracer writes rows top to bottom"},
          {"shading", "learnopengl: assumed for a captured program; compare lighting.frag with docs/lighting.md"},
          {"shininess", shininessFrom}}},
        {"unmapped", unmappedText}};
    std::string const path = dir + "/manifest.json";
    std::ofstream out(path);
    out << m.dump(2) << "\n";
    if (!out) {
        *error = "cannot write " + path;
        return std::nullopt;
    }
    return CaptureResult{path, unmappedText};
}

}  // namespace gbl::capture
