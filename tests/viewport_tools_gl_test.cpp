// The viewer tools' service on real frames: the depth viewer's stencil picture (the integers the
// stencil holds, coloured on the CPU) and the pixel sample's stencil, and the viewport's tools
// drawing an attachment with their own range and fitting it.
#include "editor/viewer_tools_service.h"
#include "gl_fixture.h"
#include "model/colormap.h"
#include "scene/default_scene.h"

#include <epoxy/gl.h>

#include <cmath>
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

}  // namespace
