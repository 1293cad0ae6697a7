// apply(DrawState): the description turned into GL state.
#include "gpu/draw_state_gl.h"

#include <stdexcept>
#include <string>

namespace gbl {

namespace {

void enable(GLenum cap, bool on) {
    if (on)
        glEnable(cap);
    else
        glDisable(cap);
}

GLenum depthFunc(DepthTest t) {
    switch (t) {
        case DepthTest::LessEqual:
            return GL_LEQUAL;
        case DepthTest::GreaterEqual:
            return GL_GEQUAL;
        case DepthTest::Always:
            return GL_ALWAYS;
        case DepthTest::Off:
        case DepthTest::Less:
            break;
    }
    return GL_LESS;
}

}  // namespace

void apply(DrawState const& s) {
    enable(GL_DEPTH_TEST, s.depthTest != DepthTest::Off);
    glDepthFunc(depthFunc(s.depthTest));
    glDepthMask(s.depthWrite ? GL_TRUE : GL_FALSE);

    enable(GL_BLEND, s.blend != Blend::Off);
    glBlendEquation(GL_FUNC_ADD);
    if (s.blend == Blend::Alpha)
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    else
        glBlendFunc(GL_ONE, GL_ONE);  // Add (and the harmless value when off)

    enable(GL_CULL_FACE, s.cull != FaceCull::Off);
    glCullFace(s.cull == FaceCull::Front ? GL_FRONT : GL_BACK);

    // msaa edges: the complex bit tested beside the group's own use, whose marks then keep to the
    // seven bits below it (core/frame_passes.h, MsaaPixels). Without it every bit is the use's own.
    GLuint const pixelMask = s.pixels == MsaaPixels::All ? 0u : GLuint(kComplexStencilBit);
    GLint const pixelRef = s.pixels == MsaaPixels::Complex ? kComplexStencilBit : 0;
    GLuint const marks = pixelMask ? GLuint(0xFF) & ~pixelMask : 0xFFu;
    enable(GL_STENCIL_TEST, s.stencil != StencilUse::Off || pixelMask != 0);
    glStencilMask(marks);
    switch (s.stencil) {
        case StencilUse::Mark:  // only depth failures count: back faces +1, front faces -1
            glStencilFunc(pixelMask ? GL_EQUAL : GL_ALWAYS, pixelRef, pixelMask ? pixelMask : 0xFFu);
            glStencilOpSeparate(GL_BACK, GL_KEEP, GL_INCR_WRAP, GL_KEEP);
            glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_DECR_WRAP, GL_KEEP);
            break;
        case StencilUse::ShadeMarked:  // a mark of exactly 1 passes, and every visit resets it
            glStencilFunc(GL_EQUAL, 1 | pixelRef, 0xFF);
            glStencilOp(GL_ZERO, GL_ZERO, GL_ZERO);
            break;
        case StencilUse::EqualBits:  // the read-back's bit planes (renderer_readback.cpp)
            glStencilFunc(GL_EQUAL, s.stencilRef, GLuint(s.stencilRef));
            glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
            break;
        case StencilUse::MarkComplex:  // every fragment drawn (a complex pixel) sets the complex bit
            glStencilMask(GLuint(kComplexStencilBit));
            glStencilFunc(GL_ALWAYS, kComplexStencilBit, 0xFF);
            glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
            break;
        case StencilUse::MarkCovered:  // every fragment drawn (a light cube) marks 1
            glStencilFunc(GL_ALWAYS, 1, 0xFF);
            glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
            break;
        case StencilUse::Covered:  // the blended surfaces again where a cube marked its pixel
            glStencilFunc(GL_EQUAL, 1, 0xFF);
            glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
            break;
        case StencilUse::Off:  // the complex bit alone (and no writes, so the test may run early), or nothing
            if (pixelMask) glStencilMask(0);
            glStencilFunc(pixelMask ? GL_EQUAL : GL_ALWAYS, pixelRef, pixelMask ? pixelMask : 0xFFu);
            glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
            break;
    }
    GLboolean const c = s.colorWrite ? GL_TRUE : GL_FALSE;
    glColorMask(c, c, c, c);
}

void applyGroup(std::span<DrawState const> states, std::size_t i) {
    if (i >= states.size())
        throw std::logic_error("applyGroup(): the pass draws group " + std::to_string(i) + " but declares " +
                               std::to_string(states.size()) + "; add it to the pass's PassDecl::states");
    apply(states[i]);
}

void clearFramebuffer(GLuint fbo, GLbitfield bits) {
    apply(kWriteAll);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glClearColor(0, 0, 0, 0);
    glClearDepth(1.0);
    glClearStencil(0);
    glClear(bits);
}

}  // namespace gbl
