// The pixel inspector's per-light breakdown, computed from a pixel sample with the CPU copy of
// the lighting shader (renderer/shading_cpu.h), so its sum is the lit value the GPU stored.
#pragma once

#include "core/camera.h"
#include "model/pixel_inspector_state.h"
#include "core/pipeline_settings.h"

#include <span>

namespace gbl::ui {

// nullopt for background pixels (nothing to light).
std::optional<PixelBreakdown> breakDownPixel(PixelSample const& sample, std::span<PointLight const> lights,
                                             Camera const& camera, PipelineSettings const& settings);

}  // namespace gbl::ui
