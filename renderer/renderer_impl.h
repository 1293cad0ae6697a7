// Renderer internals: the GPU resources of a frame and the order of its passes. Only the
// renderer's own .cpp files include this; everyone else uses renderer.h.
#pragma once

#include "core/frame_passes.h"
#include "gl/draw_count.h"
#include "gl/fullscreen_triangle.h"
#include "gl/gpu_timer.h"
#include "gl/query.h"
#include "gl/shader_checks.h"
#include "gl/shader_library.h"
#include "gl/vertex_array.h"
#include "gpu/gpu_scene.h"
#include "gpu/light_buffer.h"
#include "gpu/light_volume_gpu.h"
#include "gpu/render_targets.h"
#include "gpu/view_target.h"
#include "passes/import.h"
#include "passes/lighting_clustered.h"
#include "passes/shading_inputs.h"
#include "renderer.h"

#include <functional>
#include <glm/glm.hpp>

namespace gbl {

// Per-frame values computed once at the start of a frame (or of a view of it).
struct FrameContext {
    Camera camera;
    float aspect = 1.0f;
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    glm::mat4 viewProj{1.0f};
    std::span<PointLight const> lights;
    PipelineSettings settings;
    bool lightAlone = false;  // one light's contribution: no ambient, no emission
};

// Why a forward frame ignores `accumulation: split` (FrameStats::fallbackReason).
inline constexpr char const* kForwardRefusesSplit =
    "accumulation split needs the G-buffer's albedo and emission for its combine pass, and forward shading "
    "keeps none, so the forward frame wrote its one lit target";

// The uniforms of shaders/lighting.glsl and surface_terms.glsl for frame `f`.
ShadingUniforms shadingUniforms(FrameContext const& f);

// Times one pass under its declared name (core/frame_passes.h) and records that it ran.
class PassScope {
public:
    PassScope(GpuTimer& timer, std::vector<PassId>& ran, std::vector<PassCalls>& calls, PassId id)
        : timer_(timer), calls_(calls), name_(passName(id)), before_(gl::drawCount()) {
        timer.begin(std::string(name_));
        ran.push_back(id);
    }
    ~PassScope() {
        timer_.end();
        gl::DrawCount const& now = gl::drawCount();
        calls_.push_back({std::string(name_), now.draws - before_.draws, now.dispatches - before_.dispatches});
    }
    PassScope(PassScope const&) = delete;
    PassScope& operator=(PassScope const&) = delete;

private:
    GpuTimer& timer_;
    std::vector<PassCalls>& calls_;
    std::string_view name_;
    gl::DrawCount before_;
};

// An optional group of programs (and, for volumes, the sphere mesh), built on first use.
struct OptionalFeature {
    bool tried = false;
    std::optional<std::string> unavailable;  // why it cannot run; nullopt once it built
};

class RendererImpl {
public:
    RendererImpl(GlCaps caps, int width, int height);

    FrameStats render(FrameInput const& input);
    void resizeTargets(int width, int height);
    // Switches the G-buffer layout: the programs get its defines, the targets are recreated.
    void applyLayout(GBufferLayout layout);
    // Every program's defines: the layout's, GBL_MASKED_BRANCHES where caps.masksBranches, and
    // GBL_SHADER_CHECKS in the shader-checks build.
    std::vector<std::string> shaderDefines(GBufferLayout layout) const;
    void drawView(ViewParams const& params, FrameInput const& frame, ViewTarget& target);
    void copyDisplay(ViewTarget& target);
    void sizeViewTarget(ViewTarget& target) const;
    std::optional<std::string> modeUnavailable(LightingMode mode);
    std::vector<PassDecl> framePasses(FrameInput const& input);
    float lightCubeHalfSize() const;

    // --- resources -------------------------------------------------------------------------
    GlCaps caps;
    ShaderLibrary shaders;
    RenderTargets targets;
    GpuScene scene;
    float sceneRadius = 10.0f;  // for sizing light cubes
    LightBuffer lights;
    gl::FullscreenTriangle triangle;
    gl::VertexArray cubeVao;
    gl::Buffer cubeVertices;
    LightVolumeGpu volumes;
    GpuTimer timer;
    ShaderChecks shaderChecks;         // the shader-checks build's report (gl/shader_checks.h); empty when off
    std::vector<PassId> passesRun;     // this frame's passes so far, in order (PassScope)
    std::vector<PassCalls> passCalls;  // and what each issued (PassScope)
    gl::Query fragmentQuery;           // GL_FRAGMENT_SHADER_INVOCATIONS_ARB when available
    std::uint64_t glErrorsAtStart = 0;
    glm::mat4 frameInverseViewProj{1.0f};  // of the last frame rendered: decodes its G-buffer
    // What the coverage target counts now (runCoverage), for the pixel inspector; none before a
    // count view ran in this frame.
    std::optional<DebugView> coverageView;
    LightingMode coverageMode = LightingMode::Quad;
    OptionalFeature volumesFeature;
    OptionalFeature tiledFeature;
    OptionalFeature clusteredFeature;
    ClusterLists clusters;
    TileBins tileBins;                    // the tiled and clustered list passes' candidates, rebuilt by each
    bool splitTargetsWritten = false;     // the light targets hold an earlier split frame's sums
    std::function<void()> frameTestHook;  // renderer_test_access.h
    bool viewVariants = true;             // each view its own program (viewProgram); off only in tests
    // Set: frames re-light this imported G-buffer with its camera (Renderer::setImportedGBuffer).
    std::optional<ImportedTextures> imported;
    // The browser's read-back targets (renderer_readback.cpp): the depth copied into RGBA32F, the
    // stencil's bit planes summed into RGBA8 over the G-buffer's depth-stencil. Made on first use,
    // dropped whenever the targets are remade. Unused on the desktop, which reads both directly.
    struct ReadbackTargets {
        gl::Texture depthCopy, stencilSum;
        gl::Framebuffer depthFbo, stencilFbo;
    } readback;

private:
    FrameContext frameContext(FrameInput const& input) const;
    DeferredInputs deferredInputs(FrameContext const& f) const;
    LitTarget litTarget() const { return {targets.litFbo, targets.lighting}; }
    PassScope timed(PassId id) { return {timer, passesRun, passCalls, id}; }
    // shaders/view.frag built for `view` alone (its VIEW_ONLY): the switch over every view would
    // otherwise run whole at each pixel where branches run under a mask (4 ms against 42 ms for
    // the final image at 641x407 in SwiftShader).
    gl::Program const& viewProgram(DebugView view) {
        return viewVariants ? shaders.variant(ProgramId::View, "VIEW_ONLY " + std::to_string(int(view)))
                            : shaders.get(ProgramId::View);
    }
    bool wireframesDrawn(FrameInput const& input);  // volume outlines: the setting, or an accumulated light's
    void clearForStop();                            // FrameInput::stopAfter: the targets later passes draw
    bool volumesReady();                            // builds the volume programs and mesh on first use
    bool tiledReady();                              // builds the tiled program on first use
    bool clusteredReady();                          // builds the two clustered programs on first use
    LightingClusteredInput clusteredInput(FrameContext const& f);
    LightingClusteredConfig clusteredConfig(FrameContext const& f, bool shade) const;
    TileBinPrograms binPrograms(ProgramId bin) const;  // TileDepth and the mode's binning program
    void buildLightLists(FrameContext const& f);       // tiled and clustered: the light_lists pass
    void runLighting(FrameContext const& f);
    void runCoverage(FrameContext const& f);
    // Accumulation targets (renderer_accumulation.cpp, docs/lighting.md "Accumulation targets").
    bool splitAccumulation(FrameContext const& f) const;
    LitTarget quadTarget(FrameContext const& f) const;              // lit image, or the two light targets
    LitTarget volumeTarget(FrameContext const& f) const;            // the same with the G-buffer's depth
    gl::Texture const& lightingImage(FrameContext const& f) const;  // tiled / clustered image 0
    void prepareAccumulation(FrameContext const& f);                // zeroes split targets left from a split frame
    void combineLights(FrameContext const& f);                      // split: the two targets into `lighting`
};

}  // namespace gbl
