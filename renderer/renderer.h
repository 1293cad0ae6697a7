// The deferred renderer: owns the GPU scene, the screen-sized targets and the frame sequence.
// One instance serves the headless `render`/`bench` commands, the tests and the editor.
#pragma once

#include "core/camera.h"
#include "core/frame_types.h"
#include "core/gbuffer_layout.h"
#include "core/imported_frame.h"
#include "core/pipeline_settings.h"
#include "core/point_light.h"
#include "gl/caps.h"
#include "gpu/view_target.h"
#include "scene/scene_data.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace gbl {

struct FrameInput {
    Camera camera;
    std::span<PointLight const> lights;
    PipelineSettings settings;
    // true: block until this frame's GPU timings exist (render, bench, tests); false: report
    // the previous frame's timings so an interactive frame never waits on the GPU.
    bool waitForGpuTimings = true;
    // Which frames' timings an unwaited frame reports (GpuTimer::finishFrame): frames rendered
    // alternately with different settings (the A/B view's two sides) each keep their own.
    int timingStream = 0;
    // Light-by-light accumulation: only lights [0, k) shade the frame (in list order, in every
    // mode), and the k-th light's volume is outlined. Clamped to 0..lights.size().
    std::optional<int> accumulateLights = std::nullopt;
    // With accumulateLights = k >= 1: light k alone, without ambient -- its own contribution.
    bool lightContribution = false;
    // Draws the k-th light's volume into the lit image (off: the lit values stay pure lighting).
    bool outlineAccumulated = true;
    // >= 0: the volume wireframes outline this light only (an index into `lights`; past its end: none).
    int wireframeLight = -1;
    // Stop after this pass: the passes after it are skipped, except the display pass, which shows
    // the frame as it stands. Such a frame first clears the lit, light and coverage targets, so what
    // the skipped passes would have drawn reads as zero, not as an earlier frame's. A pass this frame
    // does not run (Renderer::framePasses) is not an error to render(): the whole frame runs, and
    // FrameStats::fallbackReason says why (stopAfterError); callers that take a name from a user check
    // it first (`render --until`).
    std::optional<PassId> stopAfter = std::nullopt;
};

// The lights a frame shades: all of them, or the accumulated prefix, or light k alone.
std::span<PointLight const> shadedLights(FrameInput const& input);
// The light (an index into input.lights) whose volume alone is outlined; -1: every volume.
int outlinedLight(FrameInput const& input);

class RendererImpl;

class Renderer {
public:
    // Needs a current GL 3.3+ context. Throws std::runtime_error naming the shader and log when
    // a core shader program fails to build (a bug, not user input). The programs of the volumes
    // and tiled modes are optional: a failure there makes only that mode unavailable.
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

    // Re-lighting (docs/import.md): uploads another program's G-buffer, resizes the targets to it,
    // and from now on every frame runs the import pass in the geometry pass's place, with the
    // frame's camera (FrameInput::camera is ignored) and no scene drawn; forward mode runs the quad
    // pass and the light cubes are off (core/frame_passes.h, importedSettings), as fallbackReason
    // says. An error (one sentence) leaves the renderer as it was.
    std::optional<std::string> setImportedGBuffer(ImportedFrame const& frame);
    void clearImportedGBuffer();
    bool hasImportedGBuffer() const;

    // A mode that is unavailable (modeUnavailable) runs the quad pass instead, and the stats'
    // fallbackReason says why.
    FrameStats render(FrameInput const& input);

    // The passes render(input) runs, in order: after any mode fallback, and before any stop.
    std::vector<PassDecl> framePasses(FrameInput const& input);

    // Why `mode` cannot run on this context (a missing GL feature, or a program of the mode that
    // failed to build, with the compiler's reason), in one sentence; nullopt when it can. Builds
    // the mode's programs on first ask.
    std::optional<std::string> modeUnavailable(LightingMode mode);

    // GL texture name of an attachment (for viewers); 0 when the targets are 0x0.
    unsigned texture(Attachment a) const;
    // After a prepass frame, Position, Normal, AlbedoSpec, Emissive and Depth read its thin G-buffer
    // (docs/deferred_lighting.md, "Seeing the thin G-buffer"), as the views of it do.
    FloatImage readAttachment(Attachment a) const;
    // The G-buffer layout of the last frame (the one its targets hold).
    GBufferLayout layout() const;
    // Attachment `index` of that layout (core/gbuffer_layout.h order) exactly as stored: 2
    // channels for RG16, 1 for the depth, else 4. Empty past the last one.
    FloatImage readRawAttachment(int index) const;
    // msaa (docs/msaa.md): sample `sample` of the last msaa frame's multisampled G-buffer attachment
    // `slot` exactly as stored, RGBA floats (the depth slot: its window depth, 1 channel), rows top
    // to bottom; empty when there is none (no msaa frame since the targets were made, a slot the
    // layout does not store, a sample past the count). What export writes as raw_<name>_s<k>.exr.
    FloatImage readMsaaSample(GBufferSlot slot, int sample);
    // ... of the pixels in `rect` only (x, y, width, height, top-left origin, clipped to the frame).
    FloatImage readMsaaSample(GBufferSlot slot, int sample, glm::ivec4 rect);
    // Sample `sample` of `slot` decoded as the lighting reads it, in every layout (the decode pass's
    // msaa variant, gbuffer_read.glsl): Position and Normal as readAttachment decodes them (xyz, w = 1
    // where drawn; position rebuilt from the sample's own depth at its own place where the layout
    // does), AlbedoSpec as stored, Emissive as stored or the layout's constant (kNoEmissiveAo). RGBA
    // floats of `rect` (as above); empty as readMsaaSample, and for the depth slot. The sample views
    // of the viewers, the magnifier and the pixel inspector read this.
    FloatImage readMsaaDecodedSample(GBufferSlot slot, int sample, glm::ivec4 rect);
    FloatImage readMsaaDecodedSample(GBufferSlot slot, int sample);
    // Where each sample lies in its pixel (0..1, GL_SAMPLE_POSITION of the multisampled G-buffer):
    // where the layouts that rebuild position unproject sample k's depth. Empty without one.
    std::vector<glm::vec2> msaaSamplePositions() const;
    // Samples per pixel of the multisampled G-buffer the last msaa frame drew (0: none since the
    // targets were made). A later frame with msaa off keeps it: FrameStats::msaaUsed says what ran.
    int msaaSampleCount() const;
    // Distinct surfaces among each pixel's samples, 1..samples, rows top to bottom, 1 channel; empty
    // without an msaa G-buffer. Counted on the GPU by the decode pass's counts variant with the
    // detection's own test (msaa_edges.glsl, the eye at `eye`, the frame's camera), so every layout is
    // decoded as the lighting decodes it; core/msaa_samples.h (msaaDistinctSamples) is its CPU twin.
    FloatImage msaaDistinctSampleCounts(glm::vec3 eye);
    // The share of pixels the last msaa frame found complex (Attachment::ComplexPixels), 0..1.
    double complexPixelShare() const;
    // x, y in pixels with the origin at the top-left, as a mouse reports them.
    PixelSample samplePixel(int x, int y, Camera const& camera) const;

    // Draws a view of the last rendered frame (the final image or a remapped attachment) into
    // `target`, allocating it at the frame size. `frame` is that frame's input: its settings
    // (tonemap, exposure, mode) and camera (clip planes of the depth views) shape the view, and
    // the heat-map and tile views recount their coverage from it. The editor's viewers use this.
    // The views carry no overlays (light cubes, wireframes): those are drawn onto the frame's own
    // display image only (copyDisplay).
    void drawView(ViewParams const& params, FrameInput const& frame, ViewTarget& target);
    // Copies the last frame's display image, with its overlays, into `target` (allocated at the frame
    // size): the A/B split keeps side B's picture this way before side A's frame replaces it.
    void copyDisplay(ViewTarget& target);
    FloatImage readViewTarget(ViewTarget const& target) const;

    // Recompiles shaders whose source files in the source tree changed. Returns one message per
    // program rebuilt or failed; a failed build keeps the last good program.
    std::vector<std::string> reloadChangedShaders();

    // Half the edge of the light cubes, in world units (scaled to the scene; picking uses it).
    float lightCubeHalfSize() const;

    // Errors reported by the GL since the renderer was created.
    std::uint64_t glErrorCount() const;

private:
    friend struct RendererTestAccess;  // renderer_test_access.h
    RendererImpl& impl() { return *impl_; }
    std::unique_ptr<RendererImpl> impl_;
};

}  // namespace gbl
