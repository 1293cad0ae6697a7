// "Why this value": per light, whether the current lighting mode evaluated it at one pixel and
// what it added, reasoned on the CPU from the same tests the GPU passes make.
#pragma once

#include "core/camera.h"
#include "core/frame_types.h"
#include "core/pipeline_settings.h"
#include "core/point_light.h"

#include <glm/glm.hpp>

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace gbl::ui {

// View depths (positive, -z in view space) of the nearest and farthest geometry in a tile: the
// bounds the tiled pass cuts each tile's frustum to.
struct TileDepthBounds {
    float minDepth = 0.0f;
    float maxDepth = 0.0f;
};

// Where the pixel sits and what the frame looked like.
struct WhyValueInput {
    PixelSample sample;       // the stored G-buffer values at the pixel (covered must be true)
    glm::ivec2 pixel{0};      // top-left origin, as the inspector reports it
    glm::ivec2 frameSize{0};  // renderer pixels
    Camera camera;
    PipelineSettings settings;  // mode and cull mode decide; shininess and ambient shade
    // The tile's depth bounds (tileDepthBounds below). Without them the tiled answer uses the
    // pixel's own depth, which can only under-count the tile's list (the real bounds contain it).
    std::optional<TileDepthBounds> tileBounds;
};

struct LightVerdict {
    int lightIndex = -1;
    bool withinRadius = false;  // the surface point is closer to the light than its radius
    bool evaluated = false;     // the mode ran this light's shading for this pixel
    int evaluations = 0;        // times it ran (2 for cull mode `none`: both faces, no depth test)
    std::string why;            // one short reason, in the mode's own terms
    glm::vec3 added{0.0f};      // what it added to the stored value: contribution * evaluations
};

// One verdict per light, in list order. Empty when the sample is background.
std::vector<LightVerdict> explainPixel(WhyValueInput const& in, std::span<PointLight const> lights);

// The local lights whose volume, as the volumes pass draws it (the enclosing sphere, or a spot's
// cone, at the pipeline's volume scale), holds the eye, in list order: the viewport's "camera inside
// light N's volume" (a volume the camera is inside loses its front faces to the near plane).
std::vector<int> lightsAroundEye(glm::vec3 eye, std::span<PointLight const> lights, float volumeScale);

// The depth bounds the tiled pass computes for the tile holding pixel (top-left origin) of a
// depth attachment read back with Renderer::readAttachment(Attachment::Depth) (rows top to
// bottom); nullopt when the tile has no geometry. Background pixels (depth 1) are left out,
// as the GPU leaves out pixels with no position.
std::optional<TileDepthBounds> tileDepthBounds(FloatImage const& depth, glm::ivec2 pixel, float nearPlane,
                                               float farPlane);

}  // namespace gbl::ui
