// The editor's scene-loading worker on the CPU: results, errors, hold-and-cancel, refusal, recent list.
#include "model/scene_loading.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
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

TEST(SceneLoading, FolderOpensItsSceneWithBuffersInSubfolders) {
    // The common layout: the .gltf beside a buffers/ folder, as the browser's folder drop writes it.
    fs::path const dir = fs::temp_directory_path() / "gbl_folder_scene";
    fs::remove_all(dir);
    fs::create_directories(dir / "Model" / "buffers");
    std::ifstream in(localFile("triangle_external.gltf"));
    std::string gltf{std::istreambuf_iterator<char>(in), {}};
    std::size_t const uri = gltf.find("\"triangle.bin\"");
    ASSERT_NE(uri, std::string::npos);
    gltf.replace(uri, 14, "\"buffers/triangle.bin\"");
    std::ofstream(dir / "Model" / "scene.gltf") << gltf;
    fs::copy_file(localFile("triangle.bin"), dir / "Model" / "buffers" / "triangle.bin");

    FolderScene const found = findFolderScene(dir.string(), "the dropped folder");
    ASSERT_TRUE(found.scene) << found.message;
    EXPECT_EQ(*found.scene, (dir / "Model" / "scene.gltf").generic_string());
    EXPECT_EQ(found.message, "opening Model/scene.gltf from the dropped folder (2 files)");
    GltfLoadResult const loaded = loadGltf(*found.scene);
    ASSERT_TRUE(loaded.scene) << loaded.error;
    EXPECT_EQ(loaded.scene->triangleCount(), 1u);
    // Moved beside the scene, the buffer is missing: the load fails, so the one above found it in buffers/.
    fs::rename(dir / "Model" / "buffers" / "triangle.bin", dir / "Model" / "triangle.bin");
    EXPECT_FALSE(loadGltf(*found.scene).scene);
    fs::remove_all(dir);
}

TEST(SceneLoading, FolderWithSeveralScenesOpensTheFirstByPathAndSaysSo) {
    fs::path const dir = fs::temp_directory_path() / "gbl_folder_scenes";
    fs::remove_all(dir);
    fs::create_directories(dir / "M" / "a");
    for (char const* name : {"M/c.gltf", "M/b.glb", "M/a/x.gltf", "M/notes.txt"}) std::ofstream(dir / name) << "{}";
    FolderScene const found = findFolderScene(dir.string(), "the folder M");
    ASSERT_TRUE(found.scene);
    EXPECT_EQ(*found.scene, (dir / "M" / "a" / "x.gltf").generic_string());
    EXPECT_EQ(found.message,
              "opening M/a/x.gltf from the folder M (4 files); one scene at a time, the first by path: the folder "
              "also holds M/b.glb, M/c.gltf");
    fs::remove_all(dir);
}

TEST(SceneLoading, FolderWithoutAScenePathSaysWhy) {
    fs::path const dir = fs::temp_directory_path() / "gbl_folder_none";
    fs::remove_all(dir);
    fs::create_directories(dir / "empty" / "sub");
    FolderScene const empty = findFolderScene((dir / "empty").string(), "the folder empty");
    EXPECT_FALSE(empty.scene);
    EXPECT_EQ(empty.message, "the folder empty holds no files: choose the folder the .gltf or .glb is in");
    std::ofstream(dir / "empty" / "sub" / "albedo.png") << "png";
    FolderScene const pictures = findFolderScene((dir / "empty").string(), "the folder empty");
    EXPECT_FALSE(pictures.scene);
    EXPECT_FALSE(pictures.gbuffer);
    EXPECT_EQ(pictures.message,
              "the folder empty holds 1 file(s) but no .gltf or .glb scene and no G-buffer (manifest.json): nothing to "
              "open");
    FolderScene const missing = findFolderScene((dir / "missing").string(), "the folder missing");
    EXPECT_FALSE(missing.scene);
    EXPECT_TRUE(missing.message.starts_with("cannot read the folder missing: ")) << missing.message;
    fs::remove_all(dir);
}

// A G-buffer folder given whole (the browser writes a dropped or picked folder into its file system): a
// manifest's folder, or a `render --out` folder (camera.json with lights.json), opens as a G-buffer; the
// first by path when there are several; a scene in the same folder wins.
TEST(SceneLoading, FolderWithAGBufferOpensIt) {
    fs::path const dir = fs::temp_directory_path() / "gbl_folder_gbuffer";
    fs::remove_all(dir);
    fs::create_directories(dir / "export");
    for (char const* name : {"export/camera.json", "export/lights.json", "export/position.exr"})
        std::ofstream(dir / name) << "{}";
    FolderScene const rendered = findFolderScene((dir / "export").string(), "the folder export");
    EXPECT_FALSE(rendered.scene);
    ASSERT_TRUE(rendered.gbuffer) << rendered.message;
    EXPECT_EQ(*rendered.gbuffer, (dir / "export").string());
    EXPECT_EQ(rendered.message, "opening the G-buffer in it from the folder export (3 files)");
    // camera.json alone is not a `render --out` folder.
    fs::remove(dir / "export" / "lights.json");
    EXPECT_FALSE(findFolderScene((dir / "export").string(), "the folder export").gbuffer);

    fs::create_directories(dir / "top" / "b");
    fs::create_directories(dir / "top" / "a");
    for (char const* name : {"top/b/manifest.json", "top/a/manifest.json", "top/a/normal.exr"})
        std::ofstream(dir / name) << "{}";
    FolderScene const two = findFolderScene((dir / "top").string(), "the folder top");
    ASSERT_TRUE(two.gbuffer) << two.message;
    EXPECT_EQ(*two.gbuffer, (dir / "top" / "a").generic_string());
    EXPECT_EQ(two.message,
              "opening the G-buffer a from the folder top (3 files); one G-buffer at a time, the first by path: the "
              "folder also holds b");
    std::ofstream(dir / "top" / "scene.gltf") << "{}";
    FolderScene const scene = findFolderScene((dir / "top").string(), "the folder top");
    EXPECT_TRUE(scene.scene);
    EXPECT_FALSE(scene.gbuffer);
    fs::remove_all(dir);
}
