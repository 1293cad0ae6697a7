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
#include "gpu/frame_resources.h"
#include "gpu/gpu_scene.h"
#include "gpu/light_buffer.h"
#include "gpu/light_volume_gpu.h"
#include "gpu/render_targets.h"
#include "gpu/view_target.h"
#include "pass_run.h"
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
// Why a prepass frame ignores `accumulation: split` (FrameStats::fallbackReason).
inline constexpr char const* kPrepassRefusesSplit =
    "accumulation split combines from the G-buffer's albedo, which prepass's thin G-buffer lacks, and prepass "
    "always sums its lights into the diffuse and specular targets, so the setting changed nothing";

// The uniforms of shaders/lighting.glsl and surface_terms.glsl for frame `f`.
ShadingUniforms shadingUniforms(FrameContext const& f);

// One frame's own record (or one view's): the values its passes share and what they did.
struct FrameRecord {
    FrameContext f;
    ShadingUniforms shading;
    bool wireframes = false;         // the volume outlines are drawn (the setting, or an accumulated light's)
    int outline = -1;                // the one volume outlined, an index into f.lights; -1: every volume
    std::vector<PassId> ran;         // the passes run so far, in order (PassScope)
    std::vector<PassCalls> calls;    // and what each issued
    std::optional<ViewParams> view;  // a view's (drawView): untimed, shown with these parameters
    bool complexCounted = false;     // the msaa_edges pass counted its complex pixels (RendererImpl::complexQuery)
};

// A pass that is not one of the renderer's own (a test's, renderer_test_access.h): its declaration
// runs after the pass `after` with `run`, through the same executor as every other.
struct ExtraPass {
    PassId after = PassId::Display;
    PassDecl decl;
    RunPass run;
};

// Times one pass under its declared name (core/frame_passes.h) and records that it ran.
class PassScope {
public:
    PassScope(GpuTimer& timer, FrameRecord& frame, PassDecl const& decl)
        : timer_(timer), calls_(frame.calls), name_(decl.name()), before_(gl::drawCount()), timed_(!frame.view) {
        if (timed_) timer.begin(std::string(name_));
        frame.ran.push_back(decl.id);
    }
    ~PassScope() {
        if (timed_) timer_.end();
        gl::DrawCount const& now = gl::drawCount();
        calls_.push_back({std::string(name_), now.draws - before_.draws, now.dispatches - before_.dispatches,
                          now.triangles - before_.triangles});
    }
    PassScope(PassScope const&) = delete;
    PassScope& operator=(PassScope const&) = delete;

private:
    GpuTimer& timer_;
    std::vector<PassCalls>& calls_;
    std::string_view name_;
    gl::DrawCount before_;
    bool timed_;
};

// An optional group of programs (and, for volumes, the sphere mesh), built on first use.
struct OptionalFeature {
    bool tried = false;
    std::optional<std::string> unavailable;  // why it cannot run; nullopt once it built
};

// What the read-backs (renderer_readback.cpp) draw with and into: not the whole renderer.
struct ReadbackContext;
// The attachments that a prepass frame's thin G-buffer stands in for (RendererImpl::readThinAttachment).
bool thinGBufferReads(Attachment a);

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
    ReadbackContext readbackContext();
    // prepass's thin G-buffer read back (renderer_readback_thin.cpp) in the layout's place, for the
    // attachments thinGBufferReads names, after a prepass frame (thinGBuffer).
    FloatImage readThinAttachment(Attachment a);
    // The pixel inspector's values there (x, glY: GL's bottom-left origin).
    void sampleThinPixel(int x, int glY, glm::mat4 const& inverseViewProj, PixelSample& s);

private:
    friend class Renderer;  // its methods are this class's interface (renderer.cpp, renderer_readback.cpp, ...)
    friend struct RendererTestAccess;
    friend struct ReadbackContext;

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
    ShaderChecks shaderChecks;  // the shader-checks build's report (gl/shader_checks.h); empty when off
    gl::Query fragmentQuery;    // GL_FRAGMENT_SHADER_INVOCATIONS_ARB when available
    gl::Query complexQuery;     // GL_SAMPLES_PASSED of the msaa_edges pass: the complex pixels (made on first use)
    std::uint64_t glErrorsAtStart = 0;
    glm::mat4 frameInverseViewProj{1.0f};  // of the last frame rendered: decodes its G-buffer
    // The last frame ran prepass: its G-buffer is the thin one (prepass.normal_exp and the lit
    // depth), which the read-backs (renderer_readback.cpp) read in the layout's place.
    bool thinGBuffer = false;
    // What the coverage target counts now (runCoverage), for the pixel inspector; none before a
    // count view ran in this frame.
    std::optional<DebugView> coverageView;
    LightingMode coverageMode = LightingMode::Quad;
    std::vector<ExtraPass> extraPasses;  // renderer_test_access.h: tests' own passes
    // renderer_test_access.h: called before each pass runs, with its declaration
    std::function<void(PassDecl const&)> passObserver;
    // renderer_test_access.h: edits the frame's declared passes before they run
    std::function<void(std::vector<PassDecl>&)> declarationEdit;
    OptionalFeature volumesFeature;
    OptionalFeature tiledFeature;
    OptionalFeature clusteredFeature;
    OptionalFeature forwardPlusFeature;
    OptionalFeature prepassFeature;
    ClusterLists clusters;
    TileBins tileBins;                    // the tiled and clustered list passes' candidates, rebuilt by each
    std::function<void()> frameTestHook;  // renderer_test_access.h
    bool viewVariants = true;             // each view its own program (viewProgram); off only in tests
    // Set: frames re-light this imported G-buffer with its camera (Renderer::setImportedGBuffer).
    std::optional<ImportedTextures> imported;
    // The browser's read-back targets (renderer_readback.cpp): the depth copied into RGBA32F, the
    // stencil's bit planes summed into RGBA8 over the G-buffer's depth-stencil. Made on first use,
    // dropped whenever the targets are remade. Unused on the desktop, which reads both directly.
    // And on every platform, msaa's one sample of an attachment copied out (Renderer::readMsaaSample).
    struct ReadbackTargets {
        gl::Texture depthCopy, stencilSum;
        gl::Framebuffer depthFbo, stencilFbo;
        gl::Texture sampleCopy;
        gl::Framebuffer sampleFbo;
    } readback;

    FrameContext frameContext(FrameInput const& input) const;
    DeferredInputs deferredInputs(FrameContext const& f, FrameResources const& io) const;
    LitTarget litTarget() const { return {targets.litFbo, targets.lighting}; }
    // --- the frame: declared passes, run (renderer.cpp, renderer_passes.cpp) ---------------------
    FrameRecord beginFrame(FrameInput const& input, FrameStats& stats);
    std::vector<PassDecl> declaredPasses(FrameInput const& input, FrameRecord const& frame, FrameStats& stats);
    void runPasses(std::span<PassDecl const> passes, FrameRecord& frame, FrameResources const& io);
    void finishFrame(FrameInput const& input, FrameRecord const& frame, FrameStats& stats);
    using RunFunction = void (RendererImpl::*)(FrameRecord&, PassRun const&);
    static RunFunction runFunction(PassId id);                     // the table of the renderer's own passes
    void runForwardShading(FrameRecord& frame, PassRun const& r);  // opaque surfaces
    void runForwardFiltered(FrameRecord& frame, PassRun const& r, MaterialFilter filter, bool backToFront);
    void runGeometry(FrameRecord& frame, PassRun const& r);
    void runImport(FrameRecord& frame, PassRun const& r);
    void runLightLists(FrameRecord& frame, PassRun const& r);
    void runVolumeDepth(FrameRecord& frame, PassRun const& r);
    void runLighting(FrameRecord& frame, PassRun const& r);
    void runLightCombine(FrameRecord& frame, PassRun const& r);
    void runDepthCopy(FrameRecord& frame, PassRun const& r);
    void runForward(FrameRecord& frame, PassRun const& r);
    void runGlassOutline(FrameRecord& frame, PassRun const& r);
    void runCoverage(FrameRecord& frame, PassRun const& r);
    void runDisplay(FrameRecord& frame, PassRun const& r);
    void runLightCubes(FrameRecord& frame, PassRun const& r);
    void runWireframes(FrameRecord& frame, PassRun const& r);
    void runDepthPrepass(FrameRecord& frame, PassRun const& r);
    // prepass (renderer_prepass.cpp, docs/deferred_lighting.md); its light pass is runLighting's
    void runThinGBuffer(FrameRecord& frame, PassRun const& r);
    void runPrepassShading(FrameRecord& frame, PassRun const& r);
    void runPrepassLight(FrameRecord& frame, PassRun const& r);
    // msaa (renderer_msaa.cpp, docs/msaa.md)
    void runMsaaEdges(FrameRecord& frame, PassRun const& r);
    void runLightingComplex(FrameRecord& frame, PassRun const& r);
    void runMsaaResolve(FrameRecord& frame, PassRun const& r);
    void runMsaaVolumes(FrameRecord& frame, PassRun const& r);  // runLighting's, for msaa volumes frames
    // Why the frame of `s` (mode after fallback) cannot have its msaa, one sentence; nullopt when it
    // can. `makeTargets`: also makes the multisampled targets, and a failure there is a reason too.
    std::optional<std::string> msaaRefusal(PipelineSettings const& s, bool makeTargets);
    // The quad program's msaa variant (shaders/lighting_quad.frag): "" per sample, "SAMPLE0" or "EDGES";
    // or another program's (the decode pass's: "" one sample, "COUNTS"), with the sample places set.
    gl::Program const& msaaProgram(std::string const& what, ProgramId id = ProgramId::LightingQuad);
    // shaders/view.frag built for `view` alone (its VIEW_ONLY): the switch over every view would
    // otherwise run whole at each pixel where branches run under a mask (4 ms against 42 ms for
    // the final image at 641x407 in SwiftShader).
    gl::Program const& viewProgram(DebugView view) {
        return viewVariants ? shaders.variant(ProgramId::View, "VIEW_ONLY " + std::to_string(int(view)))
                            : shaders.get(ProgramId::View);
    }
    bool wireframesDrawn(FrameInput const& input);  // volume outlines: the setting, or an accumulated light's
    bool volumesReady();                            // builds the volume programs and mesh on first use
    bool tiledReady();                              // builds the tiled program on first use
    bool clusteredReady();                          // builds the two clustered programs on first use
    bool forwardPlusReady();                        // builds the binning and forward+ programs on first use
    bool prepassReady();                            // builds prepass's three programs on first use
    // The clustered passes' input: `image` the lit image or diffuse light target they write.
    LightingClusteredInput clusteredInput(FrameContext const& f, FrameResources const& io, gl::Texture const& image);
    LightingClusteredConfig clusteredConfig(FrameContext const& f, bool shade) const;
    TileBinPrograms binPrograms(ProgramId bin) const;  // TileDepth and the mode's binning program
    // Accumulation targets (docs/lighting.md "Accumulation targets").
    bool splitAccumulation(FrameContext const& f) const;
};

struct ReadbackContext {
    RenderTargets const& targets;
    RendererImpl::ReadbackTargets& readback;  // the browser's: made on first use
    ShaderLibrary const& shaders;
    gl::FullscreenTriangle const& triangle;
};

inline ReadbackContext RendererImpl::readbackContext() {
    return {targets, readback, shaders, triangle};
}

// Reads a whole framebuffer attachment as floats, flipped so rows run top to bottom: one channel
// reads depth (in the browser: the red channel of a colour attachment, see readDepth), two read
// RG, four RGBA (renderer_readback.cpp).
FloatImage readFramebuffer(GLuint fbo, GLenum attachment, int width, int height, int channels);

}  // namespace gbl
