// The headless render command.
#include "render_command.h"

#include "cli_values.h"
#include "image_io.h"
#include "light_math.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace gbl {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

int badArgument(std::string const& message) {
    std::fprintf(stderr, "gbuffer-lab render: %s\n", message.c_str());
    return 2;
}

json toJson(glm::mat4 const& m) {
    json rows = json::array();
    for (int r = 0; r < 4; ++r) rows.push_back({m[0][r], m[1][r], m[2][r], m[3][r]});  // row-major for readers
    return rows;
}

json toJson(glm::vec3 v) { return {v.x, v.y, v.z}; }

bool writeJson(fs::path const& path, json const& j, std::string* error) {
    std::ofstream f(path);
    f << j.dump(2) << "\n";
    if (!f) *error = "cannot write " + path.string();
    return bool(f);
}

// The directory exists (or was created) and a file can be written into it.
std::optional<std::string> prepareOutDir(std::string const& dir) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) return "cannot create output directory " + dir + ": " + ec.message();
    fs::path const probe = fs::path(dir) / ".gbuffer-lab-write-test";
    std::ofstream f(probe);
    if (!f) return "output directory " + dir + " is not writable";
    f.close();
    fs::remove(probe, ec);
    return std::nullopt;
}

}  // namespace

void addRenderOptions(CLI::App& sub, RenderOptions& o) {
    sub.add_option("--out", o.outDir, "Directory for the images and JSON files")->required();
    sub.add_option("--size", o.size, "Frame size WxH")->capture_default_str();
    sub.add_option("--lights", o.lights, "Number of lights (default scene: 32)");
    sub.add_option("--time", o.time, "Seconds of light animation")->capture_default_str();
    sub.add_option("--blit", o.blit, "Depth copy before the forward pass: blit, shader or off")->capture_default_str();
    sub.add_option("--mode", o.mode, "Lighting mode: quad, volumes, tiled or forward")->capture_default_str();
    sub.add_option("--cull", o.cull, "Light volume cull mode: back, front, none, flip or stencil")->capture_default_str();
    sub.add_option("--view", o.views, "Extra debug view(s) to write as view_NAME.png");
    sub.add_option("--scene", o.scene, "A glTF 2.0 scene instead of the default scene");
    sub.add_flag("--allow-outside-uris", o.allowOutsideUris, "Let the glTF file read files outside its folder");
    sub.add_option("--gl", o.glLimit, "Pretend the context is at most this OpenGL version, e.g. 3.3");
}

int runRender(RenderOptions const& o) {
    std::string error;
    auto const size = parseSize(o.size, &error);
    if (!size) return badArgument(error);
    if (o.lights && *o.lights < 0) return badArgument("--lights must be 0 or more, got " + std::to_string(*o.lights));
    if (o.lights && *o.lights > kMaxLights)
        return badArgument("--lights is limited to " + std::to_string(kMaxLights) + ", got " + std::to_string(*o.lights));
    PipelineSettings settings;
    auto const mode = enumFromName<LightingMode>(kLightingModeNames, o.mode);
    auto const cull = enumFromName<CullMode>(kCullModeNames, o.cull);
    auto const blit = enumFromName<DepthCopy>(kDepthCopyNames, o.blit);
    if (!mode) return badArgument("--mode must be quad, volumes, tiled or forward, got '" + o.mode + "'");
    if (!cull) return badArgument("--cull must be back, front, none, flip or stencil, got '" + o.cull + "'");
    if (!blit) return badArgument("--blit must be blit, shader or off, got '" + o.blit + "'");
    std::vector<DebugView> views;
    for (auto const& name : o.views) {
        auto v = enumFromName<DebugView>(kDebugViewNames, name);
        if (!v) return badArgument("--view '" + name + "' is not one of final, lighting, position, normal, albedo, "
                                   "specular, depth, depth_linear, heatmap, tile_lights");
        views.push_back(*v);
    }
    settings.mode = *mode;
    settings.cull = *cull;
    settings.depthCopy = *blit;
    if (auto err = prepareOutDir(o.outDir)) return badArgument(*err);

    SceneRequest request{o.scene, o.lights, o.time, o.allowOutsideUris};
    auto prepared = prepareScene(request, &error);
    if (!prepared) return badArgument(error);

    auto headless = createHeadlessRenderer(size->width, size->height, o.glLimit, &error);
    if (!headless) {
        std::fprintf(stderr, "gbuffer-lab render: %s\n", error.c_str());
        return 1;
    }
    Renderer& renderer = *headless->renderer;
    if (settings.mode == LightingMode::Tiled && !renderer.caps().computeShaders)
        return badArgument(renderer.caps().tiledUnavailableReason());
    if (auto err = renderer.setScene(prepared->scene)) return badArgument(*err);

    FrameStats const stats = renderer.render({prepared->camera, prepared->lights, settings, true});

    fs::path const out(o.outDir);
    auto path = [&](char const* name) { return (out / name).string(); };
    FloatImage const finalImage = renderer.readAttachment(Attachment::Final);
    FloatImage const lighting = renderer.readAttachment(Attachment::Lighting);
    FloatImage const position = renderer.readAttachment(Attachment::Position);
    FloatImage const normal = renderer.readAttachment(Attachment::Normal);
    FloatImage const albedo = renderer.readAttachment(Attachment::AlbedoSpec);
    FloatImage const depth = renderer.readAttachment(Attachment::Depth);
    FloatImage depthLinear = depth;
    Camera const& cam = prepared->camera;
    for (float& z : depthLinear.pixels) {
        // Eye-space distance along the view axis, the inverse of the perspective depth mapping.
        float const ndc = z * 2.0f - 1.0f;
        z = 2.0f * cam.nearPlane * cam.farPlane / (cam.farPlane + cam.nearPlane - ndc * (cam.farPlane - cam.nearPlane));
    }
    std::optional<std::string> err;
    auto check = [&](std::optional<std::string> e) {
        if (e && !err) err = e;
    };
    check(writePng(path("final.png"), finalImage, 3));
    check(writeExr(path("lighting.exr"), lighting));
    check(writeExr(path("position.exr"), position));
    check(writeExr(path("normal.exr"), normal));
    check(writePng(path("albedo.png"), albedo, 3));
    check(writePng(path("specular.png"), FloatImage{albedo.width, albedo.height, 1, [&] {
                                              std::vector<float> a;
                                              a.reserve(albedo.pixels.size() / 4);
                                              for (std::size_t i = 3; i < albedo.pixels.size(); i += 4) a.push_back(albedo.pixels[i]);
                                              return a;
                                          }()}));
    check(writeExr(path("depth.exr"), depth));
    check(writeExr(path("depth_linear.exr"), depthLinear));
    for (DebugView v : views) {
        ViewTarget target;
        ViewParams params;
        params.view = v;
        renderer.drawView(params, cam, target);
        check(writePng((out / ("view_" + std::string(enumName(kDebugViewNames, v)) + ".png")).string(),
                       renderer.readViewTarget(target), 3));
    }
    if (err) return badArgument(*err);

    json lightsJson = json::array();
    for (auto const& l : prepared->lights) {
        LightRadius const r = lightRadius(l);
        lightsJson.push_back({{"name", l.name}, {"position", toJson(l.position)}, {"color", toJson(l.color)},
                              {"intensity", l.intensity}, {"kc", l.kc}, {"kl", l.kl}, {"kq", l.kq},
                              {"threshold", l.threshold}, {"radius", r.radius},
                              {"radius_kind", r.kind == RadiusKind::Quadratic ? "quadratic"
                                              : r.kind == RadiusKind::Linear  ? "linear"
                                              : r.kind == RadiusKind::Capped  ? "capped"
                                                                              : "zero"}});
    }
    float const aspect = float(size->width) / float(size->height);
    json cameraJson = {{"position", toJson(cam.position)}, {"yaw_degrees", cam.yawDegrees},
                       {"pitch_degrees", cam.pitchDegrees}, {"fov_y_degrees", cam.fovYDegrees},
                       {"near", cam.nearPlane}, {"far", cam.farPlane}, {"aspect", aspect},
                       {"view", toJson(cam.view())}, {"projection", toJson(cam.projection(aspect))},
                       {"matrix_layout", "row-major: view[r][c]"}};
    json passes = json::object();
    for (auto const& p : stats.passes) passes[p.name] = p.gpuMs;
    GlCaps const& caps = renderer.caps();
    json statsJson = {{"gl_vendor", caps.vendor}, {"gl_renderer", caps.renderer}, {"gl_version", caps.version},
                      {"width", size->width}, {"height", size->height}, {"lights", stats.lightsSubmitted},
                      {"lights_shaded", stats.lightsShaded}, {"mode", o.mode}, {"cull", o.cull}, {"blit", o.blit},
                      {"gpu_ms", passes}, {"gpu_frame_ms", stats.gpuFrameMs},
                      {"triangles", prepared->scene.triangleCount()},
                      {"gl_errors", renderer.glErrorCount()}};
    if (stats.fragmentInvocations) statsJson["fragment_invocations"] = *stats.fragmentInvocations;
    if (!writeJson(out / "lights.json", lightsJson, &error) || !writeJson(out / "camera.json", cameraJson, &error) ||
        !writeJson(out / "stats.json", statsJson, &error))
        return badArgument(error);
    std::printf("wrote %s (%dx%d, %d lights, %.2f GPU ms, %llu GL errors)\n", o.outDir.c_str(), size->width,
                size->height, stats.lightsSubmitted, stats.gpuFrameMs, (unsigned long long)renderer.glErrorCount());
    return 0;
}

}  // namespace gbl
