// Editor state <-> session: what is captured comes back when applied, through a file in between.
#include "session/editor_session.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

using namespace gbl;
using namespace gbl::ui;

namespace {

EditorState editedState() {
    EditorState s;
    s.sceneSource = "default";
    s.sceneBounds = {{-16.0f, 0.0f, -16.0f}, {16.0f, 10.0f, 16.0f}};
    s.camera.position = {3.0f, 4.0f, 5.0f};
    s.camera.yawDegrees = 33.0f;
    s.lights.resize(3);
    s.lights[1].intensity = 2.5f;
    s.lights[2].name = "rim";
    s.pipeline.mode = LightingMode::Volumes;
    s.pipeline.depthCopy = DepthCopy::Off;
    s.gbuffer.viewers[4].linearDepth = false;
    s.gbuffer.viewers[0].zoom = 4.0f;
    s.gbuffer.viewers[0].center = {0.2f, 0.7f};
    s.gbuffer.viewers[0].imageSize = {640, 360};
    s.gbuffer.viewers[1].colormap = Colormap::Viridis;
    s.gbuffer.viewers[1].overlays = kOverlayNaN | kOverlayNegative;
    s.gbuffer.viewers[2].showHistogram = true;
    s.gbuffer.viewers[4].rangeMin = 0.9f;
    s.gbuffer.viewers[4].rangeMax = 0.99f;
    setShowStencil(s.gbuffer.viewers[4], true);  // range 0..255 now; the depth's waits
    s.gbuffer.viewers[4].rangeMax = 16.0f;
    s.gbuffer.syncViews = true;
    s.viewportTools.open = true;
    s.viewportTools.viewer.colormap = Colormap::Turbo;
    s.viewportTools.viewer.rangeMin = -3.0f;
    s.viewportTools.viewer.autoFit = false;
    s.animation.enabled = true;
    s.animation.time = 8.5f;
    return s;
}

}  // namespace

TEST(EditorSession, CapturedSessionAppliesBackThroughJson) {
    EditorState const edited = editedState();
    Session const captured = captureSession(edited, 3);
    SessionLoad const loaded = parseSession(sessionToJson(captured), "s.json");
    ASSERT_TRUE(loaded.session) << loaded.error;

    EditorState fresh;
    fresh.sceneBounds = edited.sceneBounds;
    fresh.lightsPanel.selected = 7;  // past the end of the session's lights
    applySessionValues(*loaded.session, fresh);
    EXPECT_EQ(fresh.camera.position, edited.camera.position);
    EXPECT_EQ(fresh.camera.yawDegrees, edited.camera.yawDegrees);
    ASSERT_EQ(fresh.lights.size(), 3u);
    EXPECT_EQ(fresh.lights[1].intensity, 2.5f);
    EXPECT_EQ(fresh.lights[2].name, "rim");
    EXPECT_EQ(fresh.pipeline.mode, LightingMode::Volumes);
    EXPECT_EQ(fresh.pipeline.depthCopy, DepthCopy::Off);
    EXPECT_FALSE(fresh.gbuffer.viewers[4].linearDepth);
    EXPECT_EQ(fresh.gbuffer.viewers[0].zoom, 4.0f);
    EXPECT_EQ(fresh.gbuffer.viewers[0].center, glm::vec2(0.2f, 0.7f));
    EXPECT_EQ(fresh.gbuffer.viewers[0].imageSize, glm::ivec2(0));  // learnt at run time, not restored
    EXPECT_EQ(fresh.gbuffer.viewers[0].kind, ViewerKind::Position);
    EXPECT_TRUE(fresh.animation.enabled);
    EXPECT_EQ(fresh.animation.time, 8.5f);
    // Viewer tools.
    EXPECT_EQ(fresh.gbuffer.viewers[1].colormap, Colormap::Viridis);
    EXPECT_EQ(fresh.gbuffer.viewers[1].overlays, kOverlayNaN | kOverlayNegative);
    EXPECT_TRUE(fresh.gbuffer.viewers[2].showHistogram);
    EXPECT_FALSE(fresh.gbuffer.viewers[0].showHistogram);
    EXPECT_TRUE(fresh.gbuffer.viewers[4].showStencil);
    EXPECT_EQ(fresh.gbuffer.viewers[4].rangeMin, 0.0f);  // the stencil's range, as shown when saved
    EXPECT_EQ(fresh.gbuffer.viewers[4].rangeMax, 16.0f);
    // Switching back shows a depth range (the default's: the saved depth range was not shown).
    setShowStencil(fresh.gbuffer.viewers[4], false);
    EXPECT_EQ(fresh.gbuffer.viewers[4].rangeMax, GBufferPanelState::defaultViewers()[4].rangeMax);
    EXPECT_TRUE(fresh.gbuffer.syncViews);
    EXPECT_TRUE(fresh.viewportTools.open);
    EXPECT_EQ(fresh.viewportTools.viewer.colormap, Colormap::Turbo);
    EXPECT_EQ(fresh.viewportTools.viewer.rangeMin, -3.0f);
    EXPECT_FALSE(fresh.viewportTools.viewer.autoFit);
    EXPECT_EQ(fresh.lightsPanel.selected, 0);  // the old selection no longer exists
    // The orbit target sits ahead of the restored camera, so orbiting does not jump.
    glm::vec3 const toTarget = glm::normalize(fresh.rig.target - fresh.camera.position);
    EXPECT_NEAR(glm::dot(toTarget, fresh.camera.forward()), 1.0f, 1e-4f);
}

// A session written before the depth copy had its name says "blit"; it still loads into the editor,
// and the editor writes it back under depth_copy.
TEST(EditorSession, AnOldSessionsBlitKeyStillLoads) {
    nlohmann::json j = nlohmann::json::parse(sessionToJson(captureSession(editedState(), 3)));
    ASSERT_TRUE(j["pipeline"].contains("depth_copy"));
    j["pipeline"].erase("depth_copy");
    j["pipeline"]["blit"] = "shader";
    SessionLoad const loaded = parseSession(j.dump(), "old.json");
    ASSERT_TRUE(loaded.session) << loaded.error;
    EditorState fresh;
    applySessionValues(*loaded.session, fresh);
    EXPECT_EQ(fresh.pipeline.depthCopy, DepthCopy::Shader);
    nlohmann::json const again = nlohmann::json::parse(sessionToJson(captureSession(fresh, 3)));
    EXPECT_EQ(again["pipeline"]["depth_copy"], "shader");
    EXPECT_FALSE(again["pipeline"].contains("blit"));
}

TEST(EditorSession, CapturedSceneNamesDefaultOrTheFile) {
    EditorState s;
    EXPECT_EQ(captureSession(s, 32).scene, "default");
    s.sceneSource = "/models/a.glb";
    EXPECT_EQ(captureSession(s, 32).scene, "/models/a.glb");
}

TEST(EditorSession, UndoSnapshotsCarryLightsAndPipelineOnly) {
    EditorState s = editedState();
    UndoSnapshot const snap = undoSnapshot(s);
    s.lights.clear();
    s.lightsPanel.selected = 2;
    s.pipeline.mode = LightingMode::Forward;
    s.camera.yawDegrees = -1.0f;
    applyUndoSnapshot(snap, s);
    EXPECT_EQ(s.lights.size(), 3u);
    EXPECT_EQ(s.pipeline.mode, LightingMode::Volumes);
    EXPECT_EQ(s.camera.yawDegrees, -1.0f);  // the camera is not an undoable edit
    EXPECT_EQ(s.lightsPanel.selected, 2);
    UndoSnapshot fewer = snap;
    fewer.lights.resize(1);
    applyUndoSnapshot(fewer, s);
    EXPECT_EQ(s.lightsPanel.selected, 0);  // clamped to the lights that exist
}
