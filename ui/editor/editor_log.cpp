// --log-frames: what each frame did, for tests that drive the real window from outside.
#include "editor_loop.h"

#include "model/browser_files.h"
#include "panels/clip_check.h"

#include <imgui.h>

#include <cstdio>

namespace gbl {

namespace {

// Lights a click on their cube's centre would select, in window coordinates: the test clicks
// there. At most a few, nearest to the middle of the image first is not needed: list order.
std::vector<ui::PickableLight> pickableLights(Editor& editor) {
    std::vector<ui::PickableLight> out;
    ui::EditorState const& state = editor.state;
    Renderer& renderer = *editor.renderer;
    glm::vec4 const rect = state.viewport.imageRect;
    if (renderer.width() <= 0 || renderer.height() <= 0 || rect.z <= 0.0f || rect.w <= 0.0f) return out;
    float const aspect = float(renderer.width()) / float(renderer.height());
    glm::mat4 const viewProjection = state.camera.projection(aspect) * state.camera.view();
    for (std::size_t i = 0; i < editor.drawn.size() && out.size() < 3; ++i) {
        glm::vec4 const clip = viewProjection * glm::vec4(editor.drawn[i].position, 1.0f);
        if (clip.w <= state.camera.nearPlane) continue;
        glm::vec2 const uv(clip.x / clip.w * 0.5f + 0.5f, 0.5f - clip.y / clip.w * 0.5f);
        // Keep clear of the edges, where a click might land on the viewport's frame.
        if (uv.x < 0.05f || uv.x > 0.95f || uv.y < 0.05f || uv.y > 0.95f) continue;
        glm::ivec2 const pixel(int(uv.x * float(renderer.width())), int(uv.y * float(renderer.height())));
        if (lightAtPixel(state, renderer, editor.drawn, pixel) != int(i)) continue;
        out.push_back({int(i), glm::vec2(rect.x + uv.x * rect.z, rect.y + uv.y * rect.w)});
    }
    return out;
}

}  // namespace

void logFrame(Editor& editor, FrameTimes const& times, double frameMs) {
    ui::EditorState const& state = editor.state;
    ui::FrameLogLine line;
    line.frame = editor.frame;
    line.rendered = times.rendered;
    line.renderReason = editor.renderReason;
    line.frameMs = frameMs;
    line.camera = state.camera.position;
    line.cameraAngles = {state.camera.yawDegrees, state.camera.pitchDegrees};
    line.selectedLight = state.lightsPanel.selected;
    line.textInput = ImGui::GetIO().WantTextInput;
    line.viewportHovered = state.viewport.hovered;
    line.viewport = state.viewport.imageRect;
    line.viewerImages.assign(state.gbuffer.imageRects.begin(), state.gbuffer.imageRects.end());
    line.accumulate = state.accumulate.enabled ? state.accumulate.count : -1;
    line.scrubber = state.accumulate.sliderRect;
    line.abToggle = state.ab.toggleRect;
    line.pinLit = state.litPin.pinRect;
    line.litDiff = state.litPin.diffRect;
    line.abDivider = state.ab.enabled && state.ab.view == ui::AbView::Split ? state.ab.divider : -1.0f;
    if (state.ab.enabled && state.ab.evaluations)
        line.abEvaluations = {state.ab.evaluations->first, state.ab.evaluations->second};
    line.pickable = pickableLights(editor);
    line.events = editor.actions.applied;
    for (ui::InputEvent const& e : editor.input.imguiFrame.events)
        if (e.kind == ui::InputKind::MouseButton || e.kind == ui::InputKind::Scroll)
            line.events.push_back(ui::describeEvent(e));
    line.actions = editor.actionLog;
    line.clipped = ui::clippedItems();
    line.sessionPath = editor.sessions->panel.currentPath;
    lessonLogFields(editor, line);  // ui/editor_lessons.cpp
    line.layout = std::string(enumName(kGBufferLayoutNames, state.pipeline.layout));
    line.pipelineWindow = editor.pipelineRects.window;
    line.layoutCombo = editor.pipelineRects.layoutCombo;
    line.layoutItems = editor.pipelineRects.layoutItems;
    line.msaaCombo = editor.pipelineRects.msaaCombo;
    line.msaaItems = editor.pipelineRects.msaaItems;
    line.msaaGreyed = editor.pipelineRects.msaaGreyed;
    line.msaaSamples = editor.state.viewport.msaa.samples;
    line.msaaComplexBox = editor.state.viewport.msaa.complexRect;
    line.positionSampleCombo = editor.state.gbuffer.sampleRects[0];
    line.positionSample = editor.state.gbuffer.viewers[0].sample;
    if (ui::ViewportTools const& tools = state.viewportTools; tools.open) {
        line.toolsImage = tools.viewer.imageSize;
        line.toolsRegion = glm::ivec4(0);
        if (tools.viewer.region)
            line.toolsRegion =
                glm::ivec4(tools.viewer.region->min, tools.viewer.region->max - tools.viewer.region->min);
    }
    line.frameWindow = state.frame.windowRect;
    line.frameButton = state.frame.openButton;
    line.stopButton = state.frame.stopButton;
    line.frameTargets = state.frame.targets;
    line.stopAfter = state.frame.stopAfter ? std::string(passName(*state.frame.stopAfter)) : std::string();
    line.stoppedAfter = state.stats.last.stoppedAfter ? std::string(passName(*state.stats.last.stoppedAfter)) : "";
    line.cameraInside = state.viewport.cameraInside;
    line.wireframes = ui::outlinedVolumes(ui::editorFrameInput(state, editor.drawn, false));
    line.wireframesToggle = state.viewport.wireframesRect;
    line.wireframesAll = state.viewport.allWireframesRect;
    line.litDiffShown = state.litPin.showDiff;
    line.everyLight = state.inspector.everyLight;
    line.checksButton = state.viewport.checksRect;
    line.findings = int(state.viewport.findings.size());
    line.firstFinding = state.viewport.firstFindingRect;
    line.markedFinding = state.viewport.markedFinding;
    line.precisionLines = state.viewport.precisionShown;
    ui::OverviewState const& overview = state.viewport.overview;
    line.overview = overview.on;
    line.presentation = state.layout.presentation;
    line.presentationCaption = state.layout.presentationCaption;
    line.presentationItem = state.layout.presentationItemRect;
    line.uiScale = state.layout.scale.current;
    line.dockLayout = ui::dockLayoutName(state.layout.builtKind);
    line.viewerArea = state.gbuffer.imageArea;
    for (std::size_t i = 0; i < state.layout.docks.size(); ++i) {
        ui::WindowDock const& d = state.layout.docks[i];
        char id[16];
        std::snprintf(id, sizeof id, "=%x", d.dockId);
        line.docks.push_back(std::string(ui::kEditorWindowNames[i]) + id);
        line.windowTabs.push_back(d.tab);
    }
    line.lightsWindow = state.lightsPanel.window;
    line.plotRect = state.lightsPanel.plotRect;
    line.kqField = state.lightsPanel.kqFieldRect;
    line.plotRadius = state.lightsPanel.plotRadius;
    line.plotGhostRadius = state.lightsPanel.plotGhostRadius;
    line.plotPopup = state.lightsPanel.plotPopupRect;
    line.plotPopupRadius = state.lightsPanel.plotPopupRadius;
    line.plotLight = state.lightsPanel.plotLight;
    line.overviewButton = overview.buttonRect;
    for (ui::OverviewCell const& c : overview.cells) {
        char where[96];
        std::snprintf(where, sizeof where, "@%d,%d,%d,%d", int(c.image.x), int(c.image.y), int(c.image.z),
                      int(c.image.w));
        line.overviewCells.push_back(std::string(kDebugViewNames[std::size_t(c.view)]) + where);
    }
    line.gbuffer = editor.loading.gbuffer.path;
    line.frameSize = glm::ivec2(editor.renderer->width(), editor.renderer->height());
    line.fileMenu = state.layout.fileMenuRect;
    line.viewMenu = state.layout.viewMenuRect;
    line.resetLayoutItem = state.layout.resetLayoutRect;
    line.uiScaleMenu = state.layout.uiScaleMenuRect;
    line.uiScaleItems = state.layout.uiScaleItemRects;
    line.openGBufferItem = editor.loading.gbuffer.menuItemRect;
    line.openSceneItem = editor.loading.openItemRect;
    line.openFolderItem = editor.loading.openFolderItemRect;
    line.exportAllItem = editor.sessions->panel.exportAllItemRect;
    line.windowShotItem = editor.windowShot.itemRect;
    line.gbufferBrowser = editor.loading.gbuffer.browser.open;
    ui::ProgramCaptureState const& capture = editor.loading.capture;
    line.captureItem = capture.menuItemRect;
    line.captureDialog = capture.dialogOpen;
    line.captureCommand = capture.commandRect;
    line.captureFrame = capture.frameRect;
    line.captureOut = capture.outRect;
    line.captureEgl = capture.eglRect;
    line.captureButton = capture.captureButtonRect;
    line.capturing = ui::captureRunning(capture);
    line.captureError = capture.lastError;
    line.timing = state.stats.last.timingSource;
    line.status = editor.menuStatus;
    if (ui::kInBrowser) line.browserLimits = ui::browserLimits(editor.browserAbout, state.stats.last.timingSource);
    for (PassTiming const& p : state.stats.last.passes) line.passMs.emplace_back(p.name, p.gpuMs);
    editor.frameLog.write(line);
}

}  // namespace gbl
