// UI test script commands for scene loading: open, drop, hold, cancel, wait and check.
#include "script/script_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace gbl::ui {

namespace {

// Generous: a large scene decodes in a few seconds on two software cores, even under sanitizers.
constexpr double kLoadTimeoutSeconds = 300.0;
constexpr double kHoldTimeoutSeconds = 60.0;

char const* outcomeName(SceneLoadOutcome o) {
    switch (o) {
        case SceneLoadOutcome::None:
            return "none";
        case SceneLoadOutcome::Loaded:
            return "loaded";
        case SceneLoadOutcome::Failed:
            return "failed";
        case SceneLoadOutcome::Cancelled:
            return "cancelled";
    }
    return "?";
}

void skipUnlessExistsCommand(CommandCall const& c) {
    std::string const path = joinWords(c.w, 1);
    std::error_code ec;
    if (std::filesystem::exists(path, ec)) return;
    std::printf("ui-test SKIP %s:%d: %s is absent, so the rest of this script does not run\n", c.run.path.c_str(),
                c.command.line, path.c_str());
    std::fflush(stdout);
    c.run.skipped = true;
    c.run.next = c.run.commands.size();
}

// wait-load-held and wait-scene-loaded. A request made by the previous command starts at the
// next frame: wait for it too.
void waitLoad(CommandCall const& c, bool held) {
    ScriptHost* host = &c.host;
    c.waitUntil(
        [host, held] {
            SceneLoadingState const& l = *host->sceneLoading;
            if (held) return loadHeld(l);
            return !sceneLoading(l) && l.requests.empty() && l.dropped.empty();
        },
        held ? kHoldTimeoutSeconds : kLoadTimeoutSeconds);
}

void expectLoadStageCommand(CommandCall const& c) {
    SceneLoadingState const& loading = *c.host.sceneLoading;
    std::string const stage = currentLoadStage(loading);
    char detail[64];
    std::snprintf(detail, sizeof detail, " at %.0f %%", 100.0 * currentLoadFraction(loading));
    c.check(sceneLoading(loading) && stage.find(joinWords(c.w, 1)) != std::string::npos,
            "stage is \"" + stage + "\"" + detail);
}

void cameraFramesSceneCommand(CommandCall const& c) {
    // Every corner of the bounds projects inside the view and in front of the camera.
    EditorState const& s = c.host.state;
    Renderer const& r = c.host.renderer;
    float const aspect = r.height() > 0 ? float(r.width()) / float(r.height()) : 1.0f;
    glm::mat4 const viewProj = s.camera.projection(aspect) * s.camera.view();
    float worst = 0.0f;  // largest |ndc| coordinate of a corner
    bool inFront = true;
    for (int i = 0; i < 8; ++i) {
        glm::vec3 const p((i & 1) ? s.sceneBounds.max.x : s.sceneBounds.min.x,
                          (i & 2) ? s.sceneBounds.max.y : s.sceneBounds.min.y,
                          (i & 4) ? s.sceneBounds.max.z : s.sceneBounds.min.z);
        glm::vec4 const clip = viewProj * glm::vec4(p, 1.0f);
        inFront &= clip.w > s.camera.nearPlane;
        if (clip.w > 0.0f) worst = std::max({worst, std::abs(clip.x / clip.w), std::abs(clip.y / clip.w)});
    }
    char detail[96];
    std::snprintf(detail, sizeof detail, "corners %s, largest |ndc| %.3f", inFront ? "in front" : "behind the camera",
                  worst);
    // 1.0 is the view's edge; a framed scene also fills a fair share of it (not a dot).
    c.check(inFront && worst <= 1.0f && worst >= 0.2f, detail);
}

SceneLoadingState& loading(CommandCall const& c) {
    return *c.host.sceneLoading;
}

constexpr auto kLoads = CommandNeeds::SceneLoading;

constexpr ScriptCommandSpec kSceneCommands[] = {
    {"skip-unless-exists", "PATH...", "end the script as skipped (\"ui-test SKIP\") when PATH is absent",
     skipUnlessExistsCommand},
    {"open-scene", "PATH...", "File > Open scene: starts loading on the worker",
     [](CommandCall const& c) { loading(c).requests.push_back(joinWords(c.w, 1)); }, kLoads},
    {"drop-files", "PATH...", "the same files dropped onto the window (paths without spaces)",
     [](CommandCall const& c) {
         // As GLFW's drop callback hands them over.
         loading(c).dropped.insert(loading(c).dropped.end(), c.w.begin() + 1, c.w.end());
     },
     kLoads},
    {"hold-load", "STAGE...", "the next load waits when it first reports STAGE (\"decoding images\")",
     [](CommandCall const& c) { loading(c).holdNextAtStage = joinWords(c.w, 1); }, kLoads},
    {"wait-load-held", "", "wait until the running load waits at that stage (60 s at most)",
     [](CommandCall const& c) { waitLoad(c, true); }, kLoads},
    {"release-load", "", "let a held load go on", [](CommandCall const& c) { releaseHeldLoad(loading(c)); }, kLoads},
    {"cancel-load", "", "the Cancel button of the progress window",
     [](CommandCall const& c) {
         if (!sceneLoading(loading(c))) return c.check(false, "no load is running");
         cancelSceneLoad(loading(c));
     },
     kLoads},
    {"wait-scene-loaded", "", "wait until no load runs and its result is applied (300 s at most)",
     [](CommandCall const& c) { waitLoad(c, false); }, kLoads},
    {"expect-loading", "", "a load is running",
     [](CommandCall const& c) {
         bool const running = sceneLoading(loading(c));
         c.check(running, running ? "loading " + loading(c).job->path : "nothing is loading");
     },
     kLoads},
    {"expect-load-stage", "TEXT...", "the running load's stage contains TEXT", expectLoadStageCommand, kLoads},
    {"expect-load-outcome", "WHAT", "the last finished load: loaded | failed | cancelled",
     [](CommandCall const& c) {
         std::string const got = outcomeName(loading(c).lastOutcome);
         std::string const& error = loading(c).lastError;
         c.check(got == c.w[1], "it is " + got + (error.empty() ? "" : ": " + error));
     },
     kLoads},
    {"expect-load-error", "TEXT...", "... and its error sentence contains TEXT",
     [](CommandCall const& c) {
         SceneLoadingState const& l = loading(c);
         bool const ok =
             l.lastOutcome == SceneLoadOutcome::Failed && l.lastError.find(joinWords(c.w, 1)) != std::string::npos;
         c.check(ok, std::string(outcomeName(l.lastOutcome)) + ": \"" + l.lastError + "\"");
     },
     kLoads},
    {"expect-scene", "TEXT...", "the current scene's source contains TEXT",
     [](CommandCall const& c) {
         std::string const& source = c.host.state.sceneSource;
         c.check(source.find(joinWords(c.w, 1)) != std::string::npos, "the scene is " + source);
     },
     kLoads},
    {"expect-triangles", "N", "the current scene has N triangles",
     [](CommandCall const& c) {
         std::size_t const n = c.host.state.sceneTriangles;
         c.check(n == std::size_t(std::atoll(c.w[1].c_str())), "the scene has " + std::to_string(n));
     },
     kLoads},
    {"expect-camera-frames-scene", "", "the scene's bounds are in front of the camera and inside the view",
     cameraFramesSceneCommand, kLoads},
    {"expect-window-shown", "TITLE...", "an ImGui window (also a dialog) of that title was drawn this frame",
     [](CommandCall const& c) {
         if (!c.host.windowShown) return c.check(false, "the editor gives scripts no window query");
         c.check(c.host.windowShown(joinWords(c.w, 1)), "");
     },
     kLoads},
    {"dismiss-load-error", "", "press OK in the load error dialog",
     [](CommandCall const& c) { loading(c).errorDialogDismissed = true; }, kLoads},
    // --- another program's G-buffer (model/gbuffer_opening.h); opened at the next frame ---
    {"open-gbuffer", "PATH...", "File > Open G-buffer of a manifest or folder",
     [](CommandCall const& c) { loading(c).gbuffer.requests.push_back(joinWords(c.w, 1)); }, kLoads},
    {"close-gbuffer", "", "File > Close G-buffer",
     [](CommandCall const& c) { loading(c).gbuffer.closeRequested = true; }, kLoads},
    {"expect-gbuffer", "none|PATH...", "no G-buffer is shown, or the one shown is PATH, at its own frame size",
     [](CommandCall const& c) {
         GBufferOpenState const& g = loading(c).gbuffer;
         std::string const want = joinWords(c.w, 1);
         std::string const got = g.path.empty() ? std::string("none") : g.path;
         glm::ivec2 const frame(c.host.renderer.width(), c.host.renderer.height());
         bool const sized = g.path.empty() || frame == g.size;
         c.check(got == want && sized && c.host.renderer.hasImportedGBuffer() == !g.path.empty(),
                 "shown: " + got + ", frame " + std::to_string(frame.x) + "x" + std::to_string(frame.y));
     },
     kLoads},
    {"expect-gbuffer-error", "TEXT...", "the last refused G-buffer's sentence contains TEXT",
     [](CommandCall const& c) {
         std::string const& error = loading(c).gbuffer.lastError;
         c.check(!error.empty() && error.find(joinWords(c.w, 1)) != std::string::npos, "\"" + error + "\"");
     },
     kLoads},
};

}  // namespace

std::span<ScriptCommandSpec const> sceneCommands() {
    return kSceneCommands;
}

}  // namespace gbl::ui
