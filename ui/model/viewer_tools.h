// Logic of the viewer tools over plain state: when a viewer needs a read-back, what is computed
// from it, the fits and the pin, and the diff heat map's pixels. No GL; the loop feeds read-backs.
#pragma once

#include "model/viewer_state.h"

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace gbl::ui {

// Frames between read-backs while a tool is open (about twice a second at 60 Hz): a read-back
// of a full-size attachment costs milliseconds on a software GL.
inline constexpr long kViewerDataInterval = 30;

// Whether viewer i has a tool open that needs its values on the CPU, or a request pending.
bool viewerNeedsData(GBufferPanelState const& panel, std::size_t i);
// The same for a viewer outside the G-buffer window (the viewport's), magnifier aside.
bool viewerToolsNeedData(ViewerState const& viewer);
// Whether the values are missing, stale, or were taken for another kind or depth mode.
bool viewerDataDue(ViewerState const& viewer, ViewerData const& data, long frame);
// What identifies the values of a viewer (kind, depth linearisation, clip planes in use).
unsigned viewerValuesKey(ViewerState const& viewer);

// The range that makes a viewer's values readable (issue 26): the 1st to 99th percentile of the
// shown channels (the lit frame: 0th to 99th, so the light cubes and highlights do not leave the
// surfaces black), NaN, Inf and the background (viewerSkip) left out. samples 0 when nothing is
// drawn. What auto-fit shows by default; the Fit button takes the whole min..max instead.
ValueRange readableRange(ViewerState const& viewer, FloatImage const& values);
// A G-buffer window viewer's range from its attachment as read back (`attachment`; the stencil for
// a depth viewer showing it): the Fit button (`asked`) takes the whole min..max, auto-fit the
// readable range of the values as shown (viewerValues: linear depth through `nearPlane`..`farPlane`),
// like the viewport's. The stencil's integers always fit whole, at least one step wide.
ValueRange stripViewerRange(ViewerState const& viewer, FloatImage const& attachment, bool asked, float nearPlane,
                            float farPlane);

// Whether an auto-fitting viewer must refit now: never fitted, its values now mean something else
// (viewerValuesKey, or the clip planes its linear depth uses), or, on a newly rendered frame,
// about a second (60 frames) after the last fit.
bool autoFitDue(ViewerState const& viewer, ViewerData const& data, glm::vec2 clipPlanes, long frame, bool rendered);

// Takes a fresh read-back (already through viewerValues) and services the requests.
void setViewerValues(ViewerState& viewer, ViewerData& data, FloatImage values, long frame);
// Recomputes statistics, histogram, clipping and diff when their inputs changed; services the
// fit requests that need no new read-back. Returns true when the diff changed (re-upload it).
bool updateViewerStats(ViewerState& viewer, ViewerData& data);

// The colour a texel is shown in, from the viewer's CPU values as the view pass would draw it:
// range remap, channel isolation, colormap for one channel, then the overlays (NaN magenta, Inf
// green, negative cyan, clipping blue/red). Linear 0..1.
glm::vec3 shownTexelColour(ViewerState const& viewer, FloatImage const& values, int x, int y);
// RGBA8 rows top to bottom of the whole image in those colours: how the stencil is drawn (it has
// no view pass; see docs/viewers.md).
std::vector<std::uint8_t> viewerPicture(ViewerState const& viewer, FloatImage const& values);

// A stored float as the magnifier and the pixel inspector show it: its value to 9 significant
// digits (enough to round-trip) and its IEEE-754 bits, e.g. "0.5 (bits 0x3f000000)".
std::string storedFloatText(float value);

// The viewport's lit HDR frame (Attachment::Lighting) held and compared like a viewer's image:
// the same diffImages over RGB and the same heat map. Not saved in sessions.
struct LitPin {
    bool pinRequested = false;  // "Pin lit": the loop stores the next read-back as the pinned frame
    bool showDiff = false;      // the viewport shows |current - pinned| instead of the frame
    // Where "Pin lit" and "Diff" were drawn (x, y, w, h in window pixels; 0 while not drawn), for
    // the frame log that real-input tests click by.
    glm::vec4 pinRect{0.0f};
    glm::vec4 diffRect{0.0f};
    DiffMode diffMode = DiffMode::Absolute;
    float diffThreshold = 0.0f;
    FloatImage values;  // the last read-back of the lit frame
    long frame = -1;    // editor frame of that read-back; -1 = none yet
    std::optional<FloatImage> pinned;
    long pinnedFrame = -1;
    // "" while the pin is a frame of ours (pinnedFrame); else what was pinned from outside: an open
    // G-buffer's own lit image ("their lit image (frame.exr)"), which its Close takes away again.
    std::string pinnedName;
    ImageStats stats;  // of the current lit frame, RGB
    DiffStats diff;    // against the pinned frame while showDiff
    // Threshold and mode the diff was computed with; a change recomputes it at once.
    std::optional<std::pair<float, DiffMode>> diffFor;
};

// Whether the lit frame must be read back this frame: a pin waits for it, a diff just turned on
// is computed at once and then refreshes every kViewerDataInterval frames.
bool litPinDue(LitPin const& pin, long frame);

// Takes a fresh read-back of the lit frame: pins it when asked, recomputes statistics and diff.
void setLitValues(LitPin& pin, FloatImage lighting, long frame);

// Recomputes the lit diff from the values already read back when the threshold or the mode
// changed since (no new read-back). Returns true when it did (the heat map must be re-uploaded).
bool updateLitDiff(LitPin& pin);

// RGBA8 rows top to bottom: the diff through turbo from 0 to `scale`, NaN/Inf pixels magenta.
std::vector<std::uint8_t> diffHeatmap(DiffStats const& diff, float scale);

// Zoom and pan of `from` copied to every viewer (the "Sync zoom/pan" toggle).
void syncViewers(GBufferPanelState& panel, std::size_t from);

}  // namespace gbl::ui
