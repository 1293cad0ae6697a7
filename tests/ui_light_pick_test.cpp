// Picking light cubes: ray construction matches the projection, slab test, nearest hit wins.
#include "model/light_pick.h"

#include <gtest/gtest.h>

using namespace gbl;
using namespace gbl::ui;

TEST(UiLightPick, RayBoxHitsMissesAndStartsInside) {
    Ray const r{{0, 0, 10}, {0, 0, -1}};
    auto const t = rayBoxDistance(r, {-1, -1, -1}, {1, 1, 1});
    ASSERT_TRUE(t);
    EXPECT_FLOAT_EQ(*t, 9.0f);
    EXPECT_FALSE(rayBoxDistance(r, {2, 2, -1}, {3, 3, 1}));
    EXPECT_FALSE(rayBoxDistance(Ray{{0, 0, 10}, {0, 0, 1}}, {-1, -1, -1}, {1, 1, 1}));  // behind
    auto const inside = rayBoxDistance(Ray{{0, 0, 0}, {1, 0, 0}}, {-1, -1, -1}, {1, 1, 1});
    ASSERT_TRUE(inside);
    EXPECT_FLOAT_EQ(*inside, 0.0f);
    // Parallel to the x slabs and outside them: never hits.
    EXPECT_FALSE(rayBoxDistance(Ray{{5, 0, 10}, {0, 0, -1}}, {-1, -1, -1}, {1, 1, 1}));
}

TEST(UiLightPick, RayThroughAProjectedPointPassesThroughIt) {
    Camera cam;
    cam.position = {3, 4, 12};
    cam.lookAt({0, 1, 0});
    glm::vec2 const size(1280, 720);
    glm::vec3 const point(1.5f, 0.5f, -2.0f);
    glm::vec4 const clip = cam.projection(size.x / size.y) * cam.view() * glm::vec4(point, 1.0f);
    glm::vec2 const ndc = glm::vec2(clip) / clip.w;
    // Continuous pixel coordinate (top-left origin); cameraRay adds half a pixel for the centre.
    glm::vec2 const px((ndc.x * 0.5f + 0.5f) * size.x - 0.5f, (0.5f - ndc.y * 0.5f) * size.y - 0.5f);
    Ray const ray = cameraRay(cam, px, size);
    glm::vec3 const toPoint = point - ray.origin;
    float const along = glm::dot(toPoint, ray.direction);
    float const miss = glm::length(toPoint - ray.direction * along);
    EXPECT_GT(along, 0.0f);
    EXPECT_LT(miss, 1e-3f);  // float round-off over ~15 units
}

TEST(UiLightPick, NearestCubeWinsAndMaxDistanceHidesCubesBehindWalls) {
    std::vector<PointLight> lights(3);
    lights[0].position = {0, 0, -10};
    lights[1].position = {0, 0, -5};
    lights[2].position = {4, 0, -5};
    Ray const r{{0, 0, 0}, {0, 0, -1}};
    EXPECT_EQ(pickLight(r, lights, 0.2f, 1000.0f), 1);
    // A wall at distance 3: both cubes on the ray are behind it.
    EXPECT_EQ(pickLight(r, lights, 0.2f, 3.0f), -1);
    // Beyond the wall only when the wall is past the cube.
    EXPECT_EQ(pickLight(r, lights, 0.2f, 6.0f), 1);
    EXPECT_EQ(pickLight(Ray{{0, 0, 0}, {0, 1, 0}}, lights, 0.2f, 1000.0f), -1);
}
