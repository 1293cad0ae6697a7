// The --log-frames line is valid JSON that carries each field, strings escaped.
#include "model/frame_log.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>

using namespace gbl::ui;

TEST(FrameLog, LinesAreJsonWithEveryField) {
    FrameLogLine l;
    l.frame = 41;
    l.rendered = true;
    l.renderReason = "camera";
    l.frameMs = 153.25;
    l.camera = {1.5f, -2.0f, 3.0f};
    l.selectedLight = 7;
    l.viewport = {10, 20, 640, 360};
    l.accumulate = 3;
    l.scrubber = {100, 30, 160, 18};
    l.abDivider = 0.25f;
    l.pickable = {{3, {100.5f, 200.0f}}};
    l.events = {"key 70 press mods 0 -> frame-selection", "quote \" and \\ and \n"};
    l.sessionPath = "/tmp/s.json";
    l.clipped = {"Stats: content 330 px wide in 302 px"};
    l.layout = "packed";
    l.pipelineWindow = {0, 370, 300, 350};
    l.layoutCombo = {900, 400, 200, 19};
    l.layoutItems = {{1000.0f, 430.5f}, {1000.0f, 450.5f}};
    l.toolsImage = {1262, 611};
    l.toolsRegion = {10, 20, 120, 60};
    l.viewerImages = {{4, 520, 244, 140}, {260, 520, 244, 140}};
    l.overview = true;
    l.overviewButton = {750, 40, 80, 19};
    l.overviewCells = {"final@307,178,211,133", "normal@737,178,211,133"};
    l.uiScale = 1.25f;
    l.lightsWindow = {0, 380, 320, 250};
    l.plotRect = {8, 400, 300, 160};
    l.kqField = {120, 300, 60, 19};
    l.plotRadius = 2.5f;
    l.plotGhostRadius = 3.25f;
    l.plotPopup = {400, 320, 280, 168};
    l.plotPopupRadius = 2.0f;
    l.plotLight = {1.0f, 0.7f, 0.0075f, 2.0f, 5.0f / 256.0f};
    l.precisionLines = 6;
    l.gbuffer = "/tmp/export";
    l.frameSize = {480, 270};
    l.fileMenu = {8, 0, 30, 19};
    l.openGBufferItem = {9, 88, 260, 17};
    l.openSceneItem = {9, 24, 260, 17};
    l.openFolderItem = {9, 42, 260, 17};
    l.exportAllItem = {9, 150, 260, 17};
    l.windowShotItem = {9, 168, 260, 17};
    l.gbufferBrowser = true;
    l.captureItem = {9, 106, 260, 17};
    l.captureDialog = true;
    l.captureCommand = {427, 180, 411, 19};
    l.captureFrame = {427, 203, 193, 19};
    l.captureOut = {427, 266, 411, 19};
    l.captureEgl = {579, 226, 45, 19};
    l.captureButton = {427, 294, 109, 19};
    l.capturing = true;
    l.captureError = "./x is not a program that can be run.";
    l.timing = "gpu_elapsed";
    l.passMs = {{"geometry", 1.25}, {"lighting", 3.5}};
    nlohmann::json const j = nlohmann::json::parse(frameLogJson(l));
    EXPECT_EQ(j["frame"], 41);
    EXPECT_EQ(j["rendered"], true);
    EXPECT_DOUBLE_EQ(j["frameMs"].get<double>(), 153.25);
    EXPECT_DOUBLE_EQ(j["camera"][1].get<double>(), -2.0);
    EXPECT_EQ(j["selectedLight"], 7);
    EXPECT_DOUBLE_EQ(j["viewport"][2].get<double>(), 640.0);
    // Flat: x, y, width, height of each viewer in turn (the tests' shell reader takes no nesting).
    ASSERT_EQ(j["viewerImages"].size(), 8u);
    EXPECT_DOUBLE_EQ(j["viewerImages"][4].get<double>(), 260.0);
    EXPECT_DOUBLE_EQ(j["viewerImages"][7].get<double>(), 140.0);
    EXPECT_EQ(j["accumulate"], 3);
    EXPECT_DOUBLE_EQ(j["scrubber"][2].get<double>(), 160.0);
    EXPECT_DOUBLE_EQ(j["abToggle"][0].get<double>(), 0.0);
    EXPECT_DOUBLE_EQ(j["abDivider"].get<double>(), 0.25);
    EXPECT_EQ(j["pickable"][0][0], 3);
    EXPECT_EQ(j["events"][1], "quote \" and \\ and \n");
    EXPECT_EQ(j["session"], "/tmp/s.json");
    EXPECT_EQ(j["actions"].size(), 0u);
    EXPECT_EQ(j["clipped"][0], "Stats: content 330 px wide in 302 px");
    EXPECT_EQ(j["layout"], "packed");
    EXPECT_DOUBLE_EQ(j["pipelineWindow"][1].get<double>(), 370.0);
    EXPECT_DOUBLE_EQ(j["layoutCombo"][3].get<double>(), 19.0);
    ASSERT_EQ(j["layoutItems"].size(), 4u);  // x, y of each entry, flat
    EXPECT_DOUBLE_EQ(j["layoutItems"][3].get<double>(), 450.5);
    EXPECT_EQ(j["toolsImage"][0], 1262);
    EXPECT_EQ(j["toolsRegion"][2], 120);
    EXPECT_EQ(j["overview"], true);
    EXPECT_DOUBLE_EQ(j["overviewButton"][2].get<double>(), 80.0);
    ASSERT_EQ(j["overviewCells"].size(), 2u);
    EXPECT_EQ(j["overviewCells"][1], "normal@737,178,211,133");
    EXPECT_DOUBLE_EQ(j["uiScale"].get<double>(), 1.25);
    EXPECT_EQ(j["lightsWindow"], nlohmann::json::parse("[0,380,320,250]"));
    EXPECT_EQ(j["plotRect"], nlohmann::json::parse("[8,400,300,160]"));
    EXPECT_EQ(j["kqField"], nlohmann::json::parse("[120,300,60,19]"));
    EXPECT_DOUBLE_EQ(j["plotRadius"].get<double>(), 2.5);
    EXPECT_DOUBLE_EQ(j["plotGhostRadius"].get<double>(), 3.25);
    EXPECT_EQ(j["plotPopup"], nlohmann::json::parse("[400,320,280,168]"));
    EXPECT_DOUBLE_EQ(j["plotPopupRadius"].get<double>(), 2.0);
    ASSERT_EQ(j["plotLight"].size(), 5u);
    EXPECT_FLOAT_EQ(j["plotLight"][2].get<float>(), 0.0075f);
    EXPECT_FLOAT_EQ(j["plotLight"][4].get<float>(), 5.0f / 256.0f);
    EXPECT_EQ(j["toolsRegion"][3], 60);
    EXPECT_EQ(j["precisionLines"], 6);
    EXPECT_EQ(j["gbuffer"], "/tmp/export");
    EXPECT_EQ(j["frameSize"], nlohmann::json::parse("[480,270]"));
    EXPECT_EQ(j["fileMenu"], nlohmann::json::parse("[8,0,30,19]"));
    EXPECT_EQ(j["openGBufferItem"], nlohmann::json::parse("[9,88,260,17]"));
    EXPECT_EQ(j["openSceneItem"], nlohmann::json::parse("[9,24,260,17]"));
    EXPECT_EQ(j["openFolderItem"], nlohmann::json::parse("[9,42,260,17]"));
    EXPECT_EQ(j["exportAllItem"], nlohmann::json::parse("[9,150,260,17]"));
    EXPECT_EQ(j["windowShotItem"], nlohmann::json::parse("[9,168,260,17]"));
    EXPECT_EQ(j["gbufferBrowser"], true);
    EXPECT_EQ(j["captureItem"], nlohmann::json::parse("[9,106,260,17]"));
    EXPECT_EQ(j["captureDialog"], true);
    EXPECT_EQ(j["captureCommand"], nlohmann::json::parse("[427,180,411,19]"));
    EXPECT_EQ(j["captureFrame"], nlohmann::json::parse("[427,203,193,19]"));
    EXPECT_EQ(j["captureOut"], nlohmann::json::parse("[427,266,411,19]"));
    EXPECT_EQ(j["captureEgl"], nlohmann::json::parse("[579,226,45,19]"));
    EXPECT_EQ(j["captureButton"], nlohmann::json::parse("[427,294,109,19]"));
    EXPECT_EQ(j["capturing"], true);
    EXPECT_EQ(j["captureError"], "./x is not a program that can be run.");
    EXPECT_EQ(j["timing"], "gpu_elapsed");
    EXPECT_EQ(j["passMs"], nlohmann::json::parse(R"([["geometry",1.25],["lighting",3.5]])"));
}

TEST(FrameLog, WritesOneLinePerFrame) {
    std::string const path = ::testing::TempDir() + "frame_log_test.jsonl";
    {
        FrameLog log;
        ASSERT_FALSE(log.open(path));
        for (long f = 1; f <= 3; ++f) {
            FrameLogLine l;
            l.frame = f;
            log.write(l);
        }
    }
    std::ifstream in(path);
    std::string line;
    long count = 0;
    while (std::getline(in, line)) EXPECT_EQ(nlohmann::json::parse(line)["frame"], ++count);
    EXPECT_EQ(count, 3);
    FrameLog bad;
    auto const error = bad.open("/nonexistent-folder/x.jsonl");
    ASSERT_TRUE(error);
    EXPECT_NE(error->find("/nonexistent-folder/x.jsonl"), std::string::npos);
}
