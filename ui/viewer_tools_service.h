// The editor loop's side of the viewer tools: reads back the attachments the open tools need,
// services the viewers' fit/pin requests and uploads the diff heat maps.
#pragma once

#include "gl/texture.h"
#include "model/editor_state.h"
#include "renderer.h"

#include <array>

namespace gbl::ui {

// One heat-map texture per viewer, made on first use.
struct ViewerToolsGpu {
    std::array<gl::Texture, 5> diff;
    gl::Texture litDiff;  // the viewport's lit-frame diff
};

// Uploads a diff's heat map into tex, (re)making it at the diff's size; a new texture is always
// filled, an existing one when `changed`. Scale: the threshold when one is set, else the max.
void uploadDiff(gl::Texture& tex, DiffStats const& diff, float threshold, bool changed);

// Call after the viewers' views are drawn; replaces textures[i] with the diff heat map where a
// viewer shows its difference to the pinned image.
void serviceViewerTools(EditorState& state, Renderer& renderer, long frame, std::array<unsigned, 5>& textures,
                        ViewerToolsGpu& gpu);
// The same for the viewport's lit frame: returns the heat map to show instead of the frame while
// the lit diff is on, else 0.
unsigned serviceLitPin(LitPin& pin, Renderer& renderer, long frame, ViewerToolsGpu& gpu);

}  // namespace gbl::ui
