// Everything the editor knows between frames, as plain values: what the panels edit, what
// sessions save and what UI tests drive. No GL objects and no ImGui types here.
#pragma once

#include "core/camera.h"
#include "core/pipeline_settings.h"
#include "core/point_light.h"
#include "model/ab_accumulate.h"
#include "model/ab_compare.h"
#include "model/camera_rig.h"
#include "model/frame_diagram.h"
#include "model/layout_state.h"
#include "model/lights_state.h"
#include "model/log_state.h"
#include "model/pixel_inspector_state.h"
#include "model/stats_state.h"
#include "model/viewer_state.h"
#include "model/viewer_tools.h"
#include "model/viewport_state.h"
#include "scene/scene_data.h"

#include <string>
#include <string_view>
#include <vector>

namespace gbl::ui {

// The scene name the editor's scene loader (and a lesson step with "scene": {"glass": true}) uses for
// the default scene with its glass panes; "default" is the scene without them.
inline constexpr std::string_view kDefaultSceneGlass = "default+glass";

// Wall-clock cost of each part of the frame, with glFinish between parts so the GPU work of
// one part is not billed to the next. Only while a measurement runs (it slows the frame).
struct CostMeasurement {
    int remaining = 0;  // frames still to measure; 0 = not measuring
    int frames = 0;
    double renderMs = 0.0;   // Renderer::render: the deferred frame itself
    double viewersMs = 0.0;  // view passes of the G-buffer viewers, range fits, pixel sample
    double uiMs = 0.0;       // building the ImGui frame (all panels)
    double imguiMs = 0.0;    // drawing ImGui's draw lists
    double frameMs = 0.0;    // whole iteration, swap included
};

struct EditorState {
    // --- the scene being looked at ------------------------------------------------------
    std::string sceneSource;  // "default" or the glTF path
    bool sceneGlass = false;  // the default scene stands its glass panes (DefaultSceneOptions::glass)
    // "default", "default+glass" (kDefaultSceneGlass) or the glTF path: what the scene loader takes.
    std::string sceneName() const {
        if (sceneSource.empty() || sceneSource == "default")
            return std::string(sceneGlass ? kDefaultSceneGlass : "default");
        return sceneSource;
    }
    Bounds sceneBounds;
    std::vector<SceneCamera> sceneCameras;  // the file's own cameras, offered as views
    std::size_t sceneTriangles = 0;
    glm::vec3 orbitCenter{0.0f};     // lights orbit around this point when animated
    std::vector<PointLight> lights;  // as edited; animation moves a copy, never these
    LightAnimation animation;
    Camera camera;
    CameraRig rig;
    PipelineSettings pipeline;

    // --- panels ---------------------------------------------------------------------------
    LayoutState layout;
    LightsPanelState lightsPanel;
    ViewportState viewport;
    LitPin litPin;                // the viewport's pinned lit frame and its diff
    AccumulateState accumulate;   // the light-by-light scrubber
    AbState ab;                   // the viewport's A/B split and diff
    ViewportTools viewportTools;  // the viewer tools in the viewport while it shows an attachment
    GBufferPanelState gbuffer;
    PixelInspectorState inspector;
    StatsState stats;
    FramePanelState frame;  // the Frame window and the stop after a pass
    LogState log;

    CostMeasurement measurement;
    bool quitRequested = false;
};

}  // namespace gbl::ui
