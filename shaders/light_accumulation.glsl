// What a pixel's lights add up to, kept as two sums: diffuse light (without albedo) and specular
// light (with the specular intensity). A single-target frame writes surface + albedo * diffuse +
// specular; `accumulation: split` writes the two sums and light_combine.frag adds the rest
// (docs/lighting.md, "Accumulation targets").
#ifndef GBL_LIGHT_ACCUMULATION_GLSL
#define GBL_LIGHT_ACCUMULATION_GLSL
uniform bool uSplitAccumulation;

struct LightSum {
    vec3 diffuse;
    vec3 specular;
};

LightSum noLight() { return LightSum(vec3(0.0), vec3(0.0)); }

// Returns whether the light reached the surface (added more than zero): the coverage views count
// those, and a second shading call to find out would cost its full price again (llvmpipe runs
// both sides of every branch, and the compiler does not merge the two calls).
bool accumulateLight(inout LightSum sum, Light l, SurfacePoint s, float specularIntensity) {
    vec3 diffuseLight, specularLight;
    shadeLightSplit(l, s, diffuseLight, specularLight);
    sum.diffuse += diffuseLight;
    sum.specular += specularIntensity * specularLight;
    return any(greaterThan(diffuseLight + specularLight, vec3(0.0)));
}

// Whether a point or spot light (texel 0 of the light buffer: position, radius) can add anything
// at the surface point: the point lies within its radius (windowedAttenuation is zero from the
// radius on) and in front of the surface (Blinn-Phong adds neither diffuse nor specular light
// where N.L <= 0). Where it is false, shading the light adds exactly zero, so skipping it is exact.
// The learnopengl shading lights beyond the radius (unless the mode cuts there) and behind the
// surface (its specular term is not gated by N.L).
bool lightMayLight(vec4 positionRadius, SurfacePoint s) {
    vec3 toLight = positionRadius.xyz - s.p;
    if (uShadingModel == SHADING_LEARNOPENGL)
        return positionRadius.w > 0.0 && (!uCutAtRadius || length(toLight) < positionRadius.w);
    return length(toLight) < positionRadius.w && dot(s.n, toLight) > 0.0;
}

// Light i of a loop over lights at a surface point, if `listed` (false: a padding entry past the
// end of a list, which must add nothing). Returns whether it reached the surface.
// Where branches skip work (GPUs), lights that cannot light the point are skipped after one
// texel. Where branches are masked (GBL_MASKED_BRANCHES: CPU rasterisers such as llvmpipe run
// both sides of every `if`), a test only adds the cost of its mask: the light is shaded anyway,
// which adds exactly zero where lightMayLight is false, and a padding entry's colour is scaled by
// zero.
bool accumulateListedLight(inout LightSum sum, int i, bool listed, SurfacePoint s, float specularIntensity) {
#ifdef GBL_MASKED_BRANCHES
    Light l = fetchLight(i);
    l.color *= listed ? 1.0 : 0.0;
    return accumulateLight(sum, l, s, specularIntensity);
#else
    if (!listed || !lightMayLight(lightTexel(i * 4), s)) return false;
    return accumulateLight(sum, fetchLight(i), s, specularIntensity);
#endif
}

// Every directional light (light_fetch.glsl's list: no volume, no tile, every pixel) into the sums.
void accumulateGlobalLights(inout LightSum sum, SurfacePoint s, float specularIntensity) {
    for (int k = 0; k < min(uDirectionalCount, MAX_DIRECTIONAL_LIGHTS); ++k) {
        vec3 diffuseLight, specularLight;
        shadeDirectionalSplit(fetchLight(uDirectionalLights[k]), s, diffuseLight, specularLight);
        sum.diffuse += diffuseLight;
        sum.specular += specularIntensity * specularLight;
    }
}

// Attachment 0's value: the lit value, or (split) the diffuse light. Attachment 1 (split only)
// takes sum.specular.
vec4 accumulationTarget0(LightSum sum, vec3 surface, vec3 albedo) {
    return vec4(uSplitAccumulation ? sum.diffuse : surface + albedo * sum.diffuse + sum.specular, 1.0);
}
#endif
