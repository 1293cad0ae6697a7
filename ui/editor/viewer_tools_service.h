// The editor loop's side of the viewer tools: reads back the attachments the open tools need,
// services the viewers' fit/pin requests and uploads the diff heat maps and stencil pictures.
#pragma once

#include "gl/texture.h"
#include "gpu/view_target.h"
#include "import/gbuffer_checks.h"
#include "model/editor_state.h"
#include "model/msaa_views.h"
#include "renderer.h"

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace gbl::ui {

// Textures of the viewer tools, made on first use.
struct ViewerToolsGpu {
    std::array<gl::Texture, 5> diff;
    std::array<gl::Texture, 5> picture;                      // views made on the CPU (the depth viewer's stencil)
    std::array<std::optional<ViewParams>, 5> pictureParams;  // what each picture was coloured with
    std::array<long, 5> pictureFrame{-1, -1, -1, -1, -1};    // ... and from which read-back
    std::array<unsigned, 5> pictureKey{};                    // ... of what (viewerValuesKey: the sample)
    gl::Texture viewportPicture;                             // the viewport tools' one msaa sample
    long viewportPictureFrame = -1;
    unsigned viewportPictureKey = 0;
    std::optional<ViewParams> viewportPictureParams;
    gl::Texture litDiff;  // the viewport's lit-frame diff
    // The marked G-buffer check finding's pixels, and which finding of which G-buffer it holds.
    gl::Texture findingMask;
    std::pair<std::string, int> findingMaskFor{"", -1};
    // The viewport's attachment view with the viewer tools' range, colormap and overlays.
    ViewTarget viewport;
    std::optional<ViewParams> viewportParams;
    gl::Texture viewportDiff;
    // The attachment overview's cells (model/attachment_overview.h), one view target each.
    std::vector<ViewTarget> overview;
    std::vector<std::optional<ViewParams>> overviewParams;
};

// Uploads a diff's heat map into tex, (re)making it at the diff's size; a new texture is always
// filled, an existing one when `changed`. Scale: the threshold when one is set, else the max.
void uploadDiff(gl::Texture& tex, DiffStats const& diff, float threshold, bool changed);
// Uploads RGBA8 rows (top to bottom) of a w x h picture made on the CPU into tex, (re)making it.
void uploadPicture(gl::Texture& tex, int w, int h, std::vector<std::uint8_t> const& rgba, char const* label);
// The open G-buffer's marked check finding (viewport.markedFinding) as a translucent magenta mask
// to lay over the image; 0 when none is marked.
unsigned findingMaskTexture(ViewerToolsGpu& gpu, GBufferCheckReport const& report, std::string const& path, int marked);

// Call after the viewers' views are drawn; replaces textures[i] with the diff heat map where a
// viewer shows its difference to the pinned image, and with the stencil picture where the depth
// viewer shows the stencil.
void serviceViewerTools(EditorState& state, Renderer& renderer, long frame, std::array<unsigned, 5>& textures,
                        ViewerToolsGpu& gpu);
// The same for the viewport's lit frame: returns the heat map to show instead of the frame while
// the lit diff is on, else 0.
unsigned serviceLitPin(LitPin& pin, Renderer& renderer, long frame, ViewerToolsGpu& gpu);
// The viewport's viewer tools while it shows a G-buffer attachment with its Tools on: draws the
// view with the tools' settings, reads back and fits as the G-buffer viewers do. Returns the
// texture to show instead of the renderer's final image, else 0. `frameInput` is the frame
// last rendered; `rendered`: a new frame was rendered this iteration.
unsigned serviceViewportTools(EditorState& state, Renderer& renderer, FrameInput const& frameInput, long frame,
                              bool rendered, ViewerToolsGpu& gpu);
// The attachment overview's cells while it is on: each view of overviewViews drawn with its
// readable range (the viewport tools' auto-fit), in cell order; empty while it is off.
std::vector<unsigned> serviceOverview(EditorState& state, Renderer& renderer, FrameInput const& frameInput, long frame,
                                      bool rendered, ViewerToolsGpu& gpu);

}  // namespace gbl::ui
