// The editor's UI build: the ImGui frame, the main menu bar and every panel, and the UI tests'
// check that an editor window is usable.
#include "editor_loop.h"
#include "panels/item_rect.h"

#include <algorithm>

#include "model/browser_files.h"
#include "model/why_value.h"
#include "panels/gui_util.h"
#include "panels/layout.h"
#include "panels/panel_confirm.h"
#include "panels/panel_frame.h"
#include "panels/panel_gbuffer.h"
#include "panels/panel_lights.h"
#include "panels/panel_log.h"
#include "panels/panel_pipeline.h"
#include "panels/panel_pixel_inspector.h"
#include "panels/panel_presentation.h"
#include "panels/panel_scene_loading.h"
#include "panels/panel_shortcuts.h"
#include "panels/panel_stats.h"
#include "panels/panel_viewport.h"
#include "panels/viewer_tools.h"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>
#include <imgui_internal.h>

namespace gbl {

namespace {

using ui::EditorState;

// The selected light's centre in the viewport image (0..1, top-left origin), when in front.
std::optional<glm::vec2> selectedLightInImage(EditorState const& state, std::span<PointLight const> drawn,
                                              Renderer const& renderer) {
    int const i = state.lightsPanel.selected;
    if (i < 0 || i >= int(drawn.size()) || renderer.width() <= 0 || renderer.height() <= 0) return std::nullopt;
    float const aspect = float(renderer.width()) / float(renderer.height());
    glm::vec4 const clip =
        state.camera.projection(aspect) * state.camera.view() * glm::vec4(drawn[std::size_t(i)].position, 1.0f);
    if (clip.w <= state.camera.nearPlane) return std::nullopt;
    glm::vec2 const ndc = glm::vec2(clip) / clip.w;
    return glm::vec2(ndc.x * 0.5f + 0.5f, 0.5f - ndc.y * 0.5f);
}

char const* keysFor(ui::EditorAction action) {
    return ui::shortcutFor(action).keys.data();
}

EditRequest drawMainMenu(Editor& editor) {
    EditorState& state = editor.state;
    ui::SessionController& sessions = *editor.sessions;
    EditRequest edit;
    editor.loading.gbuffer.menuItemRect = glm::vec4(0.0f);
    editor.loading.capture.menuItemRect = glm::vec4(0.0f);
    editor.loading.openItemRect = glm::vec4(0.0f);
    editor.loading.openFolderItemRect = glm::vec4(0.0f);
    sessions.panel.exportAllItemRect = glm::vec4(0.0f);
    editor.windowShot.itemRect = glm::vec4(0.0f);
    if (!ImGui::BeginMainMenuBar()) return edit;
    bool const fileMenu = ImGui::BeginMenu("File");
    state.layout.fileMenuRect = ui::lastItemRect();
    if (fileMenu) {
        // A page never gets Ctrl+N: the browser opens a window with it.
        if (ImGui::MenuItem("New session", ui::kInBrowser ? nullptr : keysFor(ui::EditorAction::NewSession)))
            edit.newSession = true;
        ImGui::Separator();
        ui::drawSceneMenuItems(editor.loading);
        ImGui::Separator();
        ui::drawSessionMenuItems(sessions.panel);
        if (ui::kInBrowser) {
            // Natively `--screenshot` and the desktop's own tools take the window.
            if (ImGui::MenuItem("Save window as PNG")) editor.windowShot.framesLeft = 2;
            editor.windowShot.itemRect = ui::lastItemRect();
        }
        if (!ui::kInBrowser) {  // a page ends with its tab
            ImGui::Separator();
            if (ImGui::MenuItem("Quit", keysFor(ui::EditorAction::Quit))) edit.quit = true;
        }
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Edit")) {
        if (ImGui::MenuItem("Undo", keysFor(ui::EditorAction::Undo), false, sessions.history().canUndo()))
            edit.undo = true;
        if (ImGui::MenuItem("Redo", keysFor(ui::EditorAction::Redo), false, sessions.history().canRedo()))
            edit.redo = true;
        ImGui::EndMenu();
    }
    bool const viewMenu = ImGui::BeginMenu("View");
    state.layout.viewMenuRect = ui::lastItemRect();
    state.layout.resetLayoutRect = glm::vec4(0.0f);
    state.layout.presentationItemRect = glm::vec4(0.0f);
    state.layout.uiScaleMenuRect = glm::vec4(0.0f);
    state.layout.uiScaleItemRects.clear();
    if (viewMenu) {
        if (ImGui::MenuItem("Reset layout")) state.layout.resetRequested = true;
        state.layout.resetLayoutRect = ui::lastItemRect();
        ImGui::MenuItem("Presentation", keysFor(ui::EditorAction::TogglePresentation), &state.layout.presentation);
        state.layout.presentationItemRect = ui::lastItemRect();
        if (ImGui::MenuItem("Frame selection", keysFor(ui::EditorAction::FrameSelection))) edit.frameSelection = true;
        if (ImGui::MenuItem("Home view", keysFor(ui::EditorAction::HomeView))) edit.homeView = true;
        if (ImGui::MenuItem("Frame the whole scene")) ui::frameBounds(state.rig, state.camera, state.sceneBounds);
        ImGui::Separator();
        // UI scale: bigger text and controls for a projector; applied before the next frame. Its
        // row is measured before BeginMenu, which leaves the open submenu as the last item.
        ImVec2 const row = ImGui::GetCursorScreenPos();
        state.layout.uiScaleMenuRect = glm::vec4(row.x, row.y, ImGui::GetContentRegionAvail().x, ImGui::GetFontSize());
        if (ImGui::BeginMenu("UI scale")) {
            ui::UiScaleState& scale = state.layout.scale;
            for (ui::UiScaleChoice const& choice : ui::kUiScaleChoices) {
                if (ImGui::MenuItem(choice.label, nullptr, scale.current == choice.scale))
                    scale.requested = choice.scale;
                state.layout.uiScaleItemRects.push_back(ui::lastItemRect());
            }
            ImGui::EndMenu();
        }
        ImGui::Separator();
        // The Frame window: the frame's passes as a diagram (over the G-buffer strip while open).
        ImGui::MenuItem("Frame diagram", nullptr, &state.frame.open);
        std::vector<ui::NamedView> const fileViews =
            ui::sceneCameraViews(state.sceneCameras, state.sceneBounds, state.rig);
        if (!fileViews.empty()) ui::separatorText("The file's cameras");
        for (std::size_t i = 0; i < fileViews.size(); ++i) {
            ImGui::PushID(int(i));
            if (ImGui::MenuItem(fileViews[i].name.c_str())) {
                state.camera = fileViews[i].view.camera;
                state.rig = fileViews[i].view.rig;
            }
            ImGui::PopID();
        }
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Help")) {
        if (ImGui::MenuItem("Shortcuts", keysFor(ui::EditorAction::ShowShortcuts))) editor.showShortcuts = true;
        if (ImGui::MenuItem("Glossary")) editor.glossaryWindow.open = true;
        if (ui::kInBrowser && ImGui::MenuItem("About this browser")) editor.browserAbout.open = true;
        ImGui::EndMenu();
    }
    GlCaps const& caps = editor.caps;
    // Status on the right: context and the newest log line.
    std::string status = caps.renderer + " | GL " + std::to_string(caps.major) + "." + std::to_string(caps.minor);
    if (!state.log.lines.empty()) status = state.log.lines.back() + "   " + status;
    editor.menuStatus = status;
    float const width = ImGui::CalcTextSize(status.c_str()).x;
    float const x = ImGui::GetWindowWidth() - width - 12.0f;
    if (x > ImGui::GetCursorPosX()) {
        ImGui::SetCursorPosX(x);
        ImGui::TextDisabled("%s", status.c_str());
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("light loops: %s", caps.lightLoopsNote().c_str());
    }
    ImGui::EndMainMenuBar();
    return edit;
}

// The docked layout's windows but the Lessons window (drawn by drawLessons in both layouts).
void drawDockedPanels(Editor& editor, FrameTimes const& times, unsigned viewportTexture,
                      std::optional<float> pixelDistance) {
    EditorState& state = editor.state;
    Renderer const& renderer = *editor.renderer;
    ui::drawLightsPanel(state.lightsPanel, state.lights, state.animation, state.sceneBounds, pixelDistance);
    GlCaps const& caps = editor.renderer->caps();
    ui::MsaaReasons const msaa = ui::msaaReasons([&](int n) { return caps.msaaUnavailableReason(n); });
    ui::drawPipelinePanel(state.pipeline,
                          ui::modeReasons([&](LightingMode m) { return editor.renderer->modeUnavailable(m); }),
                          &state.ab, &editor.pipelineRects, &msaa);
    int const k = std::clamp(state.accumulate.count, 0, int(state.lights.size()));
    ui::ViewportTeaching ab{state.ab,
                            state.accumulate,
                            int(state.lights.size()),
                            k > 0 ? state.lights[std::size_t(k - 1)].name : std::string(),
                            ui::sideB(state.ab, state.pipeline),
                            editor.gpu.ab.b.texture.id(),
                            editor.gpu.ab.diff.id()};
    state.viewport.clipPlanes = {state.camera.nearPlane, state.camera.farPlane};
    state.viewport.findingTexture = ui::findingMaskTexture(editor.gpu.viewerTools, editor.loading.gbuffer.checks,
                                                           editor.loading.gbuffer.path, state.viewport.markedFinding);
    state.viewport.cameraInside = ui::lightsAroundEye(state.camera.position, editor.drawn, state.pipeline.volumeScale);
    state.viewport.stoppedAfter =
        state.stats.last.stoppedAfter ? std::string(passName(*state.stats.last.stoppedAfter)) : std::string();
    ui::drawViewportPanel(state.viewport, state.pipeline, state.litPin, state.viewportTools, viewportTexture,
                          {renderer.width(), renderer.height()}, selectedLightInImage(state, editor.drawn, renderer),
                          &ab, state.inspector.locked ? state.inspector.pixel : std::nullopt, times.overviewTextures);
    for (std::size_t i = 0; i < state.gbuffer.viewers.size(); ++i) {
        ui::ViewerKind const kind = state.gbuffer.viewers[i].kind;
        state.gbuffer.noGBuffer[i] = ui::noGBufferNote(state.pipeline.mode, kind);
        state.gbuffer.source[i] = ui::thinGBufferSource(state.pipeline.mode, kind);
    }
    ui::drawGBufferPanel(state.gbuffer, times.viewerTextures, {renderer.width(), renderer.height()},
                         state.inspector.locked ? state.inspector.pixel : std::nullopt);
    ui::drawFramePanel(state.frame, state.pipeline, state.stats.last);
    ui::drawViewerMagnifier(state.gbuffer, state.viewportTools);
    ui::drawPixelInspectorPanel(state.inspector);
    ui::drawStatsPanel(state.stats, editor.caps.pipelineStatisticsUnavailableReason(), int(state.lights.size()),
                       editor.caps.maxStorageBlockBytes, &editor.render, editor.renderReason, &state.frame);
    ui::drawLogPanel(state.log);
}

}  // namespace

std::string windowProblem(ui::EditorWindow which) {
    ImGuiWindow const* w = ImGui::FindWindowByName(ui::windowName(which));
    if (!w) return "does not exist";
    if (!w->Active) return "was not drawn this frame";
    if (w->Hidden) return "is hidden";
    if (w->Collapsed) return "is collapsed";
    if (w->Size.x < 40.0f || w->Size.y < 40.0f) return "is too small to use";
    ImVec2 const display = ImGui::GetIO().DisplaySize;
    if (w->Pos.x < -1.0f || w->Pos.y < -1.0f || w->Pos.x + w->Size.x > display.x + 1.0f ||
        w->Pos.y + w->Size.y > display.y + 1.0f)
        return "extends past the window";
    return {};
}

EditRequest drawPanels(Editor& editor, FrameTimes const& times) {
    EditorState& state = editor.state;
    Renderer const& renderer = *editor.renderer;
    applyRequestedUiScale(editor);  // a scale chosen in the last frame's View menu
    ImGui_ImplOpenGL3_NewFrame();
    feedImGuiEvents(editor.input, editor.window());
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    markImGuiDoubleClicks(editor.input);
    EditRequest const edit = drawMainMenu(editor);
    ui::beginLayout(state.layout);
    // The inspected pixel's distance from the selected light as drawn (animation included).
    std::optional<float> pixelDistance;
    if (int const s = state.lightsPanel.selected;
        s >= 0 && std::size_t(s) < editor.drawn.size() && state.inspector.sample && state.inspector.sample->covered)
        pixelDistance =
            glm::distance(glm::vec3(state.inspector.sample->position), editor.drawn[std::size_t(s)].position);
    unsigned const viewportTexture = times.litDiffTexture         ? times.litDiffTexture
                                     : times.viewportToolsTexture ? times.viewportToolsTexture
                                                                  : renderer.texture(Attachment::Final);
    state.layout.presentationCaption = state.layout.presentationLesson = glm::vec4(0.0f);
    if (state.layout.presentation)
        ui::drawPresentationWindow(state.layout, state.viewport, state.pipeline, viewportTexture,
                                   editor.course.lessons.lesson >= 0);
    else
        drawDockedPanels(editor, times, viewportTexture, pixelDistance);
    drawLessons(editor);  // the Lessons window; applies the step it asks for (editor_lessons.cpp)
    // The Lessons window fitted again for each step and for a hint that appears.
    // The Lights window for its plot while a light is selected. Neither while presenting (the dock
    // tree is kept as it is).
    ui::LessonState const& lesson = editor.course.lessons;
    if (!state.layout.presentation) {
        // The viewport's image as drawn this frame: the frame the viewers show next has its size.
        glm::vec4 const image = state.viewport.imageRect;
        ui::fitStripHeight(state.layout.stripFit, state.gbuffer.imageArea, glm::ivec2(image.z, image.w));
        ui::fitWindowHeight(state.layout.lessonFit, ui::EditorWindow::Lessons, lesson.lesson >= 0,
                            long(lesson.lesson) * 100000 + lesson.step * 100 + lesson.hintsShown, lesson.regionShortPx);
        // In the one-column layout the plot shares its column with the lesson or the course, which
        // keeps its first rows.
        int const keepLines = state.layout.builtKind == ui::DockLayoutKind::OneColumn ? 4 : 1;
        ui::fitWindowHeight(state.layout.lightsFit, ui::EditorWindow::Lights, state.lightsPanel.plotShortPx >= 0.0f,
                            state.lightsPanel.selected, std::max(0.0f, state.lightsPanel.plotShortPx), keepLines);
    }
    ui::recordDocks(state.layout);
    ui::drawSceneLoadingUi(editor.loading);
    ui::drawShortcutsWindow(editor.showShortcuts);
    if (ui::kInBrowser)
        ui::drawBrowserAboutWindow(editor.browserAbout,
                                   ui::browserLimits(editor.browserAbout, state.stats.last.timingSource));
    ui::drawDiscardConfirmation(editor.discard);
    return edit;
}

}  // namespace gbl
