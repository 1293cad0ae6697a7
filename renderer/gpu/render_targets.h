// Every screen-sized target of the frame, rebuilt together by resizeTargets().
#pragma once

#include "core/gbuffer_layout.h"
#include "gl/framebuffer.h"
#include "gl/texture.h"

#include <glm/vec2.hpp>

#include <optional>
#include <string>
#include <vector>

namespace gbl {

// The textures of one G-buffer layout (core/gbuffer_layout.h says which exist and their formats).
struct GBuffer {
    GBufferLayout layout = GBufferLayout::Classic;
    gl::Texture position;    // world position, w = 1 where drawn; empty when rebuilt from depth
    gl::Texture normal;      // the encoded world normal
    gl::Texture albedoSpec;  // RGBA8 albedo rgb + specular a
    gl::Texture emissive;    // emitted radiance rgb + ambient occlusion a
    gl::Texture depth;       // depth-stencil, sampled by position rebuilding, depth views and the shader copy
    gl::Framebuffer fbo;     // colour attachments in the layout's order

    gl::Texture const& texture(GBufferSlot slot) const {
        switch (slot) {
            case GBufferSlot::Position:
                return position;
            case GBufferSlot::Normal:
                return normal;
            case GBufferSlot::AlbedoSpec:
                return albedoSpec;
            case GBufferSlot::Emissive:
                return emissive;
            case GBufferSlot::Depth:
                break;
        }
        return depth;
    }
};

// The GL internal format of a layout's texel format.
GLenum glInternalFormat(TexelFormat f);

// msaa (docs/msaa.md): the multisampled G-buffer the geometry pass draws into (the frame's layout),
// and the complex pixels' mask with the lit target's depth-stencil, whose stencil marks them.
// Made by createMsaaTargets when a frame first asks for its sample count; empty otherwise.
struct MsaaTargets {
    int samples = 0;
    // Each sample's place in its pixel (0..1), as the driver reports it for these targets
    // (GL_SAMPLE_POSITION): where the layouts that rebuild position unproject each sample's depth.
    std::vector<glm::vec2> samplePositions;
    GBuffer gbuffer;             // GL_TEXTURE_2D_MULTISAMPLE attachments, one per slot of the layout
    gl::Texture complexMask;     // R8: 1 where the pixel's samples differ (msaa_edges pass)
    gl::Framebuffer complexFbo;  // complexMask + RenderTargets::litDepth
};

struct RenderTargets {
    int width = 0;
    int height = 0;
    GBuffer gbuffer;
    gl::Texture lighting;    // RGBA16F HDR
    gl::Texture litDepth;    // the G-buffer depth's format, so blits work
    gl::Framebuffer litFbo;  // lighting + litDepth: lighting passes and the forward pass
    // The depth-stencil the volume passes test against (and mark in stencil cull): a copy of the
    // G-buffer's, blitted before them (volumeDepthPass), in the layouts whose lighting samples the
    // G-buffer's depth to rebuild position; empty in the others, which attach the G-buffer's own.
    // Attaching a texture the pass samples is a feedback loop, undefined in GL.
    gl::Texture volumeDepth;
    // lighting + volumeDepthStencil(): the light volumes test against the scene depth (and use its
    // stencil) without needing the blit step.
    gl::Framebuffer volumeFbo;
    // Accumulation targets of `accumulation: split` (RGBA16F each): diffuse light (N.L * att *
    // colour, no albedo) and specular light; the combine pass turns them into `lighting`.
    gl::Texture diffuseLight;
    gl::Texture specularLight;
    gl::Framebuffer splitFbo;        // diffuseLight + specularLight: the full-screen pass
    gl::Framebuffer splitVolumeFbo;  // the same with volumeDepthStencil(): the volumes
    gl::Texture coverage;            // RG32F: x = volumes that covered the pixel, y = lights that lit it
    gl::Framebuffer coverageFbo;     // coverage + volumeDepthStencil(): the volume counts
    gl::Texture display;             // RGBA8 final image
    gl::Framebuffer displayFbo;      // display alone: the view pass
    // prepass (deferred lighting): the thin G-buffer's normal target (RGBA16F: world normal xyz,
    // specular exponent w), drawn with litDepth as its depth; the light pass sums into
    // diffuseLight and specularLight (splitFbo), the second geometry pass into litFbo.
    gl::Texture prepassNormal;
    gl::Framebuffer prepassFbo;  // prepassNormal + litDepth
    // The overlays (light cubes, volume wireframes) are drawn onto the display image after the view
    // pass, so the lit image stays the light sum. Each framebuffer pairs the display with a scene
    // depth to test against; neither depth is sampled by the overlays, and the display image is
    // sampled by nothing, so there is no feedback loop.
    // display + litDepth: the cubes (and forward mode's wireframes). In deferred modes litDepth
    // holds the scene only when the depth-copy step ran, so without it the cubes show through walls.
    gl::Framebuffer overlayFbo;
    // display + the G-buffer's depth-stencil: the deferred modes' wireframes, which test against
    // the scene's depth whether or not the depth-copy step ran.
    gl::Framebuffer overlayGBufferDepthFbo;
    MsaaTargets msaa;

    bool empty() const { return width == 0 || height == 0; }
    // What volumeFbo, splitVolumeFbo and coverageFbo attach as depth-stencil.
    gl::Texture const& volumeDepthStencil() const { return volumeDepth ? volumeDepth : gbuffer.depth; }
};

// Creates all targets at w x h (0 x 0 gives empty targets) with the G-buffer in `layout`. Returns
// the first incomplete framebuffer's error, if any.
std::optional<std::string> createRenderTargets(int width, int height, GBufferLayout layout, RenderTargets& out);

// Makes out.msaa for `samples` per pixel at the targets' size and layout (gpu/msaa_targets.cpp), with
// the volumes' targets when `volumes`; the first incomplete framebuffer's error, or the texture the
// driver could not allocate (GL_OUT_OF_MEMORY), if any (out.msaa is then empty).
std::optional<std::string> createMsaaTargets(int samples, RenderTargets& out);

}  // namespace gbl
