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
