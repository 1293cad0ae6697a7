// From the two state dumps of a captured frame to a G-buffer manifest (docs/import.md) with its
// images: which attachment is which, the camera and the lights, each with a note saying why.
#pragma once

#include "capture/state_dump.h"
#include "capture/trace_scan.h"

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace gbl::capture {

struct ViewProjection {
    glm::mat4 view, projection;
};
// Splits a perspective view-projection into a rigid view and an OpenGL-style projection (a frustum,
// possibly off-centre); nullopt when it is not of that form.
std::optional<ViewProjection> splitViewProjection(glm::mat4 const& viewProj);

struct CaptureSource {
    std::string trace;
    int frame = 0;
};

struct CaptureResult {
    std::string manifestPath;
    std::string unmapped;  // one sentence, empty when everything was mapped
};

// Writes the images, lighting.frag and manifest.json into `dir`. Error: one sentence.
std::optional<CaptureResult> writeCapture(TraceScan const& scan, StateDump const& geometry, StateDump const& lighting,
                                          CaptureSource const& source, std::string const& dir, std::string* error);

}  // namespace gbl::capture
