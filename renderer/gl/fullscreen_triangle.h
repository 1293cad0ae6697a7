// The one full-screen draw: a triangle covering the viewport, positions made from gl_VertexID in
// shaders/fullscreen.vert. Core profile needs a bound vertex array even without attributes.
#pragma once

#include "gl/draw_count.h"
#include "gl/vertex_array.h"

namespace gbl::gl {

class FullscreenTriangle {
public:
    FullscreenTriangle() = default;
    static FullscreenTriangle create() {
        FullscreenTriangle t;
        t.vao_ = VertexArray::create("fullscreen");
        return t;
    }
    // Draws with the program in use into the bound framebuffer.
    void draw() const {
        glBindVertexArray(vao_.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        countDraw(1);
        glBindVertexArray(0);
    }

private:
    VertexArray vao_;
};

}  // namespace gbl::gl
