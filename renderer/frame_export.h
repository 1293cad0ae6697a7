// Writing every image and JSON description of a rendered frame to a folder: the set that
// `render --out` writes and the editor's "Export all" writes, from one implementation.
#pragma once

#include "core/camera.h"
#include "core/pipeline_settings.h"
#include "core/point_light.h"
#include "renderer.h"

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace gbl {

struct FrameExport {
    Camera camera;                       // the camera the frame was rendered with
    std::span<PointLight const> lights;  // the lights as rendered (after animation)
    PipelineSettings settings;
    FrameStats stats;                   // what Renderer::render returned for the frame
    std::size_t triangles = 0;          // scene size, for stats.json
    std::vector<DebugView> extraViews;  // also written as view_<name>.png
};

// Writes into `dir` (which must exist): final.png, lighting.exr, position.exr and normal.exr (decoded:
// what the lighting read),
// albedo.png, specular.png, depth.exr, depth_linear.exr, raw_<name>.exr/.png per attachment of the
// G-buffer layout as stored, view_<name>.png per extra view,
// lights.json, camera.json and stats.json, from the renderer's current frame. Returns the
// first error as one sentence naming the file; files before it stay written.
// A prepass frame (docs/deferred_lighting.md) writes its thin G-buffer instead: normal.exr,
// specular_exponent.exr, raw_prepass_normal_exp.exr, depth.exr (its lit depth), position.exr
// (rebuilt from that depth), and diffuse_light.exr and specular_light.exr; no albedo.png,
// specular.png, emissive.exr or raw_ file of the layout, which it never drew (kPrepassExportNote,
// stats.json's gbuffer_note, says so).
std::optional<std::string> exportFrame(Renderer& renderer, FrameExport const& frame, std::string const& dir);

// Eye-space distances from a read-back depth attachment (the inverse of the perspective depth
// mapping with the camera's near and far planes), as depth_linear.exr stores them.
FloatImage linearDepthImage(FloatImage depth, Camera const& camera);

// The range a remapped extra view (position, depth, depth_linear) is written with: the 1st to 99th
// percentile (nearest rank) of the drawn pixels' values as that view shows them, as the editor's
// auto-fit does, so that view_depth_linear.png is not all white. nullopt for the views that do not
// remap, or when nothing is drawn. `position` and `depth` are read-back attachments.
std::optional<std::pair<float, float>> readableViewRange(DebugView view, FloatImage const& position,
                                                         FloatImage const& depth, Camera const& camera);

// stats.json's gbuffer_note for a prepass frame: which files hold its thin G-buffer, which are left out.
extern char const* const kPrepassExportNote;

// The alpha channel of the albedo/specular attachment as a one-channel image (specular.png).
FloatImage specularImage(FloatImage const& albedoSpec);

}  // namespace gbl
