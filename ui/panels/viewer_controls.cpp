// The viewers' own controls (channels, range, fit, depth options) shared by the G-buffer cells
// and the viewport's tools, and the viewport's tools rows and image input.
#include "panels/viewer_tools.h"

#include "model/msaa_views.h"
#include "model/viewer_tools.h"
#include "panels/gui_util.h"

#include <algorithm>
#include <utility>

namespace gbl::ui {

namespace {

constexpr char const* kChannelLabels[4] = {"R", "G", "B", "A"};
constexpr ImU32 kChannelColours[4] = {IM_COL32(200, 60, 60, 255), IM_COL32(60, 170, 60, 255),
                                      IM_COL32(70, 100, 220, 255), IM_COL32(150, 150, 150, 255)};

}  // namespace

void viewerChannelToggles(ViewerState& v) {
    for (int c = 0; c < 4; ++c) {
        if (c > 0) ImGui::SameLine(0, 2);
        bool const on = v.channelMask & (1u << c);
        ImGui::PushStyleColor(ImGuiCol_Button, on ? kChannelColours[c] : IM_COL32(50, 50, 55, 255));
        if (ImGui::SmallButton(kChannelLabels[c])) {
            // Ctrl+click adds or removes a channel; a plain click isolates it (or restores RGB).
            if (ImGui::GetIO().KeyCtrl)
                v.channelMask ^= 1u << c;
            else
                v.channelMask = (v.channelMask == (1u << c)) ? 0x7u : (1u << c);
        }
        ImGui::PopStyleColor();
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("click: show %s alone (grey); Ctrl+click: add/remove", kChannelLabels[c]);
    }
}

void viewerSampleSelector(int& sample, int samples, bool offered, char const* id) {
    if (samples <= 0) return;
    ImGui::PushID(id);
    ImGui::SetNextItemWidth(ImGui::CalcTextSize("sample 0").x + ImGui::GetFrameHeight() + 8.0f);
    ImGui::BeginDisabled(!offered);
    if (ImGui::BeginCombo("##sample", sampleChoiceLabel(offered ? sample : -1).c_str())) {
        for (int k = -1; k < samples; ++k)
            if (ImGui::Selectable(sampleChoiceLabel(k).c_str(), sample == k)) sample = k;
        ImGui::EndCombo();
    }
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip(
            offered ? "msaa: all = the resolved (averaged) attachment; sample k = that sample of the\n"
                      "multisampled G-buffer decoded as the lighting reads it (read back, coloured on the CPU)"
                    : "msaa: depth and the lit frame are shown resolved; their samples are not read back");
    ImGui::PopID();
}

void viewerControls(ViewerState& v, bool stencilChoice, int msaaSamples) {
    // Cells are narrow at 1280x720: what does not fit beside the channel toggles or the range
    // goes on a row of its own instead of being cut off at the cell's edge.
    float const font = ImGui::GetFontSize();
    float const cellWidth = ImGui::GetContentRegionAvail().x;
    float const cellRight = ImGui::GetCursorScreenPos().x + cellWidth;
    viewerChannelToggles(v);
    if (msaaSamples > 0) {
        ImGui::SameLine();
        viewerSampleSelector(v.sample, msaaSamples, viewerSampleSlot(v.kind).has_value(), "viewer-sample");
    }
    if (v.kind == ViewerKind::Normal) {
        if (cellWidth >= font * 12.0f) ImGui::SameLine();
        int mode = int(v.normalDisplay);
        ImGui::SetNextItemWidth(-1);
        char const* items[] = {"biased", "|n|"};
        if (ImGui::Combo("##normals", &mode, items, 2)) v.normalDisplay = NormalDisplay(mode);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("biased: n*0.5+0.5 as colour; |n|: absolute values");
        return;
    }
    if (v.kind == ViewerKind::Depth && stencilChoice) {
        if (cellWidth >= font * 12.0f) ImGui::SameLine();
        bool stencil = v.showStencil;
        if (ImGui::Checkbox("stencil", &stencil)) setShowStencil(v, stencil);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(
                "show the stencil bits (0..255) of the depth-stencil target instead of the depth;\n"
                "read back on the CPU (glReadPixels of GL_STENCIL_INDEX) and coloured there, so it\n"
                "works on every GL without ARB_stencil_texturing");
    }
    if (v.kind == ViewerKind::Depth && !v.showStencil) {
        float const width =
            ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize("linear").x;
        if (ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + width <= cellRight) ImGui::SameLine();
        ImGui::Checkbox("linear", &v.linearDepth);
    }
    // Fit, auto and (depth) the clip-plane button need about this much beside the range field.
    bool const planes = v.kind == ViewerKind::Depth && v.linearDepth && !v.showStencil;
    float const buttons = font * (planes ? 7.0f : 5.5f);
    bool const oneRow = cellWidth >= buttons + font * 6.0f;
    ImGui::SetNextItemWidth(oneRow ? -buttons : -1.0f);
    float const speed = std::max((v.rangeMax - v.rangeMin) * 0.005f, 1e-5f);
    ImGui::DragFloatRange2("##range", &v.rangeMin, &v.rangeMax, speed, 0.0f, 0.0f, "%.3g", "%.3g");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("shown value = (v - min) / (max - min)");
    if (oneRow) ImGui::SameLine(0, 2);
    if (ImGui::SmallButton("Fit")) v.fitRequested = true;
    ImGui::SameLine(0, 2);
    ImGui::Checkbox("##auto", &v.autoFit);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("auto: refit the range to the data about once a second");
    if (planes) {
        ImGui::SameLine(0, 2);
        if (ImGui::SmallButton("...")) ImGui::OpenPopup("clip-planes");
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("near and far planes used to linearise depth");
        if (ImGui::BeginPopup("clip-planes")) {
            ImGui::Checkbox("camera's near/far", &v.cameraClipPlanes);
            ImGui::BeginDisabled(v.cameraClipPlanes);
            ImGui::DragFloat("near", &v.nearPlane, 0.01f, 0.001f, v.farPlane, "%.3f", ImGuiSliderFlags_AlwaysClamp);
            ImGui::DragFloat("far", &v.farPlane, 0.5f, v.nearPlane + 0.001f, 1e6f, "%.1f",
                             ImGuiSliderFlags_AlwaysClamp);
            ImGui::EndDisabled();
            ImGui::EndPopup();
        }
    }
}

void outlineTexels(ImDrawList* dl, ImVec2 p0, ImVec2 full, glm::ivec2 imageSize, glm::ivec2 a, glm::ivec2 b,
                   ImU32 colour) {
    float const tw = full.x / float(imageSize.x), th = full.y / float(imageSize.y);
    dl->AddRect(ImVec2(p0.x + float(a.x) * tw, p0.y + float(a.y) * th),
                ImVec2(p0.x + float(b.x) * tw, p0.y + float(b.y) * th), colour, 0.0f, 0, 1.5f);
}

void markLockedPixel(ImDrawList* dl, ImVec2 p0, ImVec2 full, glm::ivec2 imageSize, glm::ivec2 pixel) {
    ImVec2 const c(p0.x + (float(pixel.x) + 0.5f) * full.x / float(imageSize.x),
                   p0.y + (float(pixel.y) + 0.5f) * full.y / float(imageSize.y));
    for (auto [colour, width] :
         {std::pair{IM_COL32(0, 0, 0, 220), 3.0f}, std::pair{IM_COL32(255, 255, 255, 255), 1.0f}}) {
        dl->AddLine(ImVec2(c.x - 9, c.y), ImVec2(c.x - 3, c.y), colour, width);
        dl->AddLine(ImVec2(c.x + 3, c.y), ImVec2(c.x + 9, c.y), colour, width);
        dl->AddLine(ImVec2(c.x, c.y - 9), ImVec2(c.x, c.y - 3), colour, width);
        dl->AddLine(ImVec2(c.x, c.y + 3), ImVec2(c.x, c.y + 9), colour, width);
    }
}

// --- the viewport's tools -----------------------------------------------------------------

void viewportToolsRow(ViewportTools& tools, DebugView view, int msaaSamples) {
    if (!viewerKindOfView(view)) {
        tools.hoverTexel.reset();
        return;  // the final image and the heat views: no attachment values to read
    }
    ImGui::PushStyleColor(ImGuiCol_Button, tools.open ? IM_COL32(70, 110, 170, 255) : IM_COL32(50, 50, 55, 255));
    if (ImGui::Button("Tools")) tools.open = !tools.open;
    ImGui::PopStyleColor();
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "the G-buffer viewers' tools on this attachment (lighting: the HDR values before the\n"
            "tonemap): range, colormap, histogram, overlays, pin/diff in \"...\"; Shift+drag in the\n"
            "image: region statistics, Shift+right-click: magnifier texel");
    if (!tools.open) return;
    ViewerState& v = tools.viewer;
    ViewerData const& d = tools.data;
    // Everything else in a popover: the row keeps one line, so the frame never changes size
    // (which would make a pinned frame incomparable).
    ImGui::SameLine(0, 2);
    if (ImGui::Button("...##viewport-tools")) ImGui::OpenPopup("viewport-tools");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("range, channels, histogram, colormap, overlays, pin and diff");
    float const width = ImGui::GetFontSize() * 22.0f;
    ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0.0f), ImVec2(width, 1e6f));
    if (ImGui::BeginPopup("viewport-tools")) {
        ImGui::TextUnformatted(viewerKindName(v.kind).data());
        viewerHeaderCounts(v, d);
        viewerControls(v, false, msaaSamples);
        viewerToolsRow(v, d);
        viewerHistogram(v, d);
        viewerRegionAndDiff(v, d);
        ImGui::EndPopup();
    }
}

bool viewportToolsImage(ViewportTools& tools, ImVec2 origin, ImVec2 size, glm::ivec2 imageSize) {
    tools.hoverTexel.reset();
    ViewerState& v = tools.viewer;
    if (!tools.open || imageSize.x <= 0 || imageSize.y <= 0 || size.x < 1.0f || size.y < 1.0f) return false;
    ImGuiIO const& io = ImGui::GetIO();
    auto texelAt = [&](ImVec2 m) {
        glm::vec2 const uv((m.x - origin.x) / size.x, (m.y - origin.y) / size.y);
        return glm::clamp(glm::ivec2(glm::floor(uv * glm::vec2(imageSize))), glm::ivec2(0), imageSize - 1);
    };
    bool const hovered = ImGui::IsItemHovered();
    if (hovered) tools.hoverTexel = texelAt(io.MousePos);
    // Shift turns the left drag into the region and the right click into the magnifier's pick;
    // without it the mouse moves the camera as always.
    if (ImGui::IsItemActivated() && io.KeyShift && ImGui::IsMouseDown(ImGuiMouseButton_Left))
        v.regionDragStart = texelAt(io.MousePos);
    if (!ImGui::IsItemActive()) v.regionDragStart.reset();
    bool const taken = v.regionDragStart.has_value() || (hovered && io.KeyShift);
    if (v.regionDragStart) v.region = rectFromCorners(*v.regionDragStart, texelAt(io.MousePos));
    if (hovered && io.KeyShift && ImGui::IsMouseClicked(ImGuiMouseButton_Right)) {
        v.picked = texelAt(io.MousePos);
        tools.pickedThisFrame = true;
    }
    ImDrawList* dl = ImGui::GetWindowDrawList();
    ImVec2 const full(size.x, size.y);
    dl->PushClipRect(origin, ImVec2(origin.x + size.x, origin.y + size.y), true);
    if (v.region)
        outlineTexels(dl, origin, full, imageSize, v.region->min, v.region->max, IM_COL32(255, 255, 255, 230));
    if (v.picked) outlineTexels(dl, origin, full, imageSize, *v.picked, *v.picked + 1, IM_COL32(255, 160, 0, 255));
    dl->PopClipRect();
    return taken;
}

}  // namespace gbl::ui
