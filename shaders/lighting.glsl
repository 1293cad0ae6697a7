// The lighting equation of docs/lighting.md, shared by every lighting mode.
struct Light {
    vec3 position;
    vec3 color;       // colour * intensity
    vec3 attenuation; // Kc, Kl, Kq
    float radius;
    float cutoff;     // attenuation at the radius (threshold / Imax)
    vec3 direction;   // unit, where a spot or directional light shines
    float cosOuter;   // spot cone: factor = saturate((cos(angle) - cosOuter) * coneScale)^2;
    float coneScale;  // points have cosOuter = -2, coneScale = 1: factor 1 (core/light_math.h)
};

uniform vec3 uViewPos;
uniform float uShininess;
// The specular exponent: the setting, or (GBL_SHININESS_PER_PIXEL: prepass's light pass) the one its
// thin G-buffer stored at the pixel, which that shader reads into gShininess before its lights.
#ifdef GBL_SHININESS_PER_PIXEL
float gShininess = 32.0;
#define GBL_SHININESS gShininess
#else
#define GBL_SHININESS uShininess
#endif
// gbl::ShadingModel (core/pipeline_settings.h): docs/lighting.md's model, or LearnOpenGL's deferred
// lighting shader (docs/lighting.md, "The learnopengl shading"): attenuation 1/(Kc + Kl d + Kq d^2)
// with no window, specular not gated by N.L. uCutAtRadius: the mode lights only inside the
// radius (volumes, tiled, clustered), so that shading ends there too rather than at a tile's or a
// volume mesh's edge.
#define SHADING_GBUFFER_LAB 0
#define SHADING_LEARNOPENGL 1
uniform int uShadingModel;
uniform bool uCutAtRadius;

// A surface point as the light loops see it: position, unit normal, and the unit direction to the
// eye, which is the same for every light and so is worked out once per pixel, not once per light.
struct SurfacePoint {
    vec3 p;
    vec3 n;
    vec3 V;
};

SurfacePoint surfacePoint(vec3 p, vec3 n) { return SurfacePoint(p, n, normalize(uViewPos - p)); }

// Windowed attenuation: the classic 1/(Kc + Kl d + Kq d^2) minus its value at the radius, so
// the contribution is exactly zero at and beyond the radius in every mode. The learnopengl
// shading takes the classic term as it is.
float windowedAttenuation(Light l, float d) {
    float att = 1.0 / (l.attenuation.x + l.attenuation.y * d + l.attenuation.z * d * d);
    // A light of radius 0 (too dim to reach the threshold, or invalid) adds nothing in either.
    if (uShadingModel == SHADING_LEARNOPENGL) return l.radius > 0.0 && !(uCutAtRadius && d >= l.radius) ? att : 0.0;
    return d < l.radius ? max(att - l.cutoff, 0.0) : 0.0;
}

// The spot cone factor for the unit vector L from the surface to the light (1 for points).
float spotConeFactor(Light l, vec3 L) {
    float t = clamp((dot(-L, l.direction) - l.cosOuter) * l.coneScale, 0.0, 1.0);
    return t * t;
}

// Blinn-Phong of light arriving from unit direction L with `radiance`, before the material:
// diffuse light N.L * radiance (the albedo multiplies it) and specular light
// (N.H)^shininess * radiance (the specular intensity multiplies it). `accumulation: split` keeps
// the two sums apart.
void blinnPhongSplit(vec3 L, vec3 radiance, SurfacePoint s, out vec3 diffuseLight, out vec3 specularLight) {
    vec3 H = normalize(L + s.V);
    float diff = max(dot(s.n, L), 0.0);
    float spec = diff > 0.0 || uShadingModel == SHADING_LEARNOPENGL ? pow(max(dot(s.n, H), 0.0), GBL_SHININESS) : 0.0;
    diffuseLight = diff * radiance;
    specularLight = spec * radiance;
}

// One point or spot light at a surface point, as the two sums.
// No early return where the light adds nothing: the factor att * cone is zero there and zeroes both
// sums. The loops over lights test whether the light can light the point first where that skips
// work on the machine (lightMayLight, light_accumulation.glsl); llvmpipe runs both sides of every
// branch under a mask, and the masks of two early returns here cost quad and tiled about a tenth
// of their lighting pass (bench, 512 lights, radius x1).
void shadeLightSplit(Light l, SurfacePoint s, out vec3 diffuseLight, out vec3 specularLight) {
    vec3 toLight = l.position - s.p;
    float d = length(toLight);
    vec3 L = toLight / max(d, 1e-30);  // a surface point at the light itself: L = 0, not NaN
    float factor = windowedAttenuation(l, d) * spotConeFactor(l, L);
    blinnPhongSplit(L, l.color * factor, s, diffuseLight, specularLight);
}

// One directional light, as the two sums: from -direction everywhere, no attenuation.
void shadeDirectionalSplit(Light l, SurfacePoint s, out vec3 diffuseLight, out vec3 specularLight) {
    blinnPhongSplit(-l.direction, l.color, s, diffuseLight, specularLight);
}

// One point or spot light at a surface point, with its material.
vec3 shadeLight(Light l, SurfacePoint s, vec3 albedo, float specular) {
    vec3 diffuseLight, specularLight;
    shadeLightSplit(l, s, diffuseLight, specularLight);
    return albedo * diffuseLight + specular * specularLight;
}
vec3 shadeLight(Light l, vec3 p, vec3 n, vec3 albedo, float specular) { return shadeLight(l, surfacePoint(p, n), albedo, specular); }

// One directional light at a surface point, with its material.
vec3 shadeDirectional(Light l, vec3 p, vec3 n, vec3 albedo, float specular) {
    vec3 diffuseLight, specularLight;
    shadeDirectionalSplit(l, surfacePoint(p, n), diffuseLight, specularLight);
    return albedo * diffuseLight + specular * specularLight;
}
