// The editor's frame with the teaching views: light-by-light accumulation and the A/B comparison
// (side B rendered first and kept as a texture and a pinned lit frame, then side A as usual).
#pragma once

#include "gl/texture.h"
#include "gpu/view_target.h"
#include "model/editor_state.h"
#include "renderer.h"
#include "viewer_tools_service.h"

namespace gbl::ui {

struct AbGpu {
    ViewTarget b;      // side B's image as the viewport shows it
    gl::Texture diff;  // |A - B| heat map
};

// The frame the editor renders for side A: the pipeline, the scrubber and the wireframe option.
FrameInput editorFrameInput(EditorState const& state, std::span<PointLight const> lights, bool waitForGpuTimings);

// How many light volumes the wireframes of `in` outline: every light, the selected one alone, or
// none (wireframes off, or selected-only with nothing selected). For the frame log.
int outlinedVolumes(FrameInput const& in);

// The part of `a` and the A/B state that RenderInputs does not already hold.
TeachingInputs teachingInputs(FrameInput const& a, AbState const& ab);

// Renders the frame (and, with A/B on, side B before it); returns side A's statistics.
FrameStats renderEditorFrame(EditorState& state, Renderer& renderer, FrameInput const& a, long frame, AbGpu& gpu);

}  // namespace gbl::ui
