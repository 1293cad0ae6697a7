// Renderer internals: the GPU resources and the passes of one frame. Pass code includes this;
// users of the renderer include renderer.h only.
#pragma once

#include "gl/vertex_array.h"
#include "gpu/gpu_scene.h"
#include "gl/gpu_timer.h"
#include "gpu/light_buffer.h"
#include "gpu/light_volume_gpu.h"
#include "gpu/render_targets.h"
#include "renderer.h"
#include "gl/shader_library.h"
#include "gpu/view_target.h"

#include <glm/glm.hpp>

namespace gbl {

// Per-frame values every pass may need, computed once at the start of the frame.
struct FrameContext {
    Camera camera;
    float aspect = 1.0f;
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    glm::mat4 viewProj{1.0f};
    std::span<PointLight const> lights;
    PipelineSettings settings;
};

class RendererImpl {
public:
    RendererImpl(GlCaps caps, int width, int height);

    FrameStats render(FrameInput const& input);
    void resizeTargets(int width, int height);
    // Draws `params` into `target`, (re)allocating it to the frame size when needed.
    void drawView(ViewParams const& params, Camera const& camera, ViewTarget& target);

    // --- resources -------------------------------------------------------------------------
    GlCaps caps;
    ShaderLibrary shaders;
    RenderTargets targets;
    GpuScene scene;
    float sceneRadius = 10.0f;  // for sizing light cubes
    LightBuffer lights;
    gl::VertexArray emptyVao;   // full-screen triangles need a bound VAO in core profile
    gl::VertexArray cubeVao;
    gl::Buffer cubeVertices;
    GpuTimer timer;
    gl::Query fragmentQuery;    // GL_FRAGMENT_SHADER_INVOCATIONS_ARB when available
    std::uint64_t glErrors = 0;

    // --- passes (renderer/passes.cpp) -------------------------------------------------------
    void geometryPass(FrameContext const& f);
    void lightingQuadPass(FrameContext const& f);
    void forwardShadingPass(FrameContext const& f, MaterialFilter filter);
    void depthCopyPass(FrameContext const& f);
    void lightCubesPass(FrameContext const& f);
    void displayPass(FrameContext const& f);
    void drawViewInto(ViewParams const& params, Camera const& camera, PipelineSettings const& settings, int width,
                      int height);
    float lightCubeHalfSize() const;

    // Binds the G-buffer attachments to units 0..2 and the light buffer to unit 3 and sets the
    // uniforms of shaders/lighting.glsl on `program`.
    void bindLightingInputs(gl::Program const& program, FrameContext const& f) const;

    // --- light volumes, tiled lighting, coverage and overlays -------------------------------
    // renderer/volume_pass.cpp, renderer/tiled_pass.cpp, renderer/overlay_pass.cpp
    LightVolumeGpu volumes;
    FrameContext lastFrame;      // the last frame's context (lights left empty) for late coverage
    bool coverageValid = false;  // targets.coverage holds the last frame's counts

    void initLightVolumes();  // creates the sphere mesh and the programs on first use
    void prepareVolumeInstances(FrameContext const& f);
    // Ambient full-screen, then one instanced sphere per light added by blending, culled per
    // f.settings.cull. Writes targets.volumeFbo (lighting + the G-buffer's depth-stencil).
    void lightingVolumesPass(FrameContext const& f);
    // Draws the light volumes with `program` into the bound framebuffer, with the face culling,
    // depth and stencil state of `cull` (shared by the lighting and the coverage passes).
    void drawLightVolumes(FrameContext const& f, gl::Program const& program, CullMode cull);
    // Compute pass over 16x16 tiles (needs caps.computeShaders): shade writes the lit image,
    // coverage writes targets.coverage (x = lights in the tile, y = lights that lit the pixel).
    void lightingTiledPass(FrameContext const& f, bool shade, bool coverage);
    // Fills targets.coverage for the heat map (per mode) or the lights-per-tile view.
    void coveragePass(FrameContext const& f);
    void volumeWireframesPass(FrameContext const& f);
    // Computes the coverage of the last frame when a view needs it and the frame did not.
    void ensureCoverage(DebugView view);
};

}  // namespace gbl
