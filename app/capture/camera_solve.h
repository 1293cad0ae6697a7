// The camera of a captured frame whose geometry program names no view/projection uniforms: solved from
// the position attachment, whose world positions and their pixel centres determine the view-projection
// (a direct linear transform, normalised, least squares), then made a rigid view and a frustum.
#pragma once

#include "core/frame_types.h"

#include <glm/glm.hpp>

#include <optional>
#include <string>

namespace gbl::capture {

struct SolvedCamera {
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    double rmsPixels = 0.0;  // reprojection error of the samples through projection * view
    double maxPixels = 0.0;
    std::size_t samples = 0;
    bool depthFitted = false;  // near/far from the depth attachment, else from the positions' range
};

// `position`: rows top to bottom, world (or view) positions in channels 0..2, (0, 0, 0) where nothing was
// drawn. `depth` (optional, same size): window depth in channel 0, which fixes the projection's depth
// rows; without it near and far bracket the positions. nullopt and *why (a clause) when the positions
// do not determine a perspective camera.
std::optional<SolvedCamera> solveCameraFromPositions(FloatImage const& position, FloatImage const* depth,
                                                     std::string* why);

// The pixel-space distance between where `viewProj` puts each drawn position and its pixel centre.
struct Reprojection {
    double rms = 0.0, max = 0.0;
    std::size_t samples = 0;
};
Reprojection reprojectionError(FloatImage const& position, glm::mat4 const& viewProj);

}  // namespace gbl::capture
