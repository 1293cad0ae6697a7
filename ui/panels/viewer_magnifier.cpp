// Magnifier: 9x9 texels around the picked texel of the active viewer, values on hover, and the
// go-to-pixel popup (Ctrl+G).
#include "panels/viewer_tools.h"

#include "model/colormap.h"
#include "model/msaa_views.h"
#include "model/viewer_tools.h"

#include <algorithm>
#include <cstdint>

namespace gbl::ui {

namespace {

constexpr int kRadius = 4;  // 9x9 texels

// The texel's colour as the viewer shows it, from the CPU values (the model's shownTexelColour).
ImU32 shownColour(ViewerState const& v, ViewerData const& d, int x, int y) {
    glm::vec3 const c = shownTexelColour(v, d.values, x, y);
    return IM_COL32(int(c.r * 255.0f + 0.5f), int(c.g * 255.0f + 0.5f), int(c.b * 255.0f + 0.5f), 255);
}

void texelValues(ViewerState const& v, ViewerData const& d, glm::ivec2 t) {
    ImGui::Text("texel %d, %d", t.x, t.y);
    if (v.kind == ViewerKind::Depth && v.showStencil) {
        ImGui::Text("stencil %d", int(d.values.at(t.x, t.y, 0)));
        return;
    }
    if (v.kind == ViewerKind::Depth) {
        ImGui::Text("%s %.6g", v.linearDepth ? "eye depth" : "depth", d.values.at(t.x, t.y, 0));
        ImGui::Text("stored %s", storedFloatText(d.values.at(t.x, t.y, 1)).c_str());
        return;
    }
    static constexpr char const* kChannel[4] = {"R", "G", "B", "A"};
    for (int c = 0; c < 4; ++c) ImGui::Text("%s %.6g", kChannel[c], d.values.at(t.x, t.y, c));
}

void goToPixelPopup(GBufferPanelState& panel, ViewerState& v) {
    if (panel.goToOpen) {
        ImGui::OpenPopup("Go to pixel");
        panel.goToOpen = false;
    }
    if (!ImGui::BeginPopup("Go to pixel")) return;
    ImGui::TextUnformatted("x, y (top-left origin)");
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    bool go = ImGui::InputInt2("##xy", &panel.goToInput.x, ImGuiInputTextFlags_EnterReturnsTrue);
    go |= ImGui::Button("Go");
    if (go && v.imageSize.x > 0) {
        glm::ivec2 const p = glm::clamp(panel.goToInput, glm::ivec2(0), v.imageSize - 1);
        v.picked = p;
        v.zoom = std::max(v.zoom, 8.0f);
        v.center = (glm::vec2(p) + 0.5f) / glm::vec2(v.imageSize);
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

}  // namespace

void drawViewerMagnifier(GBufferPanelState& panel, ViewportTools& viewport) {
    if (viewport.pickedThisFrame) {
        // Shift+right-click in the viewport: the magnifier follows the viewport's texel.
        viewport.pickedThisFrame = false;
        panel.activeViewer = kViewportViewer;
        panel.showMagnifier = true;
    }
    bool const onViewport = panel.activeViewer == kViewportViewer && viewport.open;
    std::size_t const i = std::size_t(std::clamp(panel.activeViewer, 0, 4));
    ViewerState& v = onViewport ? viewport.viewer : panel.viewers[i];
    goToPixelPopup(panel, v);
    if (!panel.showMagnifier) return;
    ViewerData const& d = onViewport ? viewport.data : panel.data[i];
    float const cell = ImGui::GetFontSize() * 1.4f;
    ImGui::SetNextWindowSize(ImVec2(cell * 9 + 40.0f, cell * 9 + ImGui::GetFontSize() * 9), ImGuiCond_FirstUseEver);
    if (!ImGui::Begin("Magnifier", &panel.showMagnifier)) {
        ImGui::End();
        return;
    }
    ImGui::Text("%s %s", viewerKindName(v.kind).data(),
                onViewport      ? "in the viewport"
                : v.showStencil ? "viewer (stencil)"
                                : "viewer");
    if (panel.msaaSamples > 0) {
        ImGui::SameLine();
        viewerSampleSelector(v.sample, panel.msaaSamples, viewerSampleSlot(v.kind).has_value(), "magnifier-sample");
    }
    if (!v.picked) {
        ImGui::TextWrapped(onViewport
                               ? "Shift+right-click a texel in the viewport to pick it; Ctrl+G goes to one."
                               : "Right-click a texel in a viewer to pick it; arrow keys step it; Ctrl+G goes to one.");
    } else if (d.frame < 0 || d.values.width <= 0) {
        ImGui::TextDisabled("reading values...");
    } else {
        glm::ivec2 const c = glm::clamp(*v.picked, glm::ivec2(0), glm::ivec2(d.values.width, d.values.height) - 1);
        ImVec2 const p0 = ImGui::GetCursorScreenPos();
        ImGui::InvisibleButton("grid", ImVec2(cell * 9, cell * 9));
        bool const hovered = ImGui::IsItemHovered();
        ImDrawList* dl = ImGui::GetWindowDrawList();
        std::optional<glm::ivec2> hoverTexel;
        for (int dy = -kRadius; dy <= kRadius; ++dy) {
            for (int dx = -kRadius; dx <= kRadius; ++dx) {
                glm::ivec2 const t = c + glm::ivec2(dx, dy);
                ImVec2 const a(p0.x + float(dx + kRadius) * cell, p0.y + float(dy + kRadius) * cell);
                ImVec2 const b(a.x + cell, a.y + cell);
                if (t.x < 0 || t.y < 0 || t.x >= d.values.width || t.y >= d.values.height) {
                    dl->AddRectFilled(a, b, IM_COL32(30, 30, 30, 255));
                    continue;
                }
                dl->AddRectFilled(a, b, shownColour(v, d, t.x, t.y));
                if (hovered && ImGui::IsMouseHoveringRect(a, b)) hoverTexel = t;
            }
        }
        ImVec2 const ca(p0.x + kRadius * cell, p0.y + kRadius * cell);
        dl->AddRect(ca, ImVec2(ca.x + cell, ca.y + cell), IM_COL32(255, 255, 0, 255), 0.0f, 0, 2.0f);
        if (hoverTexel) {
            ImGui::BeginTooltip();
            texelValues(v, d, *hoverTexel);
            ImGui::EndTooltip();
        }
        texelValues(v, d, c);
        ImGui::TextDisabled("values from frame %ld", d.frame);
    }
    ImGui::End();
}

}  // namespace gbl::ui
