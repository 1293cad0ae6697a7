// prepass (docs/deferred_lighting.md): the surface at a pixel of the thin G-buffer, as its light pass
// reads it (prepass_light.frag full screen, light_volume.frag built with PREPASS_LIGHTS): the world
// position rebuilt from the thin pass's depth, the normal and the specular exponent it stored. Needs
// lighting.glsl built with GBL_SHININESS_PER_PIXEL (the exponent goes to gShininess).
#ifndef GBL_PREPASS_SURFACE_GLSL
#define GBL_PREPASS_SURFACE_GLSL
uniform sampler2D uPrepassNormal;  // xyz unit world normal, w specular exponent
uniform sampler2D uDepth;          // the thin pass's depth (window space, 1 = background)
uniform mat4 uInverseViewProj;

// False on the background: the thin pass clears depth to 1 and draws with GL_LESS.
bool prepassSurface(ivec2 px, out SurfacePoint s) {
    float d = texelFetch(uDepth, px, 0).r;
    // The world position rebuilt from depth, as gbuffer_read.glsl does for the layouts without one.
    vec2 ndc = (vec2(px) + 0.5) / vec2(textureSize(uDepth, 0)) * 2.0 - 1.0;
    vec4 world = uInverseViewProj * vec4(ndc, d * 2.0 - 1.0, 1.0);
    vec4 stored = texelFetch(uPrepassNormal, px, 0);
    gShininess = stored.w;
    s = surfacePoint(world.xyz / world.w, normalize(stored.xyz));
    return d < 1.0;
}
#endif
