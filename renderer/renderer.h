// The deferred renderer: owns the GPU scene, the screen-sized targets and the frame sequence.
// One instance serves the headless `render`/`bench` commands, the tests and the editor.
#pragma once

#include "camera.h"
#include "gl_caps.h"
#include "pipeline_settings.h"
#include "point_light.h"
#include "scene_data.h"
#include "view_pass.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace gbl {

// Images the renderer keeps per frame. Values are what the pass wrote, exactly as stored.
enum class Attachment {
    Position,    // RGBA16F world-space position, w = 1 where geometry was drawn
    Normal,      // RGBA16F world-space unit normal, w = 1 where drawn
    AlbedoSpec,  // RGBA8 linear albedo, alpha = specular intensity
    Depth,       // DEPTH32F_STENCIL8 window-space depth of the geometry pass
    Lighting,    // RGBA16F HDR lit image (lighting + forward passes, before tonemap)
    Final,       // RGBA8 display image: tonemapped, gamma-encoded, or the chosen debug view
};

struct PassTiming {
    std::string name;
    double gpuMs = 0.0;
};

struct FrameStats {
    int width = 0;
    int height = 0;
    std::vector<PassTiming> passes;  // in frame order
    double gpuFrameMs = 0.0;         // sum of the passes
    int lightsSubmitted = 0;
    int lightsShaded = 0;            // lights with a radius > 0
    std::optional<std::uint64_t> fragmentInvocations;  // lighting pass, when pipeline statistics exist
    std::uint64_t glErrors = 0;      // errors reported while rendering this frame
    // The lighting mode that actually ran; differs from the requested one only after a fallback
    // (tiled without compute shaders runs quad), and then fallbackReason says why.
    LightingMode modeUsed = LightingMode::Quad;
    std::string fallbackReason;
};

struct FrameInput {
    Camera camera;
    std::span<PointLight const> lights;
    PipelineSettings settings;
    // true: block until this frame's GPU timings exist (render, bench, tests); false: report
    // the previous frame's timings so an interactive frame never waits on the GPU.
    bool waitForGpuTimings = true;
};

// Everything stored at one pixel, read back as floats (for the pixel inspector and tests).
struct PixelSample {
    bool covered = false;          // geometry was drawn here
    glm::vec4 position{0.0f};
    glm::vec4 normal{0.0f};
    glm::vec4 albedoSpec{0.0f};
    float depth = 1.0f;            // window-space depth 0..1
    glm::vec3 reconstructedPosition{0.0f};  // world position rebuilt from depth and the camera
    glm::vec4 lighting{0.0f};
};

// Float image read back from a target, rows top to bottom.
struct FloatImage {
    int width = 0;
    int height = 0;
    int channels = 0;
    std::vector<float> pixels;
    float at(int x, int y, int c) const { return pixels[(std::size_t(y) * width + x) * channels + c]; }
};

// Light cubes are drawn unlit with the light's colour times this, in HDR: bright enough to read as
// emissive, low enough that tonemapping keeps their hue.
inline constexpr float kLightCubeEmissive = 1.5f;

class RendererImpl;

class Renderer {
public:
    // Needs a current GL 3.3+ context. Throws std::runtime_error naming the shader and log when
    // the embedded shaders fail to build (a bug, not user input).
    Renderer(GlCaps caps, int width, int height);
    ~Renderer();
    Renderer(Renderer const&) = delete;
    Renderer& operator=(Renderer const&) = delete;

    GlCaps const& caps() const;

    // Rebuilds every screen-sized target. 0x0 (a minimised window) is allowed: render() then
    // draws nothing until a real size arrives.
    void resizeTargets(int width, int height);
    int width() const;
    int height() const;

    // Uploads a scene, replacing the current one. On failure the current scene stays and the
    // error is returned.
    std::optional<std::string> setScene(SceneData const& scene);

    FrameStats render(FrameInput const& input);

    // GL texture name of an attachment (for viewers); 0 when the targets are 0x0.
    unsigned texture(Attachment a) const;
    FloatImage readAttachment(Attachment a) const;
    // x, y in pixels with the origin at the top-left, as a mouse reports them.
    PixelSample samplePixel(int x, int y, Camera const& camera) const;

    // Draws a view of the current frame (the final image or a remapped attachment) into
    // `target`, allocating it at the frame size. The editor's texture viewers use this.
    void drawView(ViewParams const& params, Camera const& camera, ViewTarget& target);
    FloatImage readViewTarget(ViewTarget const& target) const;

    // Recompiles shaders whose source files in the source tree changed. Returns one message per
    // program rebuilt or failed; a failed build keeps the last good program.
    std::vector<std::string> reloadChangedShaders();

    // Half the edge of the light cubes, in world units (scaled to the scene; picking uses it).
    float lightCubeHalfSize() const;

    // Errors reported by the GL since the renderer was created.
    std::uint64_t glErrorCount() const;

    RendererImpl& impl() { return *impl_; }

private:
    std::unique_ptr<RendererImpl> impl_;
};

}  // namespace gbl
