// The editor's scene-loading worker on the CPU: results, errors, hold-and-cancel, refusal, recent list.
#include "model/scene_loading.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

using namespace gbl;
using namespace gbl::ui;
namespace fs = std::filesystem;

namespace {

std::string localFile(std::string const& name) {
    return (fs::path(test::dataDir()) / "gltf" / name).string();
}

// Polls as the editor does once per frame, with a deadline far above any real load of these files.
std::optional<GltfLoadResult> waitForLoad(SceneLoadingState& state) {
    auto const deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (std::chrono::steady_clock::now() < deadline) {
        if (auto r = takeFinishedLoad(state)) return r;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return std::nullopt;
}

bool waitUntilHeld(SceneLoadingState const& state) {
    auto const deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (std::chrono::steady_clock::now() < deadline) {
        if (loadHeld(state)) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    return false;
}

}  // namespace

TEST(SceneLoading, LoadsOnTheWorkerAndHandsOverTheWholeScene) {
    SceneLoadingState state;
    ASSERT_FALSE(startSceneLoad(state, localFile("triangle.gltf")));
    EXPECT_TRUE(sceneLoading(state));
    auto const r = waitForLoad(state);
    ASSERT_TRUE(r);
    ASSERT_TRUE(r->scene) << r->error;
    EXPECT_EQ(r->scene->triangleCount(), 1u);
    EXPECT_FALSE(sceneLoading(state));
    EXPECT_EQ(currentLoadStage(state), "");
}

TEST(SceneLoading, BrokenFileGivesTheLoadersSentenceAndNoScene) {
    SceneLoadingState state;
    ASSERT_FALSE(startSceneLoad(state, localFile("malformed.gltf")));
    auto const r = waitForLoad(state);
    ASSERT_TRUE(r);
    EXPECT_FALSE(r->scene);
    EXPECT_FALSE(r->cancelled);
    EXPECT_NE(r->error.find("malformed.gltf"), std::string::npos) << r->error;
}

TEST(SceneLoading, HoldReportsTheStageAndCancelEndsTheLoadWithoutAScene) {
    SceneLoadingState state;
    state.holdNextAtStage = "parsing";
    ASSERT_FALSE(startSceneLoad(state, localFile("triangle.gltf")));
    EXPECT_TRUE(state.holdNextAtStage.empty()) << "the hook applies to one load only";
    ASSERT_TRUE(waitUntilHeld(state));
    EXPECT_EQ(currentLoadStage(state), "parsing");
    EXPECT_GT(currentLoadFraction(state), 0.0f);
    EXPECT_LT(currentLoadFraction(state), 1.0f);
    // Held, the load cannot finish on its own.
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    EXPECT_FALSE(takeFinishedLoad(state));

    // A second load while one runs is refused with a sentence naming both files.
    auto const refused = startSceneLoad(state, localFile("lights.gltf"));
    ASSERT_TRUE(refused);
    EXPECT_NE(refused->find("triangle.gltf"), std::string::npos) << *refused;
    EXPECT_NE(refused->find("lights.gltf"), std::string::npos) << *refused;

    cancelSceneLoad(state);
    auto const r = waitForLoad(state);
    ASSERT_TRUE(r);
    EXPECT_TRUE(r->cancelled);
    EXPECT_FALSE(r->scene);
    EXPECT_NE(r->error.find("cancelled"), std::string::npos) << r->error;
}

TEST(SceneLoading, ReleasedHoldLoadsToTheEnd) {
    SceneLoadingState state;
    state.holdNextAtStage = "parsing";
    ASSERT_FALSE(startSceneLoad(state, localFile("triangle.gltf")));
    ASSERT_TRUE(waitUntilHeld(state));
    releaseHeldLoad(state);
    auto const r = waitForLoad(state);
    ASSERT_TRUE(r);
    EXPECT_TRUE(r->scene) << r->error;
}

TEST(SceneLoading, DestroyingAHeldLoadStopsTheWorker) {
    // The editor quitting mid-load must not hang on a held (or slow) worker.
    auto const t0 = std::chrono::steady_clock::now();
    {
        SceneLoadingState state;
        state.holdNextAtStage = "parsing";
        ASSERT_FALSE(startSceneLoad(state, localFile("triangle.gltf")));
        ASSERT_TRUE(waitUntilHeld(state));
    }
    EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(30));
}

TEST(SceneLoading, RecentListIsMostRecentFirstWithoutDuplicatesAndBounded) {
    SceneLoadingState state;
    rememberRecentScene(state, "a.gltf");
    rememberRecentScene(state, "b.gltf");
    rememberRecentScene(state, "a.gltf");
    ASSERT_EQ(state.recent.size(), 2u);
    EXPECT_EQ(state.recent[0], "a.gltf");
    EXPECT_EQ(state.recent[1], "b.gltf");
    for (int i = 0; i < 20; ++i) rememberRecentScene(state, std::to_string(i) + ".gltf");
    EXPECT_EQ(state.recent.size(), kMaxRecentScenes);
    EXPECT_EQ(state.recent.front(), "19.gltf");
}

TEST(SceneLoading, InstallingAFileSceneKeepsTheLoadersLightsExactly) {
    // triangle.gltf has no lights: the loader gives it a rig for its bounds, and installing the
    // scene must take that rig as it is (no second, editor-side rig or rescaled fall-off).
    SceneLoadingState loading;
    ASSERT_FALSE(startSceneLoad(loading, localFile("triangle.gltf")));
    auto const r = waitForLoad(loading);
    ASSERT_TRUE(r && r->scene) << (r ? r->error : "timed out");
    ASSERT_FALSE(r->scene->lights.empty());
    EditorState state;
    int uploads = 0;
    auto const upload = [&uploads](SceneData const&) -> std::optional<std::string> {
        ++uploads;
        return std::nullopt;
    };
    ASSERT_FALSE(installScene(*r->scene, true, 7, state, upload));
    EXPECT_EQ(uploads, 1);
    EXPECT_TRUE(state.lights == r->scene->lights);
    // The procedural scene gets the default rig of the requested size instead.
    ASSERT_FALSE(installScene(*r->scene, false, 7, state, upload));
    EXPECT_EQ(state.lights.size(), 7u);
}

TEST(SceneLoading, DroppedSessionAndLessonFilesAreToldApartFromOtherJson) {
    // What the editor opens a dropped .json as (in the browser every picked file arrives so).
    EXPECT_EQ(droppedDocumentKind((fs::path(test::dataDir()) / "sessions" / "three_lights.json").string()),
              DroppedDocument::Session);
    EXPECT_EQ(droppedDocumentKind((fs::path(GBL_SOURCE_DIR) / "assets" / "lessons" / "01_gbuffer.json").string()),
              DroppedDocument::Lesson);
    fs::path const dir = fs::temp_directory_path() / "gbl_dropped_kind";
    fs::create_directories(dir);
    auto write = [&](std::string const& name, std::string const& text) {
        std::ofstream(dir / name) << text;
        return (dir / name).string();
    };
    // Spacing does not matter; a manifest, another format, no format, a glTF and a missing file are Other.
    EXPECT_EQ(droppedDocumentKind(write("s.json", "{\"format\"  :\n \"gbuffer-lab-session\", \"version\": 3}")),
              DroppedDocument::Session);
    EXPECT_EQ(droppedDocumentKind(write("m.json", "{\"preset\": \"gbuffer-lab\", \"normal\": {}}")),
              DroppedDocument::Other);
    EXPECT_EQ(droppedDocumentKind(write("o.json", "{\"format\": \"gbuffer-lab-sessions\"}")), DroppedDocument::Other);
    EXPECT_EQ(droppedDocumentKind(write("x.gltf", "{\"format\": \"gbuffer-lab-session\"}")), DroppedDocument::Other);
    EXPECT_EQ(droppedDocumentKind((dir / "missing.json").string()), DroppedDocument::Other);
    fs::remove_all(dir);
}
