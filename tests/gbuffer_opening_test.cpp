// Opening another program's G-buffer in the editor (ui/model/gbuffer_opening.h) on handmade raw
// G-buffers: a good one takes the camera, lights and shininess and closing gives the scene's back;
// each bad input is one logged sentence naming the problem, and what was shown stays.
#include "model/gbuffer_opening.h"
#include "import/relight_frame.h"
#include "run_command.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

using namespace gbl;
using namespace gbl::ui;
namespace fs = std::filesystem;

namespace {

constexpr int kW = 8, kH = 6;

void writeRaw(std::string const& path, int w, int h, int channels, std::vector<float> const& perPixel) {
    std::ofstream f(path, std::ios::binary);
    for (int i = 0; i < w * h; ++i)
        f.write(reinterpret_cast<char const*>(perPixel.data()), std::streamsize(4 * channels));
}

std::string raw(char const* file, int w, int h, int channels) {
    return std::string(R"({"file": ")") + file + R"(", "raw": {"type": "float", "width": )" + std::to_string(w) +
           R"(, "height": )" + std::to_string(h) + R"(, "channels": )" + std::to_string(channels) + "}";
}

// A wall at z = 0 seen from (0, 0, 5) (every pixel at one point: enough to re-light), albedo
// (0.5, 0.25, 1), two lights, shininess 16. `albedoHeight` other than kH plants a size mismatch;
// `normal` replaces the normal attachment.
std::string writeGBuffer(std::string const& name, int albedoHeight = kH, std::string normal = {}) {
    std::string const dir = test::freshTempDir(name);
    writeRaw(dir + "/position.raw", kW, kH, 4, {0.1f, 0.2f, 0.0f, 1.0f});
    writeRaw(dir + "/normal.raw", kW, kH, 3, {0.0f, 0.0f, 1.0f});
    writeRaw(dir + "/albedo.raw", kW, albedoHeight, 3, {0.5f, 0.25f, 1.0f});
    std::ofstream(dir + "/manifest.json") << R"({"format": "gbuffer-lab-gbuffer", "version": 1, "shininess": 16,
      "position": )" + raw("position.raw", kW, kH, 4) +
                                                 R"(, "channels": "rgb", "coverage": "a"},
      "normal": )" + (normal.empty() ? raw("normal.raw", kW, kH, 3) + R"(, "encoding": "float"})" : normal) +
                                                 R"(,
      "albedo": )" + raw("albedo.raw", kW, albedoHeight, 3) +
                                                 R"(},
      "camera": {"position": [0, 0, 5], "target": [0, 0, 0], "fov_y_degrees": 50, "near": 0.1, "far": 50},
      "lights": {"positions": [[0, 1, 2], [1, 0, 2]], "colors": [[1, 1, 1], [1, 0.5, 0]], "linear": 0.7, "quadratic": 1.8}})";
    return dir + "/manifest.json";
}

// Adds `fields` (ending in ", ") to writeGBuffer's manifest at `path`, before its shininess.
bool addToManifest(std::string const& path, std::string const& fields) {
    std::string text;
    {
        std::ifstream in(path);
        text.assign(std::istreambuf_iterator<char>(in), {});
    }
    std::size_t const at = text.find(R"("shininess": 16,)");
    if (at == std::string::npos) return false;
    text.insert(at, fields);
    std::ofstream(path) << text;
    return true;
}

// The editor showing a scene: a camera, three lights and shininess 32 that a G-buffer replaces.
EditorState sceneState() {
    EditorState s;
    s.sceneSource = "default";
    s.camera.position = {1.0f, 2.0f, 3.0f};
    s.camera.yawDegrees = 12.0f;
    s.rig.target = {0.5f, 0.5f, 0.5f};
    s.lights.resize(3);
    s.lights[2].position = {7.0f, 8.0f, 9.0f};
    s.lightsPanel.selected = 2;
    s.pipeline.shininess = 32.0f;
    s.pipeline.ambient = glm::vec3(0.05f);
    return s;
}

// An uploader that records what it was given, as Renderer::setImportedGBuffer would take it.
struct FakeRenderer {
    std::optional<glm::ivec2> uploaded;
    int uploads = 0;
    int clears = 0;
    std::optional<std::string> refuse;
    GBufferUploader upload() {
        return [this](ImportedFrame const& f) -> std::optional<std::string> {
            ++uploads;
            if (refuse) return refuse;
            uploaded = glm::ivec2(f.width, f.height);
            return std::nullopt;
        };
    }
    std::function<void()> clear() {
        return [this] {
            ++clears;
            uploaded.reset();
        };
    }
};

int errors(EditorState const& s) {
    return s.log.errorCount;
}

void expectSceneIntact(EditorState const& s) {
    EditorState const scene = sceneState();
    EXPECT_EQ(s.camera.position, scene.camera.position);
    EXPECT_EQ(s.camera.yawDegrees, scene.camera.yawDegrees);
    ASSERT_EQ(s.lights.size(), 3u);
    EXPECT_EQ(s.lights[2].position, scene.lights[2].position);
    EXPECT_EQ(s.lightsPanel.selected, 2);
    EXPECT_EQ(s.pipeline.shininess, 32.0f);
    EXPECT_EQ(s.pipeline.shading, ShadingModel::GbufferLab);
    EXPECT_EQ(s.pipeline.ambient, glm::vec3(0.05f));
    EXPECT_TRUE(s.viewport.importedFrame.empty());
}

// Opens `path` in an editor showing the scene and expects it refused with `text` in the sentence.
void expectRefused(std::string const& path, std::string const& text) {
    EditorState s = sceneState();
    GBufferOpenState g;
    FakeRenderer r;
    g.requests.push_back(path);
    EXPECT_EQ(updateGBufferOpening(g, s, r.upload(), r.clear()), GBufferChange::Failed);
    EXPECT_FALSE(gbufferOpen(g));
    EXPECT_FALSE(r.uploaded);
    EXPECT_NE(g.lastError.find(text), std::string::npos) << g.lastError;
    // One sentence in the log, naming the file, saying what stays.
    EXPECT_EQ(errors(s), 1);
    ASSERT_FALSE(s.log.lines.empty());
    EXPECT_NE(s.log.lines.back().find(text), std::string::npos) << s.log.lines.back();
    EXPECT_NE(s.log.lines.back().find("The scene stays shown."), std::string::npos) << s.log.lines.back();
    expectSceneIntact(s);
}

}  // namespace

TEST(GBufferOpening, FoldersAndManifestsAreGBuffersScenesAreNot) {
    std::string const dir = test::freshTempDir("gbopen_paths");
    EXPECT_TRUE(isGBufferPath(dir));
    EXPECT_TRUE(isGBufferPath(dir + "/manifest.json"));
    EXPECT_TRUE(isGBufferPath("/x/M.JSON"));
    EXPECT_FALSE(isGBufferPath("/x/Box.gltf"));
    EXPECT_FALSE(isGBufferPath("/x/Box.glb"));

    GBufferOpenState g;
    std::vector<std::string> dropped{"/x/a.gltf", dir, "/x/b.glb", "/x/m.json"};
    takeGBufferDrops(dropped, g);
    EXPECT_EQ(dropped, (std::vector<std::string>{"/x/a.gltf", "/x/b.glb"}));
    EXPECT_EQ(g.requests, (std::vector<std::string>{"/x/m.json"}));  // one at a time: the last dropped
    std::vector<std::string> scenes{"/x/a.gltf"};
    takeGBufferDrops(scenes, g);
    EXPECT_EQ(scenes.size(), 1u);
    EXPECT_EQ(g.requests.size(), 1u);
}

TEST(GBufferOpening, OpenTakesTheManifestsCameraLightsAndShininessAndCloseGivesTheSceneBack) {
    std::string const path = writeGBuffer("gbopen_good");
    EditorState s = sceneState();
    GBufferOpenState g;
    FakeRenderer r;
    g.requests.push_back(path);
    ASSERT_EQ(updateGBufferOpening(g, s, r.upload(), r.clear()), GBufferChange::Opened) << g.lastError;
    EXPECT_TRUE(gbufferOpen(g));
    EXPECT_EQ(g.path, path);
    EXPECT_EQ(r.uploaded, glm::ivec2(kW, kH));
    EXPECT_EQ(g.size, glm::ivec2(kW, kH));
    EXPECT_EQ(s.viewport.importedFrame, path);
    EXPECT_EQ(s.viewport.importedSize, glm::ivec2(kW, kH));
    EXPECT_EQ(errors(s), 0);
    // The manifest's camera: at (0, 0, 5) looking down -z (yaw -90, pitch 0), fov 50.
    EXPECT_NEAR(s.camera.position.z, 5.0f, 1e-5f);
    EXPECT_NEAR(s.camera.yawDegrees, -90.0f, 1e-3f);
    EXPECT_NEAR(s.camera.pitchDegrees, 0.0f, 1e-3f);
    EXPECT_NEAR(s.camera.fovYDegrees, 50.0f, 1e-3f);
    ASSERT_EQ(s.lights.size(), 2u);
    EXPECT_EQ(s.lights[1].position, glm::vec3(1.0f, 0.0f, 2.0f));
    EXPECT_EQ(s.lightsPanel.selected, 0);
    EXPECT_EQ(s.pipeline.shininess, 16.0f);
    EXPECT_EQ(s.pipeline.shading, ShadingModel::GbufferLab) << "no \"shading\" in the manifest";
    EXPECT_EQ(s.pipeline.ambient, glm::vec3(0.05f));

    // What a session's unsaved edits are judged on: the scene behind the G-buffer.
    EditorState const behind = sceneBehind(s, g);
    EXPECT_EQ(behind.lights.size(), 3u);
    EXPECT_EQ(behind.camera.position, sceneState().camera.position);
    EXPECT_EQ(behind.pipeline.shininess, 32.0f);

    // The user edits a light over the G-buffer; closing gives back the scene's, not the edit.
    s.lights[0].intensity = 9.0f;
    g.closeRequested = true;
    EXPECT_EQ(updateGBufferOpening(g, s, r.upload(), r.clear()), GBufferChange::Closed);
    EXPECT_EQ(r.clears, 1);
    EXPECT_FALSE(gbufferOpen(g));
    EXPECT_EQ(s.rig.target, glm::vec3(0.5f));
    expectSceneIntact(s);
    // A second close does nothing.
    g.closeRequested = true;
    EXPECT_EQ(updateGBufferOpening(g, s, r.upload(), r.clear()), GBufferChange::None);
    EXPECT_EQ(r.clears, 1);
}

TEST(GBufferOpening, MissingFileIsOneSentenceAndTheSceneStays) {
    expectRefused(test::freshTempDir("gbopen_missing") + "/nowhere.json", "cannot read the manifest");
    // A folder that is neither a manifest's nor a `render --out` one.
    expectRefused(test::freshTempDir("gbopen_empty_dir"), "no manifest.json");
}

TEST(GBufferOpening, BadManifestIsOneSentenceNamingTheField) {
    std::string const dir = test::freshTempDir("gbopen_bad_manifest");
    std::ofstream(dir + "/m.json") << R"({"format": "gbuffer-lab-gbuffer", "version": 1, "preset": "learnopengl",
      "normal": {"encoding": "spherical"}})";
    expectRefused(dir + "/m.json", "m.json: normal.encoding");
    std::ofstream(dir + "/broken.json") << "{\"format\": ";
    expectRefused(dir + "/broken.json", "broken.json: not valid JSON");
}

TEST(GBufferOpening, SizeMismatchIsOneSentence) {
    expectRefused(writeGBuffer("gbopen_size", kH - 2), "albedo");
}

TEST(GBufferOpening, UnreadableImageIsOneSentence) {
    std::string const path = writeGBuffer("gbopen_unreadable", kH, R"({"file": "normal.exr", "encoding": "float"})");
    std::ofstream(fs::path(path).parent_path() / "normal.exr") << "not an image at all";
    expectRefused(path, "normal.file");
}

TEST(GBufferOpening, ARefusedOpenKeepsTheGBufferShownAndAFailedUploadChangesNothing) {
    std::string const good = writeGBuffer("gbopen_keep");
    EditorState s = sceneState();
    GBufferOpenState g;
    FakeRenderer r;
    g.requests.push_back(good);
    ASSERT_EQ(updateGBufferOpening(g, s, r.upload(), r.clear()), GBufferChange::Opened) << g.lastError;
    g.requests.push_back(writeGBuffer("gbopen_keep_bad", kH - 1));
    EXPECT_EQ(updateGBufferOpening(g, s, r.upload(), r.clear()), GBufferChange::Failed);
    EXPECT_EQ(g.path, good);
    EXPECT_EQ(s.lights.size(), 2u);
    EXPECT_EQ(errors(s), 1);
    EXPECT_NE(s.log.lines.back().find("The G-buffer " + good + " stays shown."), std::string::npos)
        << s.log.lines.back();
    // Closing still gives back the scene from before the first open.
    g.closeRequested = true;
    updateGBufferOpening(g, s, r.upload(), r.clear());
    expectSceneIntact(s);

    // The GPU refuses it (too large a texture, say): nothing changes.
    EditorState t = sceneState();
    GBufferOpenState h;
    FakeRenderer refusing;
    refusing.refuse = "the texture is too large";
    h.requests.push_back(good);
    EXPECT_EQ(updateGBufferOpening(h, t, refusing.upload(), refusing.clear()), GBufferChange::Failed);
    EXPECT_NE(h.lastError.find("could not be uploaded: the texture is too large"), std::string::npos) << h.lastError;
    EXPECT_FALSE(gbufferOpen(h));
    expectSceneIntact(t);
}

// A manifest with "shading": "learnopengl" re-lights with that text's equation and its ambient
// 0.1 (docs/lighting.md); closing gives back the scene's equation and ambient, and so does the
// scene behind the G-buffer that a session's unsaved edits are judged on.
TEST(GBufferOpening, TheLearnOpenGlShadingIsTakenAndGivenBack) {
    std::string const path = writeGBuffer("gbopen_learnopengl");
    ASSERT_TRUE(addToManifest(path, R"("shading": "learnopengl", )"));

    EditorState s = sceneState();
    GBufferOpenState g;
    FakeRenderer r;
    g.requests.push_back(path);
    ASSERT_EQ(updateGBufferOpening(g, s, r.upload(), r.clear()), GBufferChange::Opened)
        << (s.log.lines.empty() ? std::string() : s.log.lines.back());
    EXPECT_EQ(s.pipeline.shading, ShadingModel::LearnOpenGl);
    EXPECT_EQ(s.pipeline.ambient, glm::vec3(kLearnOpenGlAmbient));
    EXPECT_EQ(s.pipeline.shininess, 16.0f);
    EditorState const behind = sceneBehind(s, g);
    EXPECT_EQ(behind.pipeline.shading, ShadingModel::GbufferLab);
    EXPECT_EQ(behind.pipeline.ambient, glm::vec3(0.05f));
    g.closeRequested = true;
    EXPECT_EQ(updateGBufferOpening(g, s, r.upload(), r.clear()), GBufferChange::Closed);
    expectSceneIntact(s);
}

// A manifest with the program's own lit image: opening pins it in the viewport under its file's name
// (Diff then compares our re-light with it); Close takes that pin away, while a pin of our own frames
// made before opening a G-buffer without one stays.
TEST(GBufferOpening, TheirLitImageIsPinnedAndClosingUnpinsIt) {
    std::string const path = writeGBuffer("gbopen_lit");
    std::string const dir = std::filesystem::path(path).parent_path().string();
    writeRaw(dir + "/lit.raw", kW, kH, 3, {0.25f, 0.5f, 2.0f});
    ASSERT_TRUE(addToManifest(path, R"("lit": )" + raw("lit.raw", kW, kH, 3) + "}, "));

    EditorState s = sceneState();
    GBufferOpenState g;
    FakeRenderer r;
    g.requests.push_back(path);
    ASSERT_EQ(updateGBufferOpening(g, s, r.upload(), r.clear()), GBufferChange::Opened)
        << (s.log.lines.empty() ? std::string() : s.log.lines.back());
    ASSERT_TRUE(s.litPin.pinned);
    FloatImage const& pinned = *s.litPin.pinned;
    ASSERT_EQ(pinned.width, kW);
    ASSERT_EQ(pinned.height, kH);
    ASSERT_EQ(pinned.channels, 4);
    EXPECT_EQ(pinned.at(kW - 1, kH - 1, 0), 0.25f);
    EXPECT_EQ(pinned.at(0, 0, 2), 2.0f) << "HDR values kept as they are";
    EXPECT_EQ(pinned.at(3, 2, 3), 1.0f);
    EXPECT_EQ(s.litPin.pinnedName, "their lit image (lit.raw)");
    EXPECT_NE(s.log.lines.back().find("lit.raw is pinned"), std::string::npos) << s.log.lines.back();
    g.closeRequested = true;
    EXPECT_EQ(updateGBufferOpening(g, s, r.upload(), r.clear()), GBufferChange::Closed);
    EXPECT_FALSE(s.litPin.pinned);
    EXPECT_TRUE(s.litPin.pinnedName.empty());
    EXPECT_FALSE(s.litPin.showDiff);

    // A pin of our own frame stays through a G-buffer that brings no lit image.
    s.litPin.pinned = FloatImage{2, 2, 4, std::vector<float>(16, 0.5f)};
    s.litPin.pinnedFrame = 40;
    g.requests.push_back(writeGBuffer("gbopen_nolit"));
    ASSERT_EQ(updateGBufferOpening(g, s, r.upload(), r.clear()), GBufferChange::Opened);
    g.closeRequested = true;
    EXPECT_EQ(updateGBufferOpening(g, s, r.upload(), r.clear()), GBufferChange::Closed);
    ASSERT_TRUE(s.litPin.pinned);
    EXPECT_EQ(s.litPin.pinnedFrame, 40);
}

// Opening runs the checks of `gbuffer-lab check`: a G-buffer whose normals are half length has the
// normal_not_unit finding, listed for the viewport's Checks button and named in the Log; closing
// clears the list. The handmade frame has no background (every pixel sees the wall), which
// no_background reports in both.
TEST(GBufferOpening, TheChecksRunOnOpeningAndTheirFindingsAreListed) {
    EditorState s = sceneState();
    GBufferOpenState g;
    FakeRenderer r;
    g.requests.push_back(
        writeGBuffer("gbopen_checks", kH, raw("short_normal.raw", kW, kH, 3) + R"(, "encoding": "float"})"));
    writeRaw(std::filesystem::path(g.requests.back()).parent_path().string() + "/short_normal.raw", kW, kH, 3,
             {0.0f, 0.0f, 0.5f});
    ASSERT_EQ(updateGBufferOpening(g, s, r.upload(), r.clear()), GBufferChange::Opened)
        << (s.log.lines.empty() ? std::string() : s.log.lines.back());
    ASSERT_FALSE(g.checks.findings.empty());
    ASSERT_EQ(s.viewport.findings.size(), g.checks.findings.size());
    EXPECT_EQ(s.viewport.findings[0].check, "normal_not_unit");
    EXPECT_EQ(s.viewport.findings[0].pixels, std::size_t(kW * kH));
    EXPECT_FALSE(s.viewport.findings[0].cause.empty());
    EXPECT_EQ(g.checks.findings[0].mask.size(), std::size_t(kW * kH));
    EXPECT_TRUE(s.viewport.findings[0].mask.empty());  // the viewport's list holds no copy of a mask
    ASSERT_EQ(s.viewport.precision.size(), g.checks.precision.size());
    for (std::size_t i = 0; i < g.checks.precision.size(); ++i)
        EXPECT_EQ(s.viewport.precision[i], gbl::precisionLine(g.checks.precision[i]));
    EXPECT_EQ(s.viewport.markedFinding, -1);
    EXPECT_NE(s.log.lines.back().find("checks: 2 findings (normal_not_unit 100 %, no_background 100 %)"),
              std::string::npos)
        << s.log.lines.back();
    s.viewport.markedFinding = 0;
    g.closeRequested = true;
    EXPECT_EQ(updateGBufferOpening(g, s, r.upload(), r.clear()), GBufferChange::Closed);
    EXPECT_TRUE(g.checks.findings.empty());
    EXPECT_TRUE(s.viewport.findings.empty());
    EXPECT_TRUE(s.viewport.precision.empty());
    EXPECT_EQ(s.viewport.markedFinding, -1);

    g.requests.push_back(writeGBuffer("gbopen_clean"));
    ASSERT_EQ(updateGBufferOpening(g, s, r.upload(), r.clear()), GBufferChange::Opened);
    ASSERT_EQ(s.viewport.findings.size(), 1u);
    EXPECT_EQ(s.viewport.findings[0].check, "no_background");
    EXPECT_NE(s.log.lines.back().find("checks: 1 finding (no_background 100 %)"), std::string::npos)
        << s.log.lines.back();
}
