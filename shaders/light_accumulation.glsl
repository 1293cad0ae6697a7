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
bool accumulateLight(inout LightSum sum, Light l, vec3 p, vec3 n, float specularIntensity) {
    vec3 diffuseLight, specularLight;
    shadeLightSplit(l, p, n, diffuseLight, specularLight);
    sum.diffuse += diffuseLight;
    sum.specular += specularIntensity * specularLight;
    return any(greaterThan(diffuseLight + specularLight, vec3(0.0)));
}

// Light i of a loop over lights at a surface point, if `listed` (false: a padding entry past the
// end of a list, which must add nothing). Returns whether it reached the surface.
// Where branches skip work (GPUs), lights out of reach are skipped after one texel. Where branches
// are masked (GBL_MASKED_BRANCHES: CPU rasterisers such as llvmpipe run both sides of every `if`),
// a test only adds the cost of its mask: the light is shaded anyway, which adds exactly zero past
// its radius (windowedAttenuation), and a padding entry's colour is scaled by zero.
bool accumulateListedLight(inout LightSum sum, int i, bool listed, vec3 p, vec3 n, float specularIntensity) {
#ifdef GBL_MASKED_BRANCHES
    Light l = fetchLight(i);
    l.color *= listed ? 1.0 : 0.0;
    return accumulateLight(sum, l, p, n, specularIntensity);
#else
    vec4 positionRadius = texelFetch(uLights, i * 4);
    if (!listed || !(distance(positionRadius.xyz, p) < positionRadius.w)) return false;
    return accumulateLight(sum, fetchLight(i), p, n, specularIntensity);
#endif
}

// Every directional light (light_fetch.glsl's list: no volume, no tile, every pixel) into the sums.
void accumulateGlobalLights(inout LightSum sum, vec3 p, vec3 n, float specularIntensity) {
    for (int k = 0; k < uDirectionalCount; ++k) {
        vec3 diffuseLight, specularLight;
        shadeDirectionalSplit(fetchLight(uDirectionalLights[k]), p, n, diffuseLight, specularLight);
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
