// Export from the G-buffer viewers: what a viewer shows as PNG (channels and remap applied),
// or the raw attachment behind it as float EXR. No ImGui here, so it is tested headless.
#pragma once

#include "core/camera.h"
#include "panels/panel_gbuffer.h"
#include "renderer.h"

#include <optional>
#include <string>

namespace gbl::ui {

// The camera a viewer's view pass uses: the scene camera, or its own near/far for linear depth.
Camera viewerCamera(ViewerState const& viewer, Camera const& sceneCamera);

// Draws the viewer's view of the renderer's current frame and writes it as 8-bit RGB PNG:
// exactly the picture the viewer shows (without zoom: the whole image at frame resolution).
std::optional<std::string> exportViewerPng(Renderer& renderer, ViewerState const& viewer, Camera const& sceneCamera,
                                           std::string const& path);

// The stored values behind a viewer as 32-bit float EXR: position and normal RGBA, albedo RGB,
// specular (albedo alpha) and depth (window-space, as stored) as one channel.
std::optional<std::string> exportViewerExr(Renderer& renderer, ViewerKind kind, std::string const& path);

// Default file names for a viewer export, e.g. "normal_view.png", "normal.exr".
std::string viewerPngName(ViewerKind kind);
std::string viewerExrName(ViewerKind kind);

}  // namespace gbl::ui
