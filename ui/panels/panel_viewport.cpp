// Viewport window.
#include "panels/panel_viewport.h"
#include "panels/item_rect.h"

#include "core/cluster_math.h"
#include "core/heat_scale.h"
#include "core/view_params.h"
#include "model/colormap.h"
#include "panels/gui_util.h"
#include "panels/layout.h"
#include "panels/viewer_tools.h"
#include "panels/viewport_checks.h"
#include "panels/viewport_msaa.h"
#include "panels/viewport_overlays.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

namespace gbl::ui {

namespace {
// Movement within this many pixels between press and release still counts as a click.
constexpr float kClickSlopSq = 3.0f * 3.0f;

void viewCombo(PipelineSettings& settings) {
    int view = int(settings.view);
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 9.0f);
    if (ImGui::BeginCombo("Show", kDebugViewNames[std::size_t(view)].data())) {
        for (std::size_t i = 0; i < kDebugViewNames.size(); ++i)
            if (ImGui::Selectable(kDebugViewNames[i].data(), view == int(i))) settings.view = DebugView(i);
        ImGui::EndCombo();
    }
}
// The full text when the rest of the row holds it, else the compact one (or, where even that is
// too wide, the tiny one) with the full text as its tooltip: the row keeps one line, so showing
// statistics never resizes the frame (which would make the pinned frame incomparable).
void fittedText(char const* full, char const* compact, char const* tiny = nullptr) {
    float const avail = ImGui::GetContentRegionAvail().x;
    char const* shown = ImGui::CalcTextSize(full).x <= avail               ? full
                        : !tiny || ImGui::CalcTextSize(compact).x <= avail ? compact
                                                                           : tiny;
    ImGui::TextUnformatted(shown);
    if (shown != full && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", full);
}

// The viewport's tools, then "Pin lit", which holds the lit HDR frame; "Diff" shows |now - pinned|
// over RGB as the viewers' heat map, with the statistics of both on the row (a row of its own:
// the toolbar above is full).
void litPinRow(LitPin& pin, ViewportTools& tools, DebugView view, ViewportState& state) {
    ImGui::SetCursorPosX(ImGui::GetCursorPosX() + 6);
    // The viewport's tools share this row: opening them never adds one.
    viewportToolsRow(tools, view, state.msaa.samples);
    if (viewerKindOfView(view)) ImGui::SameLine();
    drawChecksButton(state);
    msaaViewsRow(state.msaa);
    if (ImGui::Button("Pin lit")) pin.pinRequested = true;
    pin.pinRect = lastItemRect();
    pin.diffRect = glm::vec4(0.0f);
    ImGui::SameLine();
    if (!pin.pinned) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        fittedText("pin the lit frame to compare later frames with it", "pin to compare");
        ImGui::PopStyleColor();
        return;
    }
    ImGui::Checkbox("Diff", &pin.showDiff);
    pin.diffRect = lastItemRect();
    ImGui::SameLine();
    ChannelStats const& s = pin.stats.shown;
    if (pin.showDiff && !pin.diff.comparable && pin.frame >= 0) {
        // The viewport (so the frame) changed size since the pin: no pixel-to-pixel comparison.
        ImGui::TextColored(ImVec4(1.0f, 0.6f, 0.3f, 1.0f), "the frame's size changed since the pin; pin again");
        return;
    }
    // What is pinned: a frame of ours by its number, or an open G-buffer's own lit image by name.
    std::string const pinned = pin.pinnedName.empty() ? "frame " + std::to_string(pin.pinnedFrame) : pin.pinnedName;
    if (pin.frame < 0) {  // nothing read back yet (an imported G-buffer's image was pinned on opening)
        fittedText(("pinned " + pinned + ": Diff compares the frame with it").c_str(), ("pinned " + pinned).c_str());
        return;
    }
    if (!pin.showDiff || !pin.diff.comparable) {
        char full[224], compact[160];
        std::snprintf(full, sizeof full, "pinned %s; lit RGB %.4g .. %.4g, mean %.4g, NaN px %ld", pinned.c_str(),
                      s.min, s.max, s.mean, pin.stats.nanPixels);
        std::snprintf(compact, sizeof compact, "pinned %s", pinned.c_str());
        fittedText(full, compact);
        return;
    }
    // Threshold and relative mode apply at once (the loop recomputes from the last read-back).
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 5.0f);
    ImGui::DragFloat("##lit-threshold", &pin.diffThreshold, 0.001f, 0.0f, 1e6f, "thr %.4g",
                     ImGuiSliderFlags_AlwaysClamp);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("pixels whose difference is above this are counted; 0 = any change");
    ImGui::SameLine(0, 2);
    bool rel = pin.diffMode == DiffMode::Relative;
    if (ImGui::Checkbox("rel", &rel)) pin.diffMode = rel ? DiffMode::Relative : DiffMode::Absolute;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("relative: |a - b| / |pinned|");
    ImGui::SameLine();
    DiffStats const& d = pin.diff;
    char full[256], compact[96];
    std::snprintf(full, sizeof full, "vs %s: max %.4g at %d,%d  mean %.4g  over %ld of %ld px  NaN px %ld",
                  pinned.c_str(), d.max, d.maxAt.x, d.maxAt.y, d.mean, d.overThreshold, d.pixels, d.nanPixels);
    std::snprintf(compact, sizeof compact, "max %.3g mean %.3g over %ld NaN %ld", d.max, d.mean, d.overThreshold,
                  d.nanPixels);
    // A narrow viewport at a large UI scale (the docked centre at 1.5x): the two numbers that say
    // whether anything changed.
    char tiny[64];
    std::snprintf(tiny, sizeof tiny, "max %.3g over %ld", d.max, d.overThreshold);
    fittedText(full, compact, tiny);
}

// A G-buffer view in forward mode would show the cleared (black) G-buffer: say why instead.
bool gbufferView(DebugView v) {
    switch (v) {
        case DebugView::Position:
        case DebugView::Normal:
        case DebugView::Albedo:
        case DebugView::Specular:
        case DebugView::Emissive:
        case DebugView::Occlusion:
        case DebugView::Depth:
        case DebugView::DepthLinear:
            return true;
        default:
            return false;
    }
}

void centredMessage(ImVec2 min, ImVec2 max, char const* text) {
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->AddRectFilled(min, max, IM_COL32(24, 24, 28, 255));
    float const wrap = std::max(100.0f, (max.x - min.x) * 0.8f);
    ImVec2 const size = ImGui::CalcTextSize(text, nullptr, false, wrap);
    ImVec2 const p((min.x + max.x - size.x) * 0.5f, (min.y + max.y - size.y) * 0.5f);
    dl->AddText(ImGui::GetFont(), ImGui::GetFontSize(), p, IM_COL32(235, 235, 235, 255), text, nullptr, wrap);
}

// A file's or folder's last name ("frame" for "/tmp/frame/").
std::string shortName(std::string const& path) {
    std::filesystem::path p(path);
    if (p.filename().empty()) p = p.parent_path();
    return p.filename().string();
}

// "camera inside light 3's volume"; several: "camera inside the volumes of lights 3, 7, 9".
std::string cameraInsideText(std::vector<int> const& lights) {
    if (lights.size() == 1) return "camera inside light " + std::to_string(lights[0]) + "'s volume";
    std::string out = "camera inside the volumes of lights ";
    for (std::size_t i = 0; i < lights.size() && i < 8; ++i) out += (i ? ", " : "") + std::to_string(lights[i]);
    return lights.size() > 8 ? out + ", ..." : out;
}

// The third row: "Light by light" with its slider (Left/Right step it) and the A/B toggle.
void teachingRow(ViewportTeaching& t, PipelineSettings const& settings) {
    AccumulateState& a = t.accumulate;
    ImGui::SetCursorPosX(ImGui::GetCursorPosX() + 6);
    ImGui::Checkbox("Light by light", &a.enabled);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "the frame shows the first k lights only (ambient alone at 0), light k's volume outlined;\n"
            "Left/Right arrows step k");
    ImGui::SameLine();
    a.count = std::clamp(a.count, 0, t.lightCount);
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 10.0f);
    // Touching the scrubber turns accumulation on: that is what it is for.
    ImGui::SliderInt("##k", &a.count, 0, t.lightCount, a.enabled ? "k = %d" : "k = %d (off)",
                     ImGuiSliderFlags_AlwaysClamp);
    if (ImGui::IsItemActivated()) a.enabled = true;
    a.sliderRect = lastItemRect();
    ImGui::SameLine();
    ImGui::BeginDisabled(!a.enabled);
    ImGui::Checkbox("only k", &a.contribution);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("light k alone, without ambient: what step k added to the frame");
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (a.enabled) ImGui::TextDisabled(a.count == 0 ? "ambient only" : "%s", t.kthLightName.c_str());
    ImGui::SameLine();
    if (ImGui::Checkbox("A/B", &t.ab.enabled) && t.ab.enabled) startAb(t.ab, settings);
    t.ab.toggleRect = lastItemRect();
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("two pipeline settings on the same frame: pick what B changes in the Pipeline window");
    if (t.ab.enabled) {
        ImGui::SameLine();
        int view = int(t.ab.view);
        ImGui::RadioButton("split", &view, int(AbView::Split));
        ImGui::SameLine();
        ImGui::RadioButton("diff", &view, int(AbView::Diff));
        t.ab.view = AbView(view);
    }
}

// The attachment overview: each view of overviewViews in a grid filling the image area, labelled
// above its picture; records the cells for clicks and the frame log. A G-buffer cell in forward
// mode says why it is empty, as the full-size view does.
void drawOverview(OverviewState& overview, PipelineSettings const& settings, std::span<unsigned const> textures,
                  ImVec2 origin, ImVec2 avail, glm::ivec2 textureSize) {
    std::vector<DebugView> const views = overviewViews();
    float const aspect = textureSize.x > 0 && textureSize.y > 0 ? float(textureSize.x) / float(textureSize.y)
                                                                : avail.x / std::max(avail.y, 1.0f);
    float const label = ImGui::GetTextLineHeight() + 4.0f;
    std::vector<glm::vec4> const rects =
        overviewImageRects(int(views.size()), glm::vec4(origin.x, origin.y, avail.x, avail.y), aspect, label, 4.0f);
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->AddRectFilled(origin, ImVec2(origin.x + avail.x, origin.y + avail.y), IM_COL32(16, 16, 18, 255));
    for (std::size_t i = 0; i < rects.size(); ++i) {
        glm::vec4 const r = rects[i];
        ImVec2 const a(r.x, r.y), b(r.x + r.z, r.y + r.w);
        overview.cells.push_back({views[i], r});
        std::string_view const name = overviewLabel(views[i]);
        dl->AddText(ImVec2(r.x + 2.0f, r.y - label + 1.0f), IM_COL32(235, 235, 235, 255), name.data(),
                    name.data() + name.size());
        // prepass: its thin G-buffer's views, light targets and lit image are shown; what it never stores is not.
        bool const empty = settings.mode == LightingMode::Prepass
                               ? thinGBufferLacks(views[i])
                               : shadesForward(settings.mode) && views[i] != DebugView::Final;
        if (empty)
            centredMessage(a, b,
                           settings.mode == LightingMode::Forward   ? "forward mode: no G-buffer"
                           : settings.mode == LightingMode::Prepass ? "prepass mode: not in its thin G-buffer"
                                                                    : "forward+ mode: no G-buffer");
        else if (i < textures.size() && textures[i] != 0)
            dl->AddImage(toImTexture(textures[i]), a, b, ImVec2(0, 1), ImVec2(1, 0));
        else
            centredMessage(a, b, "no frame yet");
        // The cell under the mouse is outlined: a click shows it full size.
        bool const hot =
            ImGui::IsItemHovered() &&
            overviewCellAt(overview.cells, glm::vec2(ImGui::GetIO().MousePos.x, ImGui::GetIO().MousePos.y)) == int(i);
        dl->AddRect(ImVec2(a.x - 1.0f, a.y - 1.0f), ImVec2(b.x + 1.0f, b.y + 1.0f),
                    hot ? IM_COL32(255, 230, 80, 255) : IM_COL32(70, 70, 78, 255), 0.0f, 0, hot ? 2.0f : 1.0f);
    }
    if (rects.empty())
        centredMessage(origin, ImVec2(origin.x + avail.x, origin.y + avail.y), "too small for the overview");
}

}  // namespace

void drawViewportPanel(ViewportState& state, PipelineSettings& settings, LitPin& litPin, ViewportTools& tools,
                       unsigned texture, glm::ivec2 textureSize, std::optional<glm::vec2> selectedLight,
                       ViewportTeaching* ab, std::optional<glm::ivec2> lockedPixel,
                       std::span<unsigned const> overviewTextures) {
    state.hovered = false;
    state.hoverPixel.reset();
    state.clickPixel.reset();
    state.doubleClickPixel.reset();
    state.orbitDrag = state.lookDrag = state.panDrag = glm::vec2(0.0f);
    state.wheel = 0.0f;
    state.frameRequested = false;
    OverviewState& overview = state.overview;
    overview.cells.clear();

    // No padding: the image fills the window edge to edge.
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
    bool const open = ImGui::Begin(windowName(EditorWindow::Viewport), nullptr,
                                   ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
    ImGui::PopStyleVar();
    if (!open) {
        // Collapsed or a hidden tab (another window tabbed over it): the frame keeps its last size,
        // so the G-buffer viewers, which show its attachments, keep their images.
        ImGui::End();
        return;
    }

    ImGui::SetCursorPos(ImVec2(ImGui::GetCursorPosX() + 6, ImGui::GetCursorPosY() + 3));
    // The toolbar wraps where the window is too narrow for it (a large UI scale, a narrow dock).
    float const rightEdge = rowRightEdge();
    auto const buttonWidth = [](char const* label) {
        return ImGui::CalcTextSize(label, nullptr, true).x + 2.0f * ImGui::GetStyle().FramePadding.x;
    };
    viewCombo(settings);
    // An imported G-buffer has no scene: no cubes sized to one, and its camera cannot be moved.
    bool const fixedFrame = !state.importedFrame.empty();
    sameLineIfFits(checkItemWidth("Cubes"), false, rightEdge);
    ImGui::BeginDisabled(fixedFrame);
    ImGui::Checkbox("Cubes", &settings.lightCubes);
    ImGui::EndDisabled();
    if (fixedFrame && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("the light cubes are sized to a scene, which an imported G-buffer lacks");
    sameLineIfFits(checkItemWidth("Wireframes"), false, rightEdge);
    ImGui::Checkbox("Wireframes", &settings.volumeWireframes);
    state.wireframesRect = lastItemRect();
    sameLineIfFits(checkItemWidth("all"), false, rightEdge);
    // The selected light's volume by default (32 outlines bury the frame); every light's one click
    // away, which also turns the wireframes on.
    bool every = !settings.wireframesSelectedOnly;
    if (ImGui::Checkbox("all", &every)) {
        settings.wireframesSelectedOnly = !every;
        if (every) settings.volumeWireframes = true;
    }
    state.allWireframesRect = lastItemRect();
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "Outline every light's volume, not only the selected light's (Wireframes outlines the "
            "selected one)");
    sameLineIfFits(buttonWidth("Frame (F)"), false, rightEdge);
    ImGui::BeginDisabled(fixedFrame);
    if (ImGui::Button("Frame (F)")) state.frameRequested = true;
    ImGui::EndDisabled();
    sameLineIfFits(buttonWidth("Overview (G)"), false, rightEdge);
    ImGui::PushStyleColor(ImGuiCol_Button, overview.on ? IM_COL32(70, 110, 170, 255) : IM_COL32(50, 50, 55, 255));
    if (ImGui::Button("Overview (G)")) overview.on = !overview.on;
    ImGui::PopStyleColor();
    overview.buttonRect = lastItemRect();
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "the lit frame and the G-buffer's position, normal, albedo, specular and depth at once,\n"
            "each auto-ranged; click one to show it full size (G toggles)");
    sameLineIfFits(ImGui::CalcTextSize("(?)").x, false, rightEdge);
    ImGui::TextDisabled("(?)");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "left drag: orbit    right drag: look    middle drag: pan    wheel: dolly\n"
            "W A S D / Q E: fly (shift: faster)    F: frame the selection    Home: the scene's view\n"
            "click a light cube: select it    double-click: select and frame it\n"
            "L: lock the pixel inspector    G: attachment overview    F1: every shortcut");
    litPinRow(litPin, tools, settings.view, state);
    if (ab) teachingRow(*ab, settings);

    ImVec2 avail = ImGui::GetContentRegionAvail();
    ImVec2 const scale = ImGui::GetIO().DisplayFramebufferScale;
    state.size = glm::ivec2(std::max(0, int(avail.x * scale.x)), std::max(0, int(avail.y * scale.y)));
    if (avail.x < 1.0f || avail.y < 1.0f) {
        ImGui::End();
        return;
    }

    ImVec2 origin = ImGui::GetCursorScreenPos();
    bool const imported = !state.importedFrame.empty() && textureSize.x > 0 && textureSize.y > 0;
    if (imported) {
        // An imported G-buffer keeps its size: letterboxed in the window, never stretched.
        float const fit = std::min(avail.x / float(textureSize.x), avail.y / float(textureSize.y));
        ImVec2 const shown(std::max(1.0f, std::floor(float(textureSize.x) * fit)),
                           std::max(1.0f, std::floor(float(textureSize.y) * fit)));
        origin = ImVec2(std::floor(origin.x + (avail.x - shown.x) * 0.5f),
                        std::floor(origin.y + (avail.y - shown.y) * 0.5f));
        avail = shown;
        ImGui::SetCursorScreenPos(origin);
    }
    state.imageRect = glm::vec4(origin.x, origin.y, avail.x, avail.y);
    bool const abOn = ab && ab->ab.enabled && !overview.on;
    if (abOn && ab->ab.view == AbView::Split) abDivider(ab->ab, origin, avail);
    ImGui::InvisibleButton(
        "viewport-image", avail,
        ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight | ImGuiButtonFlags_MouseButtonMiddle);
    ImVec2 const imageEnd(origin.x + avail.x, origin.y + avail.y);
    bool const noGBuffer = settings.mode == LightingMode::Prepass
                               ? thinGBufferLacks(settings.view)
                               : shadesForward(settings.mode) && gbufferView(settings.view);
    if (overview.on) {
        drawOverview(overview, settings, overviewTextures, origin, avail, textureSize);
    } else if (abOn && ab->ab.view == AbView::Diff && ab->diffTexture != 0) {
        ImGui::GetWindowDrawList()->AddImage(toImTexture(ab->diffTexture), origin, imageEnd, ImVec2(0, 1),
                                             ImVec2(1, 0));
        drawAbDiff(*ab, settings, origin, avail);
    } else if (noGBuffer) {
        char text[256];
        std::snprintf(text, sizeof text,
                      settings.mode == LightingMode::Prepass
                          ? "prepass keeps a thin G-buffer of its own (normal and exponent, depth): '%s' is not in it "
                            "(the second geometry pass reads the materials). Its light targets: the diffuse_light and "
                            "specular_light views."
                          : "forward mode has no G-buffer: '%s' is not stored anywhere. Switch to quad, volumes or "
                            "tiled to see it.",
                      kDebugViewNames[std::size_t(settings.view)].data());
        centredMessage(origin, imageEnd, text);
    } else if (texture != 0) {
        // GL images start at the bottom row; flip v so the picture is upright.
        ImGui::GetWindowDrawList()->AddImage(toImTexture(texture), origin, imageEnd, ImVec2(0, 1), ImVec2(1, 0));
        drawMsaaViews(state.msaa, origin, imageEnd);
        // The heat views' legend sits at the bottom of the image: the split's pass lines go above it.
        bool const heat = settings.view == DebugView::Heatmap || settings.view == DebugView::TileLights;
        if (abOn && ab->ab.view == AbView::Split)
            drawAbSplit(*ab, settings, origin, avail, heat ? heatLegendHeight(origin, imageEnd, textureSize) : 0.0f);
        // The marked check finding's pixels, translucent over the frame (same size: the G-buffer's).
        if (imported && state.findingTexture != 0)
            ImGui::GetWindowDrawList()->AddImage(toImTexture(state.findingTexture), origin, imageEnd, ImVec2(0, 1),
                                                 ImVec2(1, 0));
    } else {
        ImGui::GetWindowDrawList()->AddText(ImVec2(origin.x + 10, origin.y + 10), IM_COL32(200, 200, 200, 255),
                                            "no frame yet");
    }

    if (overview.on) {
        // A click (not a drag) on a cell shows that view full size and leaves the overview; the
        // drags still move the camera, and nothing else of the full-size view applies.
        ImGuiIO const& io = ImGui::GetIO();
        state.hovered = ImGui::IsItemHovered();
        if (state.hovered && ImGui::IsMouseReleased(ImGuiMouseButton_Left) &&
            io.MouseDragMaxDistanceSqr[ImGuiMouseButton_Left] < kClickSlopSq) {
            int const cell = overviewCellAt(overview.cells, glm::vec2(io.MousePos.x, io.MousePos.y));
            if (cell >= 0) {
                settings.view = overview.cells[std::size_t(cell)].view;
                overview.on = false;
                overview.cells.clear();
            }
        }
        if (ImGui::IsItemActive()) {
            glm::vec2 const delta(io.MouseDelta.x, io.MouseDelta.y);
            if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) state.orbitDrag = delta;
            if (ImGui::IsMouseDown(ImGuiMouseButton_Right)) state.lookDrag = delta;
            if (ImGui::IsMouseDown(ImGuiMouseButton_Middle)) state.panDrag = delta;
        }
        if (state.hovered) state.wheel = io.MouseWheel;
        ImGui::End();
        return;
    }
    if (selectedLight && texture != 0) {
        ImVec2 const c(origin.x + selectedLight->x * avail.x, origin.y + selectedLight->y * avail.y);
        ImDrawList* dl = ImGui::GetWindowDrawList();
        dl->PushClipRect(origin, ImVec2(origin.x + avail.x, origin.y + avail.y), true);
        dl->AddCircle(c, 11.0f, IM_COL32(0, 0, 0, 200), 24, 3.0f);
        dl->AddCircle(c, 11.0f, IM_COL32(255, 230, 80, 255), 24, 1.5f);
        dl->PopClipRect();
    }
    if (lockedPixel && textureSize.x > 0 && textureSize.y > 0) {
        ImDrawList* dl = ImGui::GetWindowDrawList();
        dl->PushClipRect(origin, imageEnd, true);
        markLockedPixel(dl, origin, avail, textureSize, *lockedPixel);
        dl->PopClipRect();
    }
    // A lesson step's measured pixel (its claim's `mark`): a ring and the measurement beside it, on
    // the side of the ring with room, kept inside the image.
    if (state.lessonMark && texture != 0 && textureSize.x > 0 && textureSize.y > 0) {
        ViewportState::Mark const& m = *state.lessonMark;
        ImVec2 const c(origin.x + (float(m.pixel.x) + 0.5f) * avail.x / float(textureSize.x),
                       origin.y + (float(m.pixel.y) + 0.5f) * avail.y / float(textureSize.y));
        ImDrawList* dl = ImGui::GetWindowDrawList();
        dl->PushClipRect(origin, imageEnd, true);
        dl->AddCircle(c, 14.0f, IM_COL32(0, 0, 0, 220), 32, 4.0f);
        dl->AddCircle(c, 14.0f, IM_COL32(255, 60, 200, 255), 32, 2.0f);
        dl->PopClipRect();
        ImVec2 const size = ImGui::CalcTextSize(m.label.c_str());
        float const line = ImGui::GetTextLineHeightWithSpacing();
        float x = c.x + 20.0f <= imageEnd.x - size.x - 8.0f ? c.x + 20.0f : c.x - 20.0f - size.x - 8.0f;
        x = std::clamp(x, origin.x + 4.0f, std::max(origin.x + 4.0f, imageEnd.x - size.x - 12.0f));
        float y = c.y + 18.0f + line <= imageEnd.y ? c.y + 18.0f : c.y - 18.0f - line;
        y = std::clamp(y, origin.y + 4.0f, std::max(origin.y + 4.0f, imageEnd.y - line - 4.0f));
        boxedText(ImVec2(x, y), m.label);
    }
    // A frame stopped after a pass (the Frame window's "Stop here") says so over the image, and so
    // does a camera inside a light's volume (why the volume passes lose that light with cull back).
    // Below the A/B header's lines (drawAbSplit: two; drawAbDiff: three, with its numbers).
    int const abLines = !abOn ? 0 : ab->ab.view == AbView::Diff ? 3 : 2;
    float notesY = origin.y + 6.0f + float(abLines) * ImGui::GetTextLineHeightWithSpacing() + (abOn ? 4.0f : 0.0f);
    if (!state.stoppedAfter.empty() && texture != 0) {
        boxedText(ImVec2(origin.x + 8, notesY), "stopped after " + state.stoppedAfter);
        notesY += ImGui::GetTextLineHeightWithSpacing() + 4.0f;
    }
    if (!state.cameraInside.empty() && texture != 0) {
        boxedText(ImVec2(origin.x + 8, notesY), cameraInsideText(state.cameraInside));
        notesY += ImGui::GetTextLineHeightWithSpacing() + 4.0f;
    }
    if (imported && state.markedFinding >= 0 && std::size_t(state.markedFinding) < state.findings.size()) {
        GBufferFinding const& f = state.findings[std::size_t(state.markedFinding)];
        boxedText(ImVec2(origin.x + 8, notesY), "marked: " + f.check + ", " + std::to_string(f.pixels) + " px");
        notesY += ImGui::GetTextLineHeightWithSpacing() + 4.0f;
    }
    if (imported)
        boxedText(ImVec2(origin.x + 8, notesY), "G-buffer " + shortName(state.importedFrame) +
                                                    ": camera fixed to the imported frame; lights editable");
    // The tools' Shift+drag and Shift+right-click are theirs, not the camera's.
    bool const toolsMouse = viewportToolsImage(tools, origin, avail, textureSize);
    if (settings.view == DebugView::Heatmap || settings.view == DebugView::TileLights)
        labelHeatLegend(origin, ImVec2(origin.x + avail.x, origin.y + avail.y), textureSize, settings.view,
                        settings.mode);
    if (settings.view == DebugView::ClusterSlices)
        labelSliceLegend(origin, ImVec2(origin.x + avail.x, origin.y + avail.y), textureSize, state.clipPlanes);

    ImGuiIO const& io = ImGui::GetIO();
    state.hovered = ImGui::IsItemHovered();
    if (state.hovered && textureSize.x > 0 && textureSize.y > 0) {
        // Mouse to renderer pixel: the image may be stretched for one frame after a resize.
        float const u = (io.MousePos.x - origin.x) / avail.x, v = (io.MousePos.y - origin.y) / avail.y;
        if (u >= 0.0f && u < 1.0f && v >= 0.0f && v < 1.0f)
            state.hoverPixel = glm::ivec2(int(u * float(textureSize.x)), int(v * float(textureSize.y)));
        state.wheel = io.MouseWheel;
    }
    if (ImGui::IsItemActive() && !toolsMouse) {
        glm::vec2 const delta(io.MouseDelta.x, io.MouseDelta.y);
        if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) state.orbitDrag = delta;
        if (ImGui::IsMouseDown(ImGuiMouseButton_Right)) state.lookDrag = delta;
        if (ImGui::IsMouseDown(ImGuiMouseButton_Middle)) state.panDrag = delta;
    }
    if (state.hovered && ImGui::IsMouseReleased(ImGuiMouseButton_Left) &&
        io.MouseDragMaxDistanceSqr[ImGuiMouseButton_Left] < kClickSlopSq && state.hoverPixel)
        state.clickPixel = state.hoverPixel;
    // Decided on event times (model/input_events.h), so it works at a few frames per second.
    if (state.hovered && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left) && state.hoverPixel)
        state.doubleClickPixel = state.hoverPixel;
    ImGui::End();
}

}  // namespace gbl::ui
