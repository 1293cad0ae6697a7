// Clipping check over ImGui's internal window and table records.
#include "panels/clip_check.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <cstdio>

namespace gbl::ui {

namespace {
// Less than a pixel over is rounding, not a cut.
constexpr float kTolerance = 1.5f;

std::string sentence(char const* format, char const* name, float a, float b) {
    char text[256];
    std::snprintf(text, sizeof text, format, name, a, b);
    return text;
}
}  // namespace

std::vector<std::string> clippedItems() {
    std::vector<std::string> out;
    ImGuiContext& g = *ImGui::GetCurrentContext();
    for (ImGuiWindow* w : g.Windows) {
        if (!w->Active || w->Hidden || w->Collapsed || w->SkipItems) continue;
        if (w->Flags & (ImGuiWindowFlags_Tooltip | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_MenuBar))
            continue;
        if (w->ScrollbarX || (w->Flags & ImGuiWindowFlags_HorizontalScrollbar)) continue;
        float const content = w->DC.CursorMaxPos.x - w->DC.CursorStartPos.x;
        float const visible = w->ContentRegionRect.GetWidth();
        if (content > visible + kTolerance)
            out.push_back(
                sentence("%s: content %.0f px wide in %.0f px, no horizontal scrollbar", w->Name, content, visible));
    }
    for (int n = 0; n < g.Tables.GetMapSize(); ++n) {
        ImGuiTable* t = g.Tables.TryGetMapData(n);
        if (!t || t->LastFrameActive != g.FrameCount || !t->OuterWindow) continue;
        for (int c = 0; c < t->ColumnsCount; ++c) {
            ImGuiTableColumn const& col = t->Columns[c];
            if (!col.IsEnabled || !col.IsVisibleX) continue;
            float const used = std::max({col.ContentMaxXFrozen, col.ContentMaxXUnfrozen, col.ContentMaxXHeadersUsed});
            if (used > col.MaxX + kTolerance) {
                char name[160];
                std::snprintf(name, sizeof name, "%s: table column %d", t->OuterWindow->Name, c);
                out.push_back(sentence("%s: text %.0f px past a column edge at %.0f", name, used - col.MaxX, col.MaxX));
            }
        }
    }
    return out;
}

}  // namespace gbl::ui
