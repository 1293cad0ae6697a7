// The light-volume sphere encloses the true sphere of the light's radius, and not wastefully.
#include "core/light_volume_mesh.h"

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
