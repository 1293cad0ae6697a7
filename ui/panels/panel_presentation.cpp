// The presentation layout's window.
#include "panels/panel_presentation.h"

#include "model/attachment_overview.h"
#include "panels/gui_util.h"
#include "panels/item_rect.h"

#include <imgui.h>

#include <algorithm>
#include <string>

namespace gbl::ui {

void drawPresentationWindow(LayoutState& layout, ViewportState& viewport, PipelineSettings const& settings,
                            unsigned texture, bool lessonOpen) {
    // No camera input here: the viewport's pointer state of this frame is empty, as its panel leaves it.
    viewport.hovered = false;
    viewport.hoverPixel.reset();
    viewport.clickPixel.reset();
    viewport.doubleClickPixel.reset();
    viewport.orbitDrag = viewport.lookDrag = viewport.panDrag = glm::vec2(0.0f);
    viewport.wheel = 0.0f;
    viewport.frameRequested = false;
    viewport.overview.cells.clear();
    ImGuiViewport const* main = ImGui::GetMainViewport();
    float const lessonW = lessonOpen ? std::floor(main->WorkSize.x * kPresentationLessonShare) : 0.0f;
    layout.presentationLesson =
        lessonOpen ? glm::vec4(main->WorkPos.x + main->WorkSize.x - lessonW, main->WorkPos.y, lessonW, main->WorkSize.y)
                   : glm::vec4(0.0f);
    ImGui::SetNextWindowPos(main->WorkPos);
    ImGui::SetNextWindowSize(ImVec2(main->WorkSize.x - lessonW, main->WorkSize.y));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(4.0f, 2.0f));
    ImGuiWindowFlags const flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoDocking |
                                   ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                                   ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoScrollWithMouse;
    bool const open = ImGui::Begin("Presentation", nullptr, flags);
    ImGui::PopStyleVar();
    if (open) {
        // One line: what is shown and how it is lit, then as many of the keys that change it as fit.
        std::string caption = std::string(overviewLabel(settings.view)) + "  |  " +
                              std::string(enumName(kLightingModeNames, settings.mode)) + " lighting";
        float const width = ImGui::GetContentRegionAvail().x;
        for (char const* keys : {"  |  V / Shift+V: view   M: mode   C: cull   B: depth copy   P: leave",
                                 "  |  V: view  M: mode  P: leave", "  |  P: leave"}) {
            if (ImGui::CalcTextSize((caption + keys).c_str()).x <= width) {
                caption += keys;
                break;
            }
        }
        ImGui::TextUnformatted(caption.c_str());
        layout.presentationCaption = lastItemRect();
        ImVec2 const avail = ImGui::GetContentRegionAvail();
        ImVec2 const scale = ImGui::GetIO().DisplayFramebufferScale;
        viewport.size = glm::ivec2(std::max(0, int(avail.x * scale.x)), std::max(0, int(avail.y * scale.y)));
        ImVec2 const origin = ImGui::GetCursorScreenPos();
        viewport.imageRect = glm::vec4(origin.x, origin.y, avail.x, avail.y);
        if (avail.x >= 1.0f && avail.y >= 1.0f) {
            ImGui::InvisibleButton("presentation-image", avail);
            ImGui::GetWindowDrawList()->AddImage(toImTexture(texture), origin,
                                                 ImVec2(origin.x + avail.x, origin.y + avail.y), ImVec2(0, 1),
                                                 ImVec2(1, 0));
        }
    }
    ImGui::End();
}

}  // namespace gbl::ui
