// Light list edits: validated changes, refusals with messages, presets, deterministic random lights.
#include "core/light_math.h"
#include "model/drag_speed.h"
#include "model/light_list.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace gbl;
using namespace gbl::ui;

TEST(UiLightList, AddDuplicateDelete) {
    std::vector<PointLight> lights;
    EXPECT_EQ(addLight(lights, {1, 2, 3}).index, 0);
    EXPECT_EQ(lights[0].position, glm::vec3(1, 2, 3));
    EXPECT_FALSE(validateLight(lights[0]));
    auto const dup = duplicateLight(lights, 0);
    ASSERT_EQ(dup.index, 1);
    EXPECT_EQ(lights.size(), 2u);
    EXPECT_NE(lights[1].position, lights[0].position);  // offset so both cubes are visible
    EXPECT_EQ(lights[1].kq, lights[0].kq);
    EXPECT_EQ(duplicateLight(lights, 7).index, -1);
    // Deleting the last selects the one before; deleting the only one selects nothing.
    EXPECT_EQ(deleteLight(lights, 1), 0);
    EXPECT_EQ(deleteLight(lights, 0), -1);
    EXPECT_TRUE(lights.empty());
    EXPECT_EQ(deleteLight(lights, 0), -1);
}

TEST(UiLightList, RefusesAtTheLimitWithAMessage) {
    std::vector<PointLight> lights(kMaxEditorLights);
    auto const r = addLight(lights, {});
    EXPECT_EQ(r.index, -1);
    EXPECT_NE(r.message.find(std::to_string(kMaxEditorLights)), std::string::npos);
    EXPECT_EQ(lights.size(), std::size_t(kMaxEditorLights));
    std::uint32_t seed = 1;
    lights.resize(kMaxEditorLights - 3);
    auto const random = addRandomLights(lights, 10, Bounds{{-1, -1, -1}, {1, 1, 1}}, seed);
    EXPECT_EQ(lights.size(), std::size_t(kMaxEditorLights));
    EXPECT_NE(random.message.find("added 3 of 10"), std::string::npos) << random.message;
}

TEST(UiLightList, BadEditsAreRefusedAndChangeNothing) {
    std::vector<PointLight> lights(1);
    PointLight const original = lights[0];
    PointLight edited = original;
    edited.kq = std::numeric_limits<float>::quiet_NaN();
    auto error = applyLightEdit(lights, 0, edited);
    ASSERT_TRUE(error);
    EXPECT_NE(error->find("Kq"), std::string::npos) << *error;
    EXPECT_EQ(lights[0].kq, original.kq);

    edited = original;
    edited.intensity = -1.0f;
    error = applyLightEdit(lights, 0, edited);
    ASSERT_TRUE(error);
    EXPECT_NE(error->find("intensity"), std::string::npos) << *error;
    EXPECT_EQ(lights[0].intensity, original.intensity);

    edited = original;
    edited.intensity = 3.0f;
    EXPECT_FALSE(applyLightEdit(lights, 0, edited));
    EXPECT_EQ(lights[0].intensity, 3.0f);
    EXPECT_TRUE(applyLightEdit(lights, 5, edited));  // no such light
}

TEST(UiLightList, PresetsRoundTripAndReachFurtherWithRange) {
    PointLight light;
    light.color = glm::vec3(1.0f);
    float previous = 0.0f;
    for (std::size_t i = 0; i < kAttenuationPresets.size(); ++i) {
        applyPreset(light, kAttenuationPresets[i]);
        EXPECT_EQ(matchingPreset(light), int(i));
        float const r = lightRadius(light).radius;
        EXPECT_GT(r, previous) << "preset for range " << kAttenuationPresets[i].range;
        previous = r;
    }
    light.kl = 0.123f;
    EXPECT_EQ(matchingPreset(light), -1);
}

TEST(UiLightList, PresetsAreNamedByTheRadiusTheyGive) {
    // A brighter light than the default, as in the report where "range 13" gave a radius of 34.6.
    for (float intensity : {1.0f, 12.0f}) {
        PointLight light;
        light.intensity = intensity;
        for (auto const& p : kAttenuationPresets) {
            PointLight applied = light;
            applyPreset(applied, p);
            float const radius = lightRadius(applied).radius;
            std::string const label = presetLabel(light, p);
            ASSERT_EQ(label.rfind("radius ", 0), 0u) << label;
            float const shown = std::stof(label.substr(7));
            EXPECT_NEAR(shown, radius, 0.05f + 1e-4f * radius) << label << " (one decimal)";
            EXPECT_FLOAT_EQ(presetRadius(light, p), radius);
        }
    }
    // The classic "13" triple on the default light reaches about 10.3, not 13.
    PointLight light;
    EXPECT_EQ(presetLabel(light, kAttenuationPresets[1]), "radius 10.3");
}

TEST(UiLightList, DragSpeedIsProportionalAndLogarithmicForAttenuation) {
    EXPECT_FLOAT_EQ(proportionalDragSpeed(0.44f, 1e-4f, kLogDragShare), 0.0088f);
    EXPECT_FLOAT_EQ(proportionalDragSpeed(-50.0f, 1e-3f), 0.5f);
    EXPECT_FLOAT_EQ(proportionalDragSpeed(0.0f, 1e-4f), 1e-4f) << "a zero can be dragged away";
    // Kq across its useful range, 0.001 to 2, in under 400 pixels (about 0.0005 per pixel before,
    // which took 4000), simulated pixel by pixel as ImGui applies the speed.
    float kq = 0.001f;
    int pixels = 0;
    while (kq < 2.0f && pixels < 10000) {
        kq += proportionalDragSpeed(kq, 1e-5f, kLogDragShare);
        ++pixels;
    }
    EXPECT_LT(pixels, 400);
    EXPECT_GT(pixels, 100) << "not so fast that a value cannot be set";
    EXPECT_NEAR(pixelsToDrag(0.001f, 2.0f), pixels, 3);
}

TEST(UiLightList, RandomLightsAreValidInsideAndDeterministic) {
    Bounds const b{{-10, 0, -10}, {10, 8, 10}};
    std::vector<PointLight> a, c;
    std::uint32_t seedA = 42, seedC = 42;
    addRandomLights(a, 20, b, seedA);
    addRandomLights(c, 20, b, seedC);
    ASSERT_EQ(a.size(), 20u);
    EXPECT_EQ(seedA, seedC);
    EXPECT_NE(seedA, 42u);  // the next batch differs
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].position, c[i].position);
        EXPECT_FALSE(validateLight(a[i]));
        EXPECT_GT(lightRadius(a[i]).radius, 0.0f);
        for (int k = 0; k < 3; ++k) {
            EXPECT_GE(a[i].position[k], b.min[k]);
            EXPECT_LE(a[i].position[k], b.max[k]);
        }
    }
    std::vector<PointLight> next;
    addRandomLights(next, 20, b, seedA);
    EXPECT_NE(next[0].position, a[0].position);
    EXPECT_TRUE(addRandomLights(next, 0, b, seedA).message.size() > 0);
}
