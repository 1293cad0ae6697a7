// Editor state <-> session and undo snapshots.
#include "session/editor_session.h"

#include "model/viewer_fields.h"

#include <glm/glm.hpp>

namespace gbl::ui {

Session captureSession(EditorState const& state, int defaultSceneLights) {
    Session s;
    s.scene = state.sceneSource.empty() ? "default" : state.sceneSource;
    s.defaultSceneLights = defaultSceneLights;
    s.defaultSceneGlass = s.scene == "default" && state.sceneGlass;
    s.camera = state.camera;
    s.lights = state.lights;
    s.pipeline = state.pipeline;
    s.viewers = state.gbuffer.viewers;
    s.animation = state.animation;
    s.syncViews = state.gbuffer.syncViews;
    s.viewportToolsOpen = state.viewportTools.open;
    s.viewportViewer = state.viewportTools.viewer;
    return s;
}

void applySessionValues(Session const& session, EditorState& state) {
    state.camera = session.camera;
    resetTargetAhead(state.rig, state.camera, glm::length(state.camera.position - state.sceneBounds.center()));
    state.lights = session.lights;
    state.pipeline = session.pipeline;
    for (std::size_t i = 0; i < state.gbuffer.viewers.size(); ++i) {
        // The session holds the settings; what the viewer learnt at run time (image size, when
        // it last fitted) starts afresh, as after opening the editor.
        ViewerState v = GBufferPanelState::defaultViewers()[i];
        copyViewerSettings(session.viewers[i], v);
        state.gbuffer.viewers[i] = v;
    }
    state.gbuffer.syncViews = session.syncViews;
    state.viewportTools = ViewportTools{};
    state.viewportTools.open = session.viewportToolsOpen;
    copyViewerSettings(session.viewportViewer, state.viewportTools.viewer, /*viewport=*/true);
    state.animation = session.animation;
    int& selected = state.lightsPanel.selected;
    if (selected >= int(state.lights.size())) selected = state.lights.empty() ? -1 : 0;
    if (selected < 0 && !state.lights.empty()) selected = 0;
    state.lightsPanel.message.clear();
}

UndoSnapshot undoSnapshot(EditorState const& state) {
    return {state.lights, state.pipeline};
}

void applyUndoSnapshot(UndoSnapshot const& snapshot, EditorState& state) {
    state.lights = snapshot.lights;
    state.pipeline = snapshot.pipeline;
    if (state.lightsPanel.selected >= int(state.lights.size()))
        state.lightsPanel.selected = state.lights.empty() ? -1 : int(state.lights.size()) - 1;
}

}  // namespace gbl::ui
