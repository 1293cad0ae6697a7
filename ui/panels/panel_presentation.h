// The presentation layout (issue 46, a class in front of a projector): the frame the viewport shows
// (the lit frame or one attachment, switched with V, M, C and B as in the docked layout) as large
// as the window allows under a one-line caption, with the open lesson's window beside it.
#pragma once

#include "core/pipeline_settings.h"
#include "model/layout_state.h"
#include "model/viewport_state.h"

namespace gbl::ui {

// The share of the work area's width the lesson keeps beside the image while a lesson is open.
inline constexpr float kPresentationLessonShare = 0.32f;

// Draws the presentation window over the main viewport's work area (left of the lesson when
// `lessonOpen`): the caption, then `texture` filling the rest. Sets viewport.size (the renderer
// draws the frame at that size next frame) and viewport.imageRect, and layout.presentationCaption
// and layout.presentationLesson (where the Lessons window goes; 0 without a lesson).
void drawPresentationWindow(LayoutState& layout, ViewportState& viewport, PipelineSettings const& settings,
                            unsigned texture, bool lessonOpen);

}  // namespace gbl::ui
