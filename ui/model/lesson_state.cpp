// Capturing the editor for a lesson and applying a lesson step to it.
#include "model/lesson_state.h"

#include "model/camera_rig.h"

#include <algorithm>
#include <cmath>

namespace gbl::ui {

LessonSnapshot captureLessonSnapshot(EditorState const& state) {
    LessonSnapshot s;
    s.camera = state.camera;
    s.lights = state.lights;
    s.pipeline = state.pipeline;
    s.viewers = state.gbuffer.viewers;
    s.animation = state.animation;
    s.selectedLight = state.lightsPanel.selected;
    s.activeViewer = state.gbuffer.activeViewer;
    s.inspectorLocked = state.inspector.locked;
    s.inspectorPixel = state.inspector.pixel;
    if (state.ab.enabled) s.ab = LessonAb{state.ab.view, state.ab.b, state.ab.overrides};
    return s;
}

glm::ivec2 lessonPixel(glm::vec2 fraction, glm::ivec2 frameSize) {
    glm::ivec2 const p(glm::floor(fraction * glm::vec2(frameSize)));
    return glm::clamp(p, glm::ivec2(0), glm::max(frameSize - 1, glm::ivec2(0)));
}

void applyLessonSnapshot(LessonSnapshot const& s, EditorState& state, glm::ivec2 frameSize) {
    state.camera = s.camera;
    resetTargetAhead(state.rig, state.camera, glm::length(state.camera.position - state.sceneBounds.center()));
    state.lights = s.lights;
    state.pipeline = s.pipeline;
    for (std::size_t i = 0; i < s.viewers.size(); ++i) {
        // Run-time facts of the viewer (image size, last fit) stay; the settings come from the step.
        ViewerState v = s.viewers[i];
        v.imageSize = state.gbuffer.viewers[i].imageSize;
        state.gbuffer.viewers[i] = v;
    }
    state.animation = s.animation;
    if (s.ab) {
        state.ab.enabled = true;
        state.ab.view = s.ab->view;
        state.ab.b = s.ab->b;
        state.ab.overrides = s.ab->overrides;
        state.ab.overrides.resize(abFields().size(), false);
    } else {
        state.ab.enabled = false;
    }
    state.accumulate.enabled = s.lightByLight.has_value();
    if (s.lightByLight) {
        state.accumulate.count = std::clamp(s.lightByLight->light + 1, 0, int(s.lights.size()));
        state.accumulate.contribution = s.lightByLight->only;
    }
    if (s.litPinDiff) {
        state.litPin.pinRequested = true;
        state.litPin.diffFor.reset();
    }
    state.litPin.showDiff = s.litPinDiff;
    state.lightsPanel.selected = s.selectedLight < int(s.lights.size()) ? s.selectedLight : -1;
    state.lightsPanel.message.clear();
    state.gbuffer.activeViewer = std::clamp(s.activeViewer, 0, int(state.gbuffer.viewers.size()) - 1);
    if (s.pixel) {
        state.inspector.pixel = lessonPixel(*s.pixel, frameSize);
        state.inspector.locked = true;
        state.inspector.source = "viewport";
    } else {
        state.inspector.pixel = s.inspectorPixel;
        state.inspector.locked = s.inspectorLocked;
    }
}

LessonReturn captureLessonReturn(EditorState const& state) {
    LessonReturn r;
    r.snapshot = captureLessonSnapshot(state);
    r.toolsOpen = state.viewportTools.open;
    r.toolsViewer = state.viewportTools.viewer;
    r.litDiff = state.litPin.showDiff;
    r.litPinned = state.litPin.pinned;
    r.litPinnedFrame = state.litPin.pinnedFrame;
    r.everyLight = state.inspector.everyLight;
    r.accumulate = state.accumulate;
    r.abDivider = state.ab.divider;
    r.abDiffMode = state.ab.diffMode;
    r.abThreshold = state.ab.threshold;
    r.abHeatToThreshold = state.ab.heatToThreshold;
    r.abMetric = state.ab.metric;
    r.abAngleThreshold = state.ab.angleThreshold;
    r.stopAfter = state.frame.stopAfter;
    return r;
}

void applyLessonReturn(LessonReturn const& r, EditorState& state, glm::ivec2 frameSize) {
    applyLessonSnapshot(r.snapshot, state, frameSize);
    state.viewportTools.open = r.toolsOpen;
    // The image size and last fit are run-time facts of the viewer; its settings come back.
    ViewerState v = r.toolsViewer;
    v.imageSize = state.viewportTools.viewer.imageSize;
    state.viewportTools.viewer = v;
    state.litPin.showDiff = r.litDiff;
    state.litPin.pinned = r.litPinned;
    state.litPin.pinnedFrame = r.litPinnedFrame;
    state.litPin.pinRequested = false;
    state.litPin.diffFor.reset();  // recomputed against the pin that came back
    state.inspector.everyLight = r.everyLight;
    glm::vec4 const slider = state.accumulate.sliderRect;
    state.accumulate = r.accumulate;
    state.accumulate.sliderRect = slider;
    state.ab.divider = r.abDivider;
    state.ab.diffMode = r.abDiffMode;
    state.ab.threshold = r.abThreshold;
    state.ab.heatToThreshold = r.abHeatToThreshold;
    state.ab.metric = r.abMetric;
    state.ab.angleThreshold = r.abAngleThreshold;
    state.frame.stopAfter = r.stopAfter;
}

bool predictionRight(LessonPrediction const& p, int choice, float typed) {
    if (!p.choices.empty()) return choice >= 0 && choice == p.correct;
    return std::isfinite(typed) && std::abs(typed - p.number) <= p.tolerance;
}

}  // namespace gbl::ui
