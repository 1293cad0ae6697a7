// Rendering a lesson step headlessly and checking its claim on the read-back images: what
// `render --lesson` runs and what the GL test of every shipped lesson asserts.
#pragma once

#include "model/lesson_claims.h"
#include "renderer.h"
#include "session/lesson_file.h"

#include <optional>

namespace gbl {

struct LessonStepFrame {
    FrameStats stats;                      // of the step's own frame (the renderer's last frame)
    glm::ivec2 pixel{0};                   // the step's pixel in renderer pixels (top-left origin)
    std::optional<ui::ClaimResult> claim;  // when the step has one
};

// Renders the step (after its claim's reference frame, so the step is the frame the renderer
// keeps for exportFrame). The renderer must already hold the lesson's scene; its size is used.
LessonStepFrame renderLessonStep(Renderer& renderer, ui::LessonStep const& step);

}  // namespace gbl
