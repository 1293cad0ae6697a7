// `gbuffer-lab capture` on tests/capture_target/deferred_demo.cpp under apitrace: the manifest's roles,
// camera and lights are the program's, the re-light is the program's own image, and every refusal is
// one sentence. GL runs in the child processes (the demo, the retracer, render --gbuffer).
#include "capture/camera_solve.h"
#include "capture/capture_mapping.h"
#include "capture/run_process.h"
#include "capture/trace_scan.h"
#include "image/image_io.h"
#include "import/gbuffer_checks.h"
#include "import/gbuffer_manifest.h"
#include "import/imported_gbuffer.h"
#include "run_command.h"
#include "test_paths.h"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>

using namespace gbl;
namespace fs = std::filesystem;

namespace {

// The demo's own scene (tests/capture_target/deferred_demo.cpp), written out again.
glm::vec3 const kEye(1.5f, 3.2f, 5.5f);
float const kLightPositions[4][3] = {{-2.0f, 1.5f, 1.5f}, {2.0f, 2.0f, 0.5f}, {0.0f, 1.0f, -2.5f}, {0.5f, 3.0f, 2.5f}};
float const kLightColors[4][3] = {{1.0f, 0.6f, 0.3f}, {0.3f, 0.6f, 1.0f}, {0.8f, 0.8f, 0.8f}, {0.5f, 1.0f, 0.4f}};
constexpr int kW = 160, kH = 120;  // small: the capture test runs three replays and a re-light on 2 cores

bool haveApitrace() {
    return capture::findProgram("apitrace") && capture::findProgram("eglretrace");
}

#define REQUIRE_APITRACE()                                                                       \
    if (std::string(GBL_DEFERRED_DEMO).empty())                                                  \
        GTEST_SKIP() << "this build has no EGL, which tests/capture_target/deferred_demo needs"; \
    if (!haveApitrace()) GTEST_SKIP() << "apitrace is not installed (Debian: apitrace apitrace-tracers)"

test::CommandResult captureDemo(std::string const& dir, int variant, int frame = 1, int frames = 3,
                                std::string const& lit = "") {
    std::vector<std::string> args{"capture",
                                  "--api",
                                  "egl",
                                  "--frame",
                                  std::to_string(frame),
                                  "--out",
                                  dir,
                                  "--",
                                  GBL_DEFERRED_DEMO,
                                  "--size",
                                  std::to_string(kW) + "x" + std::to_string(kH),
                                  "--frames",
                                  std::to_string(frames),
                                  "--variant",
                                  std::to_string(variant)};
    if (!lit.empty()) args.insert(args.end(), {"--out", lit});
    return test::runGbufferLab(args);
}

// The demo's PFM: rows bottom-up, RGB floats.
std::vector<float> readPfm(std::string const& path, int* w, int* h) {
    std::ifstream f(path, std::ios::binary);
    std::string magic;
    float scale = 0;
    f >> magic >> *w >> *h >> scale;
    f.get();
    std::vector<float> v(std::size_t(*w) * std::size_t(*h) * 3);
    f.read(reinterpret_cast<char*>(v.data()), std::streamsize(v.size() * sizeof(float)));
    return v;
}

void expectVec3(nlohmann::json const& j, float const* want, char const* what) {
    ASSERT_TRUE(j.is_array() && j.size() == 3) << what << ": " << j.dump();
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(j[std::size_t(k)].get<float>(), want[k], 1e-5f) << what;
}

// The largest difference, over every pixel and channel, between gbuffer-lab's re-light of `manifest`
// and the demo's own lit image `lit` (its 8-bit pbuffer: clamped to [0, 1], rows bottom-up); *where says
// at which pixel. 2 when the re-light fails.
float relitDifference(std::string const& manifest, std::string const& lit, std::string const& out, std::string* where) {
    auto const relit = test::runGbufferLab({"render", "--gbuffer", manifest, "--out", out});
    EXPECT_EQ(relit.exitCode, 0) << relit.output;
    std::string error;
    auto const ours = readImage(out + "/lighting.exr", &error);
    EXPECT_TRUE(ours) << error;
    int w = 0, h = 0;
    std::vector<float> const own = readPfm(lit, &w, &h);
    if (!ours || w != ours->width || h != ours->height) {
        *where = "the re-light is not the program's size";
        return 2.0f;
    }
    float worst = 0.0f;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c) {
                float const theirs =
                    own[(std::size_t(h - 1 - y) * std::size_t(w) + std::size_t(x)) * 3 + std::size_t(c)];
                float const mine = std::clamp(ours->at(x, y, c), 0.0f, 1.0f);
                if (std::abs(mine - theirs) > worst)
                    *where = "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") channel " +
                             std::to_string(c) + ": re-lit " + std::to_string(mine) + ", the program's " +
                             std::to_string(theirs);
                worst = std::max(worst, std::abs(mine - theirs));
            }
    return worst;
}

}  // namespace

TEST(CaptureGlTest, LearnOpenGlNamesGiveRolesCameraLightsAndTheProgramsOwnImage) {
    REQUIRE_APITRACE();
    std::string const dir = test::freshTempDir("capture_v1");
    std::string const lit = dir + "/own_lit.pfm";
    auto const r = captureDemo(dir + "/cap", 1, 1, 3, lit);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    nlohmann::json const m = test::readJsonFile(dir + "/cap/manifest.json");
    EXPECT_EQ(m["position"]["file"], "gPosition.exr");
    EXPECT_EQ(m["normal"]["file"], "gNormal.exr");
    EXPECT_EQ(m["normal"]["encoding"], "float");
    EXPECT_EQ(m["albedo"]["file"], "gAlbedoSpec.png");
    EXPECT_EQ(m["specular"]["file"], "gAlbedoSpec.png");
    EXPECT_EQ(m["specular"]["channel"], "a");
    EXPECT_NE(m["position"]["guessed_from"].get<std::string>().find("gPosition"), std::string::npos);
    EXPECT_EQ(m["capture"]["unmapped"], "");
    EXPECT_TRUE(fs::exists(dir + "/cap/lighting.frag"));

    // The camera and lights as the loader reads them: the demo's eye, its four lights.
    ManifestLoad const load = loadManifest(dir + "/cap/manifest.json");
    ASSERT_TRUE(load.manifest) << load.error;
    ASSERT_TRUE(load.manifest->camera);
    glm::vec3 const eye = load.manifest->camera->position;
    EXPECT_NEAR(glm::length(eye - kEye), 0.0f, 1e-4f);
    for (int i = 0; i < 4; ++i) {
        expectVec3(m["lights"]["positions"][std::size_t(i)], kLightPositions[i], "light position");
        expectVec3(m["lights"]["colors"][std::size_t(i)], kLightColors[i], "light colour");
        EXPECT_NEAR(m["lights"]["linear"][std::size_t(i)].get<float>(), 0.22f, 1e-6f);
        EXPECT_NEAR(m["lights"]["quadratic"][std::size_t(i)].get<float>(), 0.20f, 1e-6f);
    }
    auto const check = test::runGbufferLab({"check", dir + "/cap"});
    EXPECT_EQ(check.exitCode, 0) << check.output;  // a correct capture has no findings

    // Re-lit by gbuffer-lab from the captured G-buffer: the demo's own lit image.
    std::string where;
    float const worst = relitDifference(dir + "/cap/manifest.json", lit, dir + "/relit", &where);
    // 1/255: the demo's 8-bit rounding (half a step) and float evaluation order, no more.
    EXPECT_LE(worst, 1.0f / 255.0f) << where;
}

// Variant 5 hides its camera in one matrix whose name says nothing (uTransform): capture solves the
// view-projection from the position attachment by least squares and says so; the solved matrices put
// every stored position within half a pixel of its own pixel, are the program's own, and re-light to
// the program's image.
TEST(CaptureGlTest, ACameraWithoutNamedUniformsIsSolvedFromThePositions) {
    REQUIRE_APITRACE();
    std::string const dir = test::freshTempDir("capture_v5");
    std::string const lit = dir + "/own_lit.pfm";
    auto const r = captureDemo(dir + "/cap", 5, 1, 3, lit);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    nlohmann::json const m = test::readJsonFile(dir + "/cap/manifest.json");
    ASSERT_TRUE(m.contains("camera")) << m["capture"]["unmapped"];
    std::string const why = m["camera"]["guessed_from"];
    EXPECT_NE(why.find("solved from the position attachment gPosition"), std::string::npos) << why;
    EXPECT_NE(why.find("least squares"), std::string::npos) << why;
    EXPECT_NE(why.find("fitted to the depth attachment"), std::string::npos) << why;
    EXPECT_EQ(m["capture"]["unmapped"], "");
    auto const matrix = [](nlohmann::json const& j) {
        glm::mat4 out;
        for (int c = 0; c < 4; ++c)
            for (int row = 0; row < 4; ++row) out[c][row] = j[std::size_t(c)][std::size_t(row)].get<float>();
        return out;
    };
    glm::mat4 const solved = matrix(m["camera"]["projection"]) * matrix(m["camera"]["view"]);
    std::string error;
    auto const positions = readImage(dir + "/cap/" + m["position"]["file"].get<std::string>(), &error);
    ASSERT_TRUE(positions) << error;
    capture::Reprojection const e = capture::reprojectionError(*positions, solved);
    EXPECT_GT(e.samples, std::size_t(kW * kH / 4));
    EXPECT_LT(e.rms, 0.5) << "max " << e.max;
    EXPECT_LT(e.max, 1.0) << "rms " << e.rms;
    // The program's own view-projection (its depth range included, from the depth attachment).
    glm::mat4 const own = glm::perspective(glm::radians(45.0f), float(kW) / float(kH), 0.1f, 50.0f) *
                          glm::lookAt(kEye, glm::vec3(0.0f, 0.3f, 0.0f), glm::vec3(0, 1, 0));
    for (int c = 0; c < 4; ++c)
        for (int row = 0; row < 4; ++row)
            EXPECT_NEAR(solved[c][row], own[c][row], 0.01f * (1.0f + std::abs(own[c][row]))) << c << "," << row;
    ManifestLoad const load = loadManifest(dir + "/cap/manifest.json");
    ASSERT_TRUE(load.manifest) << load.error;
    ASSERT_TRUE(load.manifest->camera);
    EXPECT_LT(glm::length(load.manifest->camera->position - kEye), 0.01f);
    auto const check = test::runGbufferLab({"check", dir + "/cap"});
    EXPECT_EQ(check.exitCode, 0) << check.output;
    std::string where;
    float const worst = relitDifference(dir + "/cap/manifest.json", lit, dir + "/relit", &where);
    EXPECT_LE(worst, 1.0f / 255.0f) << where;
}

TEST(CaptureGlTest, OtherNamesAreMappedAndWhatIsNotIsNamed) {
    REQUIRE_APITRACE();
    std::string const dir = test::freshTempDir("capture_v2");
    auto const r = captureDemo(dir, 2);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    nlohmann::json const m = test::readJsonFile(dir + "/manifest.json");
    EXPECT_EQ(m["position"]["file"], "uPositionTex.exr");
    EXPECT_EQ(m["normal"]["file"], "uNormalTex.exr");
    EXPECT_EQ(m["albedo"]["file"], "uAlbedoTex.png");
    // uAlbedoTex says albedo, not specular: its alpha is not taken as specular by name.
    EXPECT_FALSE(m.contains("specular"));
    EXPECT_NE(m["camera"]["guessed_from"].get<std::string>().find("viewProj"), std::string::npos);
    ManifestLoad const load = loadManifest(dir + "/manifest.json");
    ASSERT_TRUE(load.manifest) << load.error;
    ASSERT_TRUE(load.manifest->camera);
    EXPECT_NEAR(glm::length(load.manifest->camera->position - kEye), 0.0f, 1e-3f);
    for (int i = 0; i < 4; ++i) {
        expectVec3(m["lights"]["positions"][std::size_t(i)], kLightPositions[i], "uLightPos");
        expectVec3(m["lights"]["colors"][std::size_t(i)], kLightColors[i], "uLightColor");
    }
    // The demo hard-codes its attenuation: the manifest says so rather than inventing one.
    std::string const unmapped = m["capture"]["unmapped"];
    EXPECT_NE(unmapped.find("linear"), std::string::npos) << unmapped;
    EXPECT_NE(unmapped.find("quadratic"), std::string::npos) << unmapped;
    EXPECT_NE(r.output.find("not mapped:"), std::string::npos) << r.output;
}

TEST(CaptureGlTest, EachFailureIsOneSentence) {
    REQUIRE_APITRACE();
    std::string const dir = test::freshTempDir("capture_fail");
    auto expectOne = [](test::CommandResult const& r, std::string const& want) {
        EXPECT_EQ(r.exitCode, 2) << r.output;
        EXPECT_NE(r.output.find(want), std::string::npos) << r.output;
        EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    };
    expectOne(captureDemo(dir + "/a", 1, 5, 2), "before frame 5");
    expectOne(captureDemo(dir + "/b", 3), "this frame has no G-buffer: is it a forward renderer?");
    expectOne(captureDemo(dir + "/c", 4), "the lighting pass samples nothing of it");
    std::ofstream(dir + "/not.trace") << "not a trace\n";
    expectOne(test::runGbufferLab({"capture", "--trace", dir + "/not.trace", "--out", dir + "/d"}),
              "is not an apitrace trace");

    // apitrace missing, and a trace of another API: an apitrace of the test's own on PATH.
    std::string const fake = dir + "/fakebin";
    fs::create_directories(fake);
    {
        std::ofstream s(fake + "/apitrace");
        s << "#!/bin/sh\necho '{\"API\": \"Direct3D 11\", \"FramesCount\": 3}'\n";
    }
    fs::permissions(fake + "/apitrace", fs::perms::owner_all);
    std::string const oldPath = std::getenv("PATH");
    ::setenv("PATH", fake.c_str(), 1);  // /bin is /usr/bin here, where the real one is
    expectOne(test::runGbufferLab({"capture", "--trace", dir + "/not.trace", "--out", dir + "/e"}),
              "records Direct3D 11, not OpenGL");
    ::setenv("PATH", (dir + "/nothing").c_str(), 1);
    expectOne(test::runGbufferLab({"capture", "--out", dir + "/f", "--", GBL_DEFERRED_DEMO}),
              "apitrace is not installed: install the Debian packages apitrace and apitrace-tracers");
    ::setenv("PATH", oldPath.c_str(), 1);
}

// CPU: a view-projection alone is split back into the program's view and projection.
TEST(CaptureGlTest, ViewProjectionSplitsIntoViewAndProjection) {
    glm::mat4 const view = glm::lookAt(kEye, glm::vec3(0.0f, 0.3f, 0.0f), glm::vec3(0, 1, 0));
    glm::mat4 const proj = glm::perspective(glm::radians(45.0f), 4.0f / 3.0f, 0.1f, 50.0f);
    auto const split = capture::splitViewProjection(proj * view);
    ASSERT_TRUE(split);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) {
            EXPECT_NEAR(split->view[c][r], view[c][r], 1e-4f);
            EXPECT_NEAR(split->projection[c][r], proj[c][r], 1e-4f * (1.0f + std::abs(proj[c][r])));
        }
    EXPECT_FALSE(capture::splitViewProjection(glm::mat4(1.0f)));  // orthographic: no w row to split on
}

// Handmade faults on a real capture, each named by its cause (the correct capture has none: above).
TEST(CaptureGlTest, CheckNamesTheCauseOfEachHandmadeFault) {
    REQUIRE_APITRACE();
    std::string const dir = test::freshTempDir("capture_faults");
    auto const r = captureDemo(dir, 1);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    nlohmann::json const clean = test::readJsonFile(dir + "/manifest.json");
    struct Fault {
        char const* name;
        char const* patch;  // merged into the captured manifest
        char const* check;
        char const* causeWord;
    };
    // Without depth, so that the camera alone must place the positions (with depth, position_depth_mismatch
    // names the same causes).
    for (Fault const& f : {
             Fault{"flip", R"({"flip_y": true, "depth": null})", "reprojection", "flip_y"},
             Fault{"view", R"({"position": {"space": "view"}, "depth": null})", "reprojection",
                   "in world space, not view"},
             Fault{"transposed", R"({"camera": {"matrix_layout": "row-major"}, "depth": null})", "reprojection",
                   "matrix_layout is the other one"},
             Fault{"normals", R"({"normal": {"space": "view"}})", "normal_space", "in world space, not view"},
             Fault{"albedo", R"({"normal": {"file": "gAlbedoSpec.png"}})", "normal_wrong_attachment",
                   "looks like the albedo target"},
             Fault{"biased", R"({"normal": {"encoding": "biased"}})", "normal_encoding",
                   "stored as float (unit length, with negative components) but declared biased"},
         }) {
        nlohmann::json m = clean;
        m.merge_patch(nlohmann::json::parse(f.patch));
        std::string const path = dir + "/manifest_" + f.name + ".json";
        std::ofstream(path) << m.dump(2);
        ManifestLoad const load = loadManifest(path);
        ASSERT_TRUE(load.manifest) << f.name << ": " << load.error;
        GBufferLoad const g = loadGBuffer(*load.manifest);
        ASSERT_TRUE(g.gbuffer) << f.name << ": " << g.error;
        GBufferCheckReport const report = checkGBuffer(*g.gbuffer);
        bool found = false;
        for (auto const& finding : report.findings) {
            if (finding.check != f.check) continue;
            found = true;
            EXPECT_NE(finding.cause.find(f.causeWord), std::string::npos) << f.name << ": " << finding.cause;
            EXPECT_GT(finding.share, 0.9) << f.name;  // the fault is on every drawn pixel
        }
        EXPECT_TRUE(found) << f.name << " gave no " << f.check;
        // The symptoms a proven wrong normal target explains are not reported beside it.
        if (std::string(f.check) == "normal_wrong_attachment") {
            for (auto const& finding : report.findings) {
                EXPECT_TRUE(finding.check != "normal_not_unit" && finding.check != "normal_facing_away")
                    << finding.check;
            }
        }
    }
}

// CPU: the scan follows framebuffer, draw-buffer and texture-unit state through a listing, DSA calls
// included, and takes the first later draw that samples two of the G-buffer's targets.
TEST(CaptureGlTest, TheScanFindsBothPassesInAListing) {
    std::string const listing = R"(10 glBindFramebuffer(target = GL_FRAMEBUFFER, framebuffer = 3)
11 glFramebufferTexture2D(target = GL_FRAMEBUFFER, attachment = GL_COLOR_ATTACHMENT0, textarget = GL_TEXTURE_2D, texture = 7, level = 0)
12 glNamedFramebufferTexture(framebuffer = 3, attachment = GL_COLOR_ATTACHMENT1, texture = 8, level = 0)
13 glNamedFramebufferDrawBuffers(framebuffer = 3, n = 2, bufs = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1})
14 glDrawElements(mode = GL_TRIANGLES, count = 6, type = GL_UNSIGNED_INT, indices = NULL)
15 eglSwapBuffers(dpy = 0x1, surface = 0x2) = EGL_TRUE
16 glBindFramebuffer(target = GL_FRAMEBUFFER, framebuffer = 3)
17 glDrawElements(mode = GL_TRIANGLES, count = 6, type = GL_UNSIGNED_INT, indices = NULL)
18 glDrawElements(mode = GL_TRIANGLES, count = 6, type = GL_UNSIGNED_INT, indices = NULL)
19 glBindFramebuffer(target = GL_FRAMEBUFFER, framebuffer = 0)
20 glBindTextureUnit(unit = 4, texture = 7)
21 glDrawArrays(mode = GL_TRIANGLES, first = 0, count = 3)
22 glActiveTexture(texture = GL_TEXTURE5)
23 glBindTexture(target = GL_TEXTURE_2D, texture = 8)
24 glDrawArrays(mode = GL_TRIANGLES, first = 0, count = 3)
25 eglSwapBuffers(dpy = 0x1, surface = 0x2) = EGL_TRUE
)";
    capture::TraceScan const s = capture::scanTrace(listing, 1);
    ASSERT_TRUE(s.lightingDraw) << s.error;
    EXPECT_EQ(*s.lastGeometryDraw, 18u);
    EXPECT_EQ(*s.lightingDraw, 24u);  // call 21 samples one target only
    EXPECT_EQ(s.gbufferFramebuffer, 3u);
    EXPECT_EQ(s.sampledAttachments.at("GL_COLOR_ATTACHMENT0"), 4);
    EXPECT_EQ(s.sampledAttachments.at("GL_COLOR_ATTACHMENT1"), 5);
    EXPECT_NE(capture::scanTrace(listing, 2).error.find("before frame 2"), std::string::npos);
}
