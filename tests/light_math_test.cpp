// Light radius and attenuation against hand-computed values.
#include "core/light_math.h"
#include "core/shading_cpu.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace gbl;

namespace {

constexpr float kThreshold = 5.0f / 256.0f;  // Imax / threshold = 51.2 Imax

PointLight makeLight(float intensity, float kc, float kl, float kq) {
    PointLight l;
    l.color = glm::vec3(1.0f, 0.5f, 0.25f);  // Imax = intensity (red is the brightest channel)
    l.intensity = intensity;
    l.kc = kc;
    l.kl = kl;
    l.kq = kq;
    l.threshold = kThreshold;
    return l;
}

}  // namespace

// --- radius ---------------------------------------------------------------------------------

TEST(LightRadius, QuadraticMatchesHandComputedRoot) {
    // Kc=1, Kl=0.7, Kq=1.8, Imax=1, threshold 5/256: 1.8 d^2 + 0.7 d + 1 - 51.2 = 0
    // d = (-0.7 + sqrt(0.49 + 4*1.8*50.2)) / 3.6 = (-0.7 + 19.024...) / 3.6 = 5.0901...
    LightRadius r = solveLightRadius(1.0f, 1.0f, 0.7f, 1.8f, kThreshold);
    EXPECT_EQ(r.kind, RadiusKind::Quadratic);
    EXPECT_NEAR(r.radius, 5.090127, 1e-4);
}

TEST(LightRadius, QuadraticAtSeveralIntensities) {
    // Roots of 1.8 d^2 + 0.7 d + (1 - 51.2 Imax) = 0, worked by hand with the quadratic formula:
    //   Imax = 0.5: c = -24.6  -> d = (-0.7 + sqrt(0.49 + 177.12)) / 3.6 = 3.507511
    //   Imax = 5:   c = -255   -> d = (-0.7 + sqrt(0.49 + 1836))   / 3.6 = 11.709524
    //   Imax = 10:  c = -511   -> d = (-0.7 + sqrt(0.49 + 3679.2)) / 3.6 = 16.655680
    struct Case {
        float imax;
        double expected;
    };
    for (Case c : {Case{0.5f, 3.507511}, Case{5.0f, 11.709524}, Case{10.0f, 16.655680}}) {
        LightRadius r = solveLightRadius(c.imax, 1.0f, 0.7f, 1.8f, kThreshold);
        EXPECT_EQ(r.kind, RadiusKind::Quadratic) << "Imax " << c.imax;
        EXPECT_NEAR(r.radius, c.expected, 1e-4) << "Imax " << c.imax;
    }
}

TEST(LightRadius, BrightnessAtTheRadiusEqualsTheThreshold) {
    // The defining property, checked in double at intensities spanning four decades.
    for (float imax : {0.05f, 0.3f, 1.0f, 7.0f, 40.0f, 300.0f}) {
        LightRadius r = solveLightRadius(imax, 1.0f, 0.09f, 0.032f, kThreshold);
        ASSERT_EQ(r.kind, RadiusKind::Quadratic) << imax;
        double const d = r.radius;
        double const brightness = imax / (1.0 + 0.09 * d + 0.032 * d * d);
        EXPECT_NEAR(brightness / kThreshold, 1.0, 1e-5) << "Imax " << imax;
    }
}

TEST(LightRadius, LightHelperUsesBrightestChannelTimesIntensity) {
    PointLight l = makeLight(2.0f, 1.0f, 0.7f, 1.8f);
    l.color = glm::vec3(0.25f, 0.5f, 0.125f);  // Imax = 2 * 0.5 = 1
    EXPECT_FLOAT_EQ(lightImax(l), 1.0f);
    LightRadius r = lightRadius(l);
    EXPECT_EQ(r.kind, RadiusKind::Quadratic);
    EXPECT_NEAR(r.radius, 5.090127, 1e-4);
}

TEST(LightRadius, LinearRootWhenKqIsZero) {
    // Kq = 0: 0.7 d + 1 = 51.2 Imax  ->  Imax=1: d = 50.2/0.7 = 71.714286; Imax=2: 101.4/0.7 = 144.857143
    LightRadius r1 = solveLightRadius(1.0f, 1.0f, 0.7f, 0.0f, kThreshold);
    EXPECT_EQ(r1.kind, RadiusKind::Linear);
    EXPECT_NEAR(r1.radius, 71.714286, 1e-3);
    LightRadius r2 = solveLightRadius(2.0f, 1.0f, 0.7f, 0.0f, kThreshold);
    EXPECT_EQ(r2.kind, RadiusKind::Linear);
    EXPECT_NEAR(r2.radius, 144.857143, 1e-3);
}

TEST(LightRadius, NoFalloffIsCappedAndFlagged) {
    // Kl = Kq = 0: the brightness is Imax/Kc everywhere and never reaches the threshold.
    LightRadius r = solveLightRadius(1.0f, 1.0f, 0.0f, 0.0f, kThreshold);
    EXPECT_EQ(r.kind, RadiusKind::Capped);
    EXPECT_FLOAT_EQ(r.radius, kLightRadiusCap);
}

TEST(LightRadius, RootPastTheCapIsCappedAndFlagged) {
    // Kc=1, Kl=0, Kq=1e-6, Imax=1: d = sqrt(50.2 / 1e-6) = 7085.2 > the cap.
    LightRadius r = solveLightRadius(1.0f, 1.0f, 0.0f, 1e-6f, kThreshold);
    EXPECT_EQ(r.kind, RadiusKind::Capped);
    EXPECT_FLOAT_EQ(r.radius, kLightRadiusCap);
    // Linear: (51.2 * 100 - 1) / 0.7 = 7312.9 > the cap.
    LightRadius l = solveLightRadius(100.0f, 1.0f, 0.7f, 0.0f, kThreshold);
    EXPECT_EQ(l.kind, RadiusKind::Capped);
    EXPECT_FLOAT_EQ(l.radius, kLightRadiusCap);
}

TEST(LightRadius, TooDimLightHasZeroRadius) {
    // Imax <= threshold * Kc: even at d = 0 the light is at or below the threshold.
    EXPECT_EQ(solveLightRadius(kThreshold, 1.0f, 0.7f, 1.8f, kThreshold).kind, RadiusKind::Zero);  // equal
    EXPECT_EQ(solveLightRadius(0.01f, 1.0f, 0.7f, 1.8f, kThreshold).kind, RadiusKind::Zero);
    EXPECT_EQ(solveLightRadius(0.03f, 2.0f, 0.7f, 1.8f, kThreshold).kind, RadiusKind::Zero);  // 0.03 < 0.039
    EXPECT_EQ(solveLightRadius(0.0f, 1.0f, 0.7f, 1.8f, kThreshold).radius, 0.0f);
    // Just above threshold * Kc the root is small but positive.
    LightRadius r = solveLightRadius(0.05f, 2.0f, 0.7f, 1.8f, kThreshold);  // 1.8d^2+0.7d+2-2.56=0
    EXPECT_EQ(r.kind, RadiusKind::Quadratic);
    EXPECT_NEAR(r.radius, (-0.7 + std::sqrt(0.49 + 4 * 1.8 * 0.56)) / 3.6, 1e-4);
    // A black light is skipped too.
    PointLight black = makeLight(1.0f, 1.0f, 0.7f, 1.8f);
    black.color = glm::vec3(0.0f);
    EXPECT_EQ(lightRadius(black).kind, RadiusKind::Zero);
}

TEST(LightRadius, StableForVeryBrightLights) {
    // Imax = 1000, Kl = 100 dominant, Kq = 1e-4: the naive (-b + sqrt(b^2 - 4ac)) / 2a in float
    // subtracts 100 from 100.10 and keeps ~4 digits; the stable form must satisfy the equation
    // to float precision (d = 511.728...).
    LightRadius r = solveLightRadius(1000.0f, 1.0f, 100.0f, 1e-4f, kThreshold);
    ASSERT_EQ(r.kind, RadiusKind::Quadratic);
    double const d = r.radius;
    EXPECT_NEAR(d, 511.728, 0.01);
    double const residual = 1e-4 * d * d + 100.0 * d + 1.0 - 1000.0 * 51.2;
    EXPECT_LT(std::abs(residual) / (1000.0 * 51.2), 1e-6);
}

// --- validation -----------------------------------------------------------------------------

TEST(ValidateLight, AcceptsTheDefaultLight) {
    EXPECT_FALSE(validateLight(PointLight{}).has_value());
    EXPECT_FALSE(validateLight(makeLight(3.0f, 1.0f, 0.0f, 0.0f)).has_value());
}

TEST(ValidateLight, RejectsNaNInfiniteAndNegativeWithAMessageNamingTheField) {
    float const nan = std::numeric_limits<float>::quiet_NaN();
    float const inf = std::numeric_limits<float>::infinity();
    struct Case {
        char const* field;
        void (*spoil)(PointLight&, float);
        float value;
    };
    Case const cases[] = {
        {"intensity", [](PointLight& l, float v) { l.intensity = v; }, nan},
        {"intensity", [](PointLight& l, float v) { l.intensity = v; }, -1.0f},
        {"Kc", [](PointLight& l, float v) { l.kc = v; }, inf},
        {"Kl", [](PointLight& l, float v) { l.kl = v; }, -0.5f},
        {"Kq", [](PointLight& l, float v) { l.kq = v; }, nan},
        {"threshold", [](PointLight& l, float v) { l.threshold = v; }, -inf},
        {"color.g", [](PointLight& l, float v) { l.color.g = v; }, nan},
    };
    for (Case const& c : cases) {
        PointLight l = makeLight(1.0f, 1.0f, 0.7f, 1.8f);
        c.spoil(l, c.value);
        auto const msg = validateLight(l);
        ASSERT_TRUE(msg.has_value()) << c.field << " = " << c.value;
        EXPECT_NE(msg->find(c.field), std::string::npos) << *msg;
        // An invalid light is never drawn.
        EXPECT_EQ(lightRadius(l).kind, RadiusKind::Zero) << c.field;
        EXPECT_EQ(lightRadius(l).radius, 0.0f) << c.field;
    }
    // The raw solver rejects them too.
    EXPECT_EQ(solveLightRadius(nan, 1.0f, 0.7f, 1.8f, kThreshold).kind, RadiusKind::Zero);
    EXPECT_EQ(solveLightRadius(1.0f, 1.0f, inf, 1.8f, kThreshold).kind, RadiusKind::Zero);
    EXPECT_EQ(solveLightRadius(1.0f, 1.0f, 0.7f, -1.8f, kThreshold).kind, RadiusKind::Zero);
}

TEST(ValidateLight, RejectsNonFinitePositionZeroThresholdAndNoAttenuation) {
    PointLight l = makeLight(1.0f, 1.0f, 0.7f, 1.8f);
    l.position.y = std::numeric_limits<float>::infinity();
    ASSERT_TRUE(validateLight(l).has_value());
    EXPECT_NE(validateLight(l)->find("position"), std::string::npos);

    l = makeLight(1.0f, 1.0f, 0.7f, 1.8f);
    l.threshold = 0.0f;
    ASSERT_TRUE(validateLight(l).has_value());
    EXPECT_NE(validateLight(l)->find("threshold"), std::string::npos);

    l = makeLight(1.0f, 0.0f, 0.0f, 0.0f);
    ASSERT_TRUE(validateLight(l).has_value());
    EXPECT_NE(validateLight(l)->find("Kc"), std::string::npos);
}

TEST(LightFields, TheTableCoversEveryNumberOfPointLightOnce) {
    PointLight const base = makeLight(1.0f, 1.0f, 0.7f, 1.8f);
    PointLight probe = base;
    // Fails to compile when PointLight gains or loses a member: then give a new number an entry
    // in kLightFields (core/point_light.h) and add the member here. (A sizeof check would miss a
    // float or bool that fits in the padding before `name`; a structured binding misses nothing.)
    auto& [kind, position, color, intensity, kc, kl, kq, threshold, direction, innerConeDeg, outerConeDeg, name] =
        probe;
    // Each numeric member's floats, to check that every entry edits exactly one float of one member.
    struct Member {
        float const* first;
        int floats;
        int covered = 0;
    };
    Member members[] = {{&position.x, 3}, {&color.r, 3},   {&intensity, 1},   {&kc, 1},           {&kl, 1},
                        {&kq, 1},         {&threshold, 1}, {&direction.x, 3}, {&innerConeDeg, 1}, {&outerConeDeg, 1}};
    for (LightField const& f : kLightFields) {
        PointLight edited = base;
        f.of(edited) += 1.0f;
        // The edit is seen by == (undo's change detection) and by reading the field back.
        EXPECT_FALSE(edited == base) << f.name;
        EXPECT_EQ(f.of(edited), f.of(base) + 1.0f) << f.name;
        EXPECT_EQ(findLightField(f.name), &f) << f.name;
        float const* p = &f.of(probe);
        int hits = 0, hit = -1;
        for (int i = 0; i < int(std::size(members)); ++i) {
            if (p < members[i].first || p >= members[i].first + members[i].floats) continue;
            ++members[i].covered;
            ++hits;
            hit = i;
        }
        EXPECT_EQ(hits, 1) << f.name;
        // Position (member 0) need only be finite, direction (7) finite and not all zero, the cone
        // angles (8, 9) in degrees; every other number must be >= 0.
        EXPECT_EQ(f.range == LightFieldRange::Finite, hit == 0) << f.name;
        EXPECT_EQ(f.range == LightFieldRange::Direction, hit == 7) << f.name;
        EXPECT_EQ(f.range == LightFieldRange::ConeAngle, hit == 8 || hit == 9) << f.name;
    }
    // Every float of every numeric member has exactly one entry (16 in all).
    for (Member const& m : members) EXPECT_EQ(m.covered, m.floats);
    EXPECT_EQ(findLightField("name"), nullptr);  // the name is text, edited in the panel only
    EXPECT_EQ(findLightField("kind"), nullptr);  // the kind is a name: `light I kind spot`, the panel's combo
    name = "other";
    EXPECT_FALSE(probe == base);
    probe = base;
    kind = LightKind::Spot;
    EXPECT_FALSE(probe == base);
    for (std::size_t i = 0; i < kLightKindNames.size(); ++i)
        EXPECT_EQ(findLightKind(kLightKindNames[i]), static_cast<LightKind>(i));
    EXPECT_EQ(findLightKind("area"), std::nullopt);
}

TEST(LightFields, ValidateLightChecksEveryEntry) {
    // A negative value is refused for every NonNegative entry, a non-finite one for every entry,
    // and each sentence names the entry.
    for (LightField const& f : kLightFields) {
        PointLight l = makeLight(1.0f, 1.0f, 0.7f, 1.8f);
        f.of(l) = std::numeric_limits<float>::infinity();
        auto const msg = validateLight(l);
        ASSERT_TRUE(msg.has_value()) << f.name;
        std::string const expected = f.range == LightFieldRange::Finite ? "position" : std::string(f.label);
        EXPECT_NE(msg->find(expected), std::string::npos) << *msg;
        f.of(l) = -1.0f;
        // -1 is fine for a position or a direction component, not for the others.
        bool const signedOk = f.range == LightFieldRange::Finite || f.range == LightFieldRange::Direction;
        EXPECT_EQ(validateLight(l).has_value(), !signedOk) << f.name;
    }
}

// The Lights panel's drags stay within lightFieldBounds(): validateLight accepts both ends and
// refuses a step past a finite end, so the panel, the script and files accept the same numbers.
TEST(LightFields, BoundsAreWhatValidateLightAccepts) {
    PointLight base = makeLight(1.0f, 1.0f, 0.7f, 1.8f);
    base.kind = LightKind::Spot;
    base.innerConeDeg = 10.0f;
    base.outerConeDeg = 30.0f;
    constexpr float kMax = std::numeric_limits<float>::max();
    for (LightField const& f : kLightFields) {
        LightFieldBounds const b = lightFieldBounds(f, base);
        EXPECT_LE(b.lo, f.of(base)) << f.name;
        EXPECT_GE(b.hi, f.of(base)) << f.name;
        for (float end : {b.lo, b.hi}) {
            PointLight l = base;
            f.of(l) = end;
            EXPECT_FALSE(validateLight(l).has_value()) << f.name << " = " << end << ": " << *validateLight(l);
        }
        if (b.lo > -kMax) {
            PointLight l = base;
            f.of(l) = std::nextafter(b.lo, -kMax);
            EXPECT_TRUE(validateLight(l).has_value()) << f.name << " just below " << b.lo;
        }
        if (b.hi < kMax) {
            PointLight l = base;
            f.of(l) = std::nextafter(b.hi, kMax);
            EXPECT_TRUE(validateLight(l).has_value()) << f.name << " just above " << b.hi;
        }
        EXPECT_FALSE(f.row.empty()) << f.name << " has no row in the Lights panel";
        EXPECT_FALSE(f.help.empty()) << f.name << " has no help line";
        EXPECT_TRUE(f.usedBy(LightKind::Spot)) << f.name;  // a spot uses every number
    }
    // The cone's bounds follow the other angle: inner up to outer, outer down to inner.
    EXPECT_EQ(lightFieldBounds(*findLightField("inner"), base).hi, 30.0f);
    EXPECT_EQ(lightFieldBounds(*findLightField("outer"), base).lo, 10.0f);
    EXPECT_FALSE(findLightField("dx")->usedBy(LightKind::Point));
    EXPECT_FALSE(findLightField("outer")->usedBy(LightKind::Directional));
}

// --- windowed attenuation -------------------------------------------------------------------

TEST(WindowedAttenuation, ZeroAtAndPastTheRadius) {
    PointLight const l = makeLight(1.0f, 1.0f, 0.7f, 1.8f);
    float const r = lightRadius(l).radius;
    EXPECT_EQ(windowedAttenuation(l, r, r), 0.0f);
    EXPECT_EQ(windowedAttenuation(l, r, r * 1.001f), 0.0f);
    EXPECT_EQ(windowedAttenuation(l, r, 1e6f), 0.0f);
    EXPECT_EQ(windowedAttenuation(l, r, std::numeric_limits<float>::infinity()), 0.0f);
    EXPECT_EQ(windowedAttenuation(l, r, std::numeric_limits<float>::quiet_NaN()), 0.0f);
}

TEST(WindowedAttenuation, HandComputedInsideValues) {
    // At d = 0: 1/Kc - threshold/Imax = 1 - 5/256 = 0.98046875 (the cut-off equals threshold/Imax
    // because Imax * att(r) == threshold by the definition of r).
    PointLight const l = makeLight(1.0f, 1.0f, 0.7f, 1.8f);
    float const r = lightRadius(l).radius;
    EXPECT_NEAR(attenuationCutoff(l, r), 5.0 / 256.0, 1e-6);
    EXPECT_NEAR(windowedAttenuation(l, r, 0.0f), 0.98046875, 1e-6);
    // At d = 1: 1 / (1 + 0.7 + 1.8) - 5/256 = 0.285714 - 0.019531 = 0.266183
    EXPECT_NEAR(windowedAttenuation(l, r, 1.0f), 0.266183, 1e-5);
}

TEST(WindowedAttenuation, ContinuousAndDecreasingUpToTheRadius) {
    for (PointLight const& l : {makeLight(1.0f, 1.0f, 0.7f, 1.8f), makeLight(5.0f, 1.0f, 0.09f, 0.032f),
                                makeLight(1.0f, 1.0f, 0.7f, 0.0f), makeLight(100.0f, 1.0f, 0.7f, 0.0f) /*capped*/}) {
        float const r = lightRadius(l).radius;
        ASSERT_GT(r, 0.0f);
        // Approaching the radius from inside the value goes to 0 with the distance left.
        float const justInside = windowedAttenuation(l, r, r * (1.0f - 1e-5f));
        EXPECT_GE(justInside, 0.0f);
        EXPECT_LT(justInside, 1e-4f) << "Kq " << l.kq << " intensity " << l.intensity;
        // No step anywhere: sample densely and bound the jump between neighbours by the
        // steepest slope of the classic factor, |(Kl + 2 Kq d) / (Kc + Kl d + Kq d^2)^2|,
        // found on the same samples (10% margin for the slope varying within one step).
        int const n = 20000;
        float const step = r / n;
        double maxSlope = 0.0;
        for (int i = 0; i <= n; ++i) {
            double const d = double(step) * i, den = l.kc + l.kl * d + l.kq * d * d;
            maxSlope = std::max(maxSlope, (l.kl + 2.0 * l.kq * d) / (den * den));
        }
        float const maxJump = float(maxSlope * step * 1.1) + 1e-6f;
        float prev = windowedAttenuation(l, r, 0.0f);
        for (int i = 1; i <= n; ++i) {
            float const v = windowedAttenuation(l, r, step * i);
            EXPECT_LE(v, prev + 1e-7f) << "not decreasing at d = " << step * i;
            ASSERT_LE(prev - v, maxJump) << "step at d = " << step * i;
            prev = v;
        }
        EXPECT_EQ(prev, 0.0f);
    }
}

TEST(WindowedAttenuation, NoFalloffLightKeepsItsBrightnessUntilTheCap) {
    // Kl = Kq = 0: subtracting the (constant) factor at the radius would leave nothing, so the
    // window subtracts threshold / Imax; the documented step at the cap is the price.
    PointLight const l = makeLight(2.0f, 1.0f, 0.0f, 0.0f);
    LightRadius const r = lightRadius(l);
    ASSERT_EQ(r.kind, RadiusKind::Capped);
    EXPECT_NEAR(windowedAttenuation(l, r.radius, 10.0f), 1.0 - 5.0 / 512.0, 1e-6);
    EXPECT_EQ(windowedAttenuation(l, r.radius, r.radius), 0.0f);
}

TEST(LightRadius, ScalingTheFalloffScalesTheRadius) {
    for (float scale : {0.25f, 0.5f, 2.0f}) {
        PointLight const l = makeLight(3.0f, 1.0f, 0.7f, 1.8f);
        PointLight const s = scaleLightFalloff(l, scale);
        EXPECT_NEAR(lightRadius(s).radius, lightRadius(l).radius * scale, 1e-4 * scale) << scale;
        // The whole profile stretches: the same attenuation at scaled distances.
        for (float d : {0.0f, 0.5f, 2.0f, 4.0f})
            EXPECT_NEAR(windowedAttenuation(s, lightRadius(s).radius, d * scale),
                        windowedAttenuation(l, lightRadius(l).radius, d), 1e-5)
                << scale << " " << d;
    }
    // Linear falloff too: (51.2 * 3 - 1) / 0.7 = 218.0 -> 54.5 at a quarter.
    PointLight const lin = scaleLightFalloff(makeLight(3.0f, 1.0f, 0.7f, 0.0f), 0.25f);
    EXPECT_NEAR(lightRadius(lin).radius, (51.2 * 3 - 1) / 0.7 * 0.25, 1e-2);
}

// --- light kinds ---------------------------------------------------------------------------------

TEST(LightKinds, ValidateRefusesAZeroDirectionAndBadConesNamingTheField) {
    PointLight l = makeLight(1.0f, 1.0f, 0.7f, 1.8f);
    l.kind = LightKind::Spot;
    EXPECT_FALSE(validateLight(l).has_value());
    l.direction = glm::vec3(0.0f);
    ASSERT_TRUE(validateLight(l).has_value());
    EXPECT_NE(validateLight(l)->find("direction"), std::string::npos) << *validateLight(l);
    l = makeLight(1.0f, 1.0f, 0.7f, 1.8f);
    l.innerConeDeg = 30.0f;
    l.outerConeDeg = 20.0f;
    ASSERT_TRUE(validateLight(l).has_value());
    EXPECT_NE(validateLight(l)->find("inner_cone_deg must not exceed outer_cone_deg"), std::string::npos);
    l.innerConeDeg = 0.0f;
    l.outerConeDeg = 0.0f;
    ASSERT_TRUE(validateLight(l).has_value());
    EXPECT_NE(validateLight(l)->find("outer_cone_deg"), std::string::npos);
    l.outerConeDeg = 91.0f;
    ASSERT_TRUE(validateLight(l).has_value());
    EXPECT_NE(validateLight(l)->find("outer_cone_deg"), std::string::npos);
    l.outerConeDeg = 90.0f;  // KHR_lights_punctual's widest
    EXPECT_FALSE(validateLight(l).has_value());
}

TEST(LightKinds, ConeFactorIsOneInsideZeroOutsideAndSquaredBetween) {
    PointLight l = makeLight(1.0f, 1.0f, 0.7f, 1.8f);
    l.kind = LightKind::Spot;
    l.innerConeDeg = 20.0f;
    l.outerConeDeg = 40.0f;
    SpotCone const c = spotCone(l);
    float const ci = std::cos(glm::radians(20.0f)), co = std::cos(glm::radians(40.0f));
    EXPECT_FLOAT_EQ(c.cosOuter, co);
    EXPECT_FLOAT_EQ(c.scale, 1.0f / (ci - co));
    EXPECT_EQ(spotConeFactor(c, 1.0f), 1.0f);
    EXPECT_EQ(spotConeFactor(c, std::cos(glm::radians(10.0f))), 1.0f);
    EXPECT_EQ(spotConeFactor(c, std::cos(glm::radians(41.0f))), 0.0f);
    EXPECT_EQ(spotConeFactor(c, -1.0f), 0.0f);
    // Halfway in cosine: t = 0.5, factor 0.25 (the square of KHR_lights_punctual's sample code).
    EXPECT_NEAR(spotConeFactor(c, 0.5f * (ci + co)), 0.25f, 1e-5f);
    // Point and directional lights have no cone: 1 at every angle, even straight behind.
    l.kind = LightKind::Point;
    EXPECT_EQ(spotConeFactor(spotCone(l), -1.0f), 1.0f);
    // inner == outer: a hard edge, no division by zero.
    l.kind = LightKind::Spot;
    l.innerConeDeg = l.outerConeDeg = 30.0f;
    SpotCone const hard = spotCone(l);
    EXPECT_TRUE(std::isfinite(hard.scale));
    EXPECT_EQ(spotConeFactor(hard, std::cos(glm::radians(29.0f))), 1.0f);
    EXPECT_EQ(spotConeFactor(hard, std::cos(glm::radians(31.0f))), 0.0f);
}

TEST(LightKinds, CpuShadingOfEachKindMatchesHandComputedValues) {
    ShadingInputs s;
    s.position = glm::vec3(0.0f);
    s.normal = glm::vec3(0.0f, 1.0f, 0.0f);
    s.albedo = glm::vec3(0.5f);
    s.specular = 0.0f;  // diffuse only: N.L is all there is to check
    s.viewPosition = glm::vec3(0.0f, 5.0f, 5.0f);
    // Directional, straight down at a surface facing up: N.L = 1, no attenuation, wherever it is.
    PointLight sun = makeLight(2.0f, 1.0f, 0.7f, 1.8f);
    sun.kind = LightKind::Directional;
    sun.position = glm::vec3(1e4f);
    sun.direction = glm::vec3(0.0f, -3.0f, 0.0f);  // not unit: normalised when shading
    LightContribution c = shadeLightCpu(sun, s);
    EXPECT_EQ(c.attenuation, 1.0f);
    EXPECT_NEAR(c.diffuse.r, 0.5f * 2.0f, 1e-6f);
    // At 60 degrees, N.L = 0.5.
    sun.direction = glm::vec3(std::sin(glm::radians(60.0f)), -std::cos(glm::radians(60.0f)), 0.0f);
    EXPECT_NEAR(shadeLightCpu(sun, s).diffuse.r, 0.5f * 2.0f * 0.5f, 1e-6f);
    // Shining from below: nothing.
    sun.direction = glm::vec3(0.0f, 1.0f, 0.0f);
    EXPECT_EQ(shadeLightCpu(sun, s).total(), glm::vec3(0.0f));

    // A spot one unit above, pointing down: on its axis it equals the point light.
    PointLight spot = makeLight(1.0f, 1.0f, 0.7f, 1.8f);
    spot.position = glm::vec3(0.0f, 1.0f, 0.0f);
    PointLight const point = spot;
    spot.kind = LightKind::Spot;
    spot.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    spot.innerConeDeg = 20.0f;
    spot.outerConeDeg = 30.0f;
    EXPECT_EQ(shadeLightCpu(spot, s).total(), shadeLightCpu(point, s).total());
    EXPECT_EQ(shadeLightCpu(spot, s).cone, 1.0f);
    // A point 45 degrees off the axis is outside the 30-degree cone: dark, though the point light
    // reaches it.
    s.position = glm::vec3(1.0f, 0.0f, 0.0f);
    ASSERT_GT(shadeLightCpu(point, s).total().r, 0.0f);
    EXPECT_EQ(shadeLightCpu(spot, s).total(), glm::vec3(0.0f));
    EXPECT_FALSE(shadeLightCpu(spot, s).reaches());
    // 25 degrees: halfway between inner and outer in angle; the factor is the square of the
    // cosine ratio, times the point light's value.
    s.position = glm::vec3(std::tan(glm::radians(25.0f)), 0.0f, 0.0f);
    float const t = (std::cos(glm::radians(25.0f)) - std::cos(glm::radians(30.0f))) /
                    (std::cos(glm::radians(20.0f)) - std::cos(glm::radians(30.0f)));
    LightContribution const half = shadeLightCpu(spot, s);
    EXPECT_NEAR(half.cone, t * t, 1e-5f);
    EXPECT_NEAR(half.total().r, shadeLightCpu(point, s).total().r * t * t, 1e-6f);
    // shadePointCpu lists only the lights that reach the point.
    std::vector<LightContribution> list;
    PointLight const lights[] = {spot, point};
    s.position = glm::vec3(1.0f, 0.0f, 0.0f);
    shadePointCpu(lights, s, glm::vec3(0.0f), &list);
    ASSERT_EQ(list.size(), 1u);
    EXPECT_EQ(list[0].lightIndex, 1);
}

// The learnopengl shading against LearnOpenGL's deferred lighting shader written out here as that
// text gives it: ambient 0.1 * albedo, then per light diffuse max(N.L, 0) * albedo * colour and
// specular colour * (max(N.H, 0))^16 * specular, both times 1 / (1 + Kl d + Kq d^2); no window,
// no radius, and no N.L gate on the highlight.
TEST(ShadingModel, LearnOpenGlMatchesThatTextsLightingShader) {
    auto textShader = [](PointLight const& l, ShadingInputs const& s) {
        glm::vec3 const L = glm::normalize(l.position - s.position);
        glm::vec3 const V = glm::normalize(s.viewPosition - s.position);
        glm::vec3 const H = glm::normalize(L + V);
        float const d = glm::length(l.position - s.position);
        float const att = 1.0f / (1.0f + l.kl * d + l.kq * d * d);
        glm::vec3 const diffuse = std::max(glm::dot(s.normal, L), 0.0f) * s.albedo * l.color;
        glm::vec3 const specular = l.color * std::pow(std::max(glm::dot(s.normal, H), 0.0f), 16.0f) * s.specular;
        return (diffuse + specular) * att;
    };
    PointLight light = makeLight(1.0f, 1.0f, 0.7f, 1.8f);  // LearnOpenGL's Kl and Kq; radius ~4.8
    light.color = glm::vec3(0.9f, 0.6f, 0.3f);
    float const radius = lightRadius(light).radius;
    ASSERT_GT(radius, 1.0f);
    ASSERT_LT(radius, 5.5f);
    ShadingInputs s;
    s.model = ShadingModel::LearnOpenGl;
    s.shininess = kLearnOpenGlShininess;
    s.albedo = glm::vec3(0.8f, 0.5f, 0.2f);
    s.specular = 0.7f;
    s.viewPosition = glm::vec3(0.0f, 3.0f, 4.0f);
    glm::vec3 const ambient(kLearnOpenGlAmbient);
    int beyond = 0;
    // Points on the floor from under the light to well past its radius, lit from above.
    for (float x : {0.0f, 0.5f, 1.5f, 3.0f, 6.0f, 12.0f}) {
        s.position = glm::vec3(x, 0.0f, 0.0f);
        light.position = glm::vec3(0.0f, 1.0f, 0.0f);
        PointLight const one[] = {light};
        glm::vec3 const ours = shadePointCpu(one, s, ambient);
        glm::vec3 const text = 0.1f * s.albedo + textShader(light, s);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(ours[c], text[c], 1e-6f * std::max(1.0f, text[c])) << "x " << x;
        if (glm::length(light.position - s.position) > radius) {
            ++beyond;
            EXPECT_GT(ours.r, 0.1f * s.albedo.r) << "x " << x << ": no window, so still lit past the radius";
            ShadingInputs windowed = s;
            windowed.model = ShadingModel::GbufferLab;
            EXPECT_EQ(shadePointCpu(one, windowed, ambient), 0.1f * s.albedo) << "x " << x;
        }
    }
    EXPECT_GE(beyond, 2);
    // A light just below the surface's horizon: N.L < 0, so no diffuse light, but N.H > 0 still
    // gives that shader a highlight; gbuffer-lab's model gates it.
    s.position = glm::vec3(0.0f);
    s.viewPosition = glm::vec3(0.0f, 1.0f, 1.0f);
    light.position = glm::vec3(0.0f, -0.2f, -1.0f);
    LightContribution const behind = shadeLightCpu(light, s);
    EXPECT_EQ(behind.diffuse, glm::vec3(0.0f));
    EXPECT_GT(behind.specular.r, 0.0f);
    EXPECT_NEAR(behind.specular.r, textShader(light, s).r, 1e-6f);
    ShadingInputs gated = s;
    gated.model = ShadingModel::GbufferLab;
    EXPECT_EQ(shadeLightCpu(light, gated).total(), glm::vec3(0.0f));
}

// The modes that light a pixel only inside a light's radius cut the learnopengl shading there;
// quad and forward do not. A light too dim to reach the threshold (radius 0) shades nothing.
TEST(ShadingModel, TheCutAtTheRadiusFollowsTheMode) {
    EXPECT_FALSE(cutsAtRadius(LightingMode::Quad));
    EXPECT_FALSE(cutsAtRadius(LightingMode::Forward));
    EXPECT_TRUE(cutsAtRadius(LightingMode::Volumes));
    EXPECT_TRUE(cutsAtRadius(LightingMode::Tiled));
    EXPECT_TRUE(cutsAtRadius(LightingMode::Clustered));
    PipelineSettings settings;
    settings.shading = ShadingModel::LearnOpenGl;
    settings.shininess = 16.0f;
    PointLight light = makeLight(1.0f, 1.0f, 0.7f, 1.8f);
    light.position = glm::vec3(0.0f, 1.0f, 0.0f);
    ShadingInputs s;
    s.position = glm::vec3(6.0f, 0.0f, 0.0f);  // beyond the ~4.8 radius
    s.viewPosition = glm::vec3(0.0f, 3.0f, 4.0f);
    for (LightingMode mode : {LightingMode::Quad, LightingMode::Volumes}) {
        settings.mode = mode;
        shadingOf(settings, s);
        EXPECT_EQ(s.shininess, 16.0f);
        EXPECT_EQ(shadeLightCpu(light, s).reaches(), !cutsAtRadius(mode)) << enumName(kLightingModeNames, mode);
    }
    settings.mode = LightingMode::Quad;
    shadingOf(settings, s);
    light.intensity = kThreshold * 0.5f;  // never reaches the threshold: radius 0
    ASSERT_EQ(lightRadius(light).radius, 0.0f);
    s.position = glm::vec3(0.0f);
    EXPECT_FALSE(shadeLightCpu(light, s).reaches());
}
