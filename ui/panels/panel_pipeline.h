// Pipeline window: every pipeline setting (core/pipeline_fields.h) in its section, and the A/B table.
#pragma once

#include "core/pipeline_settings.h"
#include "model/ab_compare.h"
#include "model/msaa_views.h"

#include <glm/glm.hpp>

#include <array>
#include <optional>
#include <string>
#include <vector>

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

// Where the window and its G-buffer layout combo are, in window coordinates, for --log-frames
// (tests click there with real X input): the combo's box (0 while scrolled out of view) and, while its list is
// open, the centre of each layout's entry in kGBufferLayoutNames order (empty while closed).
struct PipelinePanelRects {
    glm::vec4 window{0.0f};  // the Pipeline window (x, y, w, h): where a test scrolls it
    glm::vec4 layoutCombo{0.0f};
    std::vector<glm::vec2> layoutItems;
    // The same for the msaa combo (kMsaaNames order), which a test opens to pick a sample count.
    glm::vec4 msaaCombo{0.0f};
    std::vector<glm::vec2> msaaItems;
    std::vector<int> msaaGreyed;  // per entry of the open list: 1 where greyed out (msaaReasons)
};

// Edits `settings` in place; the renderer reads them on the next frame. Unavailable modes and msaa
// sample counts (`msaa`, msaaReasons; none greyed when null) are greyed out with their reason.
// `ab` (optional) adds the A/B comparison's table: which settings side B changes, and to what.
void drawPipelinePanel(PipelineSettings& settings, ModeReasons const& unavailable, AbState* ab = nullptr,
                       PipelinePanelRects* rects = nullptr, MsaaReasons const* msaa = nullptr);

}  // namespace gbl::ui
