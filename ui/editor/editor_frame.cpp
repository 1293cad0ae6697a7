// The editor's per-frame work outside the panels: the deferred frame, the G-buffer viewers and their
// range fits, the inspector's sample, shader reloads, presenting, scripts, screenshots and timings.
#include "editor_loop.h"

#include "ab_frame.h"

#include "core/light_math.h"
#include "long_frame.h"
#include "model/browser_files.h"
#include "model/image_range.h"
#include "model/light_pick.h"
#include "model/pixel_breakdown.h"
#include "model/viewer_tools.h"
#include "scene/default_scene.h"
#include "script/screenshot.h"

#include "gl/gl_api.h"

#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include <cstdio>
#include <limits>

namespace gbl {

namespace {

using ui::EditorState;

std::vector<PointLight> animatedLights(EditorState const& state) {
    std::vector<PointLight> lights = state.lights;
    if (state.animation.time != 0.0f) orbitLights(lights, state.orbitCenter, state.animation.time);
    return lights;
}

// Refits viewer ranges that asked for it (button: min..max) or are on auto (about once a second: the
// readable 1-99 % range, as the viewport's viewers).
// Without a new frame the attachments hold what they held, so auto-fits wait for one.
void fitViewerRanges(EditorState& state, Renderer& renderer, long frame, bool rendered) {
    for (auto& v : state.gbuffer.viewers) {
        // Auto-fit at the first frame with data, then about once a second (60 frames).
        bool const autoDue = v.autoFit && (v.lastFitFrame < 0 || (rendered && frame - v.lastFitFrame >= 60));
        if (!v.fitRequested && !autoDue) continue;
        bool const asked = v.fitRequested;
        v.fitRequested = false;
        Attachment source = Attachment::Position;
        switch (v.kind) {
            case ui::ViewerKind::Position:
                break;
            case ui::ViewerKind::Depth:
                source = v.showStencil ? Attachment::Stencil : Attachment::Depth;
                break;
            case ui::ViewerKind::Albedo:
            case ui::ViewerKind::Specular:
                source = Attachment::AlbedoSpec;
                break;
            case ui::ViewerKind::Normal:
            case ui::ViewerKind::Lighting:  // the viewport's tools only; they fit their own values
                continue;                   // normals are shown as directions, not remapped
        }
        ui::ValueRange const r = ui::stripViewerRange(v, renderer.readAttachment(source), asked,
                                                      v.cameraClipPlanes ? state.camera.nearPlane : v.nearPlane,
                                                      v.cameraClipPlanes ? state.camera.farPlane : v.farPlane);
        if (r.samples > 0) {
            v.rangeMin = r.min;
            v.rangeMax = r.max > r.min ? r.max : r.min + 1e-6f;
            v.lastFitFrame = frame;
        }
    }
}

// Redraws the viewers whose picture is stale, plus, after a new frame, one in turn (or all when
// asked to refresh every frame).
void drawViewers(Editor& editor, FrameTimes& times) {
    Renderer& renderer = *editor.renderer;
    EditorGpu& gpu = editor.gpu;
    ui::GBufferPanelState& gb = editor.state.gbuffer;
    if (times.rendered) ++gpu.framesRendered;
    // The one viewer refreshed in turn this frame: the next one behind the latest frame.
    int turn = -1;
    for (int k = 0; k < int(gb.viewers.size()) && turn < 0; ++k) {
        int const i = (gb.nextRefresh + k) % int(gb.viewers.size());
        if (gpu.drawnFrame[std::size_t(i)] != gpu.framesRendered) turn = i;
    }
    if (turn >= 0) gb.nextRefresh = (turn + 1) % int(gb.viewers.size());
    for (std::size_t i = 0; i < gpu.viewTargets.size(); ++i) {
        ui::ViewerState const& v = gb.viewers[i];
        ViewParams const params = ui::viewerParams(v);
        ViewTarget& target = gpu.viewTargets[i];
        bool const stale = !target.texture || target.texture.width() != renderer.width() ||
                           target.texture.height() != renderer.height() || !gpu.drawnParams[i] ||
                           *gpu.drawnParams[i] != params;
        if ((times.rendered && gb.refreshEveryFrame) || int(i) == turn || stale) {
            Camera clip = editor.state.camera;
            if (v.kind == ui::ViewerKind::Depth && !v.cameraClipPlanes) {
                clip.nearPlane = v.nearPlane;
                clip.farPlane = v.farPlane;
            }
            renderer.drawView(params, FrameInput{clip, editor.drawn, editor.state.pipeline}, target);
            // Exact texels when zoomed in: the viewers are for reading values, not pictures.
            target.texture.setFilter(GL_NEAREST, GL_NEAREST);
            gpu.drawnParams[i] = params;
            gpu.drawnFrame[i] = gpu.framesRendered;
        }
        times.viewerTextures[i] = target.texture.id();
    }
    fitViewerRanges(editor.state, renderer, editor.frame, times.rendered);
    ui::serviceViewerTools(editor.state, renderer, editor.frame, times.viewerTextures, gpu.viewerTools);
}

// The pixel inspector's sample and its breakdown into per-light terms, again only when the frame
// or the pixel changed.
void samplePixel(Editor& editor, bool rendered) {
    Renderer& renderer = *editor.renderer;
    ui::PixelInspectorState& inspector = editor.state.inspector;
    if (!rendered && inspector.pixel == editor.frameMemory.sampledPixel && (inspector.sample || !inspector.pixel))
        return;
    editor.frameMemory.sampledPixel = inspector.pixel;
    if (inspector.pixel && inspector.pixel->x < renderer.width() && inspector.pixel->y < renderer.height()) {
        inspector.sample = renderer.samplePixel(inspector.pixel->x, inspector.pixel->y, editor.state.camera);
        ui::sampleMsaaPixel(inspector, renderer, editor.state.viewport.msaa.samples);
        ui::PixelInFrame where{*inspector.pixel, {renderer.width(), renderer.height()}, std::nullopt};
        // The tile list depends on every pixel of the tile: one depth read back, tiled mode only.
        if (editor.state.pipeline.mode == LightingMode::Tiled)
            where.tileBounds = ui::tileDepthBounds(renderer.readAttachment(Attachment::Depth), *inspector.pixel,
                                                   editor.state.camera.nearPlane, editor.state.camera.farPlane);
        // The lights and settings the frame was shaded with (the scrubber may hold back lights).
        FrameInput const frame = ui::editorFrameInput(editor.state, editor.drawn, false);
        inspector.settings = frame.settings;
        if (frame.accumulateLights && frame.lightContribution && *frame.accumulateLights > 0)
            inspector.settings.ambient = glm::vec3(0.0f);
        inspector.breakdown =
            ui::breakDownPixel(*inspector.sample, shadedLights(frame), editor.state.camera, inspector.settings, where);
        inspector.breakdownNote = inspector.breakdown ? "" : ui::noBreakdownNote(*inspector.sample, inspector.settings);
        // Their value beside ours: the pinned lit image of an open G-buffer, at the frame's size.
        ui::LitPin const& pin = editor.state.litPin;
        inspector.theirs.reset();
        if (!pin.pinnedName.empty() && pin.pinned && pin.pinned->width == renderer.width() &&
            pin.pinned->height == renderer.height()) {
            glm::ivec2 const p = *inspector.pixel;
            inspector.theirs =
                glm::vec3(pin.pinned->at(p.x, p.y, 0), pin.pinned->at(p.x, p.y, 1), pin.pinned->at(p.x, p.y, 2));
        }
    } else {
        inspector.sample.reset();
        inspector.msaaSamples.clear();
        inspector.breakdown.reset();
        inspector.theirs.reset();
        inspector.breakdownNote = "no pixel";
    }
}

// A measurement waits for the GPU at each boundary so the times belong to their part.
void finishIfMeasuring(FrameTimes const& times) {
    if (times.measuring) glFinish();
}

void printMeasurement(ui::CostMeasurement const& m, glm::ivec2 window, glm::ivec2 viewport, int lights) {
    double const n = std::max(m.frames, 1);
    double const editor = (m.viewersMs + m.uiMs + m.imguiMs) / n;
    double const frame = m.frameMs / n;
    std::printf("editor cost over %d frames, window %dx%d, viewport %dx%d, %d lights:\n", m.frames, window.x, window.y,
                viewport.x, viewport.y, lights);
    std::printf("  renderer frame   %8.2f ms\n", m.renderMs / n);
    std::printf("  viewers          %8.2f ms  (view passes, range fits, pixel sample)\n", m.viewersMs / n);
    std::printf("  UI build         %8.2f ms  (all panels, CPU)\n", m.uiMs / n);
    std::printf("  ImGui draw       %8.2f ms\n", m.imguiMs / n);
    std::printf("  whole frame      %8.2f ms\n", frame);
    std::printf("  editor share     %8.1f %%  (viewers + UI build + ImGui draw) / whole frame\n",
                frame > 0.0 ? 100.0 * editor / frame : 0.0);
    std::fflush(stdout);
}

}  // namespace

// Selects the light whose cube is under the pixel. With a depth step the cubes are hidden by
// walls, so only cubes in front of the surface at that pixel can be hit; without one they show
// through walls and are pickable through them too, as drawn.
int lightAtPixel(EditorState const& state, Renderer& renderer, std::span<PointLight const> drawn, glm::ivec2 pixel) {
    glm::vec2 const size(float(renderer.width()), float(renderer.height()));
    ui::Ray const ray = ui::cameraRay(state.camera, glm::vec2(pixel), size);
    float maxDistance = std::numeric_limits<float>::max();
    if (state.pipeline.depthCopy != DepthCopy::Off) {
        PixelSample const s = renderer.samplePixel(pixel.x, pixel.y, state.camera);
        // A little past the surface so a cube resting on it is still hit.
        if (s.covered) maxDistance = glm::length(glm::vec3(s.position) - state.camera.position) * 1.001f + 1e-3f;
    }
    return ui::pickLight(ray, drawn, renderer.lightCubeHalfSize(), maxDistance);
}

void pickLightAt(EditorState& state, Renderer& renderer, std::span<PointLight const> drawn, glm::ivec2 pixel) {
    int const hit = lightAtPixel(state, renderer, drawn, pixel);
    if (hit >= 0) {
        state.lightsPanel.selected = hit;
        state.lightsPanel.message.clear();
    }
}

bool beginFrame(Editor& editor, FrameTimes& times) {
    times.start = EditorClock::now();
    times.dt = float(std::chrono::duration<double>(times.start - editor.frameMemory.lastFrame).count());
    editor.frameMemory.lastFrame = times.start;
    glfwPollEvents();
    takeFrameInput(editor.input);
    // The window's close button asks first too when edits would be lost.
    if (glfwWindowShouldClose(editor.window()) && !editor.script && editor.sessions->hasUnsavedEdits(editor.state)) {
        glfwSetWindowShouldClose(editor.window(), GLFW_FALSE);
        ui::mayDiscard(editor.discard, ui::DiscardingAction::Quit, true);
    }
    glfwGetFramebufferSize(editor.window(), &times.fbWidth, &times.fbHeight);
    if ((times.fbWidth == 0 || times.fbHeight == 0) && !editor.unattended) {
        // Minimised: nothing to draw into; wait instead of spinning.
        glfwWaitEventsTimeout(0.1);
        return false;
    }
    ++editor.frame;
    times.measuring = editor.state.measurement.remaining > 0;
    return true;
}

// Before a frame estimated to take longer than --frame-warn-seconds (core/frame_cost.h), switches
// to the mode that gives the same image soonest and says so in the log; with no faster mode, says
// what the frame will cost. Checked once per mode and light count; a user who switches back to the
// mode it left, with the same lights, has been told and keeps the mode they chose.
void avoidLongFrame(Editor& editor, glm::ivec2 size) {
    EditorState& state = editor.state;
    auto const key = std::make_pair(state.pipeline.mode, editor.drawn.size());
    if (editor.frameMemory.longFrameChecked == key || size.x <= 0 || size.y <= 0) return;
    editor.frameMemory.longFrameChecked = key;
    if (editor.frameMemory.longFrameSwitchedFrom == key) return;
    FrameInput const input{state.camera, editor.drawn, state.pipeline};
    auto const warning = longFrameWarning(*editor.renderer, input, editor.options.frameWarnSeconds);
    if (!warning) return;
    if (!warning->cheaper) {
        ui::logMessage(state.log, "Slow frame ahead: " + warning->message + ".", true);
        return;
    }
    editor.frameMemory.longFrameSwitchedFrom = key;
    state.pipeline.mode = warning->cheaper->mode;
    editor.frameMemory.longFrameChecked = std::make_pair(state.pipeline.mode, editor.drawn.size());
    ui::logMessage(state.log,
                   "Switched to " + std::string(kLightingModeNames[std::size_t(state.pipeline.mode)]) +
                       " mode: " + warning->message + ". Pipeline > Lighting mode switches back.",
                   true);
}

namespace {

// The Frame window's stop after a pass that this frame no longer runs (the mode changed): dropped,
// with the reason in the log.
void dropStaleStop(Editor& editor) {
    EditorState& state = editor.state;
    if (!state.frame.stopAfter) return;
    FrameInput input = ui::editorFrameInput(state, editor.drawn, false);
    input.stopAfter.reset();
    std::vector<PassDecl> const passes = editor.renderer->framePasses(input);
    if (auto why = stopAfterError(passName(*state.frame.stopAfter), passes)) {
        ui::logMessage(state.log, *why + "; the Frame window runs the whole frame again.");
        state.frame.stopAfter.reset();
    }
}

// File > Open G-buffer, drops and --gbuffer (model/gbuffer_opening.h): the imported frame replaces
// the scene's geometry pass until closed. Every change is a new frame to render.
void openOrCloseGBuffer(Editor& editor) {
    Renderer& renderer = *editor.renderer;
    // File > Capture a program…: a finished capture's manifest is opened like any other.
    ui::ProgramCaptureState& capture = editor.loading.capture;
    if (capture.job && capture.job->done.load()) {
        if (auto const manifest = ui::finishProgramCapture(capture)) {
            ui::logMessage(editor.state.log, "Captured " + *manifest + "; opening it.");
            editor.loading.gbuffer.requests.push_back(*manifest);
        } else {
            ui::logMessage(editor.state.log, capture.lastError, true);
        }
    }
    ui::GBufferChange const change = ui::updateGBufferOpening(
        editor.loading.gbuffer, editor.state,
        [&](ImportedFrame const& frame) { return renderer.setImportedGBuffer(frame); },
        [&] { renderer.clearImportedGBuffer(); });
    if (change == ui::GBufferChange::Opened || change == ui::GBufferChange::Closed) {
        ++editor.sceneGeneration;
        // Undo steps of the scene's lights do not apply to the G-buffer's, nor the other way round.
        editor.sessions->sceneChanged(editor.state);
    }
}

// Dropped session and lesson files open as sessions and lessons (in the browser, its file picker
// hands every chosen file over as a drop); the rest go on to the scene and G-buffer openers.
void routeDroppedDocuments(Editor& editor) {
    std::vector<std::string>& dropped = editor.loading.dropped;
    for (auto it = dropped.begin(); it != dropped.end();) {
        switch (ui::droppedDocumentKind(*it)) {
            case ui::DroppedDocument::Session:
                editor.sessions->panel.openDropped = *it;
                it = dropped.erase(it);
                break;
            case ui::DroppedDocument::Lesson:
                editor.course.lessons.openPath = *it;
                editor.course.lessons.openRequested = true;
                it = dropped.erase(it);
                break;
            case ui::DroppedDocument::Other:
                ++it;
                break;
        }
    }
}

// File > "Save window as PNG" in the browser: the whole window, offered as a download.
void saveWindowShot(Editor& editor) {
    std::string const path = "/tmp/gbuffer-lab-window.png";
    ui::LogState& log = editor.state.log;
    if (auto error = ui::writePng(editor.host->readWindow(), path))
        ui::logMessage(log, *error, true);
    else if (!ui::offerDownload(path))
        ui::logMessage(log, "the window was written to " + path + " but could not be offered as a download", true);
    else
        ui::logMessage(log, "saved the window as gbuffer-lab-window.png (offered as a download)");
}

}  // namespace

void renderScene(Editor& editor, FrameTimes& times) {
    EditorState& state = editor.state;
    Renderer& renderer = *editor.renderer;
    routeDroppedDocuments(editor);
    // A finished load becomes the scene before this frame renders; requested ones start.
    if (ui::updateSceneLoading(editor.loading, editor.defaultLightCount, state,
                               [&](SceneData const& scene) { return renderer.setScene(scene); })) {
        // A scene opened over a G-buffer replaces it, with the scene's own camera and lights.
        if (ui::gbufferOpen(editor.loading.gbuffer)) {
            renderer.clearImportedGBuffer();
            ui::forgetGBuffer(editor.loading.gbuffer, state);
        }
        editor.sessions->sceneChanged(state);
        rememberHomeView(editor);
    }
    openOrCloseGBuffer(editor);

    // The deferred frame, at the size the viewport had last frame; an imported G-buffer keeps its own.
    if (!renderer.hasImportedGBuffer() && state.viewport.size != glm::ivec2(renderer.width(), renderer.height()))
        renderer.resizeTargets(state.viewport.size.x, state.viewport.size.y);
    if (state.animation.enabled) state.animation.time += times.dt * state.animation.speed;
    editor.drawn = animatedLights(state);
    avoidLongFrame(editor, glm::ivec2(renderer.width(), renderer.height()));
    finishIfMeasuring(times);
    auto t0 = EditorClock::now();
    // Render on change: the frame is rendered again only when something it depends on changed;
    // otherwise the last image, viewers and statistics stay on screen.
    glm::ivec2 const size(renderer.width(), renderer.height());
    ui::RenderInputs inputs =
        ui::renderInputs(state.camera, editor.drawn, state.pipeline, size, editor.sceneGeneration,
                         editor.frameMemory.shaderGeneration, state.animation.time, times.measuring);
    dropStaleStop(editor);
    FrameInput const frameInput = ui::editorFrameInput(state, editor.drawn, times.measuring);
    inputs.stopAfter = frameInput.stopAfter;
    inputs.teaching = ui::teachingInputs(frameInput, state.ab);
    std::optional<ui::RenderInputs> const before = editor.render.last;
    times.rendered = size.x > 0 && size.y > 0 && ui::needsRender(editor.render, inputs);
    editor.renderReason = times.rendered ? ui::describeChange(before, inputs) : std::string("nothing");
    // Re-rendered with nothing changed: Render every frame is on, and the Stats window says so.
    if (times.rendered && editor.renderReason == "nothing") editor.renderReason = "render every frame is on";
    if (times.rendered)
        // Interactive frames take the previous frame's GPU timings instead of waiting for
        // this one's; a measurement waits anyway (glFinish), so it can have exact ones.
        times.frameStats = ui::renderEditorFrame(state, renderer, frameInput, editor.frame, editor.gpu.ab);
    markLessonClaim(editor, times.rendered);
    if (times.rendered || state.frame.passes.empty())
        state.frame.passes = renderer.framePasses(frameInput);
    else
        times.frameStats = state.stats.last;
    finishIfMeasuring(times);
    times.renderMs = msSince(t0);

    // Viewers, range fits and the pixel inspector's sample.
    t0 = EditorClock::now();
    ui::serviceMsaaViews(state, renderer, times.frameStats, times.rendered, editor.gpu.msaa);
    editor.gpu.timer.begin("viewers");
    if (renderer.width() > 0 && renderer.height() > 0 && state.gbuffer.visible) drawViewers(editor, times);
    times.litDiffTexture = ui::serviceLitPin(state.litPin, renderer, editor.frame, editor.gpu.viewerTools);
    times.viewportToolsTexture =
        ui::serviceViewportTools(state, renderer, FrameInput{state.camera, editor.drawn, state.pipeline}, editor.frame,
                                 times.rendered, editor.gpu.viewerTools);
    times.overviewTextures =
        ui::serviceOverview(state, renderer, FrameInput{state.camera, editor.drawn, state.pipeline}, editor.frame,
                            times.rendered, editor.gpu.viewerTools);
    editor.gpu.timer.end();
    samplePixel(editor, times.rendered);
    finishIfMeasuring(times);
    times.viewersMs = msSince(t0);
}

void reloadShaders(Editor& editor) {
    if (std::chrono::duration<double>(EditorClock::now() - editor.frameMemory.lastReload).count() < 1.0) return;
    editor.frameMemory.lastReload = EditorClock::now();
    for (auto const& message : editor.renderer->reloadChangedShaders()) {
        ++editor.frameMemory.shaderGeneration;  // a reloaded (or failed) program: the next frame renders again
        bool const failed = message.find("fail") != std::string::npos || message.find("error") != std::string::npos;
        ui::logMessage(editor.state.log, message, failed);
    }
}

void present(Editor& editor, FrameTimes& times) {
    auto const t0 = EditorClock::now();
    editor.gpu.timer.begin("imgui");
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, times.fbWidth, times.fbHeight);
    glClearColor(0.08f, 0.08f, 0.09f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    editor.gpu.timer.end();
    finishIfMeasuring(times);
    times.imguiMs = msSince(t0);
    times.cost.uiCpuMs = times.uiMs;
    for (auto const& [name, ms] : editor.gpu.timer.finishFrame(false)) {
        if (name == "viewers") times.cost.viewersGpuMs = ms;
        if (name == "imgui") times.cost.imguiGpuMs = ms;
    }

    EditorOptions const& options = editor.options;
    EditorState& state = editor.state;
    if (editor.script) {
        editor.script->step(*editor.host);
        if (editor.script->finished()) state.quitRequested = true;
    }
    int const screenshotFrames = options.frames > 0 ? options.frames : 5;
    if (options.screenshotPath && editor.frame == screenshotFrames) {
        if (auto error = ui::writePng(editor.host->readWindow(), *options.screenshotPath)) {
            std::fprintf(stderr, "gbuffer-lab: %s\n", error->c_str());
            editor.exitCode = 2;
        } else {
            ui::offerDownload(*options.screenshotPath);  // the browser (?screenshot=NAME): its files are in memory
        }
        state.quitRequested = true;
    }
    if (editor.windowShot.framesLeft > 0 && --editor.windowShot.framesLeft == 0) saveWindowShot(editor);
    if (!options.screenshotPath && !editor.script && options.frames > 0 && editor.frame >= options.frames)
        state.quitRequested = true;

    glfwSwapBuffers(editor.window());
    // A test's slow machine: the sleep still takes events, so their times stay exact.
    if (options.frameSleepMs > 0) sleepTakingEvents(options.frameSleepMs);
    // Idle (nothing rendered, no input, nothing loading or waiting for ImGui): sleep until the
    // next event, at most 1/20 s, instead of redrawing the same UI as fast as possible. (In the
    // browser, which cannot sleep, the frame callback runs every third display frame instead.)
    editor.idle = !times.rendered && !editor.unattended && editor.input.frameEvents.empty() &&
                  editor.input.replay.pending.empty() && !editor.loading.job;
    if (options.frameSleepMs <= 0 && editor.idle) glfwWaitEventsTimeout(0.05);
}

void recordFrame(Editor& editor, FrameTimes const& times) {
    ui::EditorCost cost = times.cost;
    double const pageMs = msSince(times.start);
    cost.frameCpuMs = pageMs;
    // In the browser this function returns long before the GPU process has drawn the frame: the
    // frame's time is from one frame's start to the next (the last whole frame), as the desktop's
    // loop, whose swap waits for the drawing, measures it. The frame log keeps this thread's part.
    if (gl::kWebGL2) cost.frameCpuMs = double(times.dt) * 1000.0;
    ui::recordFrame(editor.state.stats, times.frameStats, cost);
    if (editor.frameLog.isOpen()) logFrame(editor, times, pageMs);
    if (!times.measuring) return;
    ui::CostMeasurement& m = editor.state.measurement;
    ++m.frames;
    m.renderMs += times.renderMs;
    m.viewersMs += times.viewersMs;
    m.uiMs += times.uiMs;
    m.imguiMs += times.imguiMs;
    m.frameMs += cost.frameCpuMs;
    if (--m.remaining == 0)
        printMeasurement(m, {times.fbWidth, times.fbHeight}, {editor.renderer->width(), editor.renderer->height()},
                         int(editor.drawn.size()));
}

}  // namespace gbl
