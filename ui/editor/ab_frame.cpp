// Rendering the teaching views of the editor's frame.
#include "ab_frame.h"

#include "model/lesson_claims.h"
#include "model/normal_angle.h"

#include "gl/gl_api.h"
#include "gl/gpu_timer.h"

namespace gbl::ui {

FrameInput editorFrameInput(EditorState const& state, std::span<PointLight const> lights, bool waitForGpuTimings) {
    FrameInput in{state.camera, lights, state.pipeline, waitForGpuTimings};
    in.stopAfter = state.frame.stopAfter;  // the Frame window's "Stop here"
    if (state.accumulate.enabled) {
        in.accumulateLights = state.accumulate.count;
        in.lightContribution = state.accumulate.contribution;
    }
    // Nothing selected: no volume at all, as asked ("only the selected one").
    if (state.pipeline.wireframesSelectedOnly)
        in.wireframeLight = state.lightsPanel.selected >= 0 ? state.lightsPanel.selected : int(lights.size());
    return in;
}

int outlinedVolumes(FrameInput const& in) {
    if (!in.settings.volumeWireframes) return 0;
    if (in.wireframeLight < 0) return int(in.lights.size());
    return in.wireframeLight < int(in.lights.size()) ? 1 : 0;
}

TeachingInputs teachingInputs(FrameInput const& a, AbState const& ab) {
    TeachingInputs t;
    t.accumulate = a.accumulateLights;
    t.contribution = a.lightContribution;
    t.wireframeLight = a.wireframeLight;
    if (ab.enabled) t.sideB = sideB(ab, a.settings);
    if (ab.enabled && ab.view == AbView::Diff && ab.metric == AbMetric::NormalAngle) {
        t.normalAngle = true;
        t.angleThreshold = ab.angleThreshold;
    }
    return t;
}

FrameStats renderEditorFrame(EditorState& state, Renderer& renderer, FrameInput const& a, long frame, AbGpu& gpu) {
    AbState& ab = state.ab;
    if (!ab.enabled || renderer.width() <= 0 || renderer.height() <= 0) return renderer.render(a);
    // B first: its lit frame is pinned and its picture kept, then A leaves the renderer's targets
    // as every other tool expects them (the G-buffer viewers and the inspector read side A).
    FrameInput b = a;
    b.settings = sideB(ab, a.settings);
    b.timingStream = 1;  // an unwaited frame reports an earlier frame's times: B's, not A's
    FrameStats const statsB = renderer.render(b);
    ab.pin.showDiff = true;
    ab.pin.diffMode = ab.diffMode;
    ab.pin.diffThreshold = ab.threshold;
    ab.pin.pinRequested = true;
    setLitValues(ab.pin, renderer.readAttachment(Attachment::Lighting), frame);
    // B's own display image: its view, with the overlays (light cubes, wireframes) drawn on it.
    renderer.copyDisplay(gpu.b);
    // The normal angle needs B's decoded normals: read before A's frame replaces the G-buffer.
    bool const angle = ab.view == AbView::Diff && ab.metric == AbMetric::NormalAngle;
    FloatImage const normalsB = angle ? renderer.readAttachment(Attachment::Normal) : FloatImage{};
    // The heat view counts the lighting shader's runs per pixel: both sides' sums, to compare.
    bool const heat = a.settings.view == DebugView::Heatmap;
    double const evaluationsB = heat ? evaluationCount(renderer.readAttachment(Attachment::Coverage)) : 0.0;
    FrameStats const statsA = renderer.render(a);
    setLitValues(ab.pin, renderer.readAttachment(Attachment::Lighting), frame);
    ab.evaluations.reset();
    if (heat) ab.evaluations = {evaluationCount(renderer.readAttachment(Attachment::Coverage)), evaluationsB};
    if (angle) {
        ab.normalDiff = normalAngleDiff(renderer.readAttachment(Attachment::Normal), normalsB, ab.angleThreshold);
        if (ab.normalDiff.comparable)
            uploadDiff(gpu.diff, ab.normalDiff, ab.heatToThreshold ? ab.angleThreshold : 0.0f, true);
    } else if (ab.pin.diff.comparable) {
        uploadDiff(gpu.diff, ab.pin.diff, ab.heatToThreshold ? ab.threshold : 0.0f, true);
    }
    ab.passesA = statsA.passes;
    ab.passesB = statsB.passes;
    ab.gpuMsA = statsA.gpuFrameMs;
    ab.gpuMsB = statsB.gpuFrameMs;
    ab.passesTimed = passesTimed(statsA.timingSource);
    return statsA;
}

}  // namespace gbl::ui
