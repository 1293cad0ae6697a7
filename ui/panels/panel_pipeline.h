// Pipeline window: lighting mode, volume cull mode, blit step, overlays, ambient, exposure, tonemap.
#pragma once

#include "gl/caps.h"
#include "core/pipeline_settings.h"

#include <string>

namespace gbl::ui {

// Why a lighting mode cannot run on this context, or empty when it can.
std::string lightingModeUnavailableReason(LightingMode mode, GlCaps const& caps);

// Edits `settings` in place; the renderer reads them on the next frame.
void drawPipelinePanel(PipelineSettings& settings, GlCaps const& caps);

}  // namespace gbl::ui
