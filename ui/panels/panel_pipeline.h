// Pipeline window: lighting mode, volume cull mode, blit step, overlays, ambient, exposure, tonemap.
#pragma once

#include "core/pipeline_settings.h"
#include "model/ab_compare.h"

#include <array>
#include <optional>
#include <string>

namespace gbl::ui {

// Why each lighting mode (indexed by LightingMode) cannot run on this context, empty where it
// can; the editor fills it from Renderer::modeUnavailable.
using ModeReasons = std::array<std::string, kLightingModeNames.size()>;
template <class Ask>  // std::optional<std::string>(LightingMode)
ModeReasons modeReasons(Ask ask) {
    ModeReasons r;
    for (std::size_t i = 0; i < r.size(); ++i) r[i] = ask(LightingMode(i)).value_or(std::string());
    return r;
}

// Edits `settings` in place; the renderer reads them on the next frame. Unavailable modes are
// greyed out with their reason.
// `ab` (optional) adds the A/B comparison's table: which settings side B changes, and to what.
void drawPipelinePanel(PipelineSettings& settings, ModeReasons const& unavailable, AbState* ab = nullptr);

}  // namespace gbl::ui
