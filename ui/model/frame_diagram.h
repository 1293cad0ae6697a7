// The Frame window's diagram as plain values (issue 24): what each declared pass reads and writes,
// the edges from the pass that writes a resource to the passes that read it, where the boxes, pins
// and arrows go, the viewport view that shows a resource, and a pass's state in plain words. No
// ImGui: the panel (ui/panels/panel_frame.cpp) measures the text and draws what this lays out.
#pragma once

#include "core/frame_passes.h"

#include <glm/glm.hpp>

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace gbl::ui {

// What a pass reads: what its shaders sample (or its blit copies), the depth-stencil it tests
// against, and the colour targets its draws blend over.
std::vector<Resource> passInputs(PassDecl const& p);
// What it writes: a dispatch's images and buffers; the colour targets of draws that write colour;
// the depth-stencil when depth or stencil is written (a blit writes only that).
std::vector<Resource> passOutputs(PassDecl const& p);

// `resource` flows from the pass at index `from` (the latest before `to` that writes it) into the
// pass at index `to`.
struct FrameEdge {
    int from = 0;
    int to = 0;
    Resource resource = Resource::Display;
    bool operator==(FrameEdge const&) const = default;
};
// Every input of every pass that an earlier pass wrote, in pass order then input order.
std::vector<FrameEdge> frameEdges(std::span<PassDecl const> passes);
// "geometry -> lighting via gbuffer.normal"
std::string describeEdge(FrameEdge const& e, std::span<PassDecl const> passes);

// The viewport view (Pipeline's "Show") that displays `r`; nullopt for the resources no view shows
// (buffers, the light list, the depth copies).
std::optional<DebugView> resourceView(Resource r);

// A pass's declared state, one line each: kind, what it samples, what it draws into, depth and
// stencil use, and each group of draws (depth test, blend, cull, stencil) in plain words.
std::vector<std::string> describePass(PassDecl const& p);

// The measured text of one pass's box (pixels): its widest header line and each pin's label.
struct PassBoxText {
    float header = 0.0f;
    std::vector<float> inputs;   // passInputs order
    std::vector<float> outputs;  // passOutputs order
};

struct DiagramMetrics {
    float line = 16.0f;       // a text line, and a pin's row
    int headerLines = 2;      // name, then time
    float pad = 6.0f;         // inside a box
    float pinRadius = 4.0f;   // pins sit on the box's left and right edges
    float labelGap = 16.0f;   // between the input labels and the output labels
    float columnGap = 56.0f;  // between boxes: room for arrows to turn
    float laneGap = 7.0f;     // between the lanes below the boxes
};

struct BoxPlace {
    glm::vec2 pos{0.0f};  // top-left, relative to the diagram's origin
    glm::vec2 size{0.0f};
    std::vector<glm::vec2> inputs;   // pin centres on the left edge
    std::vector<glm::vec2> outputs;  // on the right edge
    float inputLabelX = 0.0f;        // input labels start here
    float outputLabelRight = 0.0f;   // output labels end here
};

// An edge's path: a polyline from the writer's output pin to the reader's input pin. Neighbours
// are joined directly (curve = true: a bezier with the middle points as its controls); an edge
// that skips passes drops to a lane below the boxes, so it never crosses a box.
struct EdgeRoute {
    FrameEdge edge;
    std::vector<glm::vec2> points;
    bool curve = false;
};

struct DiagramLayout {
    std::vector<BoxPlace> boxes;  // one per pass, left to right in frame order
    std::vector<EdgeRoute> routes;
    glm::vec2 size{0.0f};  // everything, lanes included
};
DiagramLayout layoutDiagram(std::span<PassDecl const> passes, std::span<PassBoxText const> text,
                            DiagramMetrics const& m);

// The Frame window's state: open or not, the selected pass, the stop the editor's frames make,
// and what the last frame drew (for --log-frames, which tests click from).
struct FramePanelState {
    bool open = false;
    std::optional<PassId> selected;
    std::optional<PassId> stopAfter;  // FrameInput::stopAfter of the editor's frames
    std::vector<PassDecl> passes;     // Renderer::framePasses of the last rendered frame
    // Window coordinates (x, y, width, height): the window, the Stats button that opens it, the
    // "Stop here" / "Run whole frame" button (0 while not drawn).
    glm::vec4 windowRect{0.0f};
    glm::vec4 openButton{0.0f};
    glm::vec4 stopButton{0.0f};
    // What a click may land on this frame: "pass:NAME@X,Y", "in:PASS:RESOURCE@X,Y",
    // "out:PASS:RESOURCE@X,Y" (centres, inside the window's visible part only).
    std::vector<std::string> targets;
};

}  // namespace gbl::ui
