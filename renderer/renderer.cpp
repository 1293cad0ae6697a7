// The frame (its declared passes, run by renderer_passes.cpp) and the public Renderer API.
#include "renderer_impl.h"
#include "renderer_test_access.h"

#include "core/frame_passes.h"
#include "core/light_math.h"
#include "gl/debug.h"
#include "gl/embedded_shaders.h"
#include "passes/import.h"
#include "passes/light_volumes.h"

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
    lights.upload({}, caps);
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
    s.cutAtRadius = cutsAtRadius(f.settings);
    return s;
}

bool RendererImpl::splitAccumulation(FrameContext const& f) const {
    return f.settings.accumulation == LightAccumulation::Split && !shadesForward(f.settings.mode) &&
           f.settings.mode != LightingMode::Prepass;
}

DeferredInputs RendererImpl::deferredInputs(FrameContext const& f, FrameResources const& io) const {
    ShadingUniforms shading = shadingUniforms(f);
    shading.splitAccumulation = splitAccumulation(f);
    return {io.gbuffer(), lights, shading};
}

// The frame: the passes its settings declare (up to FrameInput::stopAfter), run in order.
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
    FrameRecord frame = beginFrame(input, stats);
    std::vector<PassDecl> const passes = declaredPasses(input, frame, stats);
    glViewport(0, 0, targets.width, targets.height);
    runPasses(passes, frame, {targets});
    finishFrame(input, frame, stats);
    stats.glErrors = glErrorCount() - errorsBefore;
    return stats;
}

// The frame's context after every fallback, its lights uploaded and the volume instances made
// where a declared pass samples them.
FrameRecord RendererImpl::beginFrame(FrameInput const& input, FrameStats& stats) {
    FrameRecord frame;
    FrameContext& f = frame.f;
    f = frameContext(input);
    auto const because = [&](std::string const& why) {
        stats.fallbackReason += (stats.fallbackReason.empty() ? "" : "; ") + why;
    };
    if (imported) {
        std::string why;
        importedSettings(input.settings, &why);
        if (!why.empty()) because(why);
    }
    if (auto why = modeUnavailable(f.settings.mode)) {
        f.settings.mode = LightingMode::Quad;
        because(*why + "; the full-screen (quad) pass ran instead");
    }
    if (f.settings.mode == LightingMode::Prepass && drawsLightVolumes(f.settings) && !volumesReady()) {
        f.settings.prepassLights = PrepassLights::Quad;
        because(*volumesFeature.unavailable + "; prepass's light pass ran full screen");
    }
    if (auto why = msaaRefusal(f.settings, true)) {
        f.settings.msaa = Msaa::Off;
        because(*why);
    }
    stats.msaaUsed = f.settings.msaa;
    stats.modeUsed = f.settings.mode;
    stats.accumulationUsed = splitAccumulation(f) ? LightAccumulation::Split : LightAccumulation::Single;
    if (f.settings.accumulation != stats.accumulationUsed)
        because(f.settings.mode == LightingMode::Prepass ? kPrepassRefusesSplit : kForwardRefusesSplit);
    frame.shading = shadingUniforms(f);
    frameInverseViewProj = frame.shading.inverseViewProj;
    thinGBuffer = f.settings.mode == LightingMode::Prepass;
    if (auto why = lights.upload(f.lights, caps)) because(*why);
    volumes.enclosingScale = volumes.meshEnclosingScale * f.settings.volumeScale;  // < 1 only to show the cut
    volumes.volumeScale = f.settings.volumeScale;
    for (auto const& l : f.lights)
        stats.lightsShaded += (isLocalLight(l) ? lightRadius(l).radius > 0.0f : !validateLight(l)) ? 1 : 0;
    // One light outlined (the accumulated k-th, or the selected one): its index among f.lights,
    // which start at input.lights[0] except for a contribution frame (light k alone).
    frame.outline = outlinedLight(input);
    if (frame.outline >= 0 && input.accumulateLights && input.lightContribution) frame.outline = 0;
    frame.wireframes = wireframesDrawn(input);
    return frame;
}

// The passes this frame runs: framePasses() for its settings, up to its stop pass, with any test's
// own passes. Checked for feedback loops in debug builds.
std::vector<PassDecl> RendererImpl::declaredPasses(FrameInput const& input, FrameRecord const& frame,
                                                   FrameStats& stats) {
    std::vector<PassDecl> passes = gbl::framePasses(frame.f.settings, frame.wireframes, bool(imported));
    if (std::optional<PassId> const stop = input.stopAfter) {
        if (auto why = stopAfterError(passName(*stop), passes)) {
            stats.fallbackReason += (stats.fallbackReason.empty() ? "" : "; ") + *why + ", so the whole frame ran";
        } else {
            stats.stoppedAfter = stop;
            passes = passesUntil(std::move(passes), *stop);
        }
    }
    if (declarationEdit) declarationEdit(passes);
    for (ExtraPass const& e : extraPasses) {
        auto const at = std::find_if(passes.begin(), passes.end(), [&](PassDecl const& p) { return p.id == e.after; });
        if (at != passes.end()) passes.insert(at + 1, e.decl);
    }
    bool const instances = std::any_of(passes.begin(), passes.end(), [](PassDecl const& p) {
        return std::find(p.samples.begin(), p.samples.end(), Resource::VolumeInstances) != p.samples.end();
    });
    if (instances) prepareVolumeInstances(volumes, {frame.f.camera, frame.f.aspect, frame.f.lights});
#ifndef NDEBUG
    checkNoFeedbackLoops(passes);
#endif
    return passes;
}

void RendererImpl::finishFrame(FrameInput const& input, FrameRecord const& frame, FrameStats& stats) {
    stats.timingSource = timingSourceName(timer.method().source);
    stats.timingReason = timer.method().reason;
    for (auto& [name, ms] : timer.finishFrame(input.waitForGpuTimings, input.timingStream)) {
        stats.passes.push_back({name, ms});
        stats.gpuFrameMs += ms;
    }
    stats.calls = frame.calls;
    // A frame stopped before the counted pass began no query. Interactive frames read the count only
    // when it is ready, so they never wait on the GPU.
    bool const counted = std::any_of(frame.ran.begin(), frame.ran.end(), countsFragments);
    if (fragmentQuery && counted && (input.waitForGpuTimings || fragmentQuery.resultAvailable()))
        stats.fragmentInvocations = fragmentQuery.result();
    if (frame.complexCounted && targets.width > 0 && targets.height > 0)
        stats.complexPixelShare = double(complexQuery.result()) / (double(targets.width) * double(targets.height));
    if (shaderChecks)
        if (auto report = shaderChecks.collect()) stats.shaderCheckReport = *report;
}

bool RendererImpl::wireframesDrawn(FrameInput const& input) {
    bool const outlined = input.accumulateLights && input.outlineAccumulated && outlinedLight(input) >= 0;
    return (input.settings.volumeWireframes || outlined) && volumesReady();
}

std::vector<PassDecl> RendererImpl::framePasses(FrameInput const& input) {
    PipelineSettings s = imported ? importedSettings(input.settings) : input.settings;
    if (modeUnavailable(s.mode)) s.mode = LightingMode::Quad;  // as render() runs it
    if (s.mode == LightingMode::Prepass && drawsLightVolumes(s) && !volumesReady())
        s.prepassLights = PrepassLights::Quad;
    if (msaaRefusal(s, false)) s.msaa = Msaa::Off;
    return gbl::framePasses(s, wireframesDrawn(input), bool(imported));
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

void RendererTestAccess::setPassObserver(Renderer& renderer, std::function<void(PassDecl const&)> observer) {
    renderer.impl().passObserver = std::move(observer);
}

void RendererTestAccess::editDeclarations(Renderer& renderer, std::function<void(std::vector<PassDecl>&)> edit) {
    renderer.impl().declarationEdit = std::move(edit);
}

void RendererTestAccess::addPass(Renderer& renderer, PassId after, PassDecl decl, RunPass run) {
    renderer.impl().extraPasses.push_back({after, std::move(decl), std::move(run)});
}

void RendererTestAccess::clearPasses(Renderer& renderer) {
    renderer.impl().extraPasses.clear();
}

void RendererTestAccess::setViewVariants(Renderer& renderer, bool on) {
    renderer.impl().viewVariants = on;
}

std::size_t RendererTestAccess::shaderBuilds(Renderer& renderer) {
    return renderer.impl().shaders.buildCount();
}

}  // namespace gbl
