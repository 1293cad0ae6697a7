// The procedural default scene, mesh builders, generated textures and orbiting lights on the CPU.
#include "scene/default_scene.h"
#include "core/light_math.h"
#include "scene/mesh_builder.h"
#include "scene/procedural_textures.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstring>
#include <vector>

using namespace gbl;

namespace {

// Builders normalise in float and transforms add a few more roundings; 1e-4 is ~1000x float
// epsilon, far below any real error (a missed normalisation or a wrong axis is off by > 1e-2).
constexpr float kUnitTolerance = 1e-4f;

template <class T>
bool sameBytes(std::vector<T> const& a, std::vector<T> const& b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

// Checks every vertex frame and every triangle of a mesh against the conventions of
// mesh_builder.h: unit normals, unit tangents orthogonal to them, |w| = 1, counter-clockwise
// winding about the normals, and tangent / bitangent agreeing with the UV gradients of each
// triangle. Returns the number of triangles whose UV frame was checked.
int checkMesh(MeshData const& m, char const* what) {
    SCOPED_TRACE(what);
    EXPECT_EQ(m.indices.size() % 3, 0u);
    for (auto const& v : m.vertices) {
        EXPECT_NEAR(glm::length(v.normal), 1.0f, kUnitTolerance);
        EXPECT_NEAR(glm::length(glm::vec3(v.tangent)), 1.0f, kUnitTolerance);
        EXPECT_NEAR(glm::dot(v.normal, glm::vec3(v.tangent)), 0.0f, kUnitTolerance);
        EXPECT_TRUE(v.tangent.w == 1.0f || v.tangent.w == -1.0f);
        if (::testing::Test::HasFailure()) return 0;  // one bad vertex is enough to report
    }
    int checked = 0;
    for (std::size_t i = 0; i + 2 < m.indices.size(); i += 3) {
        std::uint32_t const ia = m.indices[i], ib = m.indices[i + 1], ic = m.indices[i + 2];
        EXPECT_LT(ia, m.vertices.size());
        EXPECT_LT(ib, m.vertices.size());
        EXPECT_LT(ic, m.vertices.size());
        if (::testing::Test::HasFailure()) return 0;
        Vertex const &a = m.vertices[ia], &b = m.vertices[ib], &c = m.vertices[ic];
        glm::vec3 const e1 = b.position - a.position, e2 = c.position - a.position;
        glm::vec2 const d1 = b.uv - a.uv, d2 = c.uv - a.uv;
        glm::vec3 const g = glm::cross(e1, e2);
        // Winding: the geometric normal is on the same side as every vertex normal.
        for (Vertex const* v : {&a, &b, &c}) EXPECT_GT(glm::dot(g, v->normal), 0.0f) << "triangle " << i / 3;
        float const det = d1.x * d2.y - d2.x * d1.y;
        if (std::abs(det) < 1e-8f) continue;
        glm::vec3 const dPdu = glm::normalize((e1 * d2.y - e2 * d1.y) / det);
        glm::vec3 const dPdv = glm::normalize((e2 * d1.x - e1 * d2.x) / det);
        for (Vertex const* v : {&a, &b, &c}) {
            glm::vec3 const t(v->tangent);
            // A smooth surface's vertex frame differs from a flat facet's by at most about half
            // a segment's angle (< 20 degrees with >= 8 segments): cos 45 degrees leaves margin
            // yet catches a tangent along v or against u (cos <= 0).
            EXPECT_GT(glm::dot(t, dPdu), 0.7f) << "triangle " << i / 3;
            EXPECT_GT(glm::dot(glm::cross(v->normal, t) * v->tangent.w, dPdv), 0.0f) << "triangle " << i / 3;
        }
        if (::testing::Test::HasFailure()) return 0;
        ++checked;
    }
    return checked;
}

glm::vec3 decodeNormal(ImageData const& img, int x, int y) {
    std::size_t const i = (std::size_t(y) * std::size_t(img.width) + std::size_t(x)) * std::size_t(img.channels);
    return glm::vec3(img.pixels[i], img.pixels[i + 1], img.pixels[i + 2]) / 255.0f * 2.0f - 1.0f;
}

}  // namespace

// --- Mesh builders ----------------------------------------------------------------------------

TEST(MeshBuilder, BoxTopFaceFacesUpWithTangentAlongU) {
    MeshData const box = makeBox({2.0f, 1.0f, 3.0f}, 0.5f);
    EXPECT_EQ(box.indices.size(), 36u);
    EXPECT_EQ(box.vertices.size(), 24u);
    int topTriangles = 0;
    for (std::size_t i = 0; i < box.indices.size(); i += 3) {
        Vertex const* v[3] = {&box.vertices[box.indices[i]], &box.vertices[box.indices[i + 1]],
                              &box.vertices[box.indices[i + 2]]};
        if (v[0]->position.y != 0.5f || v[1]->position.y != 0.5f || v[2]->position.y != 0.5f) continue;
        ++topTriangles;
        for (Vertex const* p : v) {
            EXPECT_EQ(p->normal, glm::vec3(0, 1, 0));
            EXPECT_NEAR(p->tangent.x, 1.0f, 1e-6f);  // u grows with +X on the top face
            // UVs are world units times uvScale from the face's -X corner.
            EXPECT_NEAR(p->uv.x, (p->position.x + 1.0f) * 0.5f, 1e-6f);
        }
    }
    EXPECT_EQ(topTriangles, 2);
    EXPECT_EQ(checkMesh(box, "box"), 12);
}

TEST(MeshBuilder, SphereNormalsArePositionDirections) {
    float const r = 1.7f;
    MeshData const s = makeSphere(r, 24, 16);
    ASSERT_FALSE(s.vertices.empty());
    for (auto const& v : s.vertices) {
        EXPECT_NEAR(glm::length(v.position), r, 1e-5f);
        glm::vec3 const expected = glm::normalize(v.position);
        EXPECT_NEAR(glm::distance(v.normal, expected), 0.0f, 1e-5f);
    }
    // Pole rows collapse: 2 * 24 triangles are dropped of 24 * 16 * 2.
    EXPECT_EQ(s.indices.size() / 3, std::size_t(24 * 16 * 2 - 2 * 24));
    EXPECT_GT(checkMesh(s, "sphere"), 0);
}

TEST(MeshBuilder, CurvedShapesHaveUvConsistentFrames) {
    EXPECT_GT(checkMesh(makePlane({4, 2}, 4, 2, 1.0f), "plane"), 0);
    EXPECT_GT(checkMesh(makeCylinder(0.5f, 2.0f, 16, 3, 1.0f, true), "cylinder"), 0);
    EXPECT_GT(checkMesh(makeTorus(1.0f, 0.2f, 24, 8), "torus"), 0);
    EXPECT_GT(checkMesh(makeArch(1.0f, 1.4f, 0.5f, 16), "arch"), 0);
    EXPECT_GT(checkMesh(makeArch(1.0f, 1.4f, 0.5f, 16, 1.0f, true), "square arch"), 0);
}

TEST(MeshBuilder, CylinderSideNormalsAreHorizontalAndRadial) {
    MeshData const c = makeCylinder(0.5f, 2.0f, 16, 2, 1.0f, false);
    for (auto const& v : c.vertices) {
        EXPECT_NEAR(v.normal.y, 0.0f, 1e-6f);
        EXPECT_NEAR(glm::distance(v.normal * 0.5f, glm::vec3(v.position.x, 0, v.position.z)), 0.0f, 1e-5f);
        EXPECT_GE(v.position.y, 0.0f);
        EXPECT_LE(v.position.y, 2.0f);
    }
}

TEST(MeshBuilder, ArchStaysBetweenItsRadiiAndAboveItsFeet) {
    float const ri = 1.0f, ro = 1.4f;
    for (bool square : {false, true}) {
        MeshData const a = makeArch(ri, ro, 0.5f, 16, 1.0f, square);
        for (auto const& v : a.vertices) {
            float const r = glm::length(glm::vec2(v.position));
            EXPECT_GE(r, ri - 1e-5f);
            EXPECT_GE(v.position.y, 0.0f);
            if (square) {
                EXPECT_LE(std::abs(v.position.x), ro + 1e-5f);
                EXPECT_LE(v.position.y, ro + 1e-5f);
            } else {
                EXPECT_LE(r, ro + 1e-5f);
            }
            EXPECT_LE(std::abs(v.position.z), 0.25f + 1e-6f);
        }
    }
}

TEST(MeshBuilder, MirroringTransformKeepsFramesConsistent) {
    MeshData box = makeBox({1, 2, 3}, 1.0f);
    glm::mat4 const m = glm::rotate(glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 2.0f, 0.5f)), 0.7f,
                                    glm::normalize(glm::vec3(1, 1, 0)));
    transformMesh(box, m);
    EXPECT_EQ(checkMesh(box, "mirrored box"), 12);
    MeshData merged;
    appendMesh(merged, makeBox({1, 1, 1}), glm::mat4(1.0f));
    appendMesh(merged, makeBox({1, 1, 1}), glm::translate(glm::mat4(1.0f), {3, 0, 0}));
    EXPECT_EQ(merged.vertices.size(), 48u);
    EXPECT_EQ(merged.indices.size(), 72u);
    EXPECT_EQ(checkMesh(merged, "merged boxes"), 24);
}

// --- Textures ---------------------------------------------------------------------------------

TEST(ProceduralTextures, FlatHeightDecodesToZAndRampsTiltAgainstTheSlope) {
    int const w = 16, h = 16;
    float const strength = 2.0f;
    std::vector<float> height(std::size_t(w * h), 0.0f);
    // Flat for x < 8; a ramp rising 0.5 per texel along +x (u) for x >= 8, flat in y.
    for (int y = 0; y < h; ++y)
        for (int x = 8; x < w; ++x) height[std::size_t(y * w + x)] = 0.5f * float(x - 8);
    ImageData const n = normalMapFromHeight(height, w, h, strength, "test");
    ASSERT_EQ(n.width, w);
    ASSERT_EQ(n.channels, 4);
    EXPECT_FALSE(n.srgb);
    // 8-bit encoding: 0 encodes as 128 -> 0.0039 after decoding, so one step (2/255) of slack.
    float const byteTol = 2.0f / 255.0f;
    glm::vec3 const flat = decodeNormal(n, 3, 5);
    EXPECT_NEAR(flat.x, 0.0f, byteTol);
    EXPECT_NEAR(flat.y, 0.0f, byteTol);
    EXPECT_NEAR(flat.z, 1.0f, byteTol);
    glm::vec3 const expected = glm::normalize(glm::vec3(-strength * 0.5f, 0.0f, 1.0f));
    glm::vec3 const ramp = decodeNormal(n, 11, 7);
    EXPECT_NEAR(ramp.x, expected.x, byteTol);
    EXPECT_NEAR(ramp.y, expected.y, byteTol);
    EXPECT_NEAR(ramp.z, expected.z, byteTol);

    // The same ramp along rows (v) tilts green: the map's +Y follows growing rows.
    std::vector<float> rows(std::size_t(w * h), 0.0f);
    for (int y = 8; y < h; ++y)
        for (int x = 0; x < w; ++x) rows[std::size_t(y * w + x)] = 0.5f * float(y - 8);
    glm::vec3 const down = decodeNormal(normalMapFromHeight(rows, w, h, strength, "rows"), 4, 11);
    EXPECT_NEAR(down.x, 0.0f, byteTol);
    EXPECT_NEAR(down.y, expected.x, byteTol);
}

TEST(ProceduralTextures, SetsHaveTheRightFormatsAndAreDeterministic) {
    using Maker = TextureSet (*)(int, std::uint32_t);
    for (Maker make : {&makeBrickTextures, &makeFlagstoneTextures, &makeSandstoneTextures, &makeWoodTextures}) {
        TextureSet const a = make(128, 5U), b = make(128, 5U), c = make(128, 6U);
        EXPECT_TRUE(a.albedo.srgb);
        EXPECT_FALSE(a.normal.srgb);
        EXPECT_FALSE(a.specular.srgb);
        EXPECT_EQ(a.albedo.pixels.size(), 128u * 128u * 4u);
        EXPECT_EQ(a.normal.pixels.size(), 128u * 128u * 4u);
        EXPECT_EQ(a.specular.channels, 1);
        EXPECT_EQ(a.specular.pixels.size(), 128u * 128u);
        EXPECT_TRUE(sameBytes(a.albedo.pixels, b.albedo.pixels)) << a.albedo.name;
        EXPECT_TRUE(sameBytes(a.normal.pixels, b.normal.pixels)) << a.normal.name;
        EXPECT_TRUE(sameBytes(a.specular.pixels, b.specular.pixels)) << a.specular.name;
        EXPECT_FALSE(sameBytes(a.albedo.pixels, c.albedo.pixels)) << "seed should matter: " << a.albedo.name;
        // Every texel decodes to a near-unit normal facing out of the surface, and the map is
        // not all flat (the height field has relief).
        int tilted = 0;
        for (int y = 0; y < 128; ++y) {
            for (int x = 0; x < 128; ++x) {
                glm::vec3 const n = decodeNormal(a.normal, x, y);
                EXPECT_NEAR(glm::length(n), 1.0f, 0.02f);  // 8-bit rounding of each component
                EXPECT_GT(n.z, 0.0f);
                if (n.z < 0.98f) ++tilted;
            }
        }
        // Joints, bevels and relief: more than 2% of texels tilt by over 11 degrees.
        EXPECT_GT(tilted, 128 * 128 / 50) << a.normal.name;
    }
}

TEST(ProceduralTextures, HashAndNoiseAreInRangeAndTile) {
    for (int i = 0; i < 1000; ++i) {
        float const h = hashUnit(i, -i * 3, 9U);
        EXPECT_GE(h, 0.0f);
        EXPECT_LT(h, 1.0f);
    }
    EXPECT_EQ(hashU32(12345U), hashU32(12345U));
    EXPECT_NE(hashU32(1U), hashU32(2U));
    // Period 8: the lattice at x and x + 8 is the same, so values repeat exactly.
    EXPECT_EQ(tiledValueNoise(2.25f, 3.5f, 8, 4U), tiledValueNoise(10.25f, 3.5f, 8, 4U));
    EXPECT_EQ(tiledValueNoise(2.25f, 3.5f, 8, 4U), tiledValueNoise(2.25f, 11.5f, 8, 4U));
}

// --- Default scene ----------------------------------------------------------------------------

TEST(DefaultScene, OverHundredThousandTrianglesInFewDrawCalls) {
    SceneData const s = makeDefaultScene();
    EXPECT_EQ(s.source, "default");
    EXPECT_GT(s.triangleCount(), 100000u);
    EXPECT_LT(s.instances.size(), 50u);  // one draw per instance; llvmpipe pays per draw call
    EXPECT_GE(s.instances.size(), 5u);
    for (auto const& inst : s.instances) {
        ASSERT_GE(inst.mesh, 0);
        ASSERT_LT(std::size_t(inst.mesh), s.meshes.size());
    }
}

TEST(DefaultScene, EveryMeshHasValidFramesAndIndices) {
    SceneData const s = makeDefaultScene({0});
    for (auto const& m : s.meshes) {
        EXPECT_GT(checkMesh(m, m.name.c_str()), 0);
        EXPECT_GE(m.material, 0);
        EXPECT_LT(std::size_t(m.material), s.materials.size());
    }
}

TEST(DefaultScene, SameArgumentsGiveIdenticalScenes) {
    SceneData const a = makeDefaultScene({7}), b = makeDefaultScene({7});
    ASSERT_EQ(a.meshes.size(), b.meshes.size());
    for (std::size_t i = 0; i < a.meshes.size(); ++i) {
        EXPECT_TRUE(sameBytes(a.meshes[i].vertices, b.meshes[i].vertices)) << a.meshes[i].name;
        EXPECT_TRUE(sameBytes(a.meshes[i].indices, b.meshes[i].indices)) << a.meshes[i].name;
    }
    ASSERT_EQ(a.images.size(), b.images.size());
    for (std::size_t i = 0; i < a.images.size(); ++i)
        EXPECT_TRUE(sameBytes(a.images[i].pixels, b.images[i].pixels)) << a.images[i].name;
    ASSERT_EQ(a.lights.size(), 7u);
    ASSERT_EQ(b.lights.size(), 7u);
    for (std::size_t i = 0; i < a.lights.size(); ++i) EXPECT_TRUE(a.lights[i] == b.lights[i]);
    ASSERT_TRUE(a.camera && b.camera);
    EXPECT_EQ(a.camera->position, b.camera->position);
}

TEST(DefaultScene, CourtyardScaleAndMaterials) {
    SceneData const s = makeDefaultScene({0});
    EXPECT_TRUE(s.lights.empty());
    Bounds const b = s.bounds();
    EXPECT_NEAR(b.min.y, 0.0f, 1e-4f);  // floor at y = 0, nothing below it
    EXPECT_GT(b.max.y, 8.0f);
    EXPECT_LT(b.max.y, 12.0f);
    EXPECT_GT(b.max.x - b.min.x, 28.0f);
    EXPECT_LT(b.max.x - b.min.x, 36.0f);
    int textured = 0;
    for (auto const& m : s.materials) {
        for (int t : {m.baseColorTexture, m.normalTexture, m.specularTexture}) {
            if (t < 0) continue;
            ASSERT_LT(std::size_t(t), s.images.size());
            ImageData const& img = s.images[std::size_t(t)];
            EXPECT_EQ(img.pixels.size(), std::size_t(img.width) * std::size_t(img.height) * std::size_t(img.channels));
        }
        if (m.baseColorTexture >= 0 && m.normalTexture >= 0 && m.specularTexture >= 0) {
            ++textured;
            EXPECT_TRUE(s.images[std::size_t(m.baseColorTexture)].srgb);
            EXPECT_FALSE(s.images[std::size_t(m.normalTexture)].srgb);
        }
    }
    EXPECT_GE(textured, 3);
    // The suggested camera stands inside the walls and looks towards the centre.
    ASSERT_TRUE(s.camera);
    glm::vec3 const eye = s.camera->position;
    EXPECT_LT(std::abs(eye.x), 16.0f);
    EXPECT_LT(std::abs(eye.z), 16.0f);
    EXPECT_GT(glm::dot(s.camera->forward(), glm::normalize(defaultSceneCenter() - eye)), 0.8f);
}

// --- Lights -----------------------------------------------------------------------------------

TEST(DefaultLights, CountIsHonouredAndPrefixStable) {
    EXPECT_TRUE(makeDefaultLights(0).empty());
    EXPECT_TRUE(makeDefaultLights(-4).empty());
    auto const few = makeDefaultLights(5), many = makeDefaultLights(32);
    ASSERT_EQ(few.size(), 5u);
    ASSERT_EQ(many.size(), 32u);
    for (std::size_t i = 0; i < few.size(); ++i) EXPECT_TRUE(few[i] == many[i]);
    EXPECT_EQ(makeDefaultLights(100).size(), 100u);
    EXPECT_EQ(makeDefaultScene().lights.size(), 32u);
}

TEST(DefaultLights, RadiiHeightsAndColoursAreInRange) {
    auto const lights = makeDefaultLights(32);
    int dominant[3] = {0, 0, 0};
    for (auto const& l : lights) {
        SCOPED_TRACE(l.name);
        EXPECT_FALSE(validateLight(l).has_value());
        EXPECT_EQ(l.kc, 1.0f);
        LightRadius const r = lightRadius(l);
        EXPECT_EQ(r.kind, RadiusKind::Quadratic);
        EXPECT_GE(r.radius, 4.0f);
        EXPECT_LE(r.radius, 8.0f);
        EXPECT_GE(l.position.y, 0.5f);
        EXPECT_LE(l.position.y, 3.0f);
        // Inside the courtyard, clear of the fountain basin (radius 2.2 + rim).
        float const ring = glm::length(glm::vec2(l.position.x, l.position.z));
        EXPECT_GT(ring, 2.4f);
        EXPECT_LT(ring, 11.5f);
        // Saturated: brightest channel 1, dimmest at most 0.25.
        float const hi = std::max({l.color.r, l.color.g, l.color.b});
        float const lo = std::min({l.color.r, l.color.g, l.color.b});
        EXPECT_FLOAT_EQ(hi, 1.0f);
        EXPECT_LE(lo, 0.25f);
        for (int c = 0; c < 3; ++c) dominant[c] += l.color[c] == hi ? 1 : 0;
    }
    // Varied: each primary leads in several lights.
    for (int c = 0; c < 3; ++c) EXPECT_GE(dominant[c], 6) << "channel " << c;
}

TEST(OrbitLights, ZeroTimeIsIdentity) {
    auto const initial = makeDefaultLights(32);
    auto moved = initial;
    orbitLights(moved, defaultSceneCenter(), 0.0f);
    for (std::size_t i = 0; i < initial.size(); ++i) EXPECT_TRUE(initial[i] == moved[i]) << i;
    orbitLights(moved, glm::vec3(3.0f, 1.0f, -2.0f), 0.0f);
    for (std::size_t i = 0; i < initial.size(); ++i) EXPECT_TRUE(initial[i] == moved[i]) << i;
}

TEST(OrbitLights, KeepsRadiusAndHeightAndTurnsAtBoundedRates) {
    auto const initial = makeDefaultLights(32);
    for (glm::vec3 centre : {defaultSceneCenter(), glm::vec3(3.0f, 1.0f, -2.0f)}) {
        auto moved = initial;
        float const t = 2.0f;
        orbitLights(moved, centre, t);
        int clockwise = 0;
        for (std::size_t i = 0; i < initial.size(); ++i) {
            glm::vec2 const a(initial[i].position.x - centre.x, initial[i].position.z - centre.z);
            glm::vec2 const b(moved[i].position.x - centre.x, moved[i].position.z - centre.z);
            EXPECT_NEAR(glm::length(b), glm::length(a), 1e-4f * glm::length(a)) << i;
            EXPECT_EQ(moved[i].position.y, initial[i].position.y) << i;
            EXPECT_EQ(moved[i].color, initial[i].color);
            // Signed angle turned in the XZ plane; rates are 0.15..0.25 rad/s.
            float const turned = std::atan2(a.x * b.y - a.y * b.x, glm::dot(a, b));
            EXPECT_GE(std::abs(turned), 0.15f * t - 1e-3f) << i;
            EXPECT_LE(std::abs(turned), 0.25f * t + 1e-3f) << i;
            clockwise += turned > 0.0f ? 1 : 0;
        }
        EXPECT_EQ(clockwise, 16);  // half the lights turn each way
    }
}

TEST(OrbitLights, DependsOnlyOnInitialLightsAndTime) {
    auto const initial = makeDefaultLights(32);
    auto once = initial, twice = initial, again = initial;
    orbitLights(once, defaultSceneCenter(), 5.0f);
    orbitLights(again, defaultSceneCenter(), 5.0f);
    orbitLights(twice, defaultSceneCenter(), 2.0f);
    orbitLights(twice, defaultSceneCenter(), 3.0f);
    for (std::size_t i = 0; i < initial.size(); ++i) {
        EXPECT_TRUE(once[i] == again[i]) << i;
        // Rates depend on the index only, so orbiting in steps lands on the same circle point
        // up to float rounding of the extra rotation (~1e-6 relative).
        EXPECT_NEAR(glm::distance(once[i].position, twice[i].position), 0.0f, 1e-4f) << i;
    }
}
