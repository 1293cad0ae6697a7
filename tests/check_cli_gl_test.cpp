// `gbuffer-lab check` end to end: our own `render --out` folder opens as a G-buffer with no
// findings, and bad input is refused with exit code 2 and the field named.
#include "run_command.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <fstream>

using gbl::test::runGbufferLab;

TEST(CheckCommand, OwnRenderFolderHasNoFindings) {
    std::string const out = gbl::test::freshTempDir("check_render");
    auto const r = runGbufferLab({"render", "--out", out, "--size", "160x90", "--lights", "8"});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    auto const c = runGbufferLab({"check", out, "--json"});
    EXPECT_EQ(c.exitCode, 0) << c.output;
    EXPECT_NE(c.output.find("\"findings\": []"), std::string::npos) << c.output;
    // Without --json: the same verdict, and a precision line per attachment.
    auto const t = runGbufferLab({"check", out});
    EXPECT_EQ(t.exitCode, 0) << t.output;
    EXPECT_NE(t.output.find("no findings"), std::string::npos) << t.output;
    EXPECT_NE(t.output.find("precision (what each attachment's storage can hold):"), std::string::npos) << t.output;
    EXPECT_NE(t.output.find("  normal: "), std::string::npos) << t.output;
    EXPECT_NE(t.output.find("a highlight of shininess"), std::string::npos) << t.output;
}

// Every layout's export: what a layout rounds away (8-bit normals, packed's dropped emission) is within
// the precision the folder states, so no check mistakes it for a bug.
TEST(CheckCommand, EveryLayoutsRenderFolderHasNoFindings) {
    for (char const* layout : {"classic", "packed", "naive8", "rgb10a2"}) {
        std::string const out = gbl::test::freshTempDir(std::string("check_layout_") + layout);
        auto const r = runGbufferLab({"render", "--out", out, "--size", "160x90", "--lights", "8", "--layout", layout});
        ASSERT_EQ(r.exitCode, 0) << layout << ": " << r.output;
        auto const c = runGbufferLab({"check", out, "--json"});
        EXPECT_EQ(c.exitCode, 0) << layout << ": " << c.output;
        EXPECT_NE(c.output.find("\"findings\": []"), std::string::npos) << layout << ": " << c.output;
    }
}

TEST(CheckCommand, BadManifestIsRefusedNamingTheField) {
    std::string const dir = gbl::test::freshTempDir("check_bad");
    std::ofstream(dir + "/manifest.json")
        << R"({"format": "gbuffer-lab-gbuffer", "version": 1, "preset": "learnopengl", "normal": {"encoding": "polar"}})";
    gbl::test::expectRefused({"check", dir + "/manifest.json"}, "normal.encoding must be one of");
    gbl::test::expectRefused({"check", dir + "/none.json"}, "cannot read the manifest");
}

// A manifest of the gbuffer-lab preset in a `render --out` folder takes that folder's camera.json and
// lights.json (it was refused for want of a camera, and opened with no lights once one was added).
TEST(CheckCommand, TheGbufferLabPresetReadsTheFoldersCameraAndLights) {
    std::string const out = gbl::test::freshTempDir("check_preset");
    auto const r = runGbufferLab({"render", "--out", out, "--size", "160x90", "--lights", "8"});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::ofstream(out + "/manifest.json")
        << R"({"format": "gbuffer-lab-gbuffer", "version": 1, "preset": "gbuffer-lab"})";
    auto const c = runGbufferLab({"check", out + "/manifest.json"});
    EXPECT_EQ(c.exitCode, 0) << c.output;
    std::string const relit = gbl::test::freshTempDir("check_preset_relit");
    auto const g = runGbufferLab({"render", "--gbuffer", out + "/manifest.json", "--out", relit});
    EXPECT_EQ(g.exitCode, 0) << g.output;
    EXPECT_NE(g.output.find(", 8 lights,"), std::string::npos) << g.output;
}
