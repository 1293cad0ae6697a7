// What the panels and the keyboard asked for this frame: light picking, the inspector's pixel,
// camera views and flight, session dialogs and shortcuts, undo and redo, and the question
// before unsaved edits are discarded.
#include "editor_loop.h"

#include "core/light_math.h"
#include "model/browser_files.h"
#include "panels/panel_scene_loading.h"

#include <imgui.h>

#include <algorithm>
#include <array>

namespace gbl {

namespace {

using ui::EditorAction;
using ui::EditorState;

ui::CameraInput gatherCameraInput(Editor const& editor, float dt) {
    EditorState const& state = editor.state;
    ui::CameraInput in;
    in.orbitDrag = state.viewport.orbitDrag;
    in.lookDrag = state.viewport.lookDrag;
    in.panDrag = state.viewport.panDrag;
    in.dolly = state.viewport.wheel;
    in.dt = dt;
    in.viewportHeight = float(std::max(state.viewport.size.y, 1));
    // The fly keys' share of this frame, from their events (model/input_events.h): only over the
    // viewport, never with Ctrl/Alt/Super or while a text field has the keyboard.
    in.move = editor.actions.move;
    in.fast = editor.actions.fast;
    return in;
}

// F: the selected light, or the scene from its home view when that is inside it.
void frameSelection(Editor& editor) {
    EditorState& state = editor.state;
    if (!state.viewport.importedFrame.empty()) return;  // the imported frame's camera is fixed
    int const i = state.lightsPanel.selected;
    if (i >= 0 && i < int(editor.drawn.size())) {
        PointLight const& light = editor.drawn[std::size_t(i)];
        ui::frameLight(state.rig, state.camera, light.position, lightRadius(light).radius, state.sceneBounds);
    } else {
        ui::frameNothingSelected(state.rig, state.camera, editor.home, state.sceneBounds);
    }
}

void homeView(Editor& editor) {
    if (!editor.state.viewport.importedFrame.empty()) return;
    editor.state.camera = editor.home.camera;
    editor.state.rig = editor.home.rig;
}

// Picking, the inspector's pixel and lock, camera views and flying the camera.
void handleViewRequests(Editor& editor, float dt) {
    EditorState& state = editor.state;
    ui::PixelInspectorState& inspector = state.inspector;
    if (state.viewport.clickPixel) pickLightAt(state, *editor.renderer, editor.drawn, *state.viewport.clickPixel);
    // A double click on a cube selects it and frames it.
    if (state.viewport.doubleClickPixel) {
        int const hit = lightAtPixel(state, *editor.renderer, editor.drawn, *state.viewport.doubleClickPixel);
        if (hit >= 0) {
            state.lightsPanel.selected = hit;
            frameSelection(editor);
            editor.actionLog.push_back("double-click-frame");
        }
    }
    if (state.gbuffer.showInViewport) state.pipeline.view = *state.gbuffer.showInViewport;
    if (inspector.selectLight >= 0) state.lightsPanel.selected = inspector.selectLight;
    if (!inspector.locked || !inspector.pixel) {
        if (state.viewport.hoverPixel) {
            inspector.pixel = state.viewport.hoverPixel;
            inspector.source = "viewport";
        } else if (state.gbuffer.hoverPixel) {
            inspector.pixel = state.gbuffer.hoverPixel;
            inspector.source = "G-buffer viewer";
        }
    }
    if (state.viewport.frameRequested) frameSelection(editor);
    // An imported G-buffer was drawn from one camera: the editor cannot look at it from another.
    if (state.viewport.importedFrame.empty())
        ui::applyCameraInput(state.rig, state.camera, gatherCameraInput(editor, dt));
}

// Whether an action that replaces the session must ask first. Scripted runs never ask: a
// script sets state directly and would wait for an answer forever.
bool mustAsk(Editor const& editor) {
    return !editor.script && editor.sessions->hasUnsavedEdits(editor.state);
}

// Scene opens and session opens wait for the answer when edits would be lost.
void holdDiscardingRequests(Editor& editor, ui::SessionRequest& request) {
    ui::SceneLoadingState& loading = editor.loading;
    if (editor.held.release) {
        editor.held.release = false;
        return;
    }
    bool const scenes = !loading.requests.empty() || !loading.dropped.empty();
    if (scenes && !ui::mayDiscard(editor.discard, ui::DiscardingAction::OpenScene, mustAsk(editor))) {
        editor.held.scenes.insert(editor.held.scenes.end(), loading.requests.begin(), loading.requests.end());
        editor.held.scenes.insert(editor.held.scenes.end(), loading.dropped.begin(), loading.dropped.end());
        loading.requests.clear();
        loading.dropped.clear();
    }
    if (request.kind == ui::SessionRequestKind::Open &&
        !ui::mayDiscard(editor.discard, ui::DiscardingAction::OpenSession, mustAsk(editor))) {
        editor.held.session = request;
        request = {};
    }
}

// What a confirmed "Discard" lets through.
void releaseConfirmed(Editor& editor, ui::SessionRequest& request) {
    auto const confirmed = ui::takeConfirmed(editor.discard);
    if (!confirmed) {
        if (!editor.discard.asking) {
            // Cancelled: the held requests are dropped.
            editor.held.scenes.clear();
            editor.held.session.reset();
        }
        return;
    }
    editor.actionLog.push_back("discard-confirmed");
    switch (*confirmed) {
        case ui::DiscardingAction::Quit:
            editor.state.quitRequested = true;
            break;
        case ui::DiscardingAction::NewSession:
            closeImportedGBuffer(editor);
            if (auto error = editor.sessions->newSession(editor.state, editor.sceneLoader))
                ui::logMessage(editor.state.log, *error, true);
            break;
        case ui::DiscardingAction::OpenScene:
            editor.loading.requests.insert(editor.loading.requests.end(), editor.held.scenes.begin(),
                                           editor.held.scenes.end());
            editor.held.scenes.clear();
            editor.held.release = true;
            break;
        case ui::DiscardingAction::OpenSession:
            if (editor.held.session) request = *editor.held.session;
            editor.held.session.reset();
            break;
    }
}

void carryOut(Editor& editor, EditorAction action) {
    EditorState& state = editor.state;
    ui::SessionController& sessions = *editor.sessions;
    editor.actionLog.emplace_back(ui::actionName(action));
    switch (action) {
        case EditorAction::Undo:
            sessions.undo(state);
            break;
        case EditorAction::Redo:
            sessions.redo(state);
            break;
        case EditorAction::SaveSession:
            sessions.panel.saveRequested = true;
            break;
        case EditorAction::OpenSession:
            ui::openSessionDialog(sessions.panel, ui::SessionDialog::Open,
                                  sessions.panel.currentPath.empty() ? "session.json" : sessions.panel.currentPath);
            break;
        case EditorAction::OpenScene:
            ui::openSceneDialog(editor.loading,
                                editor.loading.recent.empty() ? std::string() : editor.loading.recent.front());
            break;
        case EditorAction::NewSession:
            if (ui::mayDiscard(editor.discard, ui::DiscardingAction::NewSession, mustAsk(editor))) {
                closeImportedGBuffer(editor);
                if (auto error = sessions.newSession(state, editor.sceneLoader))
                    ui::logMessage(state.log, *error, true);
            }
            break;
        case EditorAction::Quit:
            // A page has nothing to quit to: stopping would leave a dead canvas in the tab.
            if (ui::kInBrowser)
                ui::logMessage(state.log,
                               "in the browser the editor ends with its tab; the layout and autosave are kept in "
                               "the browser's storage");
            else if (ui::mayDiscard(editor.discard, ui::DiscardingAction::Quit, mustAsk(editor)))
                state.quitRequested = true;
            break;
        case EditorAction::FrameSelection:
            frameSelection(editor);
            break;
        case EditorAction::HomeView:
            homeView(editor);
            break;
        case EditorAction::ToggleInspectorLock:
            state.inspector.locked = !state.inspector.locked;
            break;
        case EditorAction::ShowShortcuts:
            editor.showShortcuts = !editor.showShortcuts;
            break;
        case EditorAction::AccumulatePrevious:
        case EditorAction::AccumulateNext:
            if (state.accumulate.enabled)
                ui::stepAccumulation(state.accumulate, action == EditorAction::AccumulateNext ? 1 : -1,
                                     int(state.lights.size()));
            break;
        case EditorAction::NextView:
        case EditorAction::PreviousView: {
            // Final, lighting, then the attachments in the G-buffer strip's order.
            constexpr std::array views{DebugView::Final,  DebugView::Lighting, DebugView::Position, DebugView::Normal,
                                       DebugView::Albedo, DebugView::Specular, DebugView::Depth};
            auto it = std::find(views.begin(), views.end(), state.pipeline.view);
            int i = it == views.end() ? 0 : int(it - views.begin());
            int n = int(views.size());
            state.pipeline.view = views[size_t((i + (action == EditorAction::NextView ? 1 : n - 1)) % n)];
            break;
        }
        case EditorAction::NextLightingMode:
            state.pipeline.mode = LightingMode((int(state.pipeline.mode) + 1) % 5);
            break;
        case EditorAction::NextCullMode:
            state.pipeline.cull = CullMode((int(state.pipeline.cull) + 1) % 5);
            break;
        case EditorAction::NextDepthCopy:
            state.pipeline.depthCopy = DepthCopy((int(state.pipeline.depthCopy) + 1) % 3);
            break;
        case EditorAction::ToggleOverview:
            state.viewport.overview.on = !state.viewport.overview.on;
            break;
        case EditorAction::TogglePresentation:
            state.layout.presentation = !state.layout.presentation;
            break;
        default:
            break;  // fly keys act through CameraInput::move
    }
}

// Sessions, exports, undo and crash recovery (ui/session_controller.h).
void handleSessionRequests(Editor& editor, FrameTimes const& times) {
    EditorState& state = editor.state;
    ui::SessionController& sessions = *editor.sessions;
    ui::SessionRequest request = ui::drawSessionDialogs(sessions.panel);
    holdDiscardingRequests(editor, request);
    releaseConfirmed(editor, request);
    if (request.kind == ui::SessionRequestKind::Open || request.kind == ui::SessionRequestKind::Restore)
        closeImportedGBuffer(editor);
    if (request.kind != ui::SessionRequestKind::None) {
        FrameExport exported{state.camera, editor.drawn, state.pipeline, times.frameStats, state.sceneTriangles, {}};
        sessions.handle(request, state, *editor.renderer, exported, editor.sceneLoader);
    }
    // A held slider is one edit: it becomes an undo step when released.
    sessions.afterFrame(state, ImGui::IsAnyItemActive());
}

}  // namespace

void closeImportedGBuffer(Editor& editor) {
    if (!ui::gbufferOpen(editor.loading.gbuffer)) return;
    editor.renderer->clearImportedGBuffer();
    ui::closeGBuffer(editor.loading.gbuffer, editor.state);
    ++editor.sceneGeneration;
    editor.sessions->sceneChanged(editor.state);  // the G-buffer's light edits are not undone into the scene
}

void handleRequests(Editor& editor, FrameTimes const& times, EditRequest const& edit) {
    EditorState& state = editor.state;
    // This frame's shortcuts from the queued events: every tap counts once, whatever its length.
    editor.actionLog.clear();
    editor.actions = frameActions(editor.input, state.viewport.hovered, ImGui::GetIO().WantTextInput);
    handleViewRequests(editor, times.dt);
    for (EditorAction const action : editor.actions.taps) carryOut(editor, action);
    // The menus' entries do what their shortcuts do.
    if (edit.undo) carryOut(editor, EditorAction::Undo);
    if (edit.redo) carryOut(editor, EditorAction::Redo);
    if (edit.quit) carryOut(editor, EditorAction::Quit);
    if (edit.newSession) carryOut(editor, EditorAction::NewSession);
    if (edit.frameSelection) carryOut(editor, EditorAction::FrameSelection);
    if (edit.homeView) carryOut(editor, EditorAction::HomeView);
    handleSessionRequests(editor, times);
}

}  // namespace gbl
