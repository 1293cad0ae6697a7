// The files of one exported frame: images through OpenImageIO, descriptions as JSON.
#include "frame_export.h"

#include "core/depth.h"
#include "core/frame_memory.h"
#include "core/gbuffer_layout.h"
#include "core/json_fields.h"
#include "core/light_math.h"
#include "image/image_io.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

namespace gbl {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

json toJson(glm::mat4 const& m) {
    json rows = json::array();
    for (int r = 0; r < 4; ++r) rows.push_back({m[0][r], m[1][r], m[2][r], m[3][r]});  // row-major for readers
    return rows;
}

json toJson(glm::vec3 v) {
    return {v.x, v.y, v.z};
}

std::optional<std::string> writeJson(fs::path const& path, json const& j) {
    std::ofstream f(path);
    f << j.dump(2) << "\n";
    f.close();
    if (!f) return "cannot write " + path.string();
    return std::nullopt;
}

char const* radiusKindName(RadiusKind k) {
    switch (k) {
        case RadiusKind::Quadratic:
            return "quadratic";
        case RadiusKind::Linear:
            return "linear";
        case RadiusKind::Capped:
            return "capped";
        case RadiusKind::Zero:
            return "zero";
    }
    return "zero";
}

}  // namespace

char const* const kPrepassExportNote =
    "prepass keeps a thin G-buffer: normal.exr and specular_exponent.exr are prepass.normal_exp's "
    "(raw_prepass_normal_exp.exr as stored), depth.exr its lit depth and position.exr rebuilt from it; it "
    "stores no albedo, specular intensity, emission or occlusion, so albedo.png, specular.png, emissive.exr "
    "and the layout's raw_ files are not written";

FloatImage linearDepthImage(FloatImage depth, Camera const& cam) {
    for (float& z : depth.pixels) z = linearDepth(z, cam.nearPlane, cam.farPlane);
    return depth;
}

FloatImage specularImage(FloatImage const& albedo) {
    FloatImage s{albedo.width, albedo.height, 1, {}};
    s.pixels.reserve(albedo.pixels.size() / 4);
    for (std::size_t i = 3; i < albedo.pixels.size(); i += 4) s.pixels.push_back(albedo.pixels[i]);
    return s;
}

std::optional<std::pair<float, float>> readableViewRange(DebugView view, FloatImage const& position,
                                                         FloatImage const& depth, Camera const& camera) {
    std::vector<float> values;
    if (view == DebugView::Position && position.channels == 4) {
        for (std::size_t i = 0; i + 3 < position.pixels.size(); i += 4) {
            if (position.pixels[i + 3] == 0.0f) continue;  // alpha 0: nothing drawn there
            for (std::size_t c = 0; c < 3; ++c)
                if (std::isfinite(position.pixels[i + c])) values.push_back(position.pixels[i + c]);
        }
    } else if ((view == DebugView::Depth || view == DebugView::DepthLinear) && depth.channels == 1) {
        for (float const d : depth.pixels) {
            if (!(d < 1.0f)) continue;  // the cleared far plane: background
            float const v = view == DebugView::Depth ? d : linearDepth(d, camera.nearPlane, camera.farPlane);
            if (std::isfinite(v)) values.push_back(v);
        }
    }
    if (values.empty()) return std::nullopt;
    std::sort(values.begin(), values.end());
    // Nearest rank: the smallest value with at least p % of the values at or below it.
    auto rank = [&](double p) {
        std::size_t const n = values.size();
        std::size_t const k = std::size_t(std::ceil(p / 100.0 * double(n)));
        return values[std::clamp<std::size_t>(k, 1, n) - 1];
    };
    float const low = rank(1.0), high = rank(99.0);
    return std::make_pair(low, high > low ? high : low + 1e-6f);
}

std::optional<std::string> exportFrame(Renderer& renderer, FrameExport const& frame, std::string const& dir) {
    fs::path const out(dir);
    auto path = [&](std::string const& name) { return (out / name).string(); };
    std::optional<std::string> err;
    auto check = [&](std::optional<std::string> e) {
        if (e && !err) err = e;
    };
    // A prepass frame's G-buffer is its thin one (docs/deferred_lighting.md): the read-backs below
    // read it (position rebuilt from the lit depth), and what it does not store is not written.
    bool const thin = frame.stats.modeUsed == LightingMode::Prepass;
    FloatImage const albedo = renderer.readAttachment(Attachment::AlbedoSpec);
    FloatImage const depth = renderer.readAttachment(Attachment::Depth);
    check(writePng(path("final.png"), renderer.readAttachment(Attachment::Final), 3));
    check(writeExr(path("lighting.exr"), renderer.readAttachment(Attachment::Lighting)));
    FloatImage const position = renderer.readAttachment(Attachment::Position);
    check(writeExr(path("position.exr"), position));
    check(writeExr(path("normal.exr"), renderer.readAttachment(Attachment::Normal)));
    if (thin) {
        check(writeExr(path("specular_exponent.exr"), specularImage(albedo)));
        check(writeExr(path("raw_prepass_normal_exp.exr"), renderer.readAttachment(Attachment::PrepassNormal)));
    } else {
        check(writePng(path("albedo.png"), albedo, 3));
        check(writePng(path("specular.png"), specularImage(albedo)));
        // Emitted radiance (rgb) and ambient occlusion (a), decoded: the same in every layout that stores
        // them; a layout that does not (packed) writes what it decodes, emission 0 and occlusion 1.
        check(writeExr(path("emissive.exr"), renderer.readAttachment(Attachment::Emissive)));
    }
    // The accumulation targets, when the frame used them (docs/lighting.md, "Accumulation targets"),
    // and prepass's light targets.
    if (frame.stats.accumulationUsed == LightAccumulation::Split || thin) {
        check(writeExr(path("diffuse_light.exr"), renderer.readAttachment(Attachment::DiffuseLight)));
        check(writeExr(path("specular_light.exr"), renderer.readAttachment(Attachment::SpecularLight)));
    }
    check(writeExr(path("depth.exr"), depth));
    check(writeExr(path("depth_linear.exr"), linearDepthImage(depth, frame.camera)));
    // Every attachment of the layout as stored: 8-bit ones as PNG (exact), the others as EXR.
    GBufferLayoutDesc const& layout = layoutDesc(renderer.layout());
    for (int i = 0; i < (thin ? 0 : layout.attachmentCount); ++i) {  // prepass drew none of them
        GBufferAttachmentDesc const& a = layout.attachments()[std::size_t(i)];
        FloatImage const raw = renderer.readRawAttachment(i);
        std::string const base = "raw_" + std::string(a.name);
        check(a.format == TexelFormat::RGBA8 ? writePng(path(base + ".png"), raw) : writeExr(path(base + ".exr"), raw));
    }
    if (frame.stats.msaaUsed != Msaa::Off) {  // docs/msaa.md: the complex pixels, and every sample as stored
        check(writePng(path("complex_pixels.png"), renderer.readAttachment(Attachment::ComplexPixels)));
        for (GBufferAttachmentDesc const& a : layout.attachments())  // the depth too: position rebuilds from it
            for (int k = 0; k < msaaSamples(frame.stats.msaaUsed); ++k)
                check(writeExr(path("raw_" + std::string(a.name) + "_s" + std::to_string(k) + ".exr"),
                               renderer.readMsaaSample(a.slot, k)));
    }
    for (DebugView v : frame.extraViews) {
        ViewTarget target;
        ViewParams params;
        params.view = v;
        if (auto const range = readableViewRange(v, position, depth, frame.camera)) {
            params.rangeMin = range->first;
            params.rangeMax = range->second;
        }
        renderer.drawView(params, {frame.camera, frame.lights, frame.settings}, target);
        check(writePng(path("view_" + std::string(enumName(kDebugViewNames, v)) + ".png"),
                       renderer.readViewTarget(target), 3));
    }
    if (err) return err;

    json lightsJson = json::array();
    for (auto const& l : frame.lights) {
        LightRadius const r = lightRadius(l);
        // The light as session files write it (core/json_fields.h), and what the renderer made of it.
        json entry = json_fields::lightJson<json>(l);
        entry["radius"] = r.radius;
        entry["radius_kind"] = radiusKindName(r.kind);
        lightsJson.push_back(std::move(entry));
    }
    int const width = renderer.width(), height = renderer.height();
    Camera const& cam = frame.camera;
    float const aspect = float(width) / float(height);
    json const cameraJson = {{"position", toJson(cam.position)},
                             {"yaw_degrees", cam.yawDegrees},
                             {"pitch_degrees", cam.pitchDegrees},
                             {"fov_y_degrees", cam.fovYDegrees},
                             {"near", cam.nearPlane},
                             {"far", cam.farPlane},
                             {"aspect", aspect},
                             {"view", toJson(cam.view())},
                             {"projection", toJson(cam.projection(aspect))},
                             {"matrix_layout", "row-major: view[r][c]"}};
    json passes = json::object();
    for (auto const& p : frame.stats.passes) passes[p.name] = p.gpuMs;
    // Per pass, what it issued (draws, dispatches, triangles); triangles_drawn below is their sum.
    json const calls = json_fields::passCallsJson(frame.stats.calls);
    GlCaps const& caps = renderer.caps();
    PipelineSettings const& s = frame.settings;
    // The screen-sized memory of the mode that ran (core/frame_memory.h), part by part.
    FrameMemory const memory = frameMemory(frame.stats.modeUsed, layout, width, height, caps.maxStorageBlockBytes);
    json memoryParts = json::object();
    for (MemoryPart const& part : memory.parts) memoryParts[part.name] = part.bytesPerPixel;
    json statsJson = {{"gl_vendor", caps.vendor},
                      {"gl_renderer", caps.renderer},
                      {"gl_version", caps.version},
                      {"width", width},
                      {"height", height},
                      {"lights", frame.stats.lightsSubmitted},
                      {"lights_shaded", frame.stats.lightsShaded},
                      {"mode", enumName(kLightingModeNames, s.mode)},
                      {"cull", enumName(kCullModeNames, s.cull)},
                      {"depth_copy", enumName(kDepthCopyNames, s.depthCopy)},
                      {"layout", layout.name},
                      // forward and forward+ write no G-buffer: 0 (bytes_per_pixel counts what they do write); prepass
                      // its thin one (below)
                      {"gbuffer_bytes_per_pixel", memory.gbuffer ? layoutBytesPerPixel(layout) : 0},
                      {"bytes_per_pixel", memory.bytesPerPixel()},
                      {"memory", memoryParts},
                      {"accumulation", enumName(kLightAccumulationNames, frame.stats.accumulationUsed)},
                      {"gpu_ms", passes},
                      {"gpu_frame_ms", frame.stats.gpuFrameMs},
                      {"calls", calls},
                      {"timing", frame.stats.timingSource},
                      {"timing_reason", frame.stats.timingReason},
                      {"triangles", frame.triangles},                // the scene's
                      {"triangles_drawn", frame.stats.triangles()},  // every pass's (calls), summed
                      {"gl_errors", renderer.glErrorCount()}};
    // The pass a stopped frame (`render --until`) ended at, before its display pass; null: every pass ran.
    statsJson["stopped_after"] = frame.stats.stoppedAfter ? json(passName(*frame.stats.stoppedAfter)) : json(nullptr);
    // msaa (docs/msaa.md): the sample count that ran (off after a refusal), and the complex pixels' share.
    statsJson["msaa"] = enumName(kMsaaNames, frame.stats.msaaUsed);
    if (frame.stats.msaaUsed != Msaa::Off) {
        statsJson["msaa_lighting"] = enumName(kMsaaLightingNames, s.msaaLighting);
        statsJson["complex_pixel_share"] = frame.stats.complexPixelShare.value_or(renderer.complexPixelShare());
    }
    if (frame.stats.modeUsed == LightingMode::Prepass) {  // its own thin G-buffer and light targets
        statsJson["gbuffer_bytes_per_pixel"] = prepassThinBytesPerPixel(layout);
        statsJson["light_buffer_bytes_per_pixel"] = kPrepassLightBytesPerPixel;
    }
    if (!frame.stats.fallbackReason.empty()) statsJson["fallback_reason"] = frame.stats.fallbackReason;
    if (frame.stats.fragmentInvocations) statsJson["fragment_invocations"] = *frame.stats.fragmentInvocations;
    // A layout that does not store emission and occlusion says so (emissive.exr is then 0 rgb, 1 a).
    if (std::string const note = layoutOmissionNote(layout); !note.empty()) statsJson["gbuffer_note"] = note;
    if (thin) statsJson["gbuffer_note"] = kPrepassExportNote;
    check(writeJson(out / "lights.json", lightsJson));
    check(writeJson(out / "camera.json", cameraJson));
    check(writeJson(out / "stats.json", statsJson));
    return err;
}

}  // namespace gbl
