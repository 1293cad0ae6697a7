// Everything the editor knows between frames, as plain values: what the panels edit, what
// sessions save and what UI tests drive. No GL objects and no ImGui types here.
#pragma once

#include "camera.h"
#include "camera_rig.h"
#include "layout.h"
#include "panel_gbuffer.h"
#include "panel_lights.h"
#include "panel_log.h"
#include "panel_pixel_inspector.h"
#include "panel_stats.h"
#include "panel_viewport.h"
#include "pipeline_settings.h"
#include "point_light.h"
#include "scene_data.h"

#include <string>
#include <vector>

namespace gbl::ui {

struct EditorState {
    // --- the scene being looked at ------------------------------------------------------
    std::string sceneSource;      // "default" or the glTF path
    Bounds sceneBounds;
    glm::vec3 orbitCenter{0.0f};  // lights orbit around this point when animated
    std::vector<PointLight> lights;  // as edited; animation moves a copy, never these
    LightAnimation animation;
    Camera camera;
    CameraRig rig;
    PipelineSettings pipeline;

    // --- panels ---------------------------------------------------------------------------
    LayoutState layout;
    LightsPanelState lightsPanel;
    ViewportState viewport;
    GBufferPanelState gbuffer;
    PixelInspectorState inspector;
    StatsState stats;
    LogState log;

    bool quitRequested = false;
};

}  // namespace gbl::ui
