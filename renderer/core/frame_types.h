// Plain records of a frame: which images it keeps, what each pass cost, what one pixel holds.
// Shared by the renderer, the editor's model and the tests; no GL here.
#pragma once

#include <glm/glm.hpp>

#include "core/frame_passes.h"
#include "core/pipeline_settings.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace gbl {

// Images the renderer keeps per frame. Values are what the pass wrote, exactly as stored.
enum class Attachment {
    // Position and Normal are decoded as the lighting reads them (stored or rebuilt from depth,
    // whatever the layout's encoding), as float RGBA; Renderer::readRawAttachment gives the bits.
    Position,    // world-space position, w = 1 where geometry was drawn
    Normal,      // world-space unit normal, w = 1 where drawn
    AlbedoSpec,  // RGBA8 linear albedo, alpha = specular intensity
    Depth,       // DEPTH32F_STENCIL8 window-space depth of the geometry pass
    // The stencil bits of that same depth-stencil texture, read back as 1 channel of the integer
    // values 0..255. Only the stencil cull of the volumes mode writes it (in classic; the layouts
    // that rebuild position mark a copy, RenderTargets::volumeDepth), and every shade visit resets
    // its marks to 0, so after a whole frame it reads 0 wherever the frame cleared it.
    Stencil,
    Lighting,  // RGBA16F HDR lit image (lighting + forward passes, before tonemap)
    // RG32F: x = lights evaluated at the pixel, y = lights that lit it. Read back with 2 channels;
    // filled only by a frame (or view) showing the heat map or the lights-per-tile view.
    Coverage,
    Final,  // RGBA8 display image: tonemapped, gamma-encoded, or the chosen debug view
    // The G-buffer's emissive attachment: rgb = emitted radiance (linear), a = ambient occlusion
    // (1 = unoccluded). RGBA16F in classic, RGBA8 in the other layouts.
    Emissive,
    // The accumulation targets of `accumulation: split` (RGBA16F): diffuse light (without albedo)
    // and specular light; zero after a single-target frame.
    DiffuseLight,
    SpecularLight,
    // msaa (docs/msaa.md): R8, 1 where the msaa_edges pass found the pixel's samples to differ (its
    // complex pixels); read back with 1 channel; zero without an msaa frame.
    ComplexPixels,
    // prepass (docs/deferred_lighting.md): its thin G-buffer's one colour target as stored, RGBA16F:
    // world normal xyz, specular exponent w (0 where nothing was drawn). After a prepass frame,
    // Position, Normal, AlbedoSpec and Depth read that thin G-buffer too (Renderer::readAttachment).
    PrepassNormal,
};

struct PassTiming {
    std::string name;
    double gpuMs = 0.0;
};

// What a pass issued this frame (gl/draw_count.h): glDraw* calls, an instanced draw counting one,
// the triangles they drew (every instance's), and compute dispatches.
struct PassCalls {
    std::string name;
    std::uint64_t draws = 0;
    std::uint64_t dispatches = 0;
    std::uint64_t triangles = 0;
};

struct FrameStats {
    int width = 0;
    int height = 0;
    std::vector<PassTiming> passes;  // in frame order
    std::vector<PassCalls> calls;    // this frame's passes in order; the timings may be an earlier frame's
    double gpuFrameMs = 0.0;         // sum of the passes
    // How the pass times were measured (gpu_timestamps | cpu_finish, gl/gpu_timer.h) and why.
    std::string timingSource;
    std::string timingReason;
    int lightsSubmitted = 0;
    int lightsShaded = 0;                              // lights with a radius > 0
    std::optional<std::uint64_t> fragmentInvocations;  // lighting pass, when pipeline statistics exist
    std::uint64_t glErrors = 0;                        // errors reported while rendering this frame
    // The lighting mode that actually ran; differs from the requested one only after a fallback
    // (a mode unavailable on this context runs quad), and then fallbackReason says why.
    LightingMode modeUsed = LightingMode::Quad;
    GBufferLayout layout = GBufferLayout::Classic;  // the G-buffer layout the frame used
    // The accumulation that ran: split is refused in forward mode (fallbackReason says why).
    LightAccumulation accumulationUsed = LightAccumulation::Single;
    // The msaa that ran: off where the frame refused it (fallbackReason says why; docs/msaa.md).
    Msaa msaaUsed = Msaa::Off;
    // The share of pixels its msaa_edges pass found complex (0..1); nullopt without msaa.
    std::optional<double> complexPixelShare;
    std::string fallbackReason;
    // The shader-checks build's report of this frame's out-of-range accesses (gl/shader_checks.h);
    // empty when there were none or the checks are off.
    std::string shaderCheckReport;
    // The pass the frame stopped after (FrameInput::stopAfter); nullopt: it ran every pass.
    std::optional<PassId> stoppedAfter = std::nullopt;

    // The frame's draw calls and triangles, its passes' (calls) summed.
    std::uint64_t draws() const {
        std::uint64_t n = 0;
        for (PassCalls const& c : calls) n += c.draws;
        return n;
    }
    std::uint64_t triangles() const {
        std::uint64_t n = 0;
        for (PassCalls const& c : calls) n += c.triangles;
        return n;
    }
};

// Everything stored at one pixel, read back as floats (for the pixel inspector and tests).
struct PixelSample {
    bool covered = false;                   // geometry was drawn here
    glm::vec4 position{0.0f};               // decoded, as the lighting read it
    glm::vec4 normal{0.0f};                 // decoded unit normal
    glm::vec4 rawNormal{0.0f};              // the normal attachment as stored (the layout's encoding)
    glm::vec4 albedoSpec{0.0f};             // thinGBuffer: (0, 0, 0, specular exponent)
    glm::vec4 emissiveAo{0.0f};             // emitted radiance rgb, ambient occlusion a
    float depth = 1.0f;                     // window-space depth 0..1
    unsigned stencil = 0;                   // the G-buffer's stencil bits 0..255
    glm::vec3 reconstructedPosition{0.0f};  // world position rebuilt from depth and the camera
    glm::vec4 lighting{0.0f};
    // The count heat maps' exact counts here (x: lights evaluated, y: lights that lit it), for the
    // view and mode they were last counted for since the frame rendered; no view: none counted.
    glm::vec2 coverage{0.0f};
    std::optional<DebugView> coverageView;
    LightingMode coverageMode = LightingMode::Quad;
    // Read from a prepass frame's thin G-buffer: normal and exponent from prepass.normal_exp,
    // position rebuilt from the lit depth, no albedo, emission or occlusion stored.
    bool thinGBuffer = false;
};

// Float image read back from a target, rows top to bottom.
struct FloatImage {
    int width = 0;
    int height = 0;
    int channels = 0;
    std::vector<float> pixels;
    float at(int x, int y, int c) const { return pixels[(std::size_t(y) * width + x) * channels + c]; }
};

// What a layout without the emissive_ao attachment decodes (shaders/gbuffer_read.glsl,
// gbufferEmissiveAo under GBUFFER_NO_EMISSIVE_AO): no emission (rgb 0), no occlusion (a 1).
inline constexpr glm::vec4 kNoEmissiveAo{0.0f, 0.0f, 0.0f, 1.0f};

// Light cubes are drawn unlit with the light's colour times this, in HDR: bright enough to read as
// emissive, low enough that tonemapping keeps their hue.
inline constexpr float kLightCubeEmissive = 1.5f;

}  // namespace gbl
