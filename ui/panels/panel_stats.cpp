// Stats window: frame and pass times (ImPlot history and a table), lights, memory, editor cost.
#include "panels/panel_stats.h"

#include "core/frame_memory.h"
#include "core/gbuffer_layout.h"
#include "core/msaa.h"
#include "core/timing_source.h"
#include "panels/gui_util.h"
#include "panels/layout.h"
#include "panels/wrapped_text.h"

#include <imgui.h>
#include <implot.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace gbl::ui {

namespace {
// The frame and renderer times, and each pass's, over the last StatsState::kHistory frames as
// ImPlot lines: x counts frames back from the newest (0), the ring's oldest sample first.
void drawTimingPlots(StatsState const& stats, bool timed) {
    int const offset = stats.count == StatsState::kHistory ? stats.next : 0;
    double const start = -double(std::max(stats.count - 1, 0));
    float const height = ImGui::GetFontSize() * 9.0f;
    ImPlotFlags const flags = ImPlotFlags_NoMenus | ImPlotFlags_NoBoxSelect | ImPlotFlags_NoMouseText;
    ImPlotAxisFlags const xFlags = ImPlotAxisFlags_Lock | ImPlotAxisFlags_NoMenus;
    ImPlotAxisFlags const yFlags = ImPlotAxisFlags_AutoFit | ImPlotAxisFlags_NoMenus;
    ImPlotSpec spec;
    spec.Offset = offset;
    if (ImPlot::BeginPlot("##frame times", ImVec2(-1.0f, height), flags)) {
        ImPlot::SetupAxes("frames ago", "ms", xFlags, yFlags);
        ImPlot::SetupAxisLimits(ImAxis_X1, -double(StatsState::kHistory - 1), 0.0, ImPlotCond_Always);
        ImPlot::SetupLegend(ImPlotLocation_NorthWest, ImPlotLegendFlags_NoButtons | ImPlotLegendFlags_Horizontal);
        ImPlot::PlotLine("frame", stats.frameMs.data(), stats.count, 1.0, start, spec);
        if (timed) ImPlot::PlotLine("renderer", stats.gpuFrameMs.data(), stats.count, 1.0, start, spec);
        ImPlot::EndPlot();
    }
    if (!timed || stats.passes.empty()) return;
    if (ImPlot::BeginPlot("##pass times", ImVec2(-1.0f, height * 1.4f), flags)) {
        ImPlot::SetupAxes("frames ago", "pass ms", xFlags, yFlags);
        ImPlot::SetupAxisLimits(ImAxis_X1, -double(StatsState::kHistory - 1), 0.0, ImPlotCond_Always);
        // Outside, so the lines stay visible under a long list of passes; a click on an entry hides it.
        ImPlot::SetupLegend(ImPlotLocation_South, ImPlotLegendFlags_Outside | ImPlotLegendFlags_Horizontal);
        for (StatsState::PassHistory const& p : stats.passes)
            ImPlot::PlotLine(p.name.c_str(), p.ms.data(), stats.count, 1.0, start, spec);
        ImPlot::EndPlot();
    }
}
}  // namespace

void drawStatsPanel(StatsState const& stats, std::string const& noFragmentCounts, int lightCount,
                    long long maxStorageBlockBytes, RenderOnChange* render, std::string const& renderReason,
                    FramePanelState* frame) {
    if (ImGui::Begin(windowName(EditorWindow::Stats), nullptr)) {
        FrameStats const& f = stats.last;
        double const frameMs = stats.costAverage.frameCpuMs;
        ImGui::Text("Frame %.2f ms (%.0f fps)", frameMs, frameMs > 0.0 ? 1000.0 / frameMs : 0.0);
        float const right = rowRightEdge();
        if (frame) {
            // One click to the frame's passes as a diagram (View > Frame diagram does the same),
            // beside the first line, the shorter one, so the short default window shows it.
            char const* label = frame->open ? "Hide diagram" : "Frame diagram";
            sameLineIfFits(ImGui::CalcTextSize(label).x + 2.0f * ImGui::GetStyle().FramePadding.x, false, right);
            if (ImGui::SmallButton(label)) frame->open = !frame->open;
            if (ImGui::IsItemHovered())
                ImGui::SetTooltip("the frame's passes, their resources and what flows between them");
            ImVec2 const min = ImGui::GetItemRectMin(), size = ImGui::GetItemRectSize();
            frame->openButton = glm::vec4(min.x, min.y, size.x, size.y);
        }
        // Where no timer query attributes work to passes (software rasterisers, WebGL2) the passes
        // are timed on the CPU between glFinish calls: labelled so, with the reason on hover.
        bool const cpuTimed = f.timingSource == timingSourceName(TimingSource::CpuFinish);
        bool const timed = passesTimed(f.timingSource);
        if (!timed) {
            // A browser without timer queries: the passes' CPU times say nothing there, so only
            // the frame's own time (the line above) is shown.
            ImGui::TextDisabled("Renderer at %dx%d: not timed in this browser", f.width, f.height);
            if (ImGui::IsItemHovered())
                ImGui::SetTooltip("%s;\nthe frame time above, measured on the CPU, is the measure here",
                                  f.timingReason.c_str());
        } else {
            ImGui::Text("Renderer %s %.2f ms at %dx%d", cpuTimed ? "(CPU-timed)" : "GPU", f.gpuFrameMs, f.width,
                        f.height);
            if (ImGui::IsItemHovered() && !f.timingReason.empty()) ImGui::SetTooltip("%s", f.timingReason.c_str());
        }
        if (render) {
            // Render on change: an idle editor shows the last frame again instead of re-rendering it.
            if (render->renderedLastFrame) {
                ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.8f, 0.4f, 1.0f));
                wrappedText("Last frame: re-rendered (%s)", renderReason.c_str());
                ImGui::PopStyleColor();
            } else {
                ImGui::TextDisabled("Last frame: reused, nothing changed");
            }
            ImGui::Checkbox("Render every frame", &render->continuous);
            if (ImGui::IsItemHovered())
                ImGui::SetTooltip("for timing: run the renderer each frame even when nothing changed (--continuous)");
            char counts[64];
            std::snprintf(counts, sizeof counts, "%ld rendered, %ld reused", render->renders, render->skipped);
            sameLineIfFits(ImGui::CalcTextSize(counts).x, false, rowRightEdge());
            ImGui::TextDisabled("%s", counts);
        }
        ImGui::Text("Mode run: %s", enumName(kLightingModeNames, f.modeUsed).data());
        if (!f.fallbackReason.empty()) {
            ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.6f, 0.3f, 1.0f));
            wrappedText("%s", f.fallbackReason.c_str());
            ImGui::PopStyleColor();
        }
        drawTimingPlots(stats, timed);

        if (ImGui::BeginTable(
                "passes", 2,
                ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingStretchProp)) {
            // The number column is as wide as its widest value; names take the rest.
            ImGui::TableSetupColumn("pass", ImGuiTableColumnFlags_WidthStretch);
            ImGui::TableSetupColumn("GPU ms", ImGuiTableColumnFlags_WidthFixed,
                                    ImGui::CalcTextSize("GPU ms 000.000").x);
            ImGui::TableHeadersRow();
            for (auto const& p : f.passes) {
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(p.name.c_str());
                auto const c = std::find_if(f.calls.begin(), f.calls.end(),
                                            [&](PassCalls const& calls) { return calls.name == p.name; });
                if (c != f.calls.end() && ImGui::IsItemHovered())
                    ImGui::SetTooltip("%s: %llu draws, %llu triangles, %llu dispatches this frame", p.name.c_str(),
                                      (unsigned long long)c->draws, (unsigned long long)c->triangles,
                                      (unsigned long long)c->dispatches);
                ImGui::TableNextColumn();
                if (!timed)
                    ImGui::TextDisabled("not timed");
                else
                    ImGui::Text("%.3f", p.gpuMs);
            }
            ImGui::EndTable();
        }

        // Every pass's draws and triangles summed: prepass draws the scene twice, and says so here.
        wrappedText("Draw calls %llu, triangles %llu (per pass: hover a row, or the Frame window)",
                    (unsigned long long)f.draws(), (unsigned long long)f.triangles());
        wrappedText("Lights: %d in the list, %d submitted, %d shaded", lightCount, f.lightsSubmitted, f.lightsShaded);
        if (f.fragmentInvocations)
            wrappedText("Fragment invocations (lighting): %llu", (unsigned long long)*f.fragmentInvocations);
        else {
            ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
            wrappedText("Fragment invocations: n/a (%s)", noFragmentCounts.c_str());
            ImGui::PopStyleColor();
        }
        ImGui::Text("GL errors this frame: %llu", (unsigned long long)f.glErrors);

        // The G-buffer's cost from its description (core/gbuffer_layout.h): what packing saves; the
        // forward modes write none (core/frame_memory.h), and their own targets are counted instead.
        GBufferLayoutDesc const& layout = layoutDesc(f.layout);
        FrameMemory const memory = frameMemory(f.modeUsed, layout, f.width, f.height, maxStorageBlockBytes);
        separatorText(memory.gbuffer ? "G-buffer memory" : "Frame memory");
        if (memory.gbuffer) {
            ImGui::Text("Layout %s: %d bytes a pixel", layout.name.data(), layoutBytesPerPixel(layout));
            for (GBufferAttachmentDesc const& a : layout.attachments())
                ImGui::TextDisabled("  %s %s: %d B", a.name.data(), texelFormatName(a.format).data(),
                                    texelBytes(a.format));
            if (std::string const note = layoutOmissionNote(layout); !note.empty()) {
                ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.6f, 0.3f, 1.0f));
                wrappedText("%s", note.c_str());
                ImGui::PopStyleColor();
            }
            wrappedText("%.1f MB at %dx%d, %.1f MB at 1080p, %.1f MB at 4K", layoutMegabytes(layout, f.width, f.height),
                        f.width, f.height, layoutMegabytes(layout, 1920, 1080), layoutMegabytes(layout, 3840, 2160));
        } else if (f.modeUsed == LightingMode::Prepass) {  // docs/deferred_lighting.md: a thin one of its own
            wrappedText(
                "prepass draws none of the layout's attachments: thin G-buffer %d B a pixel (RGBA16F normal "
                "and exponent, depth) + light targets %d B; classic %d B, packed %d B",
                prepassThinBytesPerPixel(layout), kPrepassLightBytesPerPixel,
                layoutBytesPerPixel(layoutDesc(GBufferLayout::Classic)),
                layoutBytesPerPixel(layoutDesc(GBufferLayout::Packed)));
        } else {
            wrappedText("No G-buffer in %s mode", std::string(enumName(kLightingModeNames, f.modeUsed)).c_str());
        }
        wrappedText("Frame: %.1f bytes a pixel (%.1f MB at %dx%d)", memory.bytesPerPixel(),
                    memory.bytesPerPixel() * f.width * f.height / 1.0e6, f.width, f.height);
        ImGui::PushTextWrapPos(0.0f);  // the parts and the msaa line wrap in a narrow column
        for (MemoryPart const& part : memory.parts)
            ImGui::TextDisabled("  %s: %.1f B", part.name.c_str(), part.bytesPerPixel);
        if (f.msaaUsed != Msaa::Off) {  // docs/msaa.md: every attachment holds that many samples
            int const n = msaaSamples(f.msaaUsed);
            wrappedText("MSAA %dx: %.1f MB at %dx%d; complex pixels %.1f%%", n,
                        msaaTargetBytes(layout, n, f.width, f.height) / 1.0e6, f.width, f.height,
                        100.0 * f.complexPixelShare.value_or(0.0));
        }
        ImGui::TextDisabled("%s", msaaMemoryLine(layout, f.width, f.height).c_str());
        ImGui::PopTextWrapPos();

        separatorText("Editor cost");
        EditorCost const& c = stats.costAverage;
        double const editor = c.uiCpuMs + c.viewersGpuMs + c.imguiGpuMs;
        ImGui::Text("UI build %.2f ms (CPU)", c.uiCpuMs);
        wrappedText("Viewers %.2f ms, ImGui draw %.2f ms (GPU)", c.viewersGpuMs, c.imguiGpuMs);
        wrappedText("Editor total %.2f ms = %.0f%% of the frame", editor,
                    frameMs > 0.0 ? 100.0 * editor / frameMs : 0.0);
    }
    ImGui::End();
}

}  // namespace gbl::ui
