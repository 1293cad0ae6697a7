// State of the viewport: its size, hover and click pixels, and this frame's camera drags.
#pragma once

#include "core/pipeline_settings.h"
#include "import/gbuffer_checks.h"
#include "model/attachment_overview.h"
#include "model/msaa_views.h"

#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <vector>

namespace gbl::ui {

struct ViewportState {
    glm::ivec2 size{0};         // image area in framebuffer pixels; the renderer follows it next frame
    glm::vec4 imageRect{0.0f};  // the image in window coordinates: x, y, width, height
    bool hovered = false;
    std::optional<glm::ivec2> hoverPixel;        // renderer pixel under the mouse, origin top-left
    std::optional<glm::ivec2> clickPixel;        // a left click that was not a drag, this frame
    std::optional<glm::ivec2> doubleClickPixel;  // the second press of a double click, this frame
    glm::vec2 orbitDrag{0.0f};                   // this frame's drags, in pixels (see CameraInput)
    glm::vec2 lookDrag{0.0f};
    glm::vec2 panDrag{0.0f};
    float wheel = 0.0f;
    bool frameRequested = false;         // the Frame button (the F key is read by the loop)
    glm::vec2 clipPlanes{0.1f, 100.0f};  // the camera's near and far: the depth-slice legend's ranges
    std::string stoppedAfter;            // the pass the frame shown stopped after ("" = every pass ran)
    std::vector<int> cameraInside;       // lights whose drawn volume holds the camera (model/why_value.h)
    // Where the "Wireframes" and "all" checkboxes were drawn (x, y, w, h in window pixels), for
    // the frame log that real-input tests click by.
    glm::vec4 wireframesRect{0.0f};
    glm::vec4 allWireframesRect{0.0f};
    OverviewState overview;  // the attachment overview (issue 26)
    MsaaViewState msaa;      // the complex-pixel overlay and the samples-that-differ heat map (issue 47)
    // An imported G-buffer shown instead of the scene (model/gbuffer_opening.h): its path ("" =
    // none) and frame size. The frame keeps its size and camera: the image is letterboxed and the
    // camera does not move.
    std::string importedFrame;
    glm::ivec2 importedSize{0};
    // Its check findings (docs/import.md, "Checks"), for the viewport's Checks list, without their
    // masks (GBufferOpenState keeps the report); the one whose pixels are marked over the image (-1:
    // none), and that mask as a texture (the editor's). Below them, one precision line per attachment.
    std::vector<GBufferFinding> findings;
    std::vector<std::string> precision;
    int markedFinding = -1;
    unsigned findingTexture = 0;
    glm::vec4 checksRect{0.0f};        // where the Checks button was drawn, for the frame log
    glm::vec4 firstFindingRect{0.0f};  // the open list's first finding (0 while the list is closed)
    int precisionShown = 0;            // precision lines the open list drew this frame
    // A lesson step's measured pixel (its claim's `mark`, measured on this frame): ringed in the
    // image, with the label beside it. nullopt: none.
    struct Mark {
        glm::ivec2 pixel{0};  // renderer pixels, top-left origin
        float value = 0.0f;
        std::string label;
    };
    std::optional<Mark> lessonMark;
};

}  // namespace gbl::ui
