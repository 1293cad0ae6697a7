// "Why this value": each mode's per-light verdict at one pixel, on hand-built frames.
#include "model/why_value.h"
#include "model/pixel_breakdown.h"

#include "core/depth.h"
#include "core/light_math.h"
#include "core/shading_cpu.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

using namespace gbl;
using namespace gbl::ui;

namespace {

// Camera at the origin looking down -Z at a wall facing it; the pixel sees (0, 0, -10).
struct Frame {
    Camera camera;
    glm::ivec2 size{64, 64};
    glm::ivec2 pixel{32, 32};
    PixelSample sample;
    Frame() {
        camera.position = glm::vec3(0.0f);
        camera.yawDegrees = -90.0f;
        camera.pitchDegrees = 0.0f;
        sample.covered = true;
        sample.position = glm::vec4(0.0f, 0.0f, -10.0f, 1.0f);
        sample.normal = glm::vec4(0.0f, 0.0f, 1.0f, 1.0f);
        sample.albedoSpec = glm::vec4(0.8f, 0.8f, 0.8f, 0.5f);
        glm::vec4 const clip = camera.projection(1.0f) * camera.view() * sample.position;
        sample.depth = clip.z / clip.w * 0.5f + 0.5f;
    }
    WhyValueInput input(LightingMode mode, CullMode cull = CullMode::Back) const {
        WhyValueInput in;
        in.sample = sample;
        in.pixel = pixel;
        in.frameSize = size;
        in.camera = camera;
        in.settings.mode = mode;
        in.settings.cull = cull;
        return in;
    }
    glm::vec3 shaded(PointLight const& l) const {
        ShadingInputs s;
        s.position = glm::vec3(sample.position);
        s.normal = glm::vec3(sample.normal);
        s.albedo = glm::vec3(sample.albedoSpec);
        s.specular = sample.albedoSpec.a;
        s.viewPosition = camera.position;
        return shadeLightCpu(l, s).total();
    }
};

PointLight light(glm::vec3 p, float kl = 0.7f, float kq = 1.8f) {
    PointLight l;
    l.position = p;
    l.kl = kl;
    l.kq = kq;
    return l;
}

bool startsWith(std::string const& s, std::string const& prefix) {
    return s.rfind(prefix, 0) == 0;
}

}  // namespace

TEST(WhyValue, CameraInsideTheVolumeIsLostWithBackFacesCulled) {
    Frame const f;
    // Radius about 15.8 around (0, 0, -2): holds both the camera and the surface.
    PointLight const big = light({0.0f, 0.0f, -2.0f}, 0.0f, 0.2f);
    ASSERT_GT(lightRadius(big).radius, 12.0f);
    PointLight const lights[] = {big};
    auto v = explainPixel(f.input(LightingMode::Volumes, CullMode::Back), lights);
    ASSERT_EQ(v.size(), 1u);
    EXPECT_TRUE(v[0].withinRadius);
    EXPECT_FALSE(v[0].evaluated);
    EXPECT_TRUE(startsWith(v[0].why, "not evaluated: camera inside the volume, back faces culled")) << v[0].why;
    EXPECT_EQ(v[0].added, glm::vec3(0.0f));

    // Front faces culled: the back face behind the wall is drawn, the light is shaded once.
    v = explainPixel(f.input(LightingMode::Volumes, CullMode::Front), lights);
    EXPECT_TRUE(v[0].evaluated);
    EXPECT_EQ(v[0].evaluations, 1);
    glm::vec3 const expected = f.shaded(big);
    EXPECT_GT(expected.r, 0.01f);
    EXPECT_NEAR(v[0].added.r, expected.r, 1e-6f);

    // No culling: only the back face is in front of the eye, so once; stencil and flip keep it.
    EXPECT_EQ(explainPixel(f.input(LightingMode::Volumes, CullMode::None), lights)[0].evaluations, 1);
    EXPECT_EQ(explainPixel(f.input(LightingMode::Volumes, CullMode::Stencil), lights)[0].evaluations, 1);
    v = explainPixel(f.input(LightingMode::Volumes, CullMode::Flip), lights);
    EXPECT_EQ(v[0].evaluations, 1);
    EXPECT_TRUE(startsWith(v[0].why, "flip, camera may be inside")) << v[0].why;
}

TEST(WhyValue, LightOutsideTheRadius) {
    Frame const f;
    PointLight const far = light({20.0f, 0.0f, -10.0f});  // radius about 5.1, 20 units away
    PointLight const lights[] = {far};
    // The quad pass tests it and adds nothing.
    auto v = explainPixel(f.input(LightingMode::Quad), lights);
    ASSERT_EQ(v.size(), 1u);
    EXPECT_FALSE(v[0].withinRadius);
    EXPECT_TRUE(v[0].evaluated);
    EXPECT_EQ(v[0].added, glm::vec3(0.0f));
    EXPECT_NE(v[0].why.find("outside its radius"), std::string::npos) << v[0].why;
    // Its volume does not cover the pixel at all.
    v = explainPixel(f.input(LightingMode::Volumes, CullMode::Back), lights);
    EXPECT_FALSE(v[0].evaluated);
    EXPECT_EQ(v[0].why, "not evaluated: pixel outside the volume's footprint");
}

TEST(WhyValue, VolumeBehindTheSurface) {
    Frame const f;
    // Radius about 5.1 around (0, 0, -16): the whole volume is behind the wall at depth 10.
    PointLight const behind = light({0.0f, 0.0f, -16.0f});
    PointLight const lights[] = {behind};
    auto v = explainPixel(f.input(LightingMode::Volumes, CullMode::Back), lights);
    EXPECT_FALSE(v[0].evaluated);
    EXPECT_TRUE(startsWith(v[0].why, "not evaluated: surface in front of the volume")) << v[0].why;
    // Culling front faces shades it anyway (its back face is behind the wall), for nothing.
    v = explainPixel(f.input(LightingMode::Volumes, CullMode::Front), lights);
    EXPECT_TRUE(v[0].evaluated);
    EXPECT_FALSE(v[0].withinRadius);
    EXPECT_EQ(v[0].added, glm::vec3(0.0f));
    // The stencil test keeps only surfaces inside the volume.
    v = explainPixel(f.input(LightingMode::Volumes, CullMode::Stencil), lights);
    EXPECT_FALSE(v[0].evaluated);
    EXPECT_TRUE(startsWith(v[0].why, "not evaluated: stencil, surface in front")) << v[0].why;
    // None: both faces, no depth test, counted twice.
    EXPECT_EQ(explainPixel(f.input(LightingMode::Volumes, CullMode::None), lights)[0].evaluations, 2);
}

TEST(WhyValue, TiledUsesThePixelsTileList) {
    Frame const f;
    // Pixel (32, 32) of 64x64 (top-left origin) is in tile (2, 1): NDC x in [0, 0.5], y in [-0.5, 0].
    PointLight const inTile = light({0.5f, -0.5f, -9.5f});
    PointLight const aside = light({-12.0f, 8.0f, -10.0f});  // 12 units left of the tile's frustum
    PointLight const deeper = light({1.0f, -1.0f, -30.0f});  // in the tile's frustum, past the wall
    PointLight const lights[] = {inTile, aside, deeper};
    WhyValueInput in = f.input(LightingMode::Tiled);
    auto v = explainPixel(in, lights);
    ASSERT_EQ(v.size(), 3u);
    EXPECT_TRUE(v[0].evaluated);
    EXPECT_TRUE(v[0].withinRadius);
    EXPECT_NEAR(v[0].added.g, f.shaded(inTile).g, 1e-6f);
    EXPECT_GT(v[0].added.g, 0.0f);
    EXPECT_FALSE(v[1].evaluated);
    EXPECT_EQ(v[1].why, "not evaluated: not in the tile's light list");
    EXPECT_FALSE(v[2].evaluated);  // the tile's depth bounds end at the wall
    // A tile whose geometry reaches depth 40 lists the deeper light too (it adds nothing here).
    in.tileBounds = TileDepthBounds{10.0f, 40.0f};
    v = explainPixel(in, lights);
    EXPECT_TRUE(v[2].evaluated);
    EXPECT_EQ(v[2].added, glm::vec3(0.0f));
    EXPECT_FALSE(v[1].evaluated);
}

TEST(WhyValue, TileDepthBoundsSkipBackgroundAndOtherTiles) {
    Camera c;
    FloatImage depth{32, 32, 1, std::vector<float>(32 * 32, 1.0f)};
    // Top-left pixel (0, 0) is in the GL tile (0, 1): image rows 0..15, columns 0..15.
    depth.pixels[3 * 32 + 4] = 0.5f;
    depth.pixels[10 * 32 + 15] = 0.9f;
    depth.pixels[20 * 32 + 4] = 0.1f;  // row 20: the tile below, left out
    auto b = tileDepthBounds(depth, {0, 0}, c.nearPlane, c.farPlane);
    ASSERT_TRUE(b);
    EXPECT_FLOAT_EQ(b->minDepth, linearDepth(0.5f, c.nearPlane, c.farPlane));
    EXPECT_FLOAT_EQ(b->maxDepth, linearDepth(0.9f, c.nearPlane, c.farPlane));
    EXPECT_FALSE(tileDepthBounds(depth, {20, 0}, c.nearPlane, c.farPlane));  // tile (1, 1): background only
}

TEST(WhyValue, BreakdownCarriesVerdictsWhoseSumIsTheTotal) {
    Frame const f;
    PointLight const lights[] = {light({0.5f, -0.5f, -9.5f}), light({20.0f, 0.0f, -10.0f}),
                                 light({-1.0f, 1.0f, -8.0f})};
    PipelineSettings settings;  // quad: every light tested
    auto b = breakDownPixel(f.sample, lights, f.camera, settings, PixelInFrame{f.pixel, f.size, std::nullopt});
    ASSERT_TRUE(b);
    ASSERT_EQ(b->verdicts.size(), 3u);
    glm::vec3 sum = b->ambient;
    for (LightVerdict const& v : b->verdicts) sum += v.added;
    EXPECT_NEAR(sum.r, b->total.r, 1e-5f);
    EXPECT_NEAR(sum.b, b->total.b, 1e-5f);
    EXPECT_EQ(int(b->lights.size()), 2);  // the far light reaches nothing
    // Without the frame, no verdicts (the old call stays as it was).
    EXPECT_TRUE(breakDownPixel(f.sample, lights, f.camera, settings)->verdicts.empty());
}

// --- the inspector's stored-vs-sum flag -------------------------------------------------------

TEST(StoredValueCheck, AgreesWithinTheFp16BoundAndNamesTheCameraInsideWithBack) {
    Frame const f;
    PointLight const big = light({0.0f, 0.0f, -2.0f}, 0.0f, 0.2f);  // holds the camera and the surface
    PointLight const lights[] = {big};
    PipelineSettings s;
    s.mode = LightingMode::Volumes;
    s.cull = CullMode::Back;
    auto const b = breakDownPixel(f.sample, lights, f.camera, s, PixelInFrame{f.pixel, f.size, std::nullopt});
    ASSERT_TRUE(b);
    // Stored = the sum, off by less than the bound: agrees.
    glm::vec3 const nearly = b->total * (1.0f + 1e-3f);
    EXPECT_TRUE(checkStoredValue(nearly, *b, s).agrees);
    // Stored = ambient alone (what `back` leaves with the camera inside): flagged, cause named.
    ValueCheck const c = checkStoredValue(b->ambient, *b, s);
    EXPECT_FALSE(c.agrees);
    EXPECT_NEAR(c.error, std::max({b->total.r - b->ambient.r, b->total.g - b->ambient.g, b->total.b - b->ambient.b}),
                1e-6f);
    EXPECT_NE(c.cause.find("camera inside light 0's volume with cull `back`"), std::string::npos) << c.cause;
}

TEST(StoredValueCheck, NamesTooSmallVolumesOverlaysAndForward) {
    Frame const f;
    PointLight const near = light({0.0f, 1.0f, -9.0f});  // the camera is outside its small volume
    PointLight const lights[] = {near};
    PipelineSettings s;
    s.mode = LightingMode::Volumes;
    s.cull = CullMode::Front;
    auto const b = breakDownPixel(f.sample, lights, f.camera, s, PixelInFrame{f.pixel, f.size, std::nullopt});
    ASSERT_TRUE(b);
    ASSERT_GT(b->total.r - b->ambient.r, 0.05f) << "the light must reach the wall";
    // The mode evaluated the light, yet less is stored: the volume cut it off.
    ValueCheck const small = checkStoredValue(b->ambient, *b, s);
    EXPECT_FALSE(small.agrees);
    EXPECT_NE(small.cause.find("too small"), std::string::npos) << small.cause;
    ValueCheck const over = checkStoredValue(b->total + glm::vec3(0.5f), *b, s);
    EXPECT_FALSE(over.agrees);
    EXPECT_NE(over.cause.find("light cubes"), std::string::npos) << over.cause;
    // Forward mode: the G-buffer is cleared, so the sample has no surface; the note says why.
    PixelSample none;
    none.covered = false;
    none.lighting = glm::vec4(0.25f, 0.5f, 0.125f, 1.0f);
    s.mode = LightingMode::Forward;
    std::string const note = noBreakdownNote(none, s);
    EXPECT_NE(note.find("forward mode has no G-buffer"), std::string::npos) << note;
    EXPECT_NE(note.find("0.2500 0.5000 0.1250"), std::string::npos) << note;
    // prepass: the layout's G-buffer is cleared too (its thin one is its own).
    s.mode = LightingMode::Prepass;
    std::string const thin = noBreakdownNote(none, s);
    EXPECT_NE(thin.find("prepass keeps a thin G-buffer of its own"), std::string::npos) << thin;
    EXPECT_NE(thin.find("0.2500 0.5000 0.1250"), std::string::npos) << thin;
    s.mode = LightingMode::Quad;
    EXPECT_EQ(noBreakdownNote(none, s), "background: no surface, no lights");
}

TEST(WhyValue, DirectionalLightsAreAddedOnceInEveryMode) {
    Frame const f;
    PointLight sun;
    sun.kind = LightKind::Directional;
    sun.direction = {0.0f, 0.0f, -1.0f};  // straight at the wall
    sun.position = {100.0f, 0.0f, 0.0f};  // far from everything: no radius applies
    PointLight const lights[] = {sun};
    for (LightingMode mode : {LightingMode::Quad, LightingMode::Volumes, LightingMode::Tiled, LightingMode::Clustered,
                              LightingMode::Forward}) {
        auto const v = explainPixel(f.input(mode, CullMode::Back), lights);
        ASSERT_EQ(v.size(), 1u);
        EXPECT_TRUE(v[0].evaluated);
        EXPECT_EQ(v[0].evaluations, 1);
        EXPECT_TRUE(startsWith(v[0].why, "directional")) << v[0].why;
        // N.L = 1: albedo 0.8 times intensity 1, plus the highlight.
        EXPECT_GE(v[0].added.r, 0.8f - 1e-6f);
        EXPECT_EQ(v[0].added, f.shaded(sun));
    }
}

TEST(WhyValue, ASpotsConeVolumeIsWhatTheVolumesPassDraws) {
    Frame const f;
    // A spot 4 units in front of the wall and 1 above the pixel's ray, pointing at the wall with
    // a 20-degree cone (the pixel is 14 degrees off its axis); radius about 5.1.
    PointLight spot = light({0.0f, 1.0f, -6.0f});
    spot.kind = LightKind::Spot;
    spot.direction = {0.0f, 0.0f, -1.0f};
    spot.innerConeDeg = 10.0f;
    spot.outerConeDeg = 20.0f;
    PointLight const lights[] = {spot};
    auto v = explainPixel(f.input(LightingMode::Volumes, CullMode::Back), lights);
    ASSERT_EQ(v.size(), 1u);
    EXPECT_TRUE(v[0].evaluated) << v[0].why;
    EXPECT_EQ(v[0].why, "front face in front of the surface");
    EXPECT_NEAR(v[0].added.r, f.shaded(spot).r, 1e-6f);
    EXPECT_GT(v[0].added.r, 0.0f);
    EXPECT_LT(v[0].added.r, f.shaded(light({0.0f, 1.0f, -6.0f})).r);  // the cone's soft edge dims it
    // Turned away from the wall: the pixel is inside the sphere but outside the cone's mesh.
    spot.direction = {1.0f, 0.0f, 0.0f};
    PointLight const aside[] = {spot};
    v = explainPixel(f.input(LightingMode::Volumes, CullMode::Back), aside);
    EXPECT_TRUE(v[0].withinRadius);
    EXPECT_FALSE(v[0].evaluated);
    EXPECT_EQ(v[0].why, "not evaluated: pixel outside the volume's footprint (it would have reached the pixel)");
    // Tiled and clustered cull it by its cone too; it would add nothing here anyway.
    EXPECT_FALSE(explainPixel(f.input(LightingMode::Tiled), aside)[0].evaluated);
    EXPECT_EQ(f.shaded(spot), glm::vec3(0.0f));
}

TEST(WhyValue, LightsAroundTheEyeAreThoseWhoseDrawnVolumeHoldsIt) {
    // A light at the origin with a radius of about 5.1; the drawn sphere is radius * 1.0301.
    PointLight const near = light({0.0f, 0.0f, 0.0f});
    float const r = lightRadius(near).radius;
    ASSERT_GT(r, 3.0f);
    PointLight far = light({100.0f, 0.0f, 0.0f});
    PointLight sun = light({0.0f, 0.0f, 0.0f});
    sun.kind = LightKind::Directional;
    PointLight const lights[] = {far, near, sun};
    EXPECT_EQ(lightsAroundEye({0.0f, 0.0f, 0.9f * r}, lights, 1.0f), std::vector<int>{1});
    // Just past the radius but inside the enclosing sphere the pass draws: still inside.
    EXPECT_EQ(lightsAroundEye({0.0f, 0.0f, 1.01f * r}, lights, 1.0f), std::vector<int>{1});
    EXPECT_TRUE(lightsAroundEye({0.0f, 0.0f, 1.05f * r}, lights, 1.0f).empty());
    // The volume scale grows and shrinks what is drawn, so the answer follows it.
    EXPECT_EQ(lightsAroundEye({0.0f, 0.0f, 1.5f * r}, lights, 2.0f), std::vector<int>{1});
    EXPECT_TRUE(lightsAroundEye({0.0f, 0.0f, 0.9f * r}, lights, 0.5f).empty());
    // A spot pointing down -Z: inside its cone, not beside it at the same distance.
    PointLight spot = light({0.0f, 0.0f, 0.0f});
    spot.kind = LightKind::Spot;
    spot.direction = {0.0f, 0.0f, -1.0f};
    spot.innerConeDeg = 10.0f;
    spot.outerConeDeg = 20.0f;
    PointLight const spots[] = {spot};
    EXPECT_EQ(lightsAroundEye({0.0f, 0.0f, -0.5f * r}, spots, 1.0f), std::vector<int>{0});
    EXPECT_TRUE(lightsAroundEye({0.5f * r, 0.0f, 0.0f}, spots, 1.0f).empty());
}
