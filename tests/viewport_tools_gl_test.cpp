// The viewer tools' service on real frames: the depth viewer's stencil picture (the integers the
// stencil holds, coloured on the CPU) and the pixel sample's stencil, and the viewport's tools
// drawing an attachment with their own range and fitting it.
#include "editor/viewer_tools_service.h"
#include "gl_fixture.h"
#include "model/attachment_overview.h"
#include "model/colormap.h"
#include "scene/default_scene.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

using namespace gbl;
using gbl::test::GlTest;

namespace {

constexpr int kW = 64, kH = 40;

class ViewportToolsGlTest : public GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        scene_ = makeDefaultScene();
        state_.camera.position = {0.0f, 11.5f, 10.0f};
        state_.camera.lookAt({0.0f, 0.0f, -2.0f});
        renderer_ = makeRenderer(kW, kH);
        ASSERT_FALSE(renderer_->setScene(scene_));
    }
    void TearDown() override {
        gpu_ = ui::ViewerToolsGpu{};
        renderer_.reset();
        GlTest::TearDown();
    }
    void render() {
        FrameStats const st = renderer_->render({state_.camera, scene_.lights, state_.pipeline, true});
        EXPECT_EQ(st.glErrors, 0u);
    }
    // Writes value into the stencil of image rows [y0, y1) (top-left origin), all columns.
    void writeStencilRows(int y0, int y1, int value) {
        GLuint fbo = 0;
        glGenFramebuffers(1, &fbo);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D,
                               renderer_->texture(Attachment::Stencil), 0);
        glDrawBuffer(GL_NONE);
        glReadBuffer(GL_NONE);
        ASSERT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
        glEnable(GL_SCISSOR_TEST);
        glScissor(0, kH - y1, kW, y1 - y0);  // GL rows run bottom to top
        glStencilMask(0xFF);
        glClearStencil(value);
        glClear(GL_STENCIL_BUFFER_BIT);
        glClearStencil(0);
        glDisable(GL_SCISSOR_TEST);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glDeleteFramebuffers(1, &fbo);
    }
    // RGBA8 texel (x, y), top-left origin, of a texture the viewers draw with v flipped.
    std::array<int, 4> texel(unsigned texture, int x, int y) {
        std::vector<std::uint8_t> rgba(std::size_t(kW) * kH * 4);
        glBindTexture(GL_TEXTURE_2D, texture);
        glPixelStorei(GL_PACK_ALIGNMENT, 4);
        glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
        glBindTexture(GL_TEXTURE_2D, 0);
        std::size_t const i = (std::size_t(kH - 1 - y) * kW + std::size_t(x)) * 4;
        return {rgba[i], rgba[i + 1], rgba[i + 2], rgba[i + 3]};
    }
    // The red bytes of a texture the views draw (v flipped), top-left origin, row by row.
    std::vector<int> reds(unsigned texture) {
        std::vector<std::uint8_t> rgba(std::size_t(kW) * kH * 4);
        glBindTexture(GL_TEXTURE_2D, texture);
        glPixelStorei(GL_PACK_ALIGNMENT, 4);
        glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
        glBindTexture(GL_TEXTURE_2D, 0);
        std::vector<int> out;
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x) out.push_back(rgba[(std::size_t(kH - 1 - y) * kW + std::size_t(x)) * 4]);
        return out;
    }
    // How the drawn pixels (alpha of the position attachment) of a grey view spread: the share at
    // 255, and the distance between the 10th and the 90th percentile of their bytes.
    struct Spread {
        float white = 0.0f;
        int p10to90 = 0;
    };
    Spread spread(unsigned texture) {
        FloatImage const drawn = renderer_->readAttachment(Attachment::Position);
        std::vector<int> const all = reds(texture);
        std::vector<int> bytes;
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x)
                if (drawn.at(x, y, 3) != 0.0f) bytes.push_back(all[std::size_t(y) * kW + std::size_t(x)]);
        if (bytes.empty()) return {};
        std::sort(bytes.begin(), bytes.end());
        Spread s;
        s.white = float(std::count(bytes.begin(), bytes.end(), 255)) / float(bytes.size());
        s.p10to90 = bytes[bytes.size() * 9 / 10] - bytes[bytes.size() / 10];
        return s;
    }

    SceneData scene_;
    ui::EditorState state_;
    std::unique_ptr<Renderer> renderer_;
    ui::ViewerToolsGpu gpu_;
};

TEST_F(ViewportToolsGlTest, DepthViewerShowsTheStencilIntegers) {
    state_.pipeline.mode = LightingMode::Volumes;
    state_.pipeline.cull = CullMode::Stencil;
    render();
    writeStencilRows(0, 10, 51);
    writeStencilRows(10, 20, 255);  // rows 20.. keep the 0 the frame left
    ui::ViewerState& depth = state_.gbuffer.viewers[4];
    ui::setShowStencil(depth, true);                  // range 0..255, grey
    std::array<unsigned, 5> textures{1, 2, 3, 4, 5};  // "the view passes' textures"
    ui::serviceViewerTools(state_, *renderer_, 1, textures, gpu_);
    ui::ViewerData const& d = state_.gbuffer.data[4];
    ASSERT_EQ(d.frame, 1);
    EXPECT_EQ(d.values.at(3, 5, 0), 51.0f);
    EXPECT_EQ(d.values.at(3, 15, 0), 255.0f);
    EXPECT_EQ(d.values.at(3, 30, 0), 0.0f);
    EXPECT_EQ(d.stats.shown.max, 255.0f);
    EXPECT_EQ(d.stats.pixels, long(kW) * kH);  // no background in a stencil
    // The depth viewer's texture is the stencil picture now; the others are untouched.
    ASSERT_EQ(textures[4], gpu_.picture[4].id());
    EXPECT_EQ(textures[0], 1u);
    // Grey over 0..255: each byte is the stored integer.
    EXPECT_EQ(texel(textures[4], 3, 5), (std::array<int, 4>{51, 51, 51, 255}));
    EXPECT_EQ(texel(textures[4], 3, 15), (std::array<int, 4>{255, 255, 255, 255}));
    EXPECT_EQ(texel(textures[4], 3, 30), (std::array<int, 4>{0, 0, 0, 255}));
    // A colormap change recolours at once, from the same read-back.
    depth.colormap = Colormap::Turbo;
    ui::serviceViewerTools(state_, *renderer_, 2, textures, gpu_);
    EXPECT_EQ(d.frame, 1);
    glm::vec3 const t = ui::colormap(Colormap::Turbo, 51.0f / 255.0f);
    EXPECT_EQ(texel(textures[4], 3, 5)[0], int(std::lround(t.r * 255.0f)));
    EXPECT_EQ(texel(textures[4], 3, 5)[1], int(std::lround(t.g * 255.0f)));
    // The pixel inspector's sample reads the same integer.
    EXPECT_EQ(renderer_->samplePixel(3, 5, state_.camera).stencil, 51u);
    EXPECT_EQ(renderer_->samplePixel(3, 30, state_.camera).stencil, 0u);
}

TEST_F(ViewportToolsGlTest, ViewportToolsDrawTheAttachmentWithTheirRange) {
    state_.pipeline.view = DebugView::DepthLinear;
    render();
    FrameInput const frame{state_.camera, scene_.lights, state_.pipeline, true};
    // Tools closed (they open with the editor): the viewport shows the renderer's own image.
    state_.viewportTools.open = false;
    EXPECT_EQ(ui::serviceViewportTools(state_, *renderer_, frame, 1, true, gpu_), 0u);
    state_.viewportTools.open = true;
    state_.pipeline.view = DebugView::Final;
    EXPECT_EQ(ui::serviceViewportTools(state_, *renderer_, frame, 1, true, gpu_), 0u);  // not an attachment
    state_.pipeline.view = DebugView::DepthLinear;
    unsigned const tex = ui::serviceViewportTools(state_, *renderer_, frame, 2, true, gpu_);
    ASSERT_NE(tex, 0u);
    EXPECT_EQ(tex, gpu_.viewport.texture.id());
    ui::ViewerState const& v = state_.viewportTools.viewer;
    EXPECT_EQ(v.kind, ui::ViewerKind::Depth);
    // Auto-fit (on by default) fitted the eye depths of the drawn pixels: in front of the near
    // plane, within the far plane, and not an empty range.
    EXPECT_GE(v.rangeMin, state_.camera.nearPlane);
    EXPECT_LE(v.rangeMax, state_.camera.farPlane);
    EXPECT_GT(v.rangeMax, v.rangeMin);
    EXPECT_EQ(v.lastFitFrame, 2);
    // The view drawn is that range: the nearest drawn pixel is black, the farthest white (grey map).
    ui::ViewerData const& d = state_.viewportTools.data;
    ASSERT_EQ(d.values.width, kW);
    int darkest = 255, brightest = 0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            if (d.values.at(x, y, 3) == 0.0f) continue;  // background
            int const g = texel(tex, x, y)[0];
            darkest = std::min(darkest, g);
            brightest = std::max(brightest, g);
        }
    EXPECT_LE(darkest, 1);
    EXPECT_GE(brightest, 254);
    // Overlays and histogram read the values; the clipping overlay with a narrowed range marks red.
    state_.viewportTools.viewer.autoFit = false;
    state_.viewportTools.viewer.rangeMax = state_.viewportTools.viewer.rangeMin + 1e-3f;
    state_.viewportTools.viewer.overlays = kOverlayClip;
    unsigned const clipped = ui::serviceViewportTools(state_, *renderer_, frame, 3, false, gpu_);
    EXPECT_EQ(clipped, tex);
    int red = 0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x)
            if (texel(clipped, x, y) == std::array<int, 4>{255, 0, 0, 255}) ++red;
    EXPECT_GT(red, kW * kH / 4);  // most of the drawn frame is beyond the narrowed white point
}

TEST_F(ViewportToolsGlTest, LightingViewToolsWorkOnTheHdrValues) {
    state_.pipeline.view = DebugView::Lighting;
    state_.pipeline.exposure = 4.0f;  // the tonemap's exposure must not reach the tools' values
    render();
    FrameInput const frame{state_.camera, scene_.lights, state_.pipeline, true};
    state_.viewportTools.open = true;
    state_.viewportTools.viewer.showHistogram = true;
    unsigned const autoTex = ui::serviceViewportTools(state_, *renderer_, frame, 1, true, gpu_);
    ASSERT_NE(autoTex, 0u);
    // The lit frame's own auto-fit stops at the 99th percentile, below the brightest highlights, so
    // lit surfaces are not left almost black.
    float const autoMax = state_.viewportTools.viewer.rangeMax;
    // Fit takes the whole range.
    state_.viewportTools.viewer.fitRequested = true;
    unsigned const tex = ui::serviceViewportTools(state_, *renderer_, frame, 2, false, gpu_);
    ASSERT_EQ(tex, autoTex);
    ui::ViewerState const& v = state_.viewportTools.viewer;
    ui::ViewerData const& d = state_.viewportTools.data;
    EXPECT_EQ(v.kind, ui::ViewerKind::Lighting);
    // The tools' values are the lit attachment as stored (HDR, before exposure and tonemap).
    FloatImage const lit = renderer_->readAttachment(Attachment::Lighting);
    ASSERT_EQ(d.values.width, kW);
    ASSERT_EQ(d.values.pixels, lit.pixels);
    float lo = INFINITY, hi = -INFINITY;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x)
            for (int c = 0; c < 3; ++c) {
                lo = std::min(lo, lit.at(x, y, c));
                hi = std::max(hi, lit.at(x, y, c));
            }
    ASSERT_GT(hi, lo);
    EXPECT_LT(autoMax, hi);
    EXPECT_GT(autoMax, lo);
    // Fit took the RGB min and max of every pixel (the lit frame has no background mask).
    EXPECT_EQ(v.rangeMin, lo);
    EXPECT_EQ(v.rangeMax, hi);
    EXPECT_EQ(d.stats.shown.min, lo);
    EXPECT_EQ(d.stats.shown.max, hi);
    EXPECT_EQ(d.stats.pixels, long(kW) * kH);
    // The drawn picture is each channel remapped over that range: within one 8-bit step of
    // (value - min) / (max - min), the rounding of the RGBA8 target.
    int worst = 0;
    for (int y = 0; y < kH; y += 3)
        for (int x = 0; x < kW; x += 3)
            for (int c = 0; c < 3; ++c) {
                float const t = (lit.at(x, y, c) - lo) / (hi - lo);
                worst = std::max(worst, std::abs(texel(tex, x, y)[std::size_t(c)] - int(std::lround(t * 255.0f))));
            }
    EXPECT_LE(worst, 1);
}

// Issue 26: the viewport's depth views opened all white (eye distances in world units written to
// an 8-bit target over 0..1) and positions as saturated blocks. By default, with the tools as the
// editor opens them, each is fitted to its data and spreads over the grey scale.
TEST_F(ViewportToolsGlTest, DefaultViewsOfTheDefaultSceneAreNotSaturated) {
    long frame = 0;
    for (DebugView const view : {DebugView::DepthLinear, DebugView::Depth, DebugView::Position}) {
        SCOPED_TRACE(kDebugViewNames[std::size_t(view)].data());
        state_.pipeline.view = view;
        render();
        FrameInput const input{state_.camera, scene_.lights, state_.pipeline, true};
        // The raw values (what the renderer's own image shows, the tools closed): the depths and
        // most positions are past 1, so the picture saturates. This is what the default avoids.
        Spread const raw = spread(renderer_->texture(Attachment::Final));
        if (view == DebugView::DepthLinear) {
            EXPECT_GT(raw.white, 0.95f);
        }
        ++frame;
        state_.viewportTools = ui::ViewportTools{};
        // Depth is one channel (grey); of the position, x alone is read (the fit spans x, y and z).
        if (view == DebugView::Position) state_.viewportTools.viewer.channelMask = 0x1;
        unsigned const tex = ui::serviceViewportTools(state_, *renderer_, input, frame, true, gpu_);
        ASSERT_NE(tex, 0u);
        Spread const shown = spread(tex);
        // The 1-99 % fit leaves about 1 % of the drawn pixels at white (nearest rank and ties on
        // an 8-bit picture: allow 5 %), where the raw view had nearly all of them.
        EXPECT_LT(shown.white, 0.05f);
        // The middle 80 % of the drawn pixels spans at least a quarter of the grey scale: a picture,
        // not a flat block (the default scene's depths and x span the frame from near to far).
        EXPECT_GE(shown.p10to90, 64);
    }
}

// A lesson going from raw depth to linear depth (or to another far plane) shows the same viewer
// kind with values of another scale: auto-fit refits at once, not at its next turn a second later,
// when render-on-change may draw no new frame for a long time.
TEST_F(ViewportToolsGlTest, AutoFitRefitsWhenDepthTurnsLinearOrTheFarPlaneMoves) {
    state_.pipeline.view = DebugView::Depth;
    render();
    FrameInput input{state_.camera, scene_.lights, state_.pipeline, true};
    ASSERT_NE(ui::serviceViewportTools(state_, *renderer_, input, 1, true, gpu_), 0u);
    ui::ViewerState const& v = state_.viewportTools.viewer;
    EXPECT_LE(v.rangeMax, 1.0f);  // window depths
    // The view changes, the frame does not (the depth attachment holds the same values).
    state_.pipeline.view = DebugView::DepthLinear;
    ASSERT_NE(ui::serviceViewportTools(state_, *renderer_, input, 2, false, gpu_), 0u);
    EXPECT_EQ(v.lastFitFrame, 2);
    EXPECT_GT(v.rangeMax, 1.0f);  // eye distances of the scene, metres away
    EXPECT_GE(v.rangeMin, state_.camera.nearPlane);
    float const max200 = v.rangeMax;
    // A far plane of 5000 rendered on the next frame: the fit is redone for it at once.
    state_.camera.farPlane = 5000.0f;
    render();
    input.camera = state_.camera;
    ASSERT_NE(ui::serviceViewportTools(state_, *renderer_, input, 3, true, gpu_), 0u);
    EXPECT_EQ(v.lastFitFrame, 3);
    // The same surfaces at the same distances, rebuilt through another projection: close, not equal.
    EXPECT_NEAR(v.rangeMax, max200, max200 * 0.05f);
}

// The overview's cells: each view drawn into its own texture, the attachments with their readable
// range, none of them a flat picture.
TEST_F(ViewportToolsGlTest, OverviewDrawsEveryCellWithItsReadableRange) {
    render();
    FrameInput const input{state_.camera, scene_.lights, state_.pipeline, true};
    EXPECT_TRUE(ui::serviceOverview(state_, *renderer_, input, 1, true, gpu_).empty());  // off
    state_.viewport.overview.on = true;
    std::vector<unsigned> const textures = ui::serviceOverview(state_, *renderer_, input, 2, true, gpu_);
    std::vector<DebugView> const views = ui::overviewViews();
    ASSERT_EQ(textures.size(), views.size());
    std::set<unsigned> const distinct(textures.begin(), textures.end());
    EXPECT_EQ(distinct.size(), textures.size());
    for (std::size_t i = 0; i < views.size(); ++i) {
        SCOPED_TRACE(kDebugViewNames[std::size_t(views[i])].data());
        ASSERT_NE(textures[i], 0u);
        std::vector<int> const r = reds(textures[i]);
        auto const [lo, hi] = std::minmax_element(r.begin(), r.end());
        EXPECT_GE(*hi - *lo, 64);  // a picture over a good part of the scale, not one colour
        ui::ViewportTools const& cell = state_.viewport.overview.viewers[i];
        if (views[i] == DebugView::Position || views[i] == DebugView::DepthLinear) {
            // Fitted as the viewport's tools fit by default: the readable range of the cell's values.
            ui::ValueRange const expected = ui::readableRange(cell.viewer, cell.data.values);
            EXPECT_EQ(cell.viewer.rangeMin, expected.min);
            EXPECT_EQ(cell.viewer.rangeMax, expected.max);
            EXPECT_EQ(cell.viewer.lastFitFrame, 2);
        }
    }
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
