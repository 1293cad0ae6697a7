// The default courtyard: architecture, props, generated materials and the 32-light demo.
#include "scene/default_scene.h"

#include "core/light_math.h"
#include "scene/mesh_builder.h"
#include "scene/procedural_textures.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace gbl {

namespace {

// --- Layout (units are metres-ish; floor at y = 0) -------------------------------------------

constexpr float kWallInner = 16.0f;  // inner faces of the outer walls
constexpr float kWallThickness = 0.5f;
constexpr float kWallHeight = 10.2f;
constexpr float kArcade = 12.5f;  // column centre lines of the four arcades
constexpr int kBays = 7;          // arches per side, so an arch (not a column) faces the centre
constexpr float kSpacing = 2.0f * kArcade / float(kBays);
constexpr float kCapitalHalf = 0.35f;  // half width of a capital; the arch feet rest on it
constexpr float kArchOuter = kSpacing * 0.5f;
constexpr float kArchInner = kArchOuter - kCapitalHalf;
constexpr float kArchDepth = 0.6f;
constexpr float kSlab = 0.3f;                              // gallery floor and cornice thickness
constexpr float kColumn1 = 3.0f;                           // ground-floor column height
constexpr float kColumn2 = 2.6f;                           // gallery column height
constexpr float kStorey2 = kColumn1 + kArchOuter + kSlab;  // gallery floor level
constexpr float kCornice = kStorey2 + kColumn2 + kArchOuter;

constexpr int kTextureSize = 512;

enum MaterialId { Flagstone, Brick, Sandstone, Wood, Iron, Marble, RedGlaze, Gold, BlueGlaze, MaterialCount };

glm::mat4 translate(glm::vec3 t) {
    return glm::translate(glm::mat4(1.0f), t);
}
glm::mat4 rotateY(float radians) {
    return glm::rotate(glm::mat4(1.0f), radians, glm::vec3(0, 1, 0));
}

// Box from min to max corner, UVs at the given density.
void addBox(MeshData& dst, glm::vec3 lo, glm::vec3 hi, float uvScale, glm::mat4 const& m = glm::mat4(1.0f)) {
    appendMesh(dst, makeBox(hi - lo, uvScale), m * translate((lo + hi) * 0.5f));
}

// A column standing on y = 0 with its capital top at y = height.
MeshData makeColumn(float height) {
    MeshData c;
    float const uv = 0.5f;
    addBox(c, {-0.35f, 0.0f, -0.35f}, {0.35f, 0.2f, 0.35f}, uv);  // plinth
    appendMesh(c, makeTorus(0.27f, 0.07f, 32, 8, uv), translate({0, 0.27f, 0}));
    appendMesh(c, makeCylinder(0.25f, height - 0.45f, 32, 4, uv, false), translate({0, 0.2f, 0}));
    appendMesh(c, makeTorus(0.27f, 0.06f, 32, 8, uv), translate({0, height - 0.31f, 0}));
    addBox(c, {-kCapitalHalf, height - 0.25f, -kCapitalHalf}, {kCapitalHalf, height, kCapitalHalf}, uv);
    return c;
}

// The placements of one arcade storey: every column position on the square, and each bay's
// centre with the rotation that turns an arch (built along X) to follow its side.
struct Bay {
    glm::vec3 centre;
    float yaw;
};

std::vector<glm::vec2> columnPositions() {
    std::vector<glm::vec2> out;
    for (int k = 0; k <= kBays; ++k) {
        float const t = -kArcade + float(k) * kSpacing;
        out.push_back({t, -kArcade});
        out.push_back({t, kArcade});
        if (k > 0 && k < kBays) {
            out.push_back({-kArcade, t});
            out.push_back({kArcade, t});
        }
    }
    return out;
}

std::vector<Bay> bays(float y) {
    std::vector<Bay> out;
    float const halfPi = std::numbers::pi_v<float> * 0.5f;
    for (int k = 0; k < kBays; ++k) {
        float const t = -kArcade + (float(k) + 0.5f) * kSpacing;
        out.push_back({{t, y, -kArcade}, 0.0f});
        out.push_back({{t, y, kArcade}, 0.0f});
        out.push_back({{-kArcade, y, t}, halfPi});
        out.push_back({{kArcade, y, t}, halfPi});
    }
    return out;
}

// A horizontal ring of slabs from the arcade line out to the walls (gallery floor, cornice).
void addRing(MeshData& dst, float inner, float outer, float y0, float y1, float uvScale) {
    addBox(dst, {-outer, y0, inner}, {outer, y1, outer}, uvScale);
    addBox(dst, {-outer, y0, -outer}, {outer, y1, -inner}, uvScale);
    addBox(dst, {inner, y0, -inner}, {outer, y1, inner}, uvScale);
    addBox(dst, {-outer, y0, -inner}, {-inner, y1, inner}, uvScale);
}

// Railing for one gallery bay, built along X centred on the origin, standing on y = 0.
MeshData makeBalustrade(float length) {
    MeshData b;
    float const uv = 0.5f, h = length * 0.5f;
    addBox(b, {-h, 0.0f, -0.15f}, {h, 0.12f, 0.15f}, uv);
    addBox(b, {-h, 0.85f, -0.15f}, {h, 0.97f, 0.15f}, uv);
    MeshData const baluster = makeCylinder(0.05f, 0.73f, 12, 1, uv, false);
    constexpr int kCount = 7;
    for (int i = 0; i < kCount; ++i)
        appendMesh(b, baluster, translate({-h + length * float(i + 1) / float(kCount + 1), 0.12f, 0.0f}));
    return b;
}

// Angle in radians from a hash, so props are turned differently but reproducibly.
float propYaw(int i) {
    return 6.2831853f * hashUnit(i, 0, 0xc0ffeeU);
}

void addArchitecture(std::array<MeshData, MaterialCount>& mat) {
    float const outer = kWallInner + kWallThickness;
    // Floor under everything, 1 m paving stones (the flagstone tile holds 4 x 4 stones).
    appendMesh(mat[Flagstone], makePlane({2.0f * outer, 2.0f * outer}, 33, 33, 0.25f));
    // Outer walls.
    addBox(mat[Brick], {-outer, 0, kWallInner}, {outer, kWallHeight, outer}, 0.5f);
    addBox(mat[Brick], {-outer, 0, -outer}, {outer, kWallHeight, -kWallInner}, 0.5f);
    addBox(mat[Brick], {kWallInner, 0, -kWallInner}, {outer, kWallHeight, kWallInner}, 0.5f);
    addBox(mat[Brick], {-outer, 0, -kWallInner}, {-kWallInner, kWallHeight, kWallInner}, 0.5f);

    // Two storeys of columns carrying square-backed arches, each topped by a slab ring.
    MeshData const arch = makeArch(kArchInner, kArchOuter, kArchDepth, 24, 0.5f, true);
    struct Storey {
        float base, columnHeight;
    };
    for (Storey s : {Storey{0.0f, kColumn1}, Storey{kStorey2, kColumn2}}) {
        MeshData const column = makeColumn(s.columnHeight);
        for (glm::vec2 p : columnPositions()) appendMesh(mat[Sandstone], column, translate({p.x, s.base, p.y}));
        for (Bay const& b : bays(s.base + s.columnHeight))
            appendMesh(mat[Sandstone], arch, translate(b.centre) * rotateY(b.yaw));
    }
    addRing(mat[Sandstone], kArcade - kCapitalHalf, kWallInner, kStorey2 - kSlab, kStorey2, 0.5f);
    addRing(mat[Sandstone], kArcade - kCapitalHalf - 0.15f, kWallInner, kCornice, kCornice + kSlab, 0.5f);

    // Gallery railings between the upper columns.
    MeshData const rail = makeBalustrade(kSpacing - 2.0f * 0.3f);
    for (Bay const& b : bays(kStorey2)) appendMesh(mat[Sandstone], rail, translate(b.centre) * rotateY(b.yaw));
}

void addProps(std::array<MeshData, MaterialCount>& mat) {
    int propIndex = 0;
    // Fountain at the centre.
    appendMesh(mat[Sandstone], makeCylinder(2.2f, 0.6f, 64, 1, 0.5f));
    appendMesh(mat[Sandstone], makeTorus(2.2f, 0.12f, 64, 12, 0.5f), translate({0, 0.6f, 0}));
    appendMesh(mat[Sandstone], makeCylinder(0.35f, 1.5f, 32, 2, 0.5f), translate({0, 0.6f, 0}));
    appendMesh(mat[Iron], makeTorus(0.5f, 0.08f, 48, 12), translate({0, 2.05f, 0}));
    appendMesh(mat[Gold], makeSphere(0.6f, 64, 48), translate({0, 2.7f, 0}));
    ++propIndex;

    // Pedestals carrying polished spheres at the four diagonals.
    MaterialId const sphereMats[4] = {Marble, RedGlaze, BlueGlaze, Gold};
    glm::vec2 const pedestals[4] = {{6.5f, 6.5f}, {-6.5f, 6.5f}, {-6.5f, -6.5f}, {6.5f, -6.5f}};
    for (int i = 0; i < 4; ++i) {
        glm::mat4 const at = translate({pedestals[i].x, 0, pedestals[i].y}) * rotateY(propYaw(propIndex++));
        addBox(mat[Sandstone], {-0.5f, 0.0f, -0.5f}, {0.5f, 0.2f, 0.5f}, 0.5f, at);
        addBox(mat[Sandstone], {-0.3f, 0.2f, -0.3f}, {0.3f, 1.3f, 0.3f}, 0.5f, at);
        addBox(mat[Sandstone], {-0.42f, 1.3f, -0.42f}, {0.42f, 1.45f, 0.42f}, 0.5f, at);
        appendMesh(mat[sphereMats[i]], makeSphere(0.42f, 48, 32), at * translate({0, 1.87f, 0}));
    }

    // Crates: x, z, edge, and the height they stand at (stacked ones sit on another crate).
    struct Crate {
        float x, z, size, base;
    };
    Crate const crates[] = {
        {9.0f, -3.2f, 1.0f, 0.0f}, {10.3f, -3.0f, 0.9f, 0.0f}, {9.5f, -1.9f, 0.8f, 0.0f}, {9.05f, -3.15f, 0.7f, 1.0f},
        {-9.2f, 3.8f, 1.1f, 0.0f}, {-10.4f, 4.6f, 0.8f, 0.0f}, {-9.0f, 5.3f, 0.9f, 0.0f}, {-9.25f, 3.85f, 0.8f, 1.1f},
        {3.0f, 9.8f, 0.9f, 0.0f},  {4.3f, 10.0f, 0.7f, 0.0f},
    };
    for (Crate const& c : crates) {
        // Stacked crates are only slightly askew on the one below.
        float const yaw = c.base > 0.0f ? 0.05f * (propYaw(propIndex) - 3.14f) : propYaw(propIndex);
        ++propIndex;
        appendMesh(mat[Wood], makeBox(glm::vec3(c.size), 1.0f / c.size),
                   translate({c.x, c.base + c.size * 0.5f, c.z}) * rotateY(yaw));
    }

    // Barrels: wooden staves with two iron hoops; some lie on their side.
    MeshData barrel = makeCylinder(0.4f, 1.0f, 32, 2, 1.0f);
    MeshData hoops;
    appendMesh(hoops, makeTorus(0.405f, 0.03f, 32, 6), translate({0, 0.18f, 0}));
    appendMesh(hoops, makeTorus(0.405f, 0.03f, 32, 6), translate({0, 0.82f, 0}));
    struct Barrel {
        float x, z;
        bool lying;
    };
    Barrel const barrels[] = {
        {-3.5f, -9.6f, false}, {-2.6f, -10.3f, false}, {-4.4f, -10.4f, false}, {-3.4f, -11.0f, false},
        {-5.8f, -9.9f, true},  {10.2f, 6.8f, false},   {10.6f, 8.0f, false},   {9.4f, 8.7f, false},
        {7.6f, -10.2f, true},  {8.9f, -10.6f, false},
    };
    for (Barrel const& b : barrels) {
        glm::mat4 m = translate({b.x, 0, b.z}) * rotateY(propYaw(propIndex++));
        // Lying barrels: turned onto their side about X, resting on their hoops, centred on (x, z).
        if (b.lying)
            m = m * translate({0, 0.435f, 0.5f}) * glm::rotate(glm::mat4(1.0f), -1.5707963f, glm::vec3(1, 0, 0));
        appendMesh(mat[Wood], barrel, m);
        appendMesh(mat[Iron], hoops, m);
    }

    // Loose balls on the floor.
    struct Ball {
        float x, z;
        MaterialId material;
    };
    Ball const balls[] = {{2.0f, -5.0f, RedGlaze}, {-3.0f, 5.0f, BlueGlaze}, {5.0f, 2.5f, Gold},
                          {-5.0f, -2.0f, Marble},  {0.5f, -6.5f, BlueGlaze}, {-1.5f, 7.0f, RedGlaze}};
    MeshData const ball = makeSphere(0.3f, 32, 24);
    for (Ball const& b : balls) {
        appendMesh(mat[b.material], ball, translate({b.x, 0.3f, b.z}));
        ++propIndex;
    }

    // Stone benches facing the fountain.
    float const halfPi = std::numbers::pi_v<float> * 0.5f;
    glm::mat4 const benches[4] = {translate({0, 0, 10.6f}), translate({0, 0, -10.6f}),
                                  translate({10.9f, 0, 0}) * rotateY(halfPi),
                                  translate({-10.9f, 0, 0}) * rotateY(halfPi)};
    for (glm::mat4 const& at : benches) {
        addBox(mat[Sandstone], {-1.2f, 0.44f, -0.3f}, {1.2f, 0.56f, 0.3f}, 0.5f, at);
        addBox(mat[Sandstone], {-1.0f, 0.0f, -0.25f}, {-0.85f, 0.44f, 0.25f}, 0.5f, at);
        addBox(mat[Sandstone], {0.85f, 0.0f, -0.25f}, {1.0f, 0.44f, 0.25f}, 0.5f, at);
        ++propIndex;
    }
}

int addTextureSet(SceneData& scene, TextureSet set, Material& m) {
    int const first = int(scene.images.size());
    scene.images.push_back(std::move(set.albedo));
    scene.images.push_back(std::move(set.normal));
    scene.images.push_back(std::move(set.specular));
    m.baseColorTexture = first;
    m.normalTexture = first + 1;
    m.specularTexture = first + 2;
    m.specularFactor = 1.0f;  // the specular map carries the values
    return first;
}

Material plainMaterial(char const* name, glm::vec3 color, float specular) {
    Material m;
    m.name = name;
    m.baseColorFactor = glm::vec4(color, 1.0f);
    m.specularFactor = specular;
    return m;
}

// HSV (all 0..1) to linear RGB; with v = 1 the largest channel is exactly 1.
glm::vec3 hsvToRgb(float h, float s, float v) {
    float const h6 = (h - std::floor(h)) * 6.0f;
    int const sector = std::min(int(h6), 5);
    float const f = h6 - float(sector);
    float const p = v * (1.0f - s), q = v * (1.0f - s * f), t = v * (1.0f - s * (1.0f - f));
    switch (sector) {
        case 0:
            return {v, t, p};
        case 1:
            return {q, v, p};
        case 2:
            return {p, v, t};
        case 3:
            return {p, q, v};
        case 4:
            return {t, p, v};
        default:
            return {v, p, q};
    }
}

float fract(double x) {
    return float(x - std::floor(x));
}

// Per-light orbit rate in rad/s: 0.15..0.25, alternating direction.
double orbitRate(std::size_t i) {
    double const speed = 0.15 + 0.1 * double(fract(double(i) * 0.6180339887));
    return i % 2 == 0 ? speed : -speed;
}

// The panes of kGlassPanes: a double-sided quad each, its own material, mesh and instance.
void addGlassPanes(SceneData& scene) {
    for (GlassPane const& g : kGlassPanes) {
        Material m;
        m.name = g.name;
        m.baseColorFactor = g.color;
        m.specularFactor = 1.0f;
        m.alphaMode = AlphaMode::Blend;
        m.doubleSided = true;
        MeshData pane = makePlane(g.size);  // in y = 0, facing +Y: stood up to face +Z
        pane.name = g.name;
        pane.material = int(scene.materials.size());
        scene.materials.push_back(m);
        glm::mat4 const model = translate(g.center) * rotateY(g.yaw) *
                                glm::rotate(glm::mat4(1.0f), std::numbers::pi_v<float> * 0.5f, glm::vec3(1, 0, 0));
        scene.instances.push_back({int(scene.meshes.size()), model});
        scene.meshes.push_back(std::move(pane));
    }
}

}  // namespace

SceneData makeDefaultScene(DefaultSceneOptions const& options) {
    SceneData scene;
    scene.source = "default";

    scene.materials.resize(MaterialCount);
    scene.materials[Flagstone].name = "flagstone";
    scene.materials[Brick].name = "brick";
    scene.materials[Sandstone].name = "sandstone";
    scene.materials[Wood].name = "wood";
    addTextureSet(scene, makeFlagstoneTextures(kTextureSize, 11U), scene.materials[Flagstone]);
    addTextureSet(scene, makeBrickTextures(kTextureSize, 23U), scene.materials[Brick]);
    addTextureSet(scene, makeSandstoneTextures(kTextureSize, 37U), scene.materials[Sandstone]);
    addTextureSet(scene, makeWoodTextures(kTextureSize, 41U), scene.materials[Wood]);
    scene.materials[Iron] = plainMaterial("iron", {0.22f, 0.22f, 0.24f}, 0.9f);
    scene.materials[Marble] = plainMaterial("marble", {0.92f, 0.91f, 0.88f}, 0.8f);
    scene.materials[RedGlaze] = plainMaterial("red glaze", {0.75f, 0.08f, 0.06f}, 1.0f);
    scene.materials[Gold] = plainMaterial("gold", {0.85f, 0.62f, 0.20f}, 1.0f);
    scene.materials[BlueGlaze] = plainMaterial("blue glaze", {0.10f, 0.25f, 0.75f}, 0.9f);

    std::array<MeshData, MaterialCount> byMaterial;
    addArchitecture(byMaterial);
    addProps(byMaterial);
    // One mesh and one identity instance per material: few draw calls for a software rasteriser.
    for (int i = 0; i < MaterialCount; ++i) {
        MeshData& m = byMaterial[std::size_t(i)];
        if (m.indices.empty()) continue;
        m.name = "courtyard " + scene.materials[std::size_t(i)].name;
        m.material = i;
        scene.instances.push_back({int(scene.meshes.size()), glm::mat4(1.0f)});
        scene.meshes.push_back(std::move(m));
    }

    if (options.glass) addGlassPanes(scene);
    scene.lights = makeDefaultLights(options.lightCount);

    Camera camera;
    camera.position = {0.0f, 5.0f, 11.5f};
    camera.lookAt({0.0f, 1.0f, -2.0f});
    scene.camera = camera;
    return scene;
}

std::vector<PointLight> makeDefaultLights(int count) {
    std::vector<PointLight> lights;
    if (count <= 0) return lights;
    lights.reserve(std::size_t(count));
    constexpr double kGoldenAngle = 2.39996322972865332;
    for (int i = 0; i < count; ++i) {
        // Low-discrepancy sequences: evenly spread, and light i never depends on count.
        double const di = double(i);
        float const hue = fract(0.05 + di * 0.6180339887);
        float const saturation = 0.75f + 0.25f * fract(0.3 + di * 0.4142135624);
        float const ring = 2.8f + 8.4f * std::sqrt(fract(0.5 + di * 0.7548776662));
        float const angle = float(std::fmod(di * kGoldenAngle, 2.0 * std::numbers::pi));
        float const height = 0.5f + 2.5f * fract(0.2 + di * 0.5698402910);

        PointLight l;
        l.position = {ring * std::cos(angle), height, ring * std::sin(angle)};
        l.color = hsvToRgb(hue, saturation, 1.0f);
        l.intensity = 1.0f + fract(0.2 + di * 0.3819660113);
        // Pick the radius, then solve Kq from Kc + Kl r + Kq r^2 = Imax / threshold.
        float const radius = 4.5f + 3.0f * fract(0.15 + di * 0.2360679775);
        l.kc = 1.0f;
        l.kl = 0.35f;
        l.kq = (lightImax(l) / l.threshold - l.kc - l.kl * radius) / (radius * radius);
        char name[32];
        std::snprintf(name, sizeof name, "light %02d", i);
        l.name = name;
        lights.push_back(l);
    }
    return lights;
}

void orbitLights(std::span<PointLight> lights, glm::vec3 center, float seconds) {
    for (std::size_t i = 0; i < lights.size(); ++i) {
        double const angle = std::fmod(orbitRate(i) * double(seconds), 2.0 * std::numbers::pi);
        float const c = float(std::cos(angle)), s = float(std::sin(angle));
        glm::vec3& p = lights[i].position;
        float const dx = p.x - center.x, dz = p.z - center.z;
        // Written as p + (R - I)(p - centre) so a zero angle changes no bit.
        float const nx = p.x + ((c - 1.0f) * dx + s * dz);
        float const nz = p.z + (-s * dx + (c - 1.0f) * dz);
        p.x = nx;
        p.z = nz;
    }
}

glm::vec3 defaultSceneCenter() {
    return {0.0f, 0.0f, 0.0f};
}

}  // namespace gbl
