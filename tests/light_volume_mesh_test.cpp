// The light-volume sphere encloses the true sphere of the light's radius, and not wastefully.
#include "core/light_volume_mesh.h"

#include "core/light_math.h"
#include "core/light_volume_cone.h"
#include "core/shading_cpu.h"
#include "core/spot_cull.h"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <random>
#include <set>
#include <stdexcept>
#include <utility>

using namespace gbl;

namespace {

struct Plane {
    glm::dvec3 normal;  // unit, outward
    double distance;    // from the centre
};

// Face planes of the mesh with every vertex scaled by `scale` in float, as the vertex shader does.
std::vector<Plane> scaledPlanes(SphereMesh const& m, float scale) {
    std::vector<Plane> planes;
    for (std::size_t t = 0; t < m.triangles.size(); t += 3) {
        glm::dvec3 const a(m.positions[m.triangles[t]] * scale), b(m.positions[m.triangles[t + 1]] * scale),
            c(m.positions[m.triangles[t + 2]] * scale);
        glm::dvec3 const n = glm::normalize(glm::cross(b - a, c - a));
        planes.push_back({n, glm::dot(n, a)});
    }
    return planes;
}

std::pair<int, int> const kTessellations[] = {
    {kLightVolumeStacks, kLightVolumeSlices}, {2, 3}, {3, 4}, {8, 12}, {9, 7}, {16, 32}, {33, 64}};

}  // namespace

TEST(LightVolumeMesh, TopologyAndUnitVertices) {
    for (auto [stacks, slices] : kTessellations) {
        SphereMesh const m = makeLightVolumeSphere(stacks, slices);
        EXPECT_EQ(m.positions.size(), std::size_t(2 + (stacks - 1) * slices));
        // Two cap fans plus (stacks - 2) bands of quads (two triangles each).
        EXPECT_EQ(m.triangles.size(), std::size_t(3 * (2 * slices + 2 * slices * (stacks - 2))));
        for (glm::vec3 p : m.positions) EXPECT_NEAR(glm::length(p), 1.0f, 1e-6f);
        for (std::uint32_t i : m.triangles) ASSERT_LT(i, m.positions.size());
    }
}

TEST(LightVolumeMesh, TrianglesWindCounterClockwiseFromOutside) {
    // Culling back faces must keep the faces turned to a camera outside the volume.
    for (auto [stacks, slices] : kTessellations) {
        SphereMesh const m = makeLightVolumeSphere(stacks, slices);
        for (std::size_t t = 0; t < m.triangles.size(); t += 3) {
            glm::vec3 const a = m.positions[m.triangles[t]], b = m.positions[m.triangles[t + 1]],
                            c = m.positions[m.triangles[t + 2]];
            glm::vec3 const n = glm::cross(b - a, c - a);
            ASSERT_GT(glm::dot(n, (a + b + c) / 3.0f), 0.0f) << stacks << "x" << slices << " triangle " << t / 3;
        }
    }
}

TEST(LightVolumeMesh, ScaledFacesLieAtOrBeyondTheRadiusAndNotWastefully) {
    for (auto [stacks, slices] : kTessellations) {
        SphereMesh const m = makeLightVolumeSphere(stacks, slices);
        float const s = enclosingScale(m);
        // Without the scale the mesh cuts into the sphere: that is what the scale repairs.
        EXPECT_LT(minFacePlaneDistance(m.positions, m.triangles), 0.999f) << stacks << "x" << slices;
        for (float r : {1.0f, 0.37f, 12.5f, 800.0f}) {
            double minDistance = 1e30;
            for (Plane const& p : scaledPlanes(m, r * s)) {
                ASSERT_GE(p.distance, double(r)) << stacks << "x" << slices << " r " << r;
                minDistance = std::min(minDistance, p.distance);
            }
            // The tightest face touches the sphere: no more than 1e-4 (relative) of slack.
            EXPECT_LT(minDistance, r * (1.0 + 1e-4)) << stacks << "x" << slices << " r " << r;
        }
    }
}

TEST(LightVolumeMesh, ScaleMatchesTheEquatorialBandFormulaForOddStacks) {
    // With an odd stack count one band of quads straddles the equator symmetrically; its plane
    // is the closest one, at cos(half the slice angle) * cos(half the stack angle).
    for (auto [stacks, slices] : {std::pair{11, 16}, std::pair{3, 4}, std::pair{9, 7}, std::pair{33, 64}}) {
        double const pi = glm::pi<double>();
        double const expected = 1.0 / (std::cos(pi / slices) * std::cos(pi / (2.0 * stacks)));
        EXPECT_NEAR(enclosingScale(makeLightVolumeSphere(stacks, slices)), expected, 1e-5) << stacks << "x" << slices;
    }
    // The renderer's tessellation is the one the header's comment quotes.
    EXPECT_NEAR(enclosingScale(makeLightVolumeSphere()), 1.0301, 1e-4);
}

TEST(LightVolumeMesh, EveryPointOfTheSphereIsInsideTheScaledMesh) {
    // Independent of the plane arithmetic above: sample the sphere densely and check each point
    // is behind every face plane of the scaled (convex) mesh, but not of the unscaled one.
    SphereMesh const m = makeLightVolumeSphere();
    std::vector<Plane> const scaled = scaledPlanes(m, enclosingScale(m));
    std::vector<Plane> const unscaled = scaledPlanes(m, 1.0f);
    std::mt19937 rng(7);
    std::normal_distribution<double> g;
    int outsideUnscaled = 0;
    for (int i = 0; i < 20000; ++i) {
        glm::dvec3 const p = glm::normalize(glm::dvec3(g(rng), g(rng), g(rng)));
        bool outside = false;
        for (Plane const& pl : scaled) ASSERT_LE(glm::dot(pl.normal, p), pl.distance + 1e-12) << i;
        for (Plane const& pl : unscaled) outside = outside || glm::dot(pl.normal, p) > pl.distance;
        outsideUnscaled += outside;
    }
    EXPECT_GT(outsideUnscaled, 1000);  // most of the sphere pokes out of the unscaled mesh
}

TEST(LightVolumeMesh, LinesAreEveryMeshEdgeExceptQuadDiagonals) {
    for (auto [stacks, slices] : kTessellations) {
        SphereMesh const m = makeLightVolumeSphere(stacks, slices);
        std::set<std::pair<std::uint32_t, std::uint32_t>> lines, triangleEdges;
        auto key = [](std::uint32_t a, std::uint32_t b) { return std::pair{std::min(a, b), std::max(a, b)}; };
        for (std::size_t i = 0; i < m.lines.size(); i += 2) {
            EXPECT_TRUE(lines.insert(key(m.lines[i], m.lines[i + 1])).second) << "duplicate line";
        }
        for (std::size_t t = 0; t < m.triangles.size(); t += 3)
            for (int e = 0; e < 3; ++e) triangleEdges.insert(key(m.triangles[t + e], m.triangles[t + (e + 1) % 3]));
        // Meridians: stacks segments per slice; rings: slices segments on each of stacks - 1 rings.
        EXPECT_EQ(lines.size(), std::size_t(slices * stacks + slices * (stacks - 1)));
        for (auto const& l : lines) EXPECT_TRUE(triangleEdges.count(l)) << "line is not a mesh edge";
        // The only triangle edges left out are the quad diagonals, one per quad.
        EXPECT_EQ(triangleEdges.size() - lines.size(), std::size_t(slices * (stacks - 2)));
    }
}

TEST(LightVolumeMesh, RejectsDegenerateTessellations) {
    EXPECT_THROW(makeLightVolumeSphere(1, 8), std::invalid_argument);
    EXPECT_THROW(makeLightVolumeSphere(8, 2), std::invalid_argument);
    try {
        makeLightVolumeSphere(0, 0);
        FAIL() << "no exception";
    } catch (std::invalid_argument const& e) {
        EXPECT_NE(std::string(e.what()).find("makeLightVolumeSphere()"), std::string::npos);
    }
}

TEST(LightVolumeMesh, CameraInsideTestAccountsForTheNearPlane) {
    // fov 90, aspect 1, near 1: the near plane's corner is at (1, 1, -1), sqrt(3) from the eye.
    float const corner = nearPlaneCornerDistance(glm::radians(90.0f), 1.0f, 1.0f);
    EXPECT_NEAR(corner, std::sqrt(3.0f), 1e-6f);
    EXPECT_NEAR(nearPlaneCornerDistance(glm::radians(90.0f), 2.0f, 1.0f), std::sqrt(6.0f), 1e-6f);
    // A volume of enclosing radius 5 at distance 6: outside the volume, but the near plane can
    // still reach into it (6 < 5 + 1.73); at distance 7 it cannot.
    EXPECT_TRUE(volumeMayContainCamera({0, 0, 0}, {6, 0, 0}, 5.0f, corner));
    EXPECT_FALSE(volumeMayContainCamera({0, 0, 0}, {0, 7, 0}, 5.0f, corner));
    EXPECT_TRUE(volumeMayContainCamera({1, 1, 1}, {1, 1, 1}, 5.0f, 0.0f));  // at the centre
}

// --- the spot lights' cone ------------------------------------------------------------------------

namespace {
// Whether p lies inside the convex mesh (behind every face plane, with a relative slack for float).
bool insideConvex(std::vector<glm::vec3> const& world, std::vector<std::uint32_t> const& tris, glm::vec3 p,
                  float slack) {
    for (std::size_t t = 0; t + 2 < tris.size(); t += 3) {
        glm::vec3 const a = world[tris[t]], b = world[tris[t + 1]], c = world[tris[t + 2]];
        glm::vec3 const n = glm::normalize(glm::cross(b - a, c - a));
        if (glm::dot(n, p - a) > slack) return false;
    }
    return true;
}
}  // namespace

TEST(LightVolumeCone, RadialScaleIsOneOverCosOfHalfTheSliceAngle) {
    ConeMesh const m = makeLightVolumeCone();
    EXPECT_EQ(m.positions.size(), std::size_t(kConeVolumeSlices + 2));
    EXPECT_EQ(m.triangles.size(), std::size_t(kConeVolumeSlices * 6));
    EXPECT_NEAR(coneRadialScale(m), 1.0 / std::cos(glm::pi<double>() / kConeVolumeSlices), 1e-5);
    EXPECT_THROW(makeLightVolumeCone(2), std::invalid_argument);
    // Every face turns outwards: the base centre's neighbour on the axis, half-way up, is behind all.
    std::vector<glm::vec3> const unit = m.positions;
    EXPECT_TRUE(insideConvex(unit, m.triangles, glm::vec3(0.0f, 0.0f, 0.5f), 0.0f));
    EXPECT_FALSE(insideConvex(unit, m.triangles, glm::vec3(0.0f, 0.0f, 1.01f), 0.0f));
    EXPECT_FALSE(insideConvex(unit, m.triangles, glm::vec3(0.0f, 0.0f, -0.01f), 0.0f));
}

TEST(LightVolumeCone, EnclosesEveryPointTheSpotLights) {
    ConeMesh const m = makeLightVolumeCone();
    float const radial = coneRadialScale(m);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (float outer : {5.0f, 20.0f, 45.0f, kConeVolumeMaxOuterDeg}) {
        for (glm::vec3 dir : {glm::vec3(0, -1, 0), glm::vec3(0, 1, 0), glm::vec3(0.3f, -1, 0.2f), glm::vec3(1, 0, 0)}) {
            PointLight l;
            l.kind = LightKind::Spot;
            l.position = {1.0f, 2.0f, -3.0f};
            l.direction = dir;
            l.outerConeDeg = outer;
            l.innerConeDeg = outer * 0.5f;
            ASSERT_EQ(volumeShape(l), VolumeShape::Cone);
            float const radius = lightRadius(l).radius;
            ConeVolume const cone = coneVolume(l, radius, radial, 1.0f);
            std::vector<glm::vec3> world;
            for (glm::vec3 const& p : m.positions) world.push_back(coneVertexToWorld(cone, p));
            glm::vec3 bx, by;
            coneBasis(lightDirection(l), bx, by);
            ShadingInputs s;
            s.viewPosition = l.position + glm::vec3(0.0f, 0.0f, 50.0f);
            int lit = 0;
            for (int i = 0; i < 4000; ++i) {
                // Points up to the radius and up to the outer angle (the edges included), at any azimuth.
                float const d = radius * std::sqrt(u(rng)), a = glm::radians(outer) * std::sqrt(u(rng));
                float const phi = glm::two_pi<float>() * u(rng);
                glm::vec3 const across = bx * std::cos(phi) + by * std::sin(phi);
                glm::vec3 const p = l.position + d * (lightDirection(l) * std::cos(a) + across * std::sin(a));
                EXPECT_TRUE(insideConvex(world, m.triangles, p, 1e-5f * radius))
                    << "outer " << outer << " d " << d << " angle " << glm::degrees(a);
                s.position = p;
                s.normal = -lightDirection(l);
                lit += shadeLightCpu(l, s).reaches() ? 1 : 0;
            }
            EXPECT_GT(lit, 1000);  // the sampled points are ones the spot really lights
        }
    }
}

TEST(LightVolumeCone, WideSpotsPointsAndDirectionalLightsGetTheirShapes) {
    PointLight l;
    EXPECT_EQ(volumeShape(l), VolumeShape::Sphere);
    l.kind = LightKind::Spot;
    l.outerConeDeg = kConeVolumeMaxOuterDeg + 1.0f;
    EXPECT_EQ(volumeShape(l), VolumeShape::Sphere);
    l.outerConeDeg = kConeVolumeMaxOuterDeg;
    EXPECT_EQ(volumeShape(l), VolumeShape::Cone);
    l.kind = LightKind::Directional;
    EXPECT_EQ(volumeShape(l), VolumeShape::None);
}

TEST(LightVolumeCone, CameraInsideUsesTheConeNotTheSphere) {
    ConeVolume cone;
    cone.apex = {0.0f, 6.0f, 0.0f};
    cone.axis = {0.0f, -1.0f, 0.0f};
    cone.height = 8.0f;
    cone.ringRadius = 8.0f * std::tan(glm::radians(40.0f));
    float const nearCorner = 0.15f;
    EXPECT_TRUE(coneMayContainCamera({0.0f, 3.0f, 2.0f}, cone, nearCorner));   // 33.7 deg off the axis
    EXPECT_FALSE(coneMayContainCamera({0.0f, 5.0f, 3.0f}, cone, nearCorner));  // 71.6 deg: in the sphere only
    EXPECT_TRUE(coneMayContainCamera({0.0f, 6.1f, 0.0f}, cone, nearCorner));   // just behind the apex
    EXPECT_FALSE(coneMayContainCamera({0.0f, 6.5f, 0.0f}, cone, nearCorner));
    EXPECT_TRUE(coneMayContainCamera({0.0f, -2.1f, 0.0f}, cone, nearCorner));  // just past the base
    EXPECT_FALSE(coneMayContainCamera({0.0f, -2.5f, 0.0f}, cone, nearCorner));
    // Just outside the side, within the near-corner distance of it.
    float const side = 3.0f * std::tan(glm::radians(40.0f));
    EXPECT_TRUE(coneMayContainCamera({side + 0.1f, 3.0f, 0.0f}, cone, nearCorner));
    EXPECT_FALSE(coneMayContainCamera({side + 0.5f, 3.0f, 0.0f}, cone, nearCorner));
}

TEST(SpotCull, TheConeTestNeverDropsASphereThatHoldsALitPoint) {
    // Random spheres around random points the spot lights: each must pass; and spheres well
    // behind or beside the cone must be culled (the test does cull).
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    glm::vec3 const apex(0.5f, 2.0f, -1.0f);
    int culled = 0;
    for (float outer : {10.0f, 35.0f, 60.0f, 89.0f}) {
        glm::vec3 const axis = glm::normalize(glm::vec3(0.2f, -1.0f, 0.4f));
        float const cosOuter = std::cos(glm::radians(outer));
        glm::vec3 bx, by;
        coneBasis(axis, bx, by);
        for (int i = 0; i < 3000; ++i) {
            float const d = 6.0f * u(rng), a = glm::radians(outer) * u(rng), phi = glm::two_pi<float>() * u(rng);
            glm::vec3 const lit =
                apex + d * (axis * std::cos(a) + (bx * std::cos(phi) + by * std::sin(phi)) * std::sin(a));
            float const r = 0.01f + 2.0f * u(rng);
            glm::vec3 const off(u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f);
            glm::vec3 const centre = lit + glm::normalize(off) * r * u(rng);  // the lit point inside the sphere
            EXPECT_TRUE(sphereMayTouchCone(centre, r, apex, axis, cosOuter)) << outer;
        }
        // Behind the apex and out to the side: culled.
        culled += sphereMayTouchCone(apex - axis * 2.0f, 1.0f, apex, axis, cosOuter) ? 0 : 1;
        culled += sphereMayTouchCone(apex - axis * 0.5f + bx * 10.0f, 0.4f, apex, axis, cosOuter) ? 0 : 1;
    }
    EXPECT_EQ(culled, 8);
}

TEST(SpotCull, TheTileSphereHoldsEveryCornerOfTheFrustumPiece) {
    std::array<glm::vec3, 4> const far{glm::vec3(-2, -1, -100), glm::vec3(-1, -1, -100), glm::vec3(-2, 0, -100),
                                       glm::vec3(-1, 0, -100)};
    glm::vec4 const s = frustumPieceSphere(far, 3.0f, 9.0f);
    for (glm::vec3 const& c : far)
        for (float d : {3.0f, 9.0f}) EXPECT_LE(glm::distance(glm::vec3(s), c * (d / 100.0f)), s.w * (1.0f + 1e-6f));
}
