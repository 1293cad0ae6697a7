// Reads one light from the light buffer texture (layout in renderer/light_buffer.h).
uniform samplerBuffer uLights;

Light fetchLight(int i) {
    vec4 a = texelFetch(uLights, i * 4 + 0);
    vec4 b = texelFetch(uLights, i * 4 + 1);
    vec4 c = texelFetch(uLights, i * 4 + 2);
    return Light(a.xyz, b.xyz, c.xyz, a.w, b.w);
}

// The light's colour without intensity (0..1), for wireframes.
vec3 fetchLightColor(int i) { return texelFetch(uLights, i * 4 + 3).rgb; }
