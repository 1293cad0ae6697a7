// Frame window: the diagram of the frame's declared passes (ui/model/frame_diagram.h lays it out).
#include "panels/panel_frame.h"

#include "panels/gui_util.h"
#include "panels/layout.h"
#include "panels/wrapped_text.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace gbl::ui {

namespace {

ImVec2 toIm(glm::vec2 v, ImVec2 origin) {
    return ImVec2(origin.x + v.x, origin.y + v.y);
}

// One hue per resource, so an arrow and its pins read as one thing.
ImU32 resourceColour(Resource r, float alpha) {
    float const hue = std::fmod(float(int(r)) * 0.61803f, 1.0f);
    ImColor c = ImColor::HSV(hue, 0.5f, 0.95f);
    c.Value.w = alpha;
    return ImU32(c);
}

ImU32 withAlpha(ImU32 c, float alpha) {
    ImVec4 v = ImGui::ColorConvertU32ToFloat4(c);
    v.w *= alpha;
    return ImGui::ColorConvertFloat4ToU32(v);
}

// "1.234 ms, 3 draws, 24576 triangles": the pass's GPU time and what it issued in the last frame (a
// compute pass's dispatches, a blit as such), then its fixed-function states.
std::string timeLine(PassDecl const& p, FrameStats const& last) {
    auto const t = std::find_if(last.passes.begin(), last.passes.end(),
                                [&](PassTiming const& timing) { return timing.name == p.name(); });
    auto const c = std::find_if(last.calls.begin(), last.calls.end(),
                                [&](PassCalls const& calls) { return calls.name == p.name(); });
    char text[64];
    if (t != last.passes.end())
        std::snprintf(text, sizeof text, "%.3f ms", t->gpuMs);
    else if (c != last.calls.end())
        std::snprintf(text, sizeof text, "ran");
    else
        std::snprintf(text, sizeof text, "not run");
    std::string out = text;
    auto const count = [](std::uint64_t n, char const* one, char const* many) {
        return std::to_string(n) + " " + (n == 1 ? one : many);
    };
    if (p.kind == PassKind::Compute)
        out += c != last.calls.end() ? ", " + count(c->dispatches, "dispatch", "dispatches") : ", compute";
    else if (p.kind == PassKind::Blit)
        out += ", blit";
    else if (c != last.calls.end())
        out += ", " + count(c->draws, "draw", "draws") + ", " + count(c->triangles, "triangle", "triangles");
    if (p.kind == PassKind::Raster && !p.states.empty())
        out += ", " + std::to_string(p.states.size()) + (p.states.size() == 1 ? " state" : " states");
    return out;
}

std::string target(char const* kind, std::string_view pass, std::string_view resource, ImVec2 at) {
    char xy[48];
    std::snprintf(xy, sizeof xy, "@%d,%d", int(std::lround(at.x)), int(std::lround(at.y)));
    std::string out = std::string(kind) + ":" + std::string(pass);
    if (!resource.empty()) {
        out += ':';
        out += resource;  // appended, not ":" + string: GCC 12 -O3's -Wrestrict false positive
    }
    return out + xy;
}

bool visibleIn(ImVec2 p, ImVec2 clipMin, ImVec2 clipMax) {
    return p.x >= clipMin.x && p.y >= clipMin.y && p.x <= clipMax.x && p.y <= clipMax.y;
}

// A pin: its circle on the box edge and its label inside; hovering says what a click does, a
// click on a resource with a view shows it in the viewport.
void pin(FramePanelState& state, PipelineSettings& settings, PassDecl const& pass, Resource r, bool input, ImVec2 at,
         float labelEdge, float alpha) {
    std::string_view const name = resourceName(r);
    float const w = ImGui::CalcTextSize(name.data(), name.data() + name.size()).x;
    float const line = ImGui::GetTextLineHeight();
    ImVec2 const min = input ? ImVec2(at.x - 5.0f, at.y - 0.5f * line) : ImVec2(labelEdge - w, at.y - 0.5f * line);
    ImVec2 const max = input ? ImVec2(labelEdge + w, at.y + 0.5f * line) : ImVec2(at.x + 5.0f, at.y + 0.5f * line);
    ImGui::SetCursorScreenPos(min);
    ImGui::PushID(input ? "in" : "out");
    ImGui::PushID(int(r));
    bool const clicked = ImGui::InvisibleButton("pin", ImVec2(max.x - min.x, max.y - min.y));
    bool const hovered = ImGui::IsItemHovered();
    ImGui::PopID();
    ImGui::PopID();
    std::optional<DebugView> const view = resourceView(r);
    bool const shown = view && *view == settings.view;
    ImDrawList* dl = ImGui::GetWindowDrawList();
    if (hovered || shown) dl->AddRectFilled(min, max, IM_COL32(255, 255, 255, hovered ? 40 : 24), 3.0f);
    dl->AddCircleFilled(at, 4.0f, resourceColour(r, alpha));
    if (shown) dl->AddCircle(at, 6.5f, IM_COL32(255, 230, 80, 255), 12, 1.5f);
    ImU32 const text = withAlpha(ImGui::GetColorU32(ImGuiCol_Text), alpha);
    dl->AddText(ImVec2(input ? labelEdge : labelEdge - w, at.y - 0.5f * line), text, name.data(),
                name.data() + name.size());
    if (hovered) {
        if (view)
            ImGui::SetTooltip("%s (%s of %s)\nclick: show it in the viewport (view '%s')", name.data(),
                              input ? "read" : "written", pass.name().data(),
                              kDebugViewNames[std::size_t(*view)].data());
        else
            ImGui::SetTooltip("%s (%s of %s)\nno view shows it in the viewport", name.data(),
                              input ? "read" : "written", pass.name().data());
    }
    if (clicked && view) settings.view = *view;
    ImVec2 const clipMin = ImGui::GetWindowDrawList()->GetClipRectMin();
    ImVec2 const clipMax = ImGui::GetWindowDrawList()->GetClipRectMax();
    ImVec2 const centre((min.x + max.x) * 0.5f, at.y);
    if (visibleIn(centre, clipMin, clipMax))
        state.targets.push_back(target(input ? "in" : "out", pass.name(), name, centre));
}

void drawArrow(ImDrawList* dl, EdgeRoute const& r, ImVec2 origin, ImU32 colour, float thickness) {
    std::vector<ImVec2> pts;
    for (glm::vec2 p : r.points) pts.push_back(toIm(p, origin));
    if (r.curve)
        dl->AddBezierCubic(pts[0], pts[1], pts[2], pts[3], colour, thickness);
    else
        dl->AddPolyline(pts.data(), int(pts.size()), colour, 0, thickness);
    ImVec2 const tip(pts.back().x - 4.0f, pts.back().y);
    dl->AddTriangleFilled(tip, ImVec2(tip.x - 7.0f, tip.y - 4.0f), ImVec2(tip.x - 7.0f, tip.y + 4.0f), colour);
}

void drawDiagram(FramePanelState& state, PipelineSettings& settings, FrameStats const& last) {
    std::vector<PassDecl> const& passes = state.passes;
    DiagramMetrics m;
    m.line = ImGui::GetTextLineHeight() + 2.0f;
    std::vector<PassBoxText> text;
    std::vector<std::string> times;
    for (PassDecl const& p : passes) {
        PassBoxText t;
        times.push_back(timeLine(p, last));
        t.header = std::max(ImGui::CalcTextSize(p.name().data()).x, ImGui::CalcTextSize(times.back().c_str()).x);
        for (Resource r : passInputs(p)) t.inputs.push_back(ImGui::CalcTextSize(resourceName(r).data()).x);
        for (Resource r : passOutputs(p)) t.outputs.push_back(ImGui::CalcTextSize(resourceName(r).data()).x);
        text.push_back(std::move(t));
    }
    DiagramLayout const d = layoutDiagram(passes, text, m);
    // The stop: passes after it (but the display pass) do not run, and are dimmed.
    auto const stopAt = std::find_if(passes.begin(), passes.end(),
                                     [&](PassDecl const& p) { return state.stopAfter && p.id == *state.stopAfter; });
    auto const skipped = [&](std::size_t i) {
        return stopAt != passes.end() && int(i) > int(stopAt - passes.begin()) && passes[i].id != PassId::Display;
    };
    ImVec2 const origin(ImGui::GetCursorScreenPos().x + 4.0f, ImGui::GetCursorScreenPos().y + 2.0f);
    ImDrawList* dl = ImGui::GetWindowDrawList();
    std::optional<std::size_t> hoveredBox;
    for (std::size_t i = 0; i < passes.size(); ++i) {
        BoxPlace const& b = d.boxes[i];
        float const alpha = skipped(i) ? 0.35f : 1.0f;
        ImVec2 const min = toIm(b.pos, origin), max = toIm(b.pos + b.size, origin);
        bool const selected = state.selected && *state.selected == passes[i].id;
        dl->AddRectFilled(min, max, withAlpha(IM_COL32(46, 50, 62, 255), alpha), 4.0f);
        ImGui::PushID(int(i));
        // Pins first: where they overlap the box, the pin takes the click.
        auto const ins = passInputs(passes[i]);
        auto const outs = passOutputs(passes[i]);
        for (std::size_t k = 0; k < ins.size(); ++k)
            pin(state, settings, passes[i], ins[k], true, toIm(b.inputs[k], origin), origin.x + b.inputLabelX, alpha);
        for (std::size_t k = 0; k < outs.size(); ++k)
            pin(state, settings, passes[i], outs[k], false, toIm(b.outputs[k], origin), origin.x + b.outputLabelRight,
                alpha);
        ImGui::SetCursorScreenPos(min);
        if (ImGui::InvisibleButton("pass", ImVec2(b.size.x, b.size.y))) state.selected = passes[i].id;
        if (ImGui::IsItemHovered()) {
            hoveredBox = i;
            ImGui::SetTooltip("%s: click for its declared state and Stop here", passes[i].name().data());
        }
        ImGui::PopID();
        ImU32 const border = selected                          ? IM_COL32(255, 230, 80, 255)
                             : hoveredBox == i                 ? IM_COL32(200, 200, 220, 255)
                             : state.stopAfter == passes[i].id ? IM_COL32(255, 140, 60, 255)
                                                               : withAlpha(IM_COL32(110, 116, 135, 255), alpha);
        dl->AddRect(min, max, border, 4.0f, 0, selected || state.stopAfter == passes[i].id ? 2.0f : 1.0f);
        ImU32 const title = withAlpha(ImGui::GetColorU32(ImGuiCol_Text), alpha);
        dl->AddText(ImVec2(min.x + m.pad, min.y + m.pad), title, passes[i].name().data());
        dl->AddText(ImVec2(min.x + m.pad, min.y + m.pad + m.line),
                    withAlpha(ImGui::GetColorU32(ImGuiCol_TextDisabled), alpha), times[i].c_str());
        ImVec2 const centre((min.x + max.x) * 0.5f, min.y + m.pad + 0.5f * m.line);
        if (visibleIn(centre, dl->GetClipRectMin(), dl->GetClipRectMax()))
            state.targets.push_back(target("pass", passes[i].name(), {}, centre));
    }
    for (EdgeRoute const& r : d.routes) {
        bool const dim = skipped(std::size_t(r.edge.to)) || skipped(std::size_t(r.edge.from));
        // The hovered pass's arrows stand out, else the selected one's.
        std::size_t const from = std::size_t(r.edge.from), to = std::size_t(r.edge.to);
        bool const lit =
            hoveredBox ? (from == *hoveredBox || to == *hoveredBox)
                       : state.selected && (passes[from].id == *state.selected || passes[to].id == *state.selected);
        drawArrow(dl, r, origin, resourceColour(r.edge.resource, dim ? 0.25f : lit ? 1.0f : 0.7f), lit ? 2.5f : 1.5f);
    }
    // The content's size, so the child scrolls to all of it.
    ImGui::SetCursorScreenPos(origin);
    ImGui::Dummy(ImVec2(d.size.x + 4.0f, d.size.y + 2.0f));
}

void drawDetails(FramePanelState& state, FrameStats const& last) {
    auto const find = [&](std::optional<PassId> id) {
        return std::find_if(state.passes.begin(), state.passes.end(),
                            [&](PassDecl const& p) { return id && p.id == *id; });
    };
    if (state.stopAfter) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.6f, 0.3f, 1.0f));
        wrappedText(
            "The frame stops after %s: the passes after it are skipped, the display pass shows the frame "
            "as it stands.",
            passName(*state.stopAfter).data());
        ImGui::PopStyleColor();
    }
    auto const selected = find(state.selected);
    if (selected == state.passes.end()) {
        ImGui::TextDisabled("Click a pass for its declared state,");
        ImGui::TextDisabled("a pin to show its resource.");
        state.stopButton = glm::vec4(0.0f);
        return;
    }
    PassDecl const& p = *selected;
    ImGui::Text("%s", p.name().data());
    ImGui::SameLine();
    bool const stopsHere = state.stopAfter == p.id;
    // The last pass: the display, or the last overlay drawn on it after the display pass.
    bool const last_ = selected + 1 == state.passes.end();
    if (last_) ImGui::BeginDisabled();
    if (ImGui::SmallButton(stopsHere ? "Run whole frame" : "Stop here")) {
        if (stopsHere)
            state.stopAfter.reset();
        else
            state.stopAfter = p.id;
    }
    if (last_) ImGui::EndDisabled();
    ImVec2 const bmin = ImGui::GetItemRectMin(), bsize = ImGui::GetItemRectSize();
    state.stopButton = glm::vec4(bmin.x, bmin.y, bsize.x, bsize.y);
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("%s", last_ ? "the frame's last pass: the whole frame runs"
                                : stopsHere
                                    ? "run every pass again"
                                    : "skip the passes after this one; the viewport shows the frame as it stands");
    if (state.stopAfter && !stopsHere) {
        ImGui::SameLine();
        if (ImGui::SmallButton("Run whole frame")) state.stopAfter.reset();
    }
    if (last.stoppedAfter && last.stoppedAfter != p.id) {
        auto const stop = find(last.stoppedAfter);
        if (stop != state.passes.end() && selected > stop && p.id != PassId::Display)
            ImGui::TextDisabled("(not run: the frame stopped before it)");
    }
    for (std::string const& line : describePass(p)) wrappedTextUnformatted(line);
}

}  // namespace

void drawFramePanel(FramePanelState& state, PipelineSettings& settings, FrameStats const& last) {
    state.targets.clear();
    state.windowRect = glm::vec4(0.0f);
    state.stopButton = glm::vec4(0.0f);
    if (!state.open) return;
    placeFrameWindow();
    bool const visible = ImGui::Begin(kFrameWindowName, &state.open);
    if (visible) {
        ImVec2 const pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
        state.windowRect = glm::vec4(pos.x, pos.y, size.x, size.y);
        ImVec2 const avail = ImGui::GetContentRegionAvail();
        float const detailsW = std::min(380.0f, std::floor(avail.x * 0.32f));
        float const diagramW = avail.x - detailsW - ImGui::GetStyle().ItemSpacing.x;
        if (beginFramedChild("diagram", ImVec2(diagramW, avail.y),
                             ImGuiWindowFlags_HorizontalScrollbar | ImGuiWindowFlags_NoScrollWithMouse)) {
            // The frame runs sideways: the wheel scrolls along it, Shift+wheel up and down.
            ImGuiIO const& io = ImGui::GetIO();
            if (ImGui::IsWindowHovered() && io.MouseWheel != 0.0f) {
                float const step = -io.MouseWheel * 3.0f * ImGui::GetFontSize();
                if (io.KeyShift)
                    ImGui::SetScrollY(ImGui::GetScrollY() + step);
                else
                    ImGui::SetScrollX(ImGui::GetScrollX() + step);
            }
            drawDiagram(state, settings, last);
        }
        ImGui::EndChild();
        ImGui::SameLine();
        if (beginFramedChild("details", ImVec2(detailsW, avail.y))) drawDetails(state, last);
        ImGui::EndChild();
    }
    ImGui::End();
}

}  // namespace gbl::ui
