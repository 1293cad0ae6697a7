// The frame sequence, the optional lighting modes and the public Renderer API.
#include "renderer_impl.h"
#include "renderer_test_access.h"

#include "core/frame_passes.h"
#include "core/light_math.h"
#include "gl/debug.h"
#include "gl/embedded_shaders.h"
#include "passes/coverage.h"
#include "passes/depth_copy.h"
#include "passes/forward.h"
#include "passes/geometry.h"
#include "passes/import.h"
#include "passes/light_cubes.h"
#include "passes/light_volumes.h"
#include "passes/view.h"
#include "passes/volume_depth.h"
#include "passes/wireframes.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace gbl {

namespace {

// 36 vertices of a unit cube centred at the origin (half-extent 1), counter-clockwise outside.
std::vector<glm::vec3> cubeTriangles() {
    static constexpr int kFaces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                         {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    std::vector<glm::vec3> out;
    auto corner = [](int i) { return glm::vec3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1); };
    for (auto const& f : kFaces)
        for (int k : {0, 1, 2, 0, 2, 3}) out.push_back(corner(f[k]));
    return out;
}

// Where hot reload watches for edited shaders: $GBL_SHADER_DIR when set (tests break and fix a
// copy of shaders/ there), else the source tree's shaders/ this binary was built from.
std::string shaderReloadDir() {
    char const* env = std::getenv("GBL_SHADER_DIR");
    return env && *env ? env : shaderSourceDir();
}

#ifndef NDEBUG
// Debug builds: a declared pass that samples what it draws into is a bug in the wiring.
void checkNoFeedbackLoops(std::span<PassDecl const> passes) {
    for (FeedbackLoop const& l : feedbackLoops(passes))
        std::fprintf(stderr,
                     "Renderer::render(): pass %s samples %s, which its framebuffer attaches: a feedback loop\n",
                     std::string(passName(l.pass)).c_str(), std::string(resourceName(l.resource)).c_str());
    assert(feedbackLoops(passes).empty() && "Renderer::render(): a feedback loop; give the pass its own attachment");
}

// Debug builds: the passes that ran are the declared ones, in order (framePasses follows render()).
void checkFrameRan(std::span<PassDecl const> declared, std::span<PassId const> ran) {
    bool const same = std::equal(declared.begin(), declared.end(), ran.begin(), ran.end(),
                                 [](PassDecl const& d, PassId id) { return d.id == id; });
    if (!same) std::fprintf(stderr, "Renderer::render(): the passes that ran differ from framePasses()\n");
    assert(same && "Renderer::render(): update framePasses() (core/frame_passes.cpp) with the frame's sequence");
}
#endif

}  // namespace

RendererImpl::RendererImpl(GlCaps capsIn, int width, int height) : caps(std::move(capsIn)), shaders(shaderReloadDir()) {
    installGlDebug(caps);
    glErrorsAtStart = glErrorCount();
    // Before the first build: the defines include the checks' own.
    if (shaderChecksRequested() && caps.computeShaders)
        shaderChecks = ShaderChecks::create(shaderCheckSiteNames(shaders.source("shader_checks.glsl").value_or("")));
    shaders.setGlobalDefines(shaderDefines(targets.gbuffer.layout), nullptr);  // nothing built yet
    // Core programs are fatal: without them there is no frame at all. Optional ones are built
    // when their mode is first asked for (volumesReady, tiledReady).
    for (ProgramInfo const& p : programTable()) {
        if (p.group != ProgramGroup::Core) continue;
        std::string log;
        if (!shaders.add(p.id, &log))
            throw std::runtime_error("Renderer: built-in shader program '" + p.desc.name + "' failed to build:\n" +
                                     log);
    }
    triangle = gl::FullscreenTriangle::create();
    cubeVao = gl::VertexArray::create("light cube");
    auto const cube = cubeTriangles();
    cubeVertices = gl::Buffer::create(GL_ARRAY_BUFFER, cube.size() * sizeof(glm::vec3), cube.data(), GL_STATIC_DRAW,
                                      "light cube.vertices");
    glBindVertexArray(cubeVao.id());
    glBindBuffer(GL_ARRAY_BUFFER, cubeVertices.id());
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    if (caps.pipelineStatistics)
        fragmentQuery = gl::Query::create(GL_FRAGMENT_SHADER_INVOCATIONS_ARB, "fragment invocations");
    lights.upload({});
    resizeTargets(width, height);
}

void RendererImpl::resizeTargets(int width, int height) {
    width = std::max(width, 0);
    height = std::max(height, 0);
    readback = {};
    if (auto err = createRenderTargets(width, height, targets.gbuffer.layout, targets))
        throw std::runtime_error("Renderer::resizeTargets(): " + *err);
}

std::vector<std::string> RendererImpl::shaderDefines(GBufferLayout layout) const {
    std::vector<std::string> defines = layoutShaderDefines(layoutDesc(layout));
    if (caps.masksBranches) defines.push_back("GBL_MASKED_BRANCHES");
    if (shaderChecks) defines.push_back("GBL_SHADER_CHECKS");
    return defines;
}

void RendererImpl::applyLayout(GBufferLayout layout) {
    if (layout == targets.gbuffer.layout) return;
    std::string log;
    // The built-in shaders compile for every layout; a failure here is a bug in them.
    if (!shaders.setGlobalDefines(shaderDefines(layout), &log))
        throw std::runtime_error("Renderer: the shaders failed to build for G-buffer layout " +
                                 std::string(layoutDesc(layout).name) + ":\n" + log);
    readback = {};
    if (auto err = createRenderTargets(targets.width, targets.height, layout, targets))
        throw std::runtime_error("Renderer::applyLayout(): " + *err);
}

// --- the frame -----------------------------------------------------------------------------------

std::span<PointLight const> shadedLights(FrameInput const& input) {
    if (!input.accumulateLights) return input.lights;
    std::size_t const k = std::size_t(std::clamp(*input.accumulateLights, 0, int(input.lights.size())));
    if (input.lightContribution && k >= 1) return input.lights.subspan(k - 1, 1);
    return input.lights.first(k);
}

int outlinedLight(FrameInput const& input) {
    if (input.accumulateLights) {
        int const k = std::clamp(*input.accumulateLights, 0, int(input.lights.size()));
        return k - 1;  // -1 at k = 0: nothing to outline
    }
    return std::max(input.wireframeLight, -1);  // past the list: no volume outlined at all
}

FrameContext RendererImpl::frameContext(FrameInput const& input) const {
    FrameContext f;
    f.camera = input.camera;
    f.aspect = float(targets.width) / float(targets.height);
    f.view = input.camera.view();
    f.projection = input.camera.projection(f.aspect);
    f.viewProj = f.projection * f.view;
    f.lights = shadedLights(input);
    f.settings = imported ? importedSettings(input.settings) : input.settings;
    if (imported) {  // the imported G-buffer's own camera
        ImportedFrame const& c = imported->camera;
        f.view = c.view;
        f.projection = c.projection;
        f.viewProj = f.projection * f.view;
        f.camera.position = c.eye;
        f.camera.nearPlane = c.nearPlane;
        f.camera.farPlane = c.farPlane;
        f.camera.fovYDegrees = glm::degrees(2.0f * std::atan(1.0f / c.projection[1][1]));
        f.aspect = c.projection[1][1] / c.projection[0][0];
    }
    // A light's own contribution: nothing else, not even the ambient term.
    f.lightAlone = input.accumulateLights && input.lightContribution && !f.lights.empty();
    if (f.lightAlone) f.settings.ambient = glm::vec3(0.0f);
    return f;
}

ShadingUniforms shadingUniforms(FrameContext const& f) {
    ShadingUniforms s{f.camera.position, f.settings.shininess, f.settings.ambient, glm::inverse(f.viewProj),
                      f.lightAlone ? 0.0f : 1.0f};
    s.model = f.settings.shading;
    s.cutAtRadius = cutsAtRadius(f.settings.mode);
    return s;
}

DeferredInputs RendererImpl::deferredInputs(FrameContext const& f) const {
    ShadingUniforms shading = shadingUniforms(f);
    shading.splitAccumulation = splitAccumulation(f);
    return {targets.gbuffer, lights, shading};
}

FrameStats RendererImpl::render(FrameInput const& input) {
    std::uint64_t const errorsBefore = glErrorCount();
    FrameStats stats;
    stats.width = targets.width;
    stats.height = targets.height;
    stats.lightsSubmitted = int(input.lights.size());
    applyLayout(input.settings.layout);
    stats.layout = input.settings.layout;
    if (targets.empty()) return stats;  // minimised: nothing to draw into

    coverageView.reset();  // counts of an earlier frame
    if (shaderChecks) shaderChecks.begin();
    FrameContext f = frameContext(input);
    if (imported) {
        std::string why;
        importedSettings(input.settings, &why);
        stats.fallbackReason = why;
    }
    if (auto why = modeUnavailable(f.settings.mode)) {
        f.settings.mode = LightingMode::Quad;
        stats.fallbackReason +=
            (stats.fallbackReason.empty() ? "" : "; ") + *why + "; the full-screen (quad) pass ran instead";
    }
    stats.modeUsed = f.settings.mode;
    stats.accumulationUsed = splitAccumulation(f) ? LightAccumulation::Split : LightAccumulation::Single;
    if (f.settings.accumulation != stats.accumulationUsed)
        stats.fallbackReason += std::string(stats.fallbackReason.empty() ? "" : "; ") + kForwardRefusesSplit;
    prepareAccumulation(f);
    PipelineSettings const& s = f.settings;
    ShadingUniforms const shading = shadingUniforms(f);
    frameInverseViewProj = shading.inverseViewProj;

    if (auto why = lights.upload(f.lights)) stats.fallbackReason += (stats.fallbackReason.empty() ? "" : "; ") + *why;
    volumes.enclosingScale = volumes.meshEnclosingScale * s.volumeScale;  // < 1 only to show what it cuts off
    volumes.volumeScale = s.volumeScale;
    for (auto const& l : f.lights)
        stats.lightsShaded += (isLocalLight(l) ? lightRadius(l).radius > 0.0f : !validateLight(l)) ? 1 : 0;
    // One light outlined (the accumulated k-th, or the selected one): its index among f.lights,
    // which start at input.lights[0] except for a contribution frame (light k alone).
    int outline = outlinedLight(input);
    if (outline >= 0 && input.accumulateLights && input.lightContribution) outline = 0;
    bool const wireframes = wireframesDrawn(input);
    bool const volumeInstances = s.mode == LightingMode::Volumes || wireframes;
    if (volumeInstances) prepareVolumeInstances(volumes, {f.camera, f.aspect, f.lights});

    // The frame as declared (core/frame_passes.h): checked for feedback loops, and against the
    // passes that ran, in debug builds.
    passesRun.clear();
    passCalls.clear();
    std::optional<PassId> stop = input.stopAfter;
    if (stop) {
        std::vector<PassDecl> const all = gbl::framePasses(s, wireframes, bool(imported));
        if (auto why = stopAfterError(passName(*stop), all)) {
            stats.fallbackReason += (stats.fallbackReason.empty() ? "" : "; ") + *why + ", so the whole frame ran";
            stop.reset();
        } else {
            stats.stoppedAfter = stop;
            clearForStop();
        }
    }
    // Whether the frame goes on to its next pass: not once its stop pass has run.
    auto const runs = [&] { return !stop || std::find(passesRun.begin(), passesRun.end(), *stop) == passesRun.end(); };
#ifndef NDEBUG
    std::vector<PassDecl> const declared = stop ? passesUntil(gbl::framePasses(s, wireframes, bool(imported)), *stop)
                                                : gbl::framePasses(s, wireframes, bool(imported));
    checkNoFeedbackLoops(declared);
#endif

    glViewport(0, 0, targets.width, targets.height);
    if (s.mode == LightingMode::Forward) {
        // No G-buffer in forward mode: clear it so the viewers show that it is unused.
        glBindFramebuffer(GL_FRAMEBUFFER, targets.gbuffer.fbo.id());
        glClearColor(0, 0, 0, 0);
        glClearDepth(1.0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        PassScope const pass = timed(PassId::ForwardShading);
        if (fragmentQuery) fragmentQuery.begin();
        forwardPass({scene, lights, shaders.get(ProgramId::Forward), litTarget()},
                    {MaterialFilter::Opaque, f.viewProj, shading, s.normalMaps});
        if (fragmentQuery) fragmentQuery.end();
    } else {
        if (imported) {
            PassScope const pass = timed(PassId::Import);
            importPass({*imported, shaders.get(ProgramId::Import), triangle, targets.gbuffer},
                       {targets.width, targets.height});
        } else {
            PassScope const pass = timed(PassId::Geometry);
            geometryPass({scene, shaders.get(ProgramId::Geometry), targets.gbuffer}, {f.viewProj, s.normalMaps});
        }
        if (frameTestHook) frameTestHook();
        if (runs() && (s.mode == LightingMode::Clustered || s.mode == LightingMode::Tiled)) {
            PassScope const pass = timed(PassId::LightLists);
            buildLightLists(f);
        }
        if (runs() && s.mode == LightingMode::Volumes && targets.volumeDepth) {
            PassScope const pass = timed(PassId::VolumeDepth);
            volumeDepthPass({targets.gbuffer, targets.volumeFbo}, {targets.width, targets.height});
        }
        if (runs()) {
            PassScope const pass = timed(PassId::Lighting);
            if (fragmentQuery) fragmentQuery.begin();
            runLighting(f);
            if (fragmentQuery) fragmentQuery.end();
        }
        if (runs() && splitAccumulation(f)) {
            PassScope const pass = timed(PassId::LightCombine);
            combineLights(f);
        }
        if (runs()) {
            PassScope const pass = timed(PassId::DepthCopy);
            depthCopyPass({targets.gbuffer, shaders.get(ProgramId::DepthCopy), triangle, targets.litFbo},
                          {s.depthCopy, targets.width, targets.height});
        }
    }
    if (runs() && !imported) {  // an imported G-buffer comes without a scene to draw
        PassScope const pass = timed(PassId::Forward);
        forwardPass({scene, lights, shaders.get(ProgramId::Forward), litTarget()},
                    {MaterialFilter::Blended, f.viewProj, shading, s.normalMaps});
    }
    // Debug counts for the heat map and tile views, only when one of them is shown.
    if (runs() && viewNeedsCoverage(s.view)) {
        PassScope const pass = timed(PassId::Coverage);
        runCoverage(f);
    }
    {
        PassScope const pass = timed(PassId::Display);
        ViewParams display;
        display.view = s.view;
        viewPass({targets.gbuffer, targets.lighting, targets.coverage, targets.diffuseLight, targets.specularLight,
                  viewProgram(s.view), triangle, targets.displayFbo},
                 {display, s.tonemap, s.exposure, f.camera.nearPlane, f.camera.farPlane, targets.width, targets.height,
                  shading.inverseViewProj});
    }
    // The overlays, drawn onto the display image so the lit image stays the light sum (what
    // lighting.exr exports and light-by-light accumulation adds up). Only on the views of the lit
    // image (viewShowsOverlays); the tonemap is the display pass's, so they look as they did when
    // they were drawn into the lit image.
    bool const overlays = viewShowsOverlays(s.view);
    DisplayTonemap const tonemap{s.tonemap, s.exposure};
    if (runs() && overlays && s.lightCubes) {
        PassScope const pass = timed(PassId::LightCubes);
        // Against the lit target's depth: the scene's only when the depth-copy step filled it (the
        // depth_blit lesson: without it, the cubes show through walls).
        lightCubesPass({lights, shaders.get(ProgramId::LightCube), cubeVao, targets.overlayFbo},
                       {f.viewProj, lightCubeHalfSize(), tonemap});
    }
    if (runs() && overlays && wireframes) {
        PassScope const pass = timed(PassId::Wireframes);
        // The G-buffer's depth is the scene's with or without the copy step; forward mode leaves the
        // G-buffer empty, so its own depth (litDepth) is the scene's there.
        gl::Framebuffer const& target =
            s.mode == LightingMode::Forward ? targets.overlayFbo : targets.overlayGBufferDepthFbo;
        WireframesConfig wire{f.viewProj};
        wire.tonemap = tonemap;
        if (outline >= 0) {
            auto const slot = volumeInstanceSlot(f.lights, outline, f.camera, f.aspect, volumes.enclosingScale,
                                                 volumes.coneRadialScale, volumes.volumeScale);
            wire.firstInstance = slot.value_or(0);
            wire.count = slot ? 1 : 0;
        }
        wireframesPass({lights, volumes, shaders.get(ProgramId::LightVolumeWire), target}, wire);
    }
#ifndef NDEBUG
    checkFrameRan(declared, passesRun);
#endif

    stats.timingSource = timingSourceName(timer.method().source);
    stats.timingReason = timer.method().reason;
    for (auto& [name, ms] : timer.finishFrame(input.waitForGpuTimings, input.timingStream)) {
        stats.passes.push_back({name, ms});
        stats.gpuFrameMs += ms;
    }
    stats.calls = passCalls;
    // Interactive frames read the count only when it is ready, so they never wait on the GPU.
    bool const counted = std::find(passesRun.begin(), passesRun.end(),
                                   s.mode == LightingMode::Forward ? PassId::ForwardShading : PassId::Lighting) !=
                         passesRun.end();  // a frame stopped before the counted pass began no query
    if (fragmentQuery && counted && (input.waitForGpuTimings || fragmentQuery.resultAvailable()))
        stats.fragmentInvocations = fragmentQuery.result();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (shaderChecks)
        if (auto report = shaderChecks.collect()) stats.shaderCheckReport = *report;
    stats.glErrors = glErrorCount() - errorsBefore;
    return stats;
}

bool RendererImpl::wireframesDrawn(FrameInput const& input) {
    bool const outlined = input.accumulateLights && input.outlineAccumulated && outlinedLight(input) >= 0;
    return (input.settings.volumeWireframes || outlined) && volumesReady();
}

std::vector<PassDecl> RendererImpl::framePasses(FrameInput const& input) {
    PipelineSettings s = imported ? importedSettings(input.settings) : input.settings;
    if (modeUnavailable(s.mode)) s.mode = LightingMode::Quad;  // as render() runs it
    return gbl::framePasses(s, wireframesDrawn(input), bool(imported));
}

// A frame that stops early skips the passes that would overwrite these targets: clear them, so the
// viewers show what this frame drew so far rather than an earlier frame's lighting.
void RendererImpl::clearForStop() {
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glStencilMask(0xFF);
    glClearColor(0, 0, 0, 0);
    glClearDepth(1.0);
    glClearStencil(0);
    glBindFramebuffer(GL_FRAMEBUFFER, targets.litFbo.id());
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    for (gl::Framebuffer const* fbo : {&targets.splitFbo, &targets.coverageFbo}) {
        glBindFramebuffer(GL_FRAMEBUFFER, fbo->id());
        glClear(GL_COLOR_BUFFER_BIT);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

float RendererImpl::lightCubeHalfSize() const {
    // Small against the scene so cubes mark positions without hiding what they light.
    return std::max(sceneRadius * 0.006f, 1e-4f);
}

// --- Renderer (public) -----------------------------------------------------------------------

Renderer::Renderer(GlCaps caps, int width, int height)
    : impl_(std::make_unique<RendererImpl>(std::move(caps), width, height)) {}
Renderer::~Renderer() = default;

GlCaps const& Renderer::caps() const {
    return impl_->caps;
}
void Renderer::resizeTargets(int width, int height) {
    impl_->resizeTargets(width, height);
}
int Renderer::width() const {
    return impl_->targets.width;
}
int Renderer::height() const {
    return impl_->targets.height;
}

std::optional<std::string> Renderer::setScene(SceneData const& scene) {
    if (auto err = uploadScene(scene, impl_->scene)) return err;
    impl_->sceneRadius = std::max(scene.bounds().radius(), 1e-3f);
    return std::nullopt;
}

FrameStats Renderer::render(FrameInput const& input) {
    return impl_->render(input);
}

std::vector<PassDecl> Renderer::framePasses(FrameInput const& input) {
    return impl_->framePasses(input);
}

std::optional<std::string> Renderer::modeUnavailable(LightingMode mode) {
    return impl_->modeUnavailable(mode);
}

void Renderer::drawView(ViewParams const& params, FrameInput const& frame, ViewTarget& target) {
    impl_->drawView(params, frame, target);
}

void Renderer::copyDisplay(ViewTarget& target) {
    impl_->copyDisplay(target);
}

std::vector<std::string> Renderer::reloadChangedShaders() {
    return impl_->shaders.reloadChanged();
}

float Renderer::lightCubeHalfSize() const {
    return impl_->lightCubeHalfSize();
}

std::uint64_t Renderer::glErrorCount() const {
    return gbl::glErrorCount() - impl_->glErrorsAtStart;
}

void RendererTestAccess::setFrameHook(Renderer& renderer, std::function<void()> hook) {
    renderer.impl().frameTestHook = std::move(hook);
}

void RendererTestAccess::setViewVariants(Renderer& renderer, bool on) {
    renderer.impl().viewVariants = on;
}

std::size_t RendererTestAccess::shaderBuilds(Renderer& renderer) {
    return renderer.impl().shaders.buildCount();
}

}  // namespace gbl
