// The clipping check on real ImGui frames (no GL: ImGui runs without a backend): a value cut at a
// table column's edge is reported, and the pixel inspector's value table leaves none cut at the
// 1280x720 layout, with the widest values "%.4g" writes.
#include "model/layout_state.h"
#include "model/pixel_inspector_state.h"
#include "panels/clip_check.h"
#include "panels/gui_util.h"
#include "panels/layout.h"
#include "panels/panel_pixel_inspector.h"

#include <gtest/gtest.h>
#include <imgui.h>

#include <algorithm>
#include <functional>
#include <string>

using namespace gbl;
using namespace gbl::ui;

namespace {

// Runs `frames` ImGui frames of `draw` at the display size and returns the last frame's cuts.
std::vector<std::string> cutsOf(glm::vec2 display, std::function<void()> const& draw, int frames = 3) {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(display.x, display.y);
    io.IniFilename = nullptr;
    enableConfigFlags(io);  // docking, as the editor has it: beginLayout builds a dock tree
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);  // builds the atlas: text has sizes
    std::vector<std::string> cuts;
    for (int f = 0; f < frames; ++f) {
        io.DeltaTime = 1.0f / 60.0f;
        ImGui::NewFrame();
        draw();
        ImGui::Render();
        cuts = clippedItems();
    }
    ImGui::DestroyContext();
    return cuts;
}

bool mentions(std::vector<std::string> const& cuts, std::string const& what) {
    return std::any_of(cuts.begin(), cuts.end(),
                       [&](std::string const& c) { return c.find(what) != std::string::npos; });
}

}  // namespace

TEST(ClipCheck, ReportsAValueCutAtAColumnEdgeAndNotOneThatFits) {
    auto table = [](float valueWidth) {
        return [valueWidth] {
            ImGui::SetNextWindowPos(ImVec2(0, 0));
            ImGui::SetNextWindowSize(ImVec2(400, 200));
            ImGui::Begin("Values", nullptr, ImGuiWindowFlags_NoSavedSettings);
            if (ImGui::BeginTable("t", 2, ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_BordersInnerV)) {
                ImGui::TableSetupColumn("v", ImGuiTableColumnFlags_WidthFixed, valueWidth);
                ImGui::TableSetupColumn("w", ImGuiTableColumnFlags_WidthFixed, 40.0f);
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                ImGui::Text("%.4g", -5.987e-05);
                ImGui::TableNextColumn();
                ImGui::TextUnformatted("1");
                ImGui::EndTable();
            }
            ImGui::End();
        };
    };
    // Narrower than the text: "-5.987e-05" loses its last digits at the column's edge.
    std::vector<std::string> const cut = cutsOf({800, 600}, table(30.0f));
    EXPECT_TRUE(mentions(cut, "Values: table column 0")) << (cut.empty() ? "nothing reported" : cut.front());
    // As wide as the font draws it: nothing to report.
    float textWidth = 0.0f;
    cutsOf(
        {800, 600}, [&] { textWidth = ImGui::CalcTextSize("-5.987e-05").x; }, 1);
    std::vector<std::string> const fits = cutsOf({800, 600}, table(textWidth));
    EXPECT_TRUE(fits.empty()) << fits.front();
}

TEST(ClipCheck, PixelInspectorCutsNoValueAt1280x720) {
    PixelInspectorState state;
    state.pixel = glm::ivec2(640, 360);
    state.source = "viewport";
    PixelSample s;
    s.covered = true;
    // The widest texts "%.4g" makes: negative with a two-digit exponent, and long fixed ones.
    s.position = {-5.987e-05f, -1234.567f, -0.0001234f, 1.0f};
    s.normal = {-0.7071068f, -5.987e-05f, -0.7071068f, 1.0f};
    s.albedoSpec = {0.1234567f, -8.888e-38f, 0.5f, 0.25f};
    s.depth = 0.987654321f;
    s.reconstructedPosition = {-5.987e-05f, -1234.567f, -0.0001234f};
    s.lighting = {-3.402e+38f, 12345.67f, -0.0001234f, 1.0f};
    state.sample = s;
    state.breakdownNote = "background: no surface, no lights";
    for (glm::vec2 const size : {glm::vec2(1280, 720), glm::vec2(1600, 900)}) {
        LayoutState layout;
        std::vector<std::string> const cuts = cutsOf(size, [&] {
            beginLayout(layout);
            drawPixelInspectorPanel(state);
        });
        EXPECT_FALSE(mentions(cuts, "Pixel")) << size.x << "x" << size.y << ": " << cuts.front();
    }
}
