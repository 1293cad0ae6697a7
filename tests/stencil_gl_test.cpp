// The stencil attachment read back through Renderer::readAttachment: known written values, and
// what a stencil-cull volumes frame leaves behind (its shade step resets every mark to 0).
#include "gl_fixture.h"
#include "scene/default_scene.h"

#include <epoxy/gl.h>

using namespace gbl;
using gbl::test::GlTest;

namespace {

constexpr int kW = 64, kH = 40;

class StencilGlTest : public test::CourtyardGlTest {
protected:
    StencilGlTest() : CourtyardGlTest(kW, kH) {}
    void renderVolumesStencil() {
        PipelineSettings s;
        s.mode = LightingMode::Volumes;
        s.cull = CullMode::Stencil;
        FrameStats const st = renderer_->render({camera_, scene_.lights, s, true});
        EXPECT_EQ(st.modeUsed, LightingMode::Volumes) << st.fallbackReason;
        EXPECT_EQ(st.glErrors, 0u);
    }
    // Writes value into the stencil of the image-space rectangle [x0, x1) x [y0, y1) (rows top to
    // bottom, as readAttachment returns them), through a framebuffer of our own on the same texture.
    void writeStencil(int x0, int y0, int x1, int y1, int value) {
        GLuint fbo = 0;
        glGenFramebuffers(1, &fbo);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D,
                               renderer_->texture(Attachment::Stencil), 0);
        glDrawBuffer(GL_NONE);
        glReadBuffer(GL_NONE);
        ASSERT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
        glViewport(0, 0, kW, kH);
        glEnable(GL_SCISSOR_TEST);
        glScissor(x0, kH - y1, x1 - x0, y1 - y0);  // GL rows run bottom to top
        glStencilMask(0xFF);
        glClearStencil(value);
        glClear(GL_STENCIL_BUFFER_BIT);
        glClearStencil(0);
        glDisable(GL_SCISSOR_TEST);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glDeleteFramebuffers(1, &fbo);
    }
};

TEST_F(StencilGlTest, ReadsTheWrittenIntegersTopRowFirst) {
    renderVolumesStencil();
    writeStencil(0, 0, kW, kH, 3);
    writeStencil(4, 2, 10, 7, 7);       // top-left block
    writeStencil(50, 30, 64, 40, 255);  // bottom-right corner block
    FloatImage const img = renderer_->readAttachment(Attachment::Stencil);
    ASSERT_EQ(img.width, kW);
    ASSERT_EQ(img.height, kH);
    ASSERT_EQ(img.channels, 1);
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            float expected = 3.0f;
            if (x >= 4 && x < 10 && y >= 2 && y < 7) expected = 7.0f;
            if (x >= 50 && y >= 30) expected = 255.0f;
            ASSERT_EQ(img.at(x, y, 0), expected) << x << ", " << y;
        }
}

TEST_F(StencilGlTest, AStencilCullFrameClearsItAndLeavesNoMarks) {
    renderVolumesStencil();
    writeStencil(0, 0, kW, kH, 9);
    ASSERT_EQ(renderer_->readAttachment(Attachment::Stencil).at(kW / 2, kH / 2, 0), 9.0f);
    // The geometry pass clears the stencil to 0; per light the mark step counts depth failures
    // and the shade step zeroes every pixel of the same footprint, so the frame ends with none.
    renderVolumesStencil();
    FloatImage const img = renderer_->readAttachment(Attachment::Stencil);
    ASSERT_EQ(img.width, kW);
    int nonZero = 0;
    for (float v : img.pixels) nonZero += v != 0.0f;
    EXPECT_EQ(nonZero, 0);
    // The depth beside it is the scene's: some pixels were drawn, so the stencil read is not the
    // only thing that could come back as zeros.
    FloatImage const depth = renderer_->readAttachment(Attachment::Depth);
    int drawn = 0;
    for (float v : depth.pixels) drawn += v < 1.0f;
    EXPECT_GT(drawn, 0);
}

}  // namespace
