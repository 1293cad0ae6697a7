// UI test script commands for scene loading: open, drop, hold, cancel, wait and check.
#include "script/ui_script.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace gbl::ui {

namespace {

struct SceneCommand {
    char const* name;
    int args;  // -1: one or more words (free text)
};
constexpr SceneCommand kSceneCommands[] = {
    {"skip-unless-exists", -1}, {"open-scene", -1}, {"drop-files", -1}, {"hold-load", -1}, {"wait-load-held", 0},
    {"release-load", 0}, {"cancel-load", 0}, {"wait-scene-loaded", 0}, {"expect-loading", 0},
    {"expect-load-stage", -1}, {"expect-load-outcome", 1}, {"expect-load-error", -1}, {"expect-scene", -1},
    {"expect-triangles", 1}, {"expect-camera-frames-scene", 0}, {"expect-window-shown", -1},
    {"dismiss-load-error", 0},
};

// Generous: a large scene decodes in a few seconds on two software cores, even under sanitizers.
constexpr double kLoadTimeoutSeconds = 300.0;
constexpr double kHoldTimeoutSeconds = 60.0;

std::string words(std::vector<std::string> const& w, std::size_t from) {
    std::string s;
    for (std::size_t i = from; i < w.size(); ++i) s += (i > from ? " " : "") + w[i];
    return s;
}

double secondsNow() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

char const* outcomeName(SceneLoadOutcome o) {
    switch (o) {
    case SceneLoadOutcome::None: return "none";
    case SceneLoadOutcome::Loaded: return "loaded";
    case SceneLoadOutcome::Failed: return "failed";
    case SceneLoadOutcome::Cancelled: return "cancelled";
    }
    return "?";
}

}  // namespace

int UiScript::sceneCommandArity(std::string const& name) {
    for (auto const& c : kSceneCommands)
        if (name == c.name) return c.args;
    return -2;
}

void UiScript::runSceneCommand(Command const& c, ScriptHost& host) {
    auto const& w = c.words;
    std::string const& cmd = w[0];
    if (cmd == "skip-unless-exists") {
        std::string const path = words(w, 1);
        std::error_code ec;
        if (std::filesystem::exists(path, ec)) return;
        std::printf("ui-test SKIP %s:%d: %s is absent, so the rest of this script does not run\n", path_.c_str(), c.line,
                    path.c_str());
        std::fflush(stdout);
        skipped_ = true;
        next_ = commands_.size();
        return;
    }
    if (!host.sceneLoading) return check(false, c, "this editor build cannot load scenes");
    SceneLoadingState& loading = *host.sceneLoading;
    EditorState const& s = host.state;

    if (cmd == "open-scene") {
        loading.requests.push_back(words(w, 1));
    } else if (cmd == "drop-files") {
        // As GLFW's drop callback hands them over (paths with spaces are not supported here).
        loading.dropped.insert(loading.dropped.end(), w.begin() + 1, w.end());
    } else if (cmd == "hold-load") {
        loading.holdNextAtStage = words(w, 1);
    } else if (cmd == "wait-load-held" || cmd == "wait-scene-loaded") {
        bool const held = cmd == "wait-load-held";
        // A request made by the previous command starts at the next frame: wait for it too.
        until_ = [&host, held] {
            SceneLoadingState const& l = *host.sceneLoading;
            if (held) return loadHeld(l);
            return !sceneLoading(l) && l.requests.empty() && l.dropped.empty();
        };
        untilCommand_ = c;
        untilDeadline_ = secondsNow() + (held ? kHoldTimeoutSeconds : kLoadTimeoutSeconds);
    } else if (cmd == "release-load") {
        releaseHeldLoad(loading);
    } else if (cmd == "cancel-load") {
        if (!sceneLoading(loading)) return check(false, c, "no load is running");
        cancelSceneLoad(loading);
    } else if (cmd == "expect-loading") {
        check(sceneLoading(loading), c, sceneLoading(loading) ? "loading " + loading.job->path : "nothing is loading");
    } else if (cmd == "expect-load-stage") {
        std::string const stage = currentLoadStage(loading);
        char detail[64];
        std::snprintf(detail, sizeof detail, " at %.0f %%", 100.0 * currentLoadFraction(loading));
        check(sceneLoading(loading) && stage.find(words(w, 1)) != std::string::npos, c,
              "stage is \"" + stage + "\"" + detail);
    } else if (cmd == "expect-load-outcome") {
        std::string const got = outcomeName(loading.lastOutcome);
        check(got == w[1], c, "it is " + got + (loading.lastError.empty() ? "" : ": " + loading.lastError));
    } else if (cmd == "expect-load-error") {
        bool const ok = loading.lastOutcome == SceneLoadOutcome::Failed &&
                        loading.lastError.find(words(w, 1)) != std::string::npos;
        check(ok, c, std::string(outcomeName(loading.lastOutcome)) + ": \"" + loading.lastError + "\"");
    } else if (cmd == "expect-scene") {
        check(s.sceneSource.find(words(w, 1)) != std::string::npos, c, "the scene is " + s.sceneSource);
    } else if (cmd == "expect-triangles") {
        check(s.sceneTriangles == std::size_t(std::atoll(w[1].c_str())), c,
              "the scene has " + std::to_string(s.sceneTriangles));
    } else if (cmd == "expect-camera-frames-scene") {
        // Every corner of the bounds projects inside the view and in front of the camera.
        float const aspect = host.renderer.height() > 0 ? float(host.renderer.width()) / float(host.renderer.height()) : 1.0f;
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
        check(inFront && worst <= 1.0f && worst >= 0.2f, c, detail);
    } else if (cmd == "expect-window-shown") {
        if (!host.windowShown) return check(false, c, "the editor gives scripts no window query");
        check(host.windowShown(words(w, 1)), c, "");
    } else if (cmd == "dismiss-load-error") {
        loading.errorDialogDismissed = true;
    }
}

}  // namespace gbl::ui
