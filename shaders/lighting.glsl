// The lighting equation of docs/lighting.md, shared by every lighting mode.
struct Light {
    vec3 position;
    vec3 color;       // colour * intensity
    vec3 attenuation; // Kc, Kl, Kq
    float radius;
    float cutoff;     // attenuation at the radius (threshold / Imax)
};

uniform vec3 uViewPos;
uniform float uShininess;

// Windowed attenuation: the classic 1/(Kc + Kl d + Kq d^2) minus its value at the radius, so
// the contribution is exactly zero at and beyond the radius in every mode.
float windowedAttenuation(Light l, float d) {
    if (!(d < l.radius)) return 0.0;
    float att = 1.0 / (l.attenuation.x + l.attenuation.y * d + l.attenuation.z * d * d);
    return max(att - l.cutoff, 0.0);
}

// Blinn-Phong of one light at a surface point, before the material: diffuse light
// N.L * colour * att (the albedo multiplies it) and specular light (N.H)^shininess * colour * att
// (the specular intensity multiplies it). `accumulation: split` keeps the two sums apart.
void shadeLightSplit(Light l, vec3 p, vec3 n, out vec3 diffuseLight, out vec3 specularLight) {
    diffuseLight = specularLight = vec3(0.0);
    vec3 toLight = l.position - p;
    float d = length(toLight);
    float att = windowedAttenuation(l, d);
    if (att <= 0.0) return;
    vec3 L = toLight / d;
    vec3 V = normalize(uViewPos - p);
    vec3 H = normalize(L + V);
    float diff = max(dot(n, L), 0.0);
    float spec = diff > 0.0 ? pow(max(dot(n, H), 0.0), uShininess) : 0.0;
    diffuseLight = diff * l.color * att;
    specularLight = spec * l.color * att;
}

// Blinn-Phong diffuse + specular of one light at a surface point.
vec3 shadeLight(Light l, vec3 p, vec3 n, vec3 albedo, float specular) {
    vec3 diffuseLight, specularLight;
    shadeLightSplit(l, p, n, diffuseLight, specularLight);
    return albedo * diffuseLight + specular * specularLight;
}
