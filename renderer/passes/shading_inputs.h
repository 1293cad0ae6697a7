// What the lighting shaders read besides their own uniforms: the G-buffer, the light buffer and
// the uniforms of shaders/lighting.glsl, bound to the slots of shaders/bindings.glsl.
#pragma once

#include "core/pipeline_settings.h"
#include "gl/framebuffer.h"
#include "gl/program.h"
#include "gpu/frame_resources.h"
#include "gpu/light_buffer.h"
#include "gpu/render_targets.h"

#include <glm/glm.hpp>

namespace gbl {

// The uniforms of shaders/lighting.glsl and the ambient term.
struct ShadingUniforms {
    glm::vec3 viewPosition{0.0f};
    float shininess = 32.0f;
    glm::vec3 ambient{0.0f};
    // Rebuilds world position from depth in layouts that do not store it (gbuffer_read.glsl).
    glm::mat4 inverseViewProj{1.0f};
    // Multiplies the surfaces' emission (shaders/surface_terms.glsl): 0 in a frame showing one
    // light's contribution alone, which leaves out the ambient term too.
    float emissiveWeight = 1.0f;
    // Split accumulation (shaders/light_accumulation.glsl): the lights go to the diffuse and
    // specular targets instead of one lit image.
    bool splitAccumulation = false;
    // The lighting equation (shaders/lighting.glsl), and whether the mode cuts it at the radius.
    ShadingModel model = ShadingModel::GbufferLab;
    bool cutAtRadius = false;
};

// Binds `texture` to texture unit `unit` (a BIND_* slot) and leaves unit 0 active.
void bindTextureUnit(int unit, GLenum target, GLuint texture);

// The G-buffer attachments on their BIND_GBUFFER_* units and its depth on BIND_DEPTH.
void bindGBuffer(GBufferTextures const& gbuffer);
// The light buffer on BIND_LIGHTS, and uLightCount.
void bindLights(gl::Program const& program, LightBuffer const& lights);
void setShadingUniforms(gl::Program const& program, ShadingUniforms const& shading);

// The display's tonemap (the uniforms of shaders/tonemap.glsl): the view pass applies it to the lit
// image, and the overlays drawn on the display image after it apply it to their HDR colour.
struct DisplayTonemap {
    Tonemap tonemap = Tonemap::Exposure;
    float exposure = 1.0f;
};
void setTonemapUniforms(gl::Program const& program, DisplayTonemap const& tonemap);

// The images a compute lighting pass writes: the lit (or diffuse) image on BIND_IMAGE_LIGHTING,
// split accumulation's specular light on BIND_IMAGE_SPECULAR_LIGHT, the counts on
// BIND_IMAGE_COVERAGE. All three are bound whatever the pass writes, so the program's declared
// images are always valid; unbindLightImages() after the dispatch.
void bindLightImages(gl::Texture const& lit, gl::Texture const& specular, gl::Texture const& coverage);
void unbindLightImages();

// All three: what every deferred lighting program reads.
struct DeferredInputs {
    GBufferTextures gbuffer;
    LightBuffer const& lights;
    ShadingUniforms shading;
};
void bindDeferredInputs(gl::Program const& program, DeferredInputs const& in);

// The HDR image a pass draws into, and the framebuffer that holds it with a depth-stencil
// (litFbo: its own depth; volumeFbo: the G-buffer's or a copy of it, RenderTargets::volumeDepth).
struct LitTarget {
    gl::Framebuffer const& fbo;
    gl::Texture const& hdr;
};
// What a lighting pass wrote.
struct LightingOutput {
    gl::Texture const& hdr;  // the lit image
};

}  // namespace gbl
