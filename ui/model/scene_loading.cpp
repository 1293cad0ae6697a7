// Scene loading for the editor: worker thread, progress, cancellation, and the hand-over to the renderer.
#include "model/scene_loading.h"

#include "model/camera_rig.h"
#include "scene/default_scene.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string_view>
#include <utility>

namespace gbl::ui {

namespace {

void wakeWorker(SceneLoadProgress& p) {
    {
        std::lock_guard lock(p.mutex);
        p.released = true;
    }
    p.wake.notify_all();
}

// Runs on the worker thread for every progress report of the loader.
bool reportProgress(SceneLoadProgress& p, float fraction, std::string_view stage) {
    p.fraction.store(fraction, std::memory_order_relaxed);
    std::unique_lock lock(p.mutex);
    p.stage = stage;
    if (!p.holdAtStage.empty() && stage == p.holdAtStage && !p.released) {
        p.held = true;
        p.wake.wait(lock, [&] { return p.released || p.cancel.load(); });
        p.held = false;
    }
    return !p.cancel.load();
}

}  // namespace

SceneLoadJob::~SceneLoadJob() {
    // The worker references `progress` through its own shared_ptr, but its result must not
    // outlive the editor: stop it and wait (it stops at its next progress report).
    if (progress) {
        progress->cancel = true;
        wakeWorker(*progress);
    }
    if (result.valid()) result.wait();
}

void rememberRecentScene(SceneLoadingState& state, std::string const& path) {
    std::erase(state.recent, path);
    state.recent.insert(state.recent.begin(), path);
    if (state.recent.size() > kMaxRecentScenes) state.recent.resize(kMaxRecentScenes);
}

std::optional<std::string> startSceneLoad(SceneLoadingState& state, std::string const& path) {
    if (state.job) return "'" + state.job->path + "' is still loading: cancel it before opening '" + path + "'.";
    auto progress = std::make_shared<SceneLoadProgress>();
    progress->holdAtStage = std::exchange(state.holdNextAtStage, {});
    GltfLoadOptions options;
    options.allowOutsideUris = state.allowOutsideUris;
    options.progress = [progress](float fraction, std::string_view stage) {
        return reportProgress(*progress, fraction, stage);
    };
    SceneLoadJob job;
    job.path = path;
    job.progress = progress;
    job.started = std::chrono::steady_clock::now();
    // std::async(launch::async) is a real thread; the future's result is the whole scene or
    // an error, so nothing half-loaded can reach the render thread.
#ifdef __EMSCRIPTEN__
    // The browser build has no threads: the load runs on the main thread when takeFinishedLoad asks.
    job.result = std::async(std::launch::deferred, [path, options] { return loadGltf(path, options); });
#else
    job.result = std::async(std::launch::async, [path, options] { return loadGltf(path, options); });
#endif
    state.job.emplace(std::move(job));
    return std::nullopt;
}

void cancelSceneLoad(SceneLoadingState& state) {
    if (!state.job) return;
    state.job->progress->cancel = true;
    wakeWorker(*state.job->progress);
}

void releaseHeldLoad(SceneLoadingState& state) {
    if (state.job) wakeWorker(*state.job->progress);
}

bool sceneLoading(SceneLoadingState const& state) {
    return state.job.has_value();
}

std::string currentLoadStage(SceneLoadingState const& state) {
    if (!state.job) return {};
    std::lock_guard lock(state.job->progress->mutex);
    return state.job->progress->stage;
}

float currentLoadFraction(SceneLoadingState const& state) {
    return state.job ? state.job->progress->fraction.load(std::memory_order_relaxed) : 0.0f;
}

bool loadHeld(SceneLoadingState const& state) {
    if (!state.job) return false;
    std::lock_guard lock(state.job->progress->mutex);
    return state.job->progress->held;
}

std::optional<GltfLoadResult> takeFinishedLoad(SceneLoadingState& state) {
    if (!state.job) return std::nullopt;
    std::future_status const status = state.job->result.wait_for(std::chrono::seconds(0));
    if (status != std::future_status::ready && status != std::future_status::deferred) return std::nullopt;
    GltfLoadResult result = state.job->result.get();
    state.job.reset();
    return result;
}

std::optional<std::string> installScene(SceneData const& scene, bool fromFile, int defaultLightCount,
                                        EditorState& state, SceneUploader const& upload) {
    // A file's scene always has lights: the loader lights a file without any itself, with a rig
    // made for its bounds (gltf/mapping.h, generateLightsForBounds).
    std::vector<PointLight> lights = fromFile ? scene.lights : makeDefaultLights(defaultLightCount);
    // The upload is the only step that can still fail; nothing in the state changes before it.
    if (auto error = upload(scene)) return *error;
    for (auto const& w : scene.warnings) logMessage(state.log, scene.source + ": " + w);
    state.lights = std::move(lights);
    state.sceneSource = scene.source;
    state.sceneBounds = scene.bounds();
    state.sceneCameras = scene.cameras;
    state.sceneTriangles = scene.triangleCount();
    state.orbitCenter = fromFile ? state.sceneBounds.center() : defaultSceneCenter();
    state.animation.time = 0.0f;
    if (scene.camera) {
        state.camera = *scene.camera;
        resetTargetAhead(state.rig, state.camera, glm::length(state.camera.position - state.sceneBounds.center()));
    } else {
        frameBounds(state.rig, state.camera, state.sceneBounds);
    }
    state.lightsPanel.selected = state.lights.empty() ? -1 : 0;
    logMessage(state.log, "scene " + scene.source + ": " + std::to_string(scene.triangleCount()) + " triangles, " +
                              std::to_string(state.lights.size()) + " lights");
    return std::nullopt;
}

DroppedDocument droppedDocumentKind(std::string const& path) {
    if (!path.ends_with(".json")) return DroppedDocument::Other;
    std::ifstream file(path, std::ios::binary);
    std::string head(4096, '\0');
    file.read(head.data(), std::streamsize(head.size()));
    head.resize(std::size_t(file.gcount()));
    // The format string follows its key ("format": "gbuffer-lab-session"), whatever the spacing.
    std::size_t const key = head.find("\"format\"");
    if (key == std::string::npos) return DroppedDocument::Other;
    std::size_t const value = head.find('"', head.find(':', key));
    if (value == std::string::npos) return DroppedDocument::Other;
    std::string_view const rest = std::string_view(head).substr(value);
    if (rest.starts_with("\"gbuffer-lab-session\"")) return DroppedDocument::Session;
    if (rest.starts_with("\"gbuffer-lab-lesson\"")) return DroppedDocument::Lesson;
    return DroppedDocument::Other;
}

FolderScene findFolderScene(std::string const& dir, std::string const& label) {
    namespace fs = std::filesystem;
    std::error_code ec;
    std::vector<std::string> files, scenes;  // paths relative to dir
    std::vector<std::string> gbuffers;       // folders relative to dir ("." for dir itself)
    for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::recursive_directory_iterator();
         it.increment(ec)) {
        if (!it->is_regular_file(ec)) continue;
        std::string const rel = it->path().lexically_relative(dir).generic_string();
        files.push_back(rel);
        if (rel.ends_with(".gltf") || rel.ends_with(".glb")) scenes.push_back(rel);
        // A manifest, or the camera.json of a `render --out` folder that also has its lights.json.
        std::string const name = it->path().filename().string();
        std::error_code ignored;
        if (name == "manifest.json" ||
            (name == "camera.json" && fs::exists(it->path().parent_path() / "lights.json", ignored)))
            gbuffers.push_back(fs::path(rel).parent_path().empty() ? "."
                                                                   : fs::path(rel).parent_path().generic_string());
    }
    if (ec) return {std::nullopt, std::nullopt, "cannot read " + label + ": " + ec.message()};
    if (files.empty())
        return {std::nullopt, std::nullopt, label + " holds no files: choose the folder the .gltf or .glb is in"};
    if (scenes.empty() && !gbuffers.empty()) {
        std::sort(gbuffers.begin(), gbuffers.end());
        gbuffers.erase(std::unique(gbuffers.begin(), gbuffers.end()), gbuffers.end());
        std::string const folder = gbuffers.front() == "." ? dir : (fs::path(dir) / gbuffers.front()).generic_string();
        FolderScene found{std::nullopt, folder,
                          "opening the G-buffer " +
                              (gbuffers.front() == "." ? std::string("in it") : gbuffers.front()) + " from " + label +
                              " (" + std::to_string(files.size()) + " files)"};
        if (gbuffers.size() > 1) {
            found.message += "; one G-buffer at a time, the first by path: the folder also holds";
            for (std::size_t i = 1; i < gbuffers.size(); ++i) found.message += (i > 1 ? ", " : " ") + gbuffers[i];
        }
        return found;
    }
    if (scenes.empty())
        return {std::nullopt, std::nullopt,
                label + " holds " + std::to_string(files.size()) +
                    " file(s) but no .gltf or .glb scene and no G-buffer (manifest.json): nothing to open"};
    std::sort(scenes.begin(), scenes.end());
    FolderScene found{(fs::path(dir) / scenes.front()).generic_string(), std::nullopt,
                      "opening " + scenes.front() + " from " + label + " (" + std::to_string(files.size()) + " files)"};
    if (scenes.size() > 1) {
        found.message += "; one scene at a time, the first by path: the folder also holds";
        for (std::size_t i = 1; i < scenes.size(); ++i) found.message += (i > 1 ? ", " : " ") + scenes[i];
    }
    return found;
}

bool updateSceneLoading(SceneLoadingState& loading, int defaultLightCount, EditorState& state,
                        SceneUploader const& upload) {
    // Requests start in order; while a load runs the others are refused with a message, so
    // two scenes never race to become current.
    takeGBufferDrops(loading.dropped, loading.gbuffer);
    if (!loading.dropped.empty()) {
        std::vector<std::string> const dropped = std::exchange(loading.dropped, {});
        // A glTF dropped with its buffers and textures (a browser drops files, not their folder,
        // and puts them side by side): the one scene file among them opens, the rest are its own.
        auto const isScene = [](std::string const& p) { return p.ends_with(".gltf") || p.ends_with(".glb"); };
        auto const scenes = std::count_if(dropped.begin(), dropped.end(), isScene);
        if (scenes == 1) {
            loading.requests.push_back(*std::find_if(dropped.begin(), dropped.end(), isScene));
        } else {
            if (dropped.size() > 1)
                logMessage(state.log, "one scene at a time: opening " + dropped.front() + " and ignoring " +
                                          std::to_string(dropped.size() - 1) + " more dropped file(s)");
            loading.requests.push_back(dropped.front());
        }
    }
    for (std::string const& path : std::exchange(loading.requests, {})) {
        if (auto refused = startSceneLoad(loading, path))
            logMessage(state.log, *refused, true);
        else
            logMessage(state.log, "loading " + path + " ...");
    }

    auto result = takeFinishedLoad(loading);
    if (!result) return false;
    auto fail = [&](std::string const& error) {
        loading.lastOutcome = SceneLoadOutcome::Failed;
        loading.lastError = error;
        loading.errorDialogRequested = true;
        logMessage(state.log, error + " The previous scene stays.", true);
    };
    if (result->cancelled) {
        loading.lastOutcome = SceneLoadOutcome::Cancelled;
        loading.lastError = result->error;
        logMessage(state.log, result->error + " The previous scene stays.");
        return false;
    }
    if (!result->scene) {
        fail(result->error);
        return false;
    }
    if (auto error = installScene(*result->scene, true, defaultLightCount, state, upload)) {
        fail(result->scene->source + ": the scene could not be uploaded: " + *error);
        return false;
    }
    loading.lastOutcome = SceneLoadOutcome::Loaded;
    loading.lastError.clear();
    rememberRecentScene(loading, result->scene->source);
    return true;
}

}  // namespace gbl::ui
