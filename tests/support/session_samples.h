// A session with every field away from its default, for the CPU tests of session files
// (session_test's round trips and atomic writes; session_errors_test breaks one field of it at a time).
#pragma once

#include "session/session.h"

#include <string>

namespace gbl::test {

// Every field away from its default, with floats that have no short decimal form, so a
// round trip that loses precision or drops a field fails.
inline ui::Session richSession() {
    using namespace ui;
    Session s;
    s.scene = "/models/Sponza \"quoted\"/Sponza.gltf";
    s.defaultSceneLights = 7;
    s.camera.position = {1.0f / 3.0f, -2.7182817f, 1e-7f};
    s.camera.yawDegrees = -123.456f;
    s.camera.pitchDegrees = 12.3456789f;
    s.camera.fovYDegrees = 47.5f;
    s.camera.nearPlane = 0.0123f;
    s.camera.farPlane = 345.6f;
    for (int i = 0; i < 5; ++i) {
        PointLight l;
        l.position = {float(i) * 0.1f, 3.14159265f, -float(i) / 7.0f};
        l.color = {0.9f, 0.1f * float(i), 1.0f / 3.0f};
        l.intensity = 1.0f + float(i) / 9.0f;
        l.kc = 1.0f;
        l.kl = 0.07f + float(i) * 0.011f;
        l.kq = i == 4 ? 0.0f : 0.017f * float(i + 1);
        l.threshold = 5.0f / 256.0f;
        l.name = i == 2 ? "lämp \"two\"\n" : "light " + std::to_string(i);
        // One of each kind beyond points, with every kind field off its default.
        if (i == 1 || i == 3) {
            l.kind = i == 1 ? LightKind::Spot : LightKind::Directional;
            l.direction = {0.1f * float(i), -1.0f / 3.0f, 0.7071068f};
            l.innerConeDeg = 12.345f;
            l.outerConeDeg = 33.3f;
        }
        s.lights.push_back(l);
    }
    s.pipeline.mode = LightingMode::Volumes;
    s.pipeline.cull = CullMode::Stencil;
    s.pipeline.depthCopy = DepthCopy::Shader;
    s.pipeline.tonemap = Tonemap::Reinhard;
    s.pipeline.view = DebugView::DepthLinear;
    s.pipeline.lightCubes = false;
    s.pipeline.volumeWireframes = true;
    s.pipeline.normalMaps = false;
    s.pipeline.ambient = {0.01f, 0.02f, 0.0333f};
    s.pipeline.exposure = 1.7f;
    s.pipeline.shininess = 64.5f;
    s.pipeline.wireframesSelectedOnly = true;
    for (std::size_t i = 0; i < s.viewers.size(); ++i) {
        ViewerState& v = s.viewers[i];
        v.channelMask = unsigned(i + 1);
        v.rangeMin = -10.5f + float(i);
        v.rangeMax = 12.25f / 3.0f + float(i);
        v.autoFit = i % 2 == 0;
        v.normalDisplay = i % 2 ? NormalDisplay::Absolute : NormalDisplay::Biased;
        v.linearDepth = i % 2 == 1;
        v.cameraClipPlanes = i % 3 == 0;
        v.nearPlane = 0.5f + float(i);
        v.farPlane = 50.0f + float(i) / 3.0f;
        v.zoom = 1.0f + float(i) * 2.5f;
        v.center = {0.25f + float(i) * 0.1f, 0.75f - float(i) * 0.1f};
        v.colormap = Colormap(i % 3);
        v.overlays = unsigned(i * 3) & 0xFu;  // 0, nan+inf, negative+inf, ...
        v.showHistogram = i % 2 == 1;
    }
    s.viewers[4].showStencil = true;  // only the depth viewer shows it
    s.syncViews = true;
    s.viewportToolsOpen = true;
    s.viewportViewer.channelMask = 0x2;
    s.viewportViewer.rangeMin = -0.125f / 3.0f;
    s.viewportViewer.rangeMax = 7.0f / 3.0f;
    s.viewportViewer.colormap = Colormap::Viridis;
    s.viewportViewer.overlays = kOverlayNaN | kOverlayClip;
    s.viewportViewer.showHistogram = true;
    s.animation.enabled = true;
    s.animation.speed = 0.35f;
    s.animation.time = 12.345678f;
    return s;
}

}  // namespace gbl::test
