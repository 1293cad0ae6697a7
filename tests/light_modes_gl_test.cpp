// The four lighting modes and the five volume cull modes on the default scene: one image, with
// the differences that are bugs (cull none, back faces with the camera inside) shown to be real.
#include "core/light_math.h"
#include "core/light_volume_mesh.h"
#include "core/tile_math.h"
#include "lighting_compare.h"
#include "scene/default_scene.h"
#include "test_scenes.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

using namespace gbl;
using namespace gbl::test;

namespace {

constexpr int kW = 320, kH = 180;

class LightModesGlTest : public LightingGlTest {
protected:
    LightModesGlTest() : LightingGlTest(kW, kH) {}

    // Volumes (inside-safe cull modes), tiled and forward against the full-screen pass from
    // `cam`, each within its bound; returns the full-screen image.
    FloatImage expectModesMatchQuad(Camera const& cam) {
        FloatImage const quad = lighting(lightingSettings(LightingMode::Quad), cam, lights_);
        for (CullMode cull : {CullMode::Front, CullMode::Flip, CullMode::Stencil}) {
            ImageDiff const d =
                compareRgb(lighting(lightingSettings(LightingMode::Volumes, cull), cam, lights_), quad, volumeBound);
            EXPECT_EQ(d.pixelsOver, 0) << "volumes/" << enumName(kCullModeNames, cull) << ": " << describe(d);
        }
        if (caps().computeShaders) {
            ImageDiff const d =
                compareRgb(lighting(lightingSettings(LightingMode::Tiled), cam, lights_), quad, sameSumBound);
            EXPECT_EQ(d.pixelsOver, 0) << "tiled: " << describe(d);
            // Clustered adds the same lights in the same order as tiled: the same bound.
            ImageDiff const c =
                compareRgb(lighting(lightingSettings(LightingMode::Clustered), cam, lights_), quad, sameSumBound);
            EXPECT_EQ(c.pixelsOver, 0) << "clustered: " << describe(c);
        }
        ImageDiff const f =
            compareRgb(lighting(lightingSettings(LightingMode::Forward), cam, lights_), quad, forwardBound);
        EXPECT_LT(f.pixelsOver, kW * kH / 200) << "forward: " << describe(f);
        return quad;
    }

    // The coverage attachment as floats (x evaluated, y lit), rows bottom to top as GL stores them.
    std::vector<glm::vec2> coverage() {
        FloatImage const img = renderer_->readAttachment(Attachment::Coverage);  // rows top to bottom
        EXPECT_EQ(img.channels, 2);
        std::vector<glm::vec2> out(std::size_t(img.width) * img.height);
        for (int y = 0; y < img.height; ++y)
            for (int x = 0; x < img.width; ++x)
                out[std::size_t(img.height - 1 - y) * img.width + x] = {img.at(x, y, 0), img.at(x, y, 1)};
        return out;
    }
};

}  // namespace

TEST_F(LightModesGlTest, TestCameraIsOutsideEveryVolume) {
    // The cull-mode assertions below rely on this; if the scene changes, pick another camera.
    float const nearCorner =
        nearPlaneCornerDistance(glm::radians(camera_.fovYDegrees), float(kW) / kH, camera_.nearPlane);
    float const scale = enclosingScale(makeLightVolumeSphere());
    ASSERT_EQ(lights_.size(), 32u);
    for (auto const& l : lights_)
        EXPECT_FALSE(volumeMayContainCamera(camera_.position, l.position, lightRadius(l).radius * scale, nearCorner));
    // ...and insideCamera() really is inside light 0.
    EXPECT_LT(glm::length(insideCamera().position - lights_[0].position), lightRadius(lights_[0]).radius);
}

TEST_F(LightModesGlTest, VolumesTiledAndForwardMatchQuad) {
    FloatImage const quad = lighting(lightingSettings(LightingMode::Quad));
    ImageDiff const q = compareRgb(quad, quad, [](double) { return 0.0; });
    ASSERT_GT(q.meanValue, 0.01) << "the default scene should be visibly lit";

    // Volumes: the same fp32 light terms, but summed by fp16 blending, one rounding per light
    // covering the pixel. The default scene has at most ~12 lights over one pixel, so 16 half-ulps
    // of the value plus 1e-4 absolute (fp16 spacing of the darkest lit values) bound it (volumeBound).
    for (CullMode cull : {CullMode::Back, CullMode::Front, CullMode::Flip, CullMode::Stencil}) {
        ImageDiff const d = compareRgb(lighting(lightingSettings(LightingMode::Volumes, cull)), quad, volumeBound);
        EXPECT_EQ(d.pixelsOver, 0) << "volumes/" << enumName(kCullModeNames, cull) << ": " << describe(d);
        // On average a handful of roundings: under 8 half-ulps of the mean value.
        EXPECT_LT(d.meanAbs, 8 * kHalfUlp * q.meanValue)
            << "volumes/" << enumName(kCullModeNames, cull) << ": " << describe(d);
    }

    if (caps().computeShaders) {
        // Tiled adds the same lights in the same order in fp32 and stores once: one fp16 rounding
        // (a half-ulp each side, so 2 half-ulps) plus slack for the compiler fusing differently.
        ImageDiff const d = compareRgb(lighting(lightingSettings(LightingMode::Tiled)), quad, sameSumBound);
        EXPECT_EQ(d.pixelsOver, 0) << "tiled: " << describe(d);
    }

    // Forward shades the interpolated surface directly; the deferred modes read it back from the
    // G-buffer: position in fp16 (1/64 unit at 16..32 units from the origin), albedo and specular
    // in 8 bits (1/510 absolute), normal in fp16. Those move the result by a few percent at worst
    // (dark albedo, grazing specular), so forward is held to a mean error of 1% of the mean
    // value and 99.5% of pixels within 3% + 2e-3.
    ImageDiff const f = compareRgb(lighting(lightingSettings(LightingMode::Forward)), quad, forwardBound);
    EXPECT_LT(f.meanAbs, 0.01 * q.meanValue) << "forward: " << describe(f);
    EXPECT_LT(f.pixelsOver, kW * kH / 200) << "forward: " << describe(f);
}

TEST_F(LightModesGlTest, AllModesMatchQuadFromTheDefaultSceneCamera) {
    // The scene's own camera stands among the lights (some volumes come within a near-plane
    // reach of it), the case the inside-safe cull modes exist for. Bounds as above.
    Camera const cam = scene_.camera.value_or(Camera{});
    expectModesMatchQuad(cam);
}

TEST_F(LightModesGlTest, CameraInsideAVolume) {
    Camera const cam = insideCamera();
    FloatImage const quad = expectModesMatchQuad(cam);

    // Culling back faces loses the light the camera is in: its front faces are behind the eye.
    // Light 0 fills most of this view, so a large share of pixels must lose light.
    ImageDiff const back =
        compareRgb(lighting(lightingSettings(LightingMode::Volumes, CullMode::Back), cam, lights_), quad, volumeBound);
    EXPECT_GT(back.pixelsOver, kW * kH / 4) << "back-face culling should fail inside a volume: " << describe(back);
}

TEST_F(LightModesGlTest, CullNoneAppliesEachLightTwice) {
    // Without culling or depth test both faces of each volume shade the pixels under it: with the
    // camera outside every volume, none = ambient + 2 x (quad - ambient).
    FloatImage const quad = lighting(lightingSettings(LightingMode::Quad));
    FloatImage const ambient = lighting(lightingSettings(LightingMode::Quad), camera_, {});
    FloatImage const none = lighting(lightingSettings(LightingMode::Volumes, CullMode::None));
    FloatImage doubled = quad;
    for (std::size_t i = 0; i < doubled.pixels.size(); ++i) doubled.pixels[i] = 2 * quad.pixels[i] - ambient.pixels[i];
    // 2x the value of the volumes bound above: every blend now happens twice.
    ImageDiff const d = compareRgb(none, doubled, [](double v) { return 32 * kHalfUlp * v + 2e-4; });
    EXPECT_EQ(d.pixelsOver, 0) << describe(d);
    ImageDiff const vsQuad = compareRgb(none, quad, volumeBound);
    EXPECT_GT(vsQuad.meanAbs, 0.3 * vsQuad.meanValue) << "cull none must differ from quad: " << describe(vsQuad);
}

TEST_F(LightModesGlTest, CoverageCountsAgreeBetweenModes) {
    // y (lights that lit the pixel) is a property of the scene, not of the mode.
    auto counts = [&](LightingMode m, CullMode c = CullMode::Front) {
        PipelineSettings s = lightingSettings(m, c);
        s.view = DebugView::Heatmap;
        renderer_->render({camera_, lights_, s, true});
        return coverage();
    };
    auto const quad = counts(LightingMode::Quad);
    auto const volumes = counts(LightingMode::Volumes);
    auto const stencil = counts(LightingMode::Volumes, CullMode::Stencil);
    int geometry = 0, litSomewhere = 0, volumeWaste = 0, stencilSaves = 0;
    for (std::size_t i = 0; i < quad.size(); ++i) {
        ASSERT_TRUE(quad[i].x == 0.0f || quad[i].x == 32.0f) << i;  // all lights, where there is geometry
        geometry += quad[i].x > 0;
        litSomewhere += quad[i].y > 0;
        ASSERT_EQ(volumes[i].y, quad[i].y) << "pixel " << i;
        ASSERT_EQ(stencil[i].y, quad[i].y) << "pixel " << i;
        ASSERT_GE(volumes[i].x, volumes[i].y) << "pixel " << i;
        // The stencil pass shades only pixels whose surface is inside the mesh: a subset of
        // what front-face culling shades (which adds surfaces in front of the volume).
        ASSERT_GE(stencil[i].x, stencil[i].y) << "pixel " << i;
        ASSERT_LE(stencil[i].x, volumes[i].x) << "pixel " << i;
        stencilSaves += stencil[i].x < volumes[i].x;
        volumeWaste += volumes[i].x > volumes[i].y;
    }
    EXPECT_GT(geometry, kW * kH / 2);
    EXPECT_GT(litSomewhere, geometry / 4);
    EXPECT_GT(volumeWaste, 0);   // the heat map has executed-but-unlit pixels to show
    EXPECT_GT(stencilSaves, 0);  // the stencil test does skip work somewhere
    if (caps().computeShaders) {
        auto const tiled = counts(LightingMode::Tiled);
        for (std::size_t i = 0; i < quad.size(); ++i) {
            ASSERT_EQ(tiled[i].y, quad[i].y) << "pixel " << i;
            ASSERT_GE(tiled[i].x, tiled[i].y) << "pixel " << i;
        }
    }
}

TEST_F(LightModesGlTest, TileListsMatchTheCpuTileMath) {
    if (!caps().computeShaders) GTEST_SKIP() << caps().tiledUnavailableReason();
    PipelineSettings s = lightingSettings(LightingMode::Tiled);
    s.view = DebugView::TileLights;
    renderer_->render({camera_, lights_, s, true});
    auto const gpu = coverage();
    FloatImage const depth = renderer_->readAttachment(Attachment::Depth);  // rows top to bottom
    FloatImage const position = renderer_->readAttachment(Attachment::Position);
    glm::mat4 const proj = camera_.projection(float(kW) / kH), view = camera_.view(), inv = glm::inverse(proj);
    TileGrid const grid = tileGrid(kW, kH);
    int tiles = 0, exact = 0, nonEmpty = 0;
    for (int ty = 0; ty < grid.tilesY; ++ty) {
        for (int tx = 0; tx < grid.tilesX; ++tx) {
            PixelRect const rect = tilePixelRect(grid, kW, kH, tx, ty);
            float minD = 1e30f, maxD = 0.0f;
            for (int y = rect.y0; y < rect.y1; ++y)
                for (int x = rect.x0; x < rect.x1; ++x) {
                    int const row = kH - 1 - y;
                    if (position.at(x, row, 3) == 0.0f) continue;
                    float const d = linearDepth(depth.at(x, row, 0), camera_.nearPlane, camera_.farPlane);
                    minD = std::min(minD, d);
                    maxD = std::max(maxD, d);
                }
            int cpu = 0;
            if (maxD > 0.0f) {
                TileFrustum const fr = tileFrustum(inv, kW, kH, rect);
                for (auto const& l : lights_) {
                    float const r = lightRadius(l).radius;
                    if (r > 0 && sphereTouchesTile(fr, minD, maxD, glm::vec3(view * glm::vec4(l.position, 1.0f)), r))
                        ++cpu;
                }
            }
            int const g = int(gpu[std::size_t(rect.y0) * kW + rect.x0].x);
            ++tiles;
            exact += g == cpu;
            nonEmpty += cpu > 0;
            // Float differences between CPU and GPU may flip a light that grazes a plane.
            EXPECT_LE(std::abs(g - cpu), 1) << "tile " << tx << "," << ty;
        }
    }
    EXPECT_GE(exact, tiles * 98 / 100);
    EXPECT_GT(nonEmpty, tiles / 2);
}

TEST_F(LightModesGlTest, LightsPastTheFirstTiledChunkAreShaded) {
    // 16,384 dark lights (intensity 0: radius 0) fill tiled's first chunk of the shared mask, so
    // the scene's real lights are all in the second: a mode that drops lights past 16,384 shows
    // ambient alone. Every mode must still equal quad.
    std::vector<PointLight> many(16384, lights_.front());
    for (auto& l : many) l.intensity = 0.0f;
    many.insert(many.end(), lights_.begin(), lights_.end());
    ASSERT_LE(int(many.size()), kMaxLights);
    // quad and forward visit all 16,416 lights at every pixel: a small frame keeps that short.
    renderer_ = makeRenderer(80, 45);
    ASSERT_FALSE(renderer_->setScene(scene_));
    FloatImage const quad = lighting(lightingSettings(LightingMode::Quad), camera_, many);
    FloatImage const dark = lighting(lightingSettings(LightingMode::Quad), camera_, std::span(many).first(16384));
    ImageDiff const lit = compareRgb(quad, dark, [](double) { return 1e-3; });
    ASSERT_GT(lit.pixelsOver, 80 * 45 / 10) << "the second chunk's lights must light the scene: " << describe(lit);
    ImageDiff const v = compareRgb(lighting(lightingSettings(LightingMode::Volumes), camera_, many), quad, volumeBound);
    EXPECT_EQ(v.pixelsOver, 0) << "volumes: " << describe(v);
    if (!caps().computeShaders) GTEST_SKIP() << caps().tiledUnavailableReason();
    for (LightingMode m : {LightingMode::Tiled, LightingMode::Clustered}) {
        ImageDiff const d = compareRgb(lighting(lightingSettings(m), camera_, many), quad, sameSumBound);
        EXPECT_EQ(d.pixelsOver, 0) << enumName(kLightingModeNames, m) << ": " << describe(d);
    }
}

TEST_F(LightModesGlTest, TiledFallsBackToQuadWithoutComputeShaders) {
    Renderer r(detectGlCaps(3, 3), kW, kH);  // pretend the context is OpenGL 3.3
    ASSERT_FALSE(r.caps().computeShaders);
    ASSERT_FALSE(r.setScene(scene_));
    FrameStats const st = r.render({camera_, lights_, lightingSettings(LightingMode::Tiled), true});
    EXPECT_EQ(st.modeUsed, LightingMode::Quad);
    EXPECT_NE(st.fallbackReason.find("OpenGL 4.3"), std::string::npos) << st.fallbackReason;
    FloatImage const img = r.readAttachment(Attachment::Lighting);
    FloatImage const quad = lighting(lightingSettings(LightingMode::Quad));
    ImageDiff const d = compareRgb(img, quad, [](double) { return 0.0; });
    EXPECT_EQ(d.pixelsOver, 0) << describe(d);
    // The other modes report no fallback.
    FrameStats const ok = renderer_->render({camera_, lights_, lightingSettings(LightingMode::Volumes), true});
    EXPECT_EQ(ok.modeUsed, LightingMode::Volumes);
    EXPECT_TRUE(ok.fallbackReason.empty());
}

TEST_F(LightModesGlTest, WireframesAreDrawnInTheLightColourAndHiddenByTheScene) {
    auto r = makeRenderer(kW, kH);
    ASSERT_FALSE(r->setScene(test::floorAndWallScene()));
    Camera cam;
    cam.position = {0.0f, 2.0f, 12.0f};
    cam.lookAt({0.0f, 2.0f, 0.0f});
    PointLight red;
    red.color = {1.0f, 0.0f, 0.0f};  // Kl 0.7, Kq 1.8: radius 5.09, enclosing sphere 5.24
    PipelineSettings s = lightingSettings(LightingMode::Volumes);
    auto litWithoutWires = [&](glm::vec3 lightPos) {
        red.position = lightPos;
        PipelineSettings plain = s;
        plain.volumeWireframes = false;
        r->render({cam, std::span<PointLight const>(&red, 1), plain, true});
        return r->readAttachment(Attachment::Lighting).pixels;
    };
    // A line's display colour: the light's colour times the wire intensity (2), tonemapped as the
    // lit image is (exposure tonemap, exposure 1): pow(1 - exp(-2), 1/2.2) = 0.936 in red.
    float const lineRed = std::pow(1.0f - std::exp(-2.0f), 1.0f / 2.2f);
    auto frame = [&](glm::vec3 lightPos, bool wires) {
        red.position = lightPos;
        s.volumeWireframes = wires;
        r->render({cam, std::span<PointLight const>(&red, 1), s, true});
        FloatImage const lit = r->readAttachment(Attachment::Lighting);
        FloatImage const shown = r->readAttachment(Attachment::Final);
        // The wireframes are an overlay on the display image (the lit image stays the light sum).
        EXPECT_EQ(lit.pixels, litWithoutWires(lightPos));
        return shown;
    };
    // Pixels the wireframe changed, inside and outside the wall's screen rectangle.
    auto changed = [&](glm::vec3 lightPos, int& onWall, int& elsewhere, int& redder) {
        FloatImage const a = frame(lightPos, false), b = frame(lightPos, true);
        glm::mat4 const vp = cam.projection(float(kW) / kH) * cam.view();
        auto toPx = [&](glm::vec3 p) {
            glm::vec4 c = vp * glm::vec4(p, 1.0f);
            return glm::vec2((c.x / c.w * 0.5f + 0.5f) * kW, (0.5f - c.y / c.w * 0.5f) * kH);
        };
        glm::vec2 const lo = toPx({-3.0f, 4.0f, 0.0f}), hi = toPx({3.0f, 0.0f, 0.0f});  // wall corners
        onWall = elsewhere = redder = 0;
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x) {
                bool diff = false;
                for (int c = 0; c < 3; ++c) diff = diff || a.at(x, y, c) != b.at(x, y, c);
                if (!diff) continue;
                bool const wall = x > lo.x + 1 && x < hi.x - 1 && y > lo.y + 1 && y < hi.y - 1;
                (wall ? onWall : elsewhere)++;
                // Lines replace the pixel with the light's tonemapped colour (RGBA8: within one step,
                // and one more for GPU exp/pow against the CPU's).
                redder += std::abs(b.at(x, y, 0) - lineRed) <= 2.0f / 255.0f && b.at(x, y, 1) == 0.0f &&
                          b.at(x, y, 2) == 0.0f;
            }
    };
    int onWall = 0, elsewhere = 0, redder = 0;
    changed({0.0f, 2.0f, -6.0f}, onWall, elsewhere, redder);  // behind the wall: z from -11.2 to -0.8
    EXPECT_EQ(onWall, 0) << "wires behind the wall must be hidden by it";
    EXPECT_GT(elsewhere, 50) << "the parts of the sphere around the wall must show";
    EXPECT_EQ(redder, onWall + elsewhere) << "wires are drawn in the light's colour (red)";
    changed({0.0f, 2.0f, 3.0f}, onWall, elsewhere, redder);  // in front of the wall, camera outside
    EXPECT_GT(onWall, 20) << "wires in front of the wall are visible over it";
}

// The two builds of the light loops (GlCaps::masksBranches, shaders/light_accumulation.glsl): where
// branches skip work, lights out of reach and padding entries past a tile's list are skipped; where
// they are masked, they are shaded with a zero factor. Both add the same lights, so every mode's
// image agrees within one fp16 rounding (the compiler may fuse the sums differently), and the
// coverage views count the same lights, exactly. Whichever build this machine picks, the other is
// forced here, so both are run on every machine.
TEST_F(LightModesGlTest, LightLoopsWithAndWithoutBranchSkippingAgree) {
    GlCaps flipped = caps();
    flipped.masksBranches = !caps().masksBranches;
    Renderer other(flipped, kW, kH);
    ASSERT_FALSE(other.setScene(scene_));
    std::vector<LightingMode> modes = {LightingMode::Quad, LightingMode::Volumes, LightingMode::Forward};
    if (caps().computeShaders) modes.insert(modes.end(), {LightingMode::Tiled, LightingMode::Clustered});
    for (Camera const& cam : {camera_, insideCamera()}) {
        for (LightingMode m : modes) {
            std::string_view const name = enumName(kLightingModeNames, m);
            PipelineSettings s = lightingSettings(m);
            FrameStats const st = other.render({cam, lights_, s, true});
            EXPECT_EQ(st.modeUsed, m) << st.fallbackReason;
            FloatImage const forced = other.readAttachment(Attachment::Lighting);
            ImageDiff const d =
                compareRgb(forced, lighting(s, cam, lights_), [](double v) { return kHalfUlp * v + 1e-6; });
            EXPECT_EQ(d.pixelsOver, 0) << name << ": " << describe(d);
            EXPECT_GT(d.meanValue, 0.0) << name << ": an unlit image proves nothing";
            if (m != LightingMode::Tiled && m != LightingMode::Clustered) continue;
            s.view = DebugView::Heatmap;
            other.render({cam, lights_, s, true});
            renderer_->render({cam, lights_, s, true});
            FloatImage const a = other.readAttachment(Attachment::Coverage);
            FloatImage const b = renderer_->readAttachment(Attachment::Coverage);
            ASSERT_EQ(a.pixels.size(), b.pixels.size());
            int differing = 0;
            double lit = 0.0;
            for (std::size_t i = 0; i < a.pixels.size(); ++i) {
                differing += a.pixels[i] != b.pixels[i];
                lit += i % 2 == 1 ? b.pixels[i] : 0.0;
            }
            EXPECT_EQ(differing, 0) << name << ": lights counted per pixel";
            EXPECT_GT(lit, 0.0) << name << ": no pixel counted a light";
        }
    }
}
