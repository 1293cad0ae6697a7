// The frame sequence and the public Renderer API.
#include "renderer_impl.h"

#include "gl/embedded_shaders.h"
#include "gl/debug.h"
#include "core/light_math.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

namespace gbl {

namespace {

std::vector<ProgramDesc> corePrograms() {
    return {
        {"geometry", {{GL_VERTEX_SHADER, "mesh.vert"}, {GL_FRAGMENT_SHADER, "geometry.frag"}}, {}},
        {"lighting_quad", {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "lighting_quad.frag"}}, {}},
        {"forward", {{GL_VERTEX_SHADER, "mesh.vert"}, {GL_FRAGMENT_SHADER, "forward.frag"}}, {}},
        {"depth_copy", {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "depth_copy.frag"}}, {}},
        {"light_cube", {{GL_VERTEX_SHADER, "light_cube.vert"}, {GL_FRAGMENT_SHADER, "light_cube.frag"}}, {}},
        {"view", {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "view.frag"}}, {}},
    };
}

// 36 vertices of a unit cube centred at the origin (half-extent 1), counter-clockwise outside.
std::vector<glm::vec3> cubeTriangles() {
    static constexpr int kFaces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
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

}  // namespace

RendererImpl::RendererImpl(GlCaps capsIn, int width, int height)
    : caps(std::move(capsIn)), shaders(shaderReloadDir()) {
    installGlDebug(caps);
    for (auto& desc : corePrograms()) {
        std::string log;
        if (!shaders.add(desc, &log))
            throw std::runtime_error("Renderer: built-in shader program '" + desc.name + "' failed to build:\n" + log);
    }
    emptyVao = gl::VertexArray::create("fullscreen");
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
    if (caps.pipelineStatistics) fragmentQuery = gl::Query::create(GL_FRAGMENT_SHADER_INVOCATIONS_ARB, "fragment invocations");
    lights.upload({});
    resizeTargets(width, height);
    glErrors += collectGlErrors();
}

void RendererImpl::resizeTargets(int width, int height) {
    width = std::max(width, 0);
    height = std::max(height, 0);
    if (auto err = createRenderTargets(width, height, targets))
        throw std::runtime_error("Renderer::resizeTargets(): " + *err);
}

FrameStats RendererImpl::render(FrameInput const& input) {
    FrameStats stats;
    stats.width = targets.width;
    stats.height = targets.height;
    stats.lightsSubmitted = int(input.lights.size());
    if (targets.empty()) return stats;  // minimised: nothing to draw into

    FrameContext f;
    f.camera = input.camera;
    f.aspect = float(targets.width) / float(targets.height);
    f.view = input.camera.view();
    f.projection = input.camera.projection(f.aspect);
    f.viewProj = f.projection * f.view;
    f.lights = input.lights;
    f.settings = input.settings;
    if (f.settings.mode == LightingMode::Tiled && !caps.computeShaders) {
        f.settings.mode = LightingMode::Quad;
        stats.fallbackReason = caps.tiledUnavailableReason() + "; the full-screen (quad) pass ran instead";
    }
    stats.modeUsed = f.settings.mode;

    lights.upload(input.lights);
    for (auto const& l : input.lights) stats.lightsShaded += lightRadius(l).radius > 0.0f ? 1 : 0;

    glViewport(0, 0, targets.width, targets.height);
    bool const forwardMode = f.settings.mode == LightingMode::Forward;
    if (forwardMode) {
        // No G-buffer in forward mode: clear it so the viewers show that it is unused.
        glBindFramebuffer(GL_FRAMEBUFFER, targets.gbuffer.fbo.id());
        glClearColor(0, 0, 0, 0);
        glClearDepth(1.0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        timer.begin("forward_shading");
        if (fragmentQuery) fragmentQuery.begin();
        forwardShadingPass(f, MaterialFilter::Opaque);
        if (fragmentQuery) fragmentQuery.end();
        timer.end();
    } else {
        timer.begin("geometry");
        geometryPass(f);
        timer.end();
        timer.begin("lighting");
        if (fragmentQuery) fragmentQuery.begin();
        switch (f.settings.mode) {
        case LightingMode::Volumes: lightingVolumesPass(f); break;
        case LightingMode::Tiled: lightingTiledPass(f, true, false); break;
        default: lightingQuadPass(f); break;
        }
        if (fragmentQuery) fragmentQuery.end();
        timer.end();
        timer.begin("depth_copy");
        depthCopyPass(f);
        timer.end();
    }
    timer.begin("forward");
    forwardShadingPass(f, MaterialFilter::Blended);
    if (f.settings.lightCubes) lightCubesPass(f);
    timer.end();
    if (f.settings.volumeWireframes) {
        timer.begin("wireframes");
        volumeWireframesPass(f);
        timer.end();
    }
    // Debug counts for the heat map and tile views, only when one of them is shown.
    coverageValid = false;
    if (f.settings.view == DebugView::Heatmap || f.settings.view == DebugView::TileLights) {
        timer.begin("coverage");
        coveragePass(f);
        timer.end();
    }
    lastFrame = f;
    lastFrame.lights = {};  // the caller's span does not outlive this call
    timer.begin("display");
    displayPass(f);
    timer.end();

    for (auto& [name, ms] : timer.finishFrame(input.waitForGpuTimings)) {
        stats.passes.push_back({name, ms});
        stats.gpuFrameMs += ms;
    }
    // Interactive frames read the count only when it is ready, so they never wait on the GPU.
    if (fragmentQuery && (input.waitForGpuTimings || fragmentQuery.resultAvailable()))
        stats.fragmentInvocations = fragmentQuery.result();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    stats.glErrors = collectGlErrors();
    glErrors += stats.glErrors;
    return stats;
}

// --- Renderer (public) -----------------------------------------------------------------------

Renderer::Renderer(GlCaps caps, int width, int height)
    : impl_(std::make_unique<RendererImpl>(std::move(caps), width, height)) {}
Renderer::~Renderer() = default;

GlCaps const& Renderer::caps() const { return impl_->caps; }
void Renderer::resizeTargets(int width, int height) { impl_->resizeTargets(width, height); }
int Renderer::width() const { return impl_->targets.width; }
int Renderer::height() const { return impl_->targets.height; }

std::optional<std::string> Renderer::setScene(SceneData const& scene) {
    if (auto err = uploadScene(scene, impl_->scene)) return err;
    impl_->sceneRadius = std::max(scene.bounds().radius(), 1e-3f);
    impl_->glErrors += collectGlErrors();
    return std::nullopt;
}

FrameStats Renderer::render(FrameInput const& input) { return impl_->render(input); }

unsigned Renderer::texture(Attachment a) const {
    RenderTargets const& t = impl_->targets;
    switch (a) {
    case Attachment::Position: return t.gbuffer.position.id();
    case Attachment::Normal: return t.gbuffer.normal.id();
    case Attachment::AlbedoSpec: return t.gbuffer.albedoSpec.id();
    case Attachment::Depth: return t.gbuffer.depth.id();
    case Attachment::Lighting: return t.lighting.id();
    case Attachment::Final: return t.display.id();
    }
    return 0;
}

namespace {
// Reads a whole framebuffer attachment as floats, flipped so rows run top to bottom.
FloatImage readFramebuffer(GLuint fbo, GLenum attachment, int width, int height, int channels) {
    FloatImage img;
    img.width = width;
    img.height = height;
    img.channels = channels;
    img.pixels.resize(std::size_t(width) * height * channels);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
    if (attachment != GL_NONE) glReadBuffer(attachment);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, width, height, channels == 1 ? GL_DEPTH_COMPONENT : GL_RGBA, GL_FLOAT, img.pixels.data());
    if (attachment != GL_NONE) glReadBuffer(GL_COLOR_ATTACHMENT0);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    // GL rows run bottom to top; images and mouse coordinates run top to bottom.
    std::size_t const row = std::size_t(width) * channels;
    for (int y = 0; y < height / 2; ++y)
        std::swap_ranges(img.pixels.begin() + std::ptrdiff_t(y * row), img.pixels.begin() + std::ptrdiff_t((y + 1) * row),
                         img.pixels.begin() + std::ptrdiff_t((height - 1 - y) * row));
    return img;
}
}  // namespace

FloatImage Renderer::readAttachment(Attachment a) const {
    RenderTargets const& t = impl_->targets;
    if (t.empty()) return {};
    switch (a) {
    case Attachment::Position: return readFramebuffer(t.gbuffer.fbo.id(), GL_COLOR_ATTACHMENT0, t.width, t.height, 4);
    case Attachment::Normal: return readFramebuffer(t.gbuffer.fbo.id(), GL_COLOR_ATTACHMENT1, t.width, t.height, 4);
    case Attachment::AlbedoSpec: return readFramebuffer(t.gbuffer.fbo.id(), GL_COLOR_ATTACHMENT2, t.width, t.height, 4);
    case Attachment::Depth: return readFramebuffer(t.gbuffer.fbo.id(), GL_NONE, t.width, t.height, 1);
    case Attachment::Lighting: return readFramebuffer(t.litFbo.id(), GL_COLOR_ATTACHMENT0, t.width, t.height, 4);
    case Attachment::Final: return readFramebuffer(t.displayFbo.id(), GL_COLOR_ATTACHMENT0, t.width, t.height, 4);
    }
    return {};
}

FloatImage Renderer::readViewTarget(ViewTarget const& target) const {
    if (!target.texture) return {};
    return readFramebuffer(target.fbo.id(), GL_COLOR_ATTACHMENT0, target.texture.width(), target.texture.height(), 4);
}

PixelSample Renderer::samplePixel(int x, int y, Camera const& camera) const {
    RenderTargets const& t = impl_->targets;
    PixelSample s;
    if (t.empty() || x < 0 || y < 0 || x >= t.width || y >= t.height) return s;
    int const glY = t.height - 1 - y;
    auto readColor = [&](GLuint fbo, GLenum attachment, glm::vec4& out) {
        glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
        glReadBuffer(attachment);
        glReadPixels(x, glY, 1, 1, GL_RGBA, GL_FLOAT, &out[0]);
        glReadBuffer(GL_COLOR_ATTACHMENT0);
    };
    readColor(t.gbuffer.fbo.id(), GL_COLOR_ATTACHMENT0, s.position);
    readColor(t.gbuffer.fbo.id(), GL_COLOR_ATTACHMENT1, s.normal);
    readColor(t.gbuffer.fbo.id(), GL_COLOR_ATTACHMENT2, s.albedoSpec);
    readColor(t.litFbo.id(), GL_COLOR_ATTACHMENT0, s.lighting);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, t.gbuffer.fbo.id());
    glReadPixels(x, glY, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &s.depth);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    s.covered = s.position.w > 0.0f;
    // World position rebuilt from depth: unproject the pixel centre through the inverse view-projection.
    float const aspect = float(t.width) / float(t.height);
    glm::mat4 const invViewProj = glm::inverse(camera.projection(aspect) * camera.view());
    glm::vec4 const ndc((float(x) + 0.5f) / float(t.width) * 2.0f - 1.0f, (float(glY) + 0.5f) / float(t.height) * 2.0f - 1.0f,
                        s.depth * 2.0f - 1.0f, 1.0f);
    glm::vec4 const world = invViewProj * ndc;
    s.reconstructedPosition = glm::vec3(world) / world.w;
    return s;
}

std::vector<std::string> Renderer::reloadChangedShaders() { return impl_->shaders.reloadChanged(); }

float Renderer::lightCubeHalfSize() const { return impl_->lightCubeHalfSize(); }

std::uint64_t Renderer::glErrorCount() const { return impl_->glErrors; }

void Renderer::drawView(ViewParams const& params, Camera const& camera, ViewTarget& target) {
    impl_->ensureCoverage(params.view);  // heat map and tile views of a frame rendered without them
    impl_->drawView(params, camera, target);
}

}  // namespace gbl
