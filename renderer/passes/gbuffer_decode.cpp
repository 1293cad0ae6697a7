// G-buffer decode pass.
#include "passes/gbuffer_decode.h"

#include "passes/shading_inputs.h"

namespace gbl {

DecodedGBuffer createDecodedGBuffer(int width, int height, bool material) {
    DecodedGBuffer d;
    d.width = width;
    d.height = height;
    d.position = gl::Texture::create2D(GL_RGBA32F, width, height, "gbuffer.decoded_position");
    d.normal = gl::Texture::create2D(GL_RGBA32F, width, height, "gbuffer.decoded_normal");
    if (!material) {
        d.fbo = gl::Framebuffer::create({&d.position, &d.normal}, nullptr, "gbuffer.decoded");
        return d;
    }
    d.albedoSpec = gl::Texture::create2D(GL_RGBA32F, width, height, "gbuffer.decoded_albedo_spec");
    d.emissiveAo = gl::Texture::create2D(GL_RGBA32F, width, height, "gbuffer.decoded_emissive_ao");
    d.fbo = gl::Framebuffer::create({&d.position, &d.normal, &d.albedoSpec, &d.emissiveAo}, nullptr,
                                    "gbuffer.decoded_sample");
    return d;
}

void gbufferDecodePass(GBufferDecodeInput const& in, GBufferDecodeConfig const& c) {
    glBindFramebuffer(GL_FRAMEBUFFER, in.target.fbo.id());
    glViewport(0, 0, in.target.width, in.target.height);
    applyGroup(c.states, 0);
    in.program.use();
    bindGBuffer(in.gbuffer);
    in.program.set("uInverseViewProj", c.inverseViewProj);
    in.program.set("uPixelOffset", c.pixelOffset);
    in.program.set("uSample", c.sample);  // the msaa variants' (no such uniform elsewhere: ignored)
    in.program.set("uViewPos", c.eye);
    in.triangle.draw();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace gbl
