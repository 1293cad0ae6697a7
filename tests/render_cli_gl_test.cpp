// `gbuffer-lab render` end to end: the files it writes, their contents, and bad arguments.
#include "core/pipeline_fields.h"
#include "image/image_io.h"
#include "run_command.h"
#include "test_paths.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>

using namespace gbl;
using gbl::test::CommandResult;
using gbl::test::runGbufferLab;
namespace fs = std::filesystem;

namespace {}  // namespace

// Every pipeline field that names an option is a `render` option (core/pipeline_fields.h): --help
// lists it with its names or range and PipelineSettings{}'s value, and a value it does not take is
// refused in one sentence that lists what it takes.
TEST(RenderCommand, EveryPipelineFieldIsAnOptionWithItsValuesAndDefault) {
    CommandResult const help = runGbufferLab({"render", "--help"});
    ASSERT_EQ(help.exitCode, 0) << help.output;
    std::string const out = test::freshTempDir("render_fields");
    int options = 0;
    for (PipelineField const& f : pipelineFields()) {
        if (f.option.empty()) continue;
        ++options;
        std::string const option(f.option);
        std::size_t const at = help.output.find("  " + option);
        ASSERT_NE(at, std::string::npos) << option << " is not in render --help";
        std::string const line = help.output.substr(at, help.output.find('\n', at) - at);
        std::string const byDefault = f.kind == SettingKind::Toggle ? (f.defaultValue() != 0.0 ? "on" : "off")
                                                                    : fieldScriptText(f, PipelineSettings{});
        EXPECT_NE(line.find("=" + byDefault), std::string::npos) << line;
        if (f.kind == SettingKind::Choice) {
            std::string names;
            for (std::string_view n : f.choices) names += (names.empty() ? "{" : ",") + std::string(n);
            EXPECT_NE(line.find(names + "}"), std::string::npos) << line;
        }
        CommandResult const r = test::expectRefused({"render", "--out", out, option, "nonsense"},
                                                    option + ": 'nonsense' is not " + fieldValuesText(f));
        EXPECT_LE(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    }
    EXPECT_EQ(options, int(pipelineFields().size()) - 1);  // every row but the view
    // The old option works but is not listed on its own: the README's list (cli_readme_test) names
    // --depth-copy, and --help marks --blit as its old name.
    EXPECT_NE(help.output.find("--depth-copy,--blit"), std::string::npos) << help.output;
    EXPECT_NE(help.output.find("(--blit: its old name)"), std::string::npos) << help.output;
}

// Each option reaches the frame: every field set to a value other than its default, through the
// options only, is what the saved session holds.
TEST(RenderCommand, EveryPipelineOptionReachesTheSavedSession) {
    std::string const dir = test::freshTempDir("render_field_values");
    std::vector<std::string> args{"render",         "--out",        dir, "--size", "32x24", "--lights", "2",
                                  "--save-session", dir + "/s.json"};
    PipelineSettings wanted;
    for (PipelineField const& f : pipelineFields()) {
        if (f.option.empty()) continue;
        double const other = f.kind == SettingKind::Choice ? double((int(f.defaultValue()) + 1) % int(f.choices.size()))
                             : f.kind == SettingKind::Toggle ? 1.0 - f.defaultValue()
                                                             : double(f.max);
        f.set(wanted, other);
        args.push_back(std::string(f.option));
        args.push_back(fieldScriptText(f, wanted));
    }
    CommandResult const r = runGbufferLab(args);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    nlohmann::json const pipeline = test::readJsonFile(dir + "/s.json")["pipeline"];
    for (PipelineField const& f : pipelineFields()) {
        if (f.option.empty()) continue;
        std::string const name(f.name);
        ASSERT_TRUE(pipeline.contains(name)) << name;
        nlohmann::json const& v = pipeline[name];
        if (f.rgb)
            EXPECT_FLOAT_EQ(v[0].get<float>(), float(f.get(wanted))) << name;
        else if (f.kind == SettingKind::Choice)
            EXPECT_EQ(v, fieldScriptText(f, wanted)) << name;
        else if (f.kind == SettingKind::Toggle)
            EXPECT_EQ(v, f.get(wanted) != 0.0) << name;
        else
            EXPECT_FLOAT_EQ(v.get<float>(), float(f.get(wanted))) << name;
    }
}

TEST(RenderCommand, WritesEveryImageAndJsonFile) {
    std::string const out = test::freshTempDir("render_all");
    auto const r = runGbufferLab({"render", "--out", out, "--size", "160x90", "--lights", "8"});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (char const* f : {"final.png", "lighting.exr", "position.exr", "normal.exr", "albedo.png", "specular.png",
                          "depth.exr", "depth_linear.exr", "lights.json", "camera.json", "stats.json"})
        EXPECT_TRUE(fs::exists(fs::path(out) / f)) << f;

    auto const stats = test::readJsonFile(fs::path(out) / "stats.json");
    EXPECT_EQ(stats["width"], 160);
    EXPECT_EQ(stats["height"], 90);
    EXPECT_EQ(stats["lights"], 8);
    EXPECT_EQ(stats["gl_errors"], 0);
    EXPECT_FALSE(stats["gl_renderer"].get<std::string>().empty());
    for (char const* pass : {"geometry", "lighting", "depth_copy", "forward", "display"}) {
        ASSERT_TRUE(stats["gpu_ms"].contains(pass)) << pass;
        // A sane time: the first-query quirk of some drivers once reported minutes here.
        EXPECT_LT(stats["gpu_ms"][pass].get<double>(), 60000.0) << pass;
    }
    auto const lights = test::readJsonFile(fs::path(out) / "lights.json");
    ASSERT_EQ(lights.size(), 8u);
    for (auto const& l : lights) {
        EXPECT_GT(l["radius"].get<double>(), 0.0);
        EXPECT_EQ(l["position"].size(), 3u);
    }
    auto const cam = test::readJsonFile(fs::path(out) / "camera.json");
    EXPECT_EQ(cam["view"].size(), 4u);
    EXPECT_LT(cam["near"].get<double>(), cam["far"].get<double>());

    // Float outputs are float, with the stored values: normals unit length where drawn,
    // linear depth between near and far.
    auto normal = readImage((fs::path(out) / "normal.exr").string());
    auto depthLinear = readImage((fs::path(out) / "depth_linear.exr").string());
    auto finalImg = readImage((fs::path(out) / "final.png").string());
    ASSERT_TRUE(normal && depthLinear && finalImg);
    EXPECT_EQ(normal->width, 160);
    EXPECT_EQ(normal->channels, 4);
    int drawn = 0;
    double brightness = 0.0;
    for (int y = 0; y < normal->height; ++y)
        for (int x = 0; x < normal->width; ++x) {
            if (normal->at(x, y, 3) == 0.0f) continue;
            ++drawn;
            float const len =
                std::sqrt(normal->at(x, y, 0) * normal->at(x, y, 0) + normal->at(x, y, 1) * normal->at(x, y, 1) +
                          normal->at(x, y, 2) * normal->at(x, y, 2));
            // Half-float components: length within 2e-3 of 1.
            EXPECT_NEAR(len, 1.0f, 2e-3f);
            float const d = depthLinear->at(x, y, 0);
            EXPECT_GE(d, cam["near"].get<float>() * 0.999f);
            EXPECT_LE(d, cam["far"].get<float>() * 1.001f);
            brightness += finalImg->at(x, y, 0) + finalImg->at(x, y, 1) + finalImg->at(x, y, 2);
        }
    EXPECT_GT(drawn, 160 * 90 / 2) << "the default camera looks into the courtyard";
    EXPECT_GT(brightness / (3.0 * drawn), 0.05) << "the final frame must not be black";
}

TEST(RenderCommand, SameArgumentsGiveTheSameFrame) {
    std::string const a = test::freshTempDir("render_det_a"), b = test::freshTempDir("render_det_b");
    for (auto const& out : {a, b}) {
        auto const r = runGbufferLab({"render", "--out", out, "--size", "96x64", "--time", "2.5"});
        ASSERT_EQ(r.exitCode, 0) << r.output;
    }
    auto ia = readImage(a + "/lighting.exr"), ib = readImage(b + "/lighting.exr");
    ASSERT_TRUE(ia && ib);
    EXPECT_EQ(ia->pixels, ib->pixels);
}

TEST(RenderCommand, TimeMovesTheLights) {
    std::string const a = test::freshTempDir("render_t0"), b = test::freshTempDir("render_t5");
    ASSERT_EQ(runGbufferLab({"render", "--out", a, "--size", "32x32", "--time", "0"}).exitCode, 0);
    ASSERT_EQ(runGbufferLab({"render", "--out", b, "--size", "32x32", "--time", "5"}).exitCode, 0);
    auto const la = test::readJsonFile(fs::path(a) / "lights.json"),
               lb = test::readJsonFile(fs::path(b) / "lights.json");
    EXPECT_NE(la[0]["position"], lb[0]["position"]);
}

// A frame estimated above --warn-seconds is announced with the mode that gives the same image
// sooner, then rendered as asked; under the threshold nothing is said.
TEST(RenderCommand, AFrameOverTheCostThresholdIsAnnouncedWithAFasterMode) {
    std::string const out = test::freshTempDir("render_slow");
    auto const slow = runGbufferLab({"render", "--out", out, "--size", "96x64", "--warn-seconds", "1e-6"});
    ASSERT_EQ(slow.exitCode, 0) << slow.output;
    EXPECT_NE(slow.output.find("this frame is estimated at"), std::string::npos) << slow.output;
    EXPECT_NE(slow.output.find("in quad mode (32 lights, 96x64"), std::string::npos) << slow.output;
    EXPECT_NE(slow.output.find("mode gives the same image in about"), std::string::npos) << slow.output;
    EXPECT_NE(slow.output.find("rendering it as asked"), std::string::npos) << slow.output;
    EXPECT_TRUE(fs::exists(fs::path(out) / "lighting.exr"));
    auto const quick = runGbufferLab({"render", "--out", out, "--size", "96x64"});
    ASSERT_EQ(quick.exitCode, 0) << quick.output;
    EXPECT_EQ(quick.output.find("estimated at"), std::string::npos) << quick.output;
}

TEST(RenderCommand, BadArgumentsExitWithCodeTwoAndOneSentence) {
    std::string const out = test::freshTempDir("render_bad");
    struct Case {
        std::vector<std::string> args;
        std::string expect;  // part of the message
    };
    std::vector<Case> const cases{
        {{"render", "--out", out, "--no-such-option"}, "no-such-option"},
        {{"render", "--out", out, "--size", "0x0"}, "--size"},
        {{"render", "--out", out, "--size", "wide"}, "--size"},
        {{"render", "--out", out, "--size", "20000x20000"}, "16384"},
        {{"render", "--out", out, "--lights", "-3"}, "--lights"},
        {{"render", "--out", out, "--lights", "300000"}, "262144"},
        // --blit is the old name of --depth-copy: the same option, named by its name.
        {{"render", "--out", out, "--blit", "sideways"}, "--depth-copy: 'sideways' is not one of blit, shader or off"},
        {{"render", "--out", out, "--depth-copy", "sideways"}, "'sideways' is not one of blit, shader or off"},
        {{"render", "--out", out, "--exposure", "99"}, "--exposure: '99' is not a number from 0.05 to 16"},
        {{"render", "--out", out, "--light-cubes", "maybe"}, "--light-cubes: 'maybe' is not 0 or 1 (or off or on)"},
        {{"render", "--out", out, "--mode", "raytraced"}, "--mode"},
        {{"render", "--out", out, "--layout", "zip"}, "--layout"},
        {{"render", "--out", out, "--accumulation", "double"}, "--accumulation"},
        {{"render", "--out", out, "--view", "xray"}, "--view"},
        {{"render", "--out", out, "--size", "16x16", "--until", "tonemap"},
         "this frame's passes are geometry, lighting, depth_copy, forward, display and light_cubes"},
        {{"render", "--out", out, "--size", "16x16", "--until", "light_lists"}, "this frame does not run it"},
        {{"render", "--out", "/proc/gbuffer-lab-cannot-write-here"}, "/proc/gbuffer-lab-cannot-write-here"},
        {{"render"}, "--out"},
    };
    for (auto const& c : cases) {
        auto const r = test::expectRefused(c.args, c.expect);
        // One sentence: a single line of output, no stack trace or usage dump.
        EXPECT_LE(std::count(r.output.begin(), r.output.end(), '\n'), 1) << c.args.back() << "\n" << r.output;
    }
}

TEST(RenderCommand, LayoutWritesItsRawAttachmentsAndTheDecodedInputs) {
    std::string const out = test::freshTempDir("render_layout_packed");
    auto const r = runGbufferLab({"render", "--out", out, "--size", "64x36", "--layout", "packed"});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (char const* f :
         {"raw_normal_oct.exr", "raw_albedo_spec.png", "raw_depth.exr", "position.exr", "normal.exr", "emissive.exr"})
        EXPECT_TRUE(fs::exists(out + "/" + f)) << f;
    EXPECT_FALSE(fs::exists(out + "/raw_position.exr"));
    // The raw files follow the layout's attachments: packed has no room for emissive_ao.
    EXPECT_FALSE(fs::exists(out + "/raw_emissive_ao.png"));
    std::ifstream statsFile(out + "/stats.json");
    auto const stats = nlohmann::json::parse(statsFile);
    EXPECT_EQ(stats["layout"], "packed");
    EXPECT_EQ(stats["gbuffer_bytes_per_pixel"], 12);  // RG16 + RGBA8 + DEPTH24_STENCIL8
    EXPECT_EQ(stats["gbuffer_note"],
              "packed: no room for emissive and occlusion in 12 bytes; emission and AO are not shown");
    // emissive.exr holds what packed decodes: emission 0, occlusion 1, at every pixel.
    auto const emissive = readImage(out + "/emissive.exr");
    ASSERT_TRUE(emissive);
    ASSERT_EQ(emissive->channels, 4);
    int notDecoded = 0;
    for (std::size_t i = 0; i + 3 < emissive->pixels.size(); i += 4)
        notDecoded += emissive->pixels[i] != 0.0f || emissive->pixels[i + 1] != 0.0f ||
                      emissive->pixels[i + 2] != 0.0f || emissive->pixels[i + 3] != 1.0f;
    EXPECT_EQ(notDecoded, 0);
    // normal.exr is decoded: unit length wherever geometry was drawn (w = 1).
    auto const normal = readImage(out + "/normal.exr");
    ASSERT_TRUE(normal);
    int drawn = 0;
    for (std::size_t i = 0; i + 3 < normal->pixels.size(); i += 4) {
        if (normal->pixels[i + 3] == 0.0f) continue;
        ++drawn;
        float const len =
            std::sqrt(normal->pixels[i] * normal->pixels[i] + normal->pixels[i + 1] * normal->pixels[i + 1] +
                      normal->pixels[i + 2] * normal->pixels[i + 2]);
        EXPECT_NEAR(len, 1.0f, 1e-3f);
    }
    EXPECT_GT(drawn, 64 * 36 / 2);
}

TEST(RenderCommand, AccumulationSplitWritesBothLightTargets) {
    std::string const out = test::freshTempDir("render_accumulation_split");
    auto const r = runGbufferLab({"render", "--out", out, "--size", "64x36", "--accumulation", "split"});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (char const* f : {"diffuse_light.exr", "specular_light.exr", "lighting.exr"})
        EXPECT_TRUE(fs::exists(out + "/" + f)) << f;
    std::ifstream statsFile(out + "/stats.json");
    EXPECT_EQ(nlohmann::json::parse(statsFile)["accumulation"], "split");
}

TEST(RenderCommand, PackedDropsTheEmissionAnEmissiveSceneHas) {
    std::string const helmet = test::sharedGltfDir() + "/DamagedHelmet/DamagedHelmet.gltf";
    if (!fs::exists(helmet)) GTEST_SKIP() << "needs the shared glTF sample models beside the project: " << helmet;
    // The helmet's emissive texture lights its visor: classic stores it, packed has no room for it.
    auto emissionSum = [&](char const* layout, bool expectRaw) {
        std::string const out = test::freshTempDir(std::string("render_emissive_") + layout);
        auto const r =
            runGbufferLab({"render", "--out", out, "--size", "64x64", "--scene", helmet, "--layout", layout});
        EXPECT_EQ(r.exitCode, 0) << r.output;
        EXPECT_EQ(fs::exists(out + "/raw_emissive_ao.exr") || fs::exists(out + "/raw_emissive_ao.png"), expectRaw)
            << layout;
        auto const emissive = readImage(out + "/emissive.exr");
        double sum = 0.0;
        if (emissive)
            for (std::size_t i = 0; i + 3 < emissive->pixels.size(); i += 4)
                sum += double(emissive->pixels[i]) + emissive->pixels[i + 1] + emissive->pixels[i + 2];
        else
            ADD_FAILURE() << layout << ": no emissive.exr";
        return sum;
    };
    EXPECT_GT(emissionSum("classic", true), 1.0) << "the scene has emission to lose";
    EXPECT_EQ(emissionSum("packed", false), 0.0) << "packed decodes emission 0 everywhere";
}

TEST(RenderCommand, NormalMapsBendTheStoredNormals) {
    // The default scene's brick and flagstone carry normal maps: the normal attachment must
    // differ from the same frame rendered with normal mapping off (the geometry normals).
    std::string const out = test::freshTempDir("render_normals");
    ASSERT_EQ(runGbufferLab({"render", "--out", out, "--size", "128x72"}).exitCode, 0);
    auto const withMaps = readImage(out + "/normal.exr");
    ASSERT_TRUE(withMaps);
    int bent = 0, axisAligned = 0, drawn = 0;
    for (int y = 0; y < withMaps->height; ++y)
        for (int x = 0; x < withMaps->width; ++x) {
            if (withMaps->at(x, y, 3) == 0.0f) continue;
            ++drawn;
            float const ny = withMaps->at(x, y, 1);
            // Floor pixels without a normal map would be exactly (0, 1, 0).
            if (ny > 0.9f && ny < 0.9995f) ++bent;
            if (ny == 1.0f) ++axisAligned;
        }
    EXPECT_GT(bent, drawn / 10) << "normal-mapped floor pixels lean away from +Y";
}

namespace {
// Sets environment variables for the commands this test runs (children inherit them) and
// restores the old values when it ends.
class ScopedEnv {
public:
    ScopedEnv(std::vector<std::pair<std::string, std::string>> vars) {
        for (auto const& [name, value] : vars) {
            char const* old = std::getenv(name.c_str());
            saved_.push_back({name, old ? std::optional<std::string>(old) : std::nullopt});
            setenv(name.c_str(), value.c_str(), 1);
        }
    }
    ~ScopedEnv() {
        for (auto const& [name, old] : saved_) {
            if (old)
                setenv(name.c_str(), old->c_str(), 1);
            else
                unsetenv(name.c_str());
        }
    }

private:
    std::vector<std::pair<std::string, std::optional<std::string>>> saved_;
};
}  // namespace

TEST(RenderCommand, OpenGl33DriverThatListsComputeStillRendersVolumes) {
    // Mesa told to be GL 3.3 / GLSL 3.30 still lists GL_ARB_compute_shader, so the tiled program
    // is tried and fails to build. Only tiled may suffer: volumes needs no compute at all.
    ScopedEnv const env({{"MESA_GL_VERSION_OVERRIDE", "3.3"}, {"MESA_GLSL_VERSION_OVERRIDE", "330"}});
    std::string const out = test::freshTempDir("render_gl33_volumes");
    auto const volumes = runGbufferLab({"render", "--out", out, "--size", "64x48", "--mode", "volumes"});
    ASSERT_EQ(volumes.exitCode, 0) << volumes.output;
    ASSERT_TRUE(fs::exists(fs::path(out) / "stats.json"));
    auto const stats = test::readJsonFile(fs::path(out) / "stats.json");
    EXPECT_EQ(stats["gl_errors"], 0);
    EXPECT_EQ(stats["gl_version"].get<std::string>().rfind("3.3", 0), 0u) << "the override took effect";

    auto const tiled = test::expectRefused({"render", "--out", out, "--size", "64x48", "--mode", "tiled"},
                                           "tiled mode is unavailable");
    // One sentence naming the program and the compiler's reason, not a stack trace or the whole log.
    EXPECT_LE(std::count(tiled.output.begin(), tiled.output.end(), '\n'), 1) << tiled.output;
    EXPECT_NE(tiled.output.find("lighting_tiled"), std::string::npos) << tiled.output;
}

TEST(RenderCommand, UntilGeometryWritesTheGBufferAndAClearedLitImage) {
    std::string const out = test::freshTempDir("render_until_geometry");
    auto const r = runGbufferLab({"render", "--out", out, "--size", "48x32", "--until", "geometry"});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("stopped after geometry"), std::string::npos) << r.output;
    auto const stats = test::readJsonFile(fs::path(out) / "stats.json");
    EXPECT_EQ(stats["stopped_after"], "geometry");
    EXPECT_EQ(stats["gpu_ms"].size(), 2u) << stats["gpu_ms"].dump();  // geometry, display
    auto const lighting = readImage(out + "/lighting.exr");
    auto const albedo = readImage(out + "/albedo.png");
    ASSERT_TRUE(lighting);
    ASSERT_TRUE(albedo);
    float litMax = 0.0f, albedoMax = 0.0f;
    for (float v : lighting->pixels) litMax = std::max(litMax, std::abs(v));
    for (float v : albedo->pixels) albedoMax = std::max(albedoMax, v);
    EXPECT_EQ(litMax, 0.0f) << "nothing lit yet";
    EXPECT_GT(albedoMax, 0.0f) << "the G-buffer is filled";
}

// --view depth_linear (and depth, position) are written with the drawn pixels' 1-99 % range, as the
// editor's auto-fit shows them: before, linear distances of metres went through a 0..1 range and
// the picture was white wherever something was drawn.
TEST(RenderCommand, RemappedViewsAreWrittenWithTheReadableRange) {
    std::string const out = test::freshTempDir("render_views");
    auto const r = runGbufferLab({"render", "--out", out, "--size", "160x90", "--lights", "4", "--view", "depth_linear",
                                  "--view", "depth", "--view", "position"});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    auto const depth = readImage((fs::path(out) / "depth.exr").string());
    ASSERT_TRUE(depth);
    for (char const* name : {"view_depth_linear.png", "view_depth.png", "view_position.png"}) {
        auto const view = readImage((fs::path(out) / name).string());
        ASSERT_TRUE(view) << name;
        ASSERT_EQ(view->width * view->height, depth->width * depth->height) << name;
        // Over the drawn pixels (depth below the far plane) the red channel spans most of 0..1:
        // the nearest surfaces dark, the farthest bright, not one saturated value.
        float low = 1.0f, high = 0.0f;
        int drawn = 0;
        for (int i = 0; i < view->width * view->height; ++i) {
            if (!(depth->pixels[std::size_t(i)] < 1.0f)) continue;
            float const v = view->pixels[std::size_t(i) * std::size_t(view->channels)];
            low = std::min(low, v);
            high = std::max(high, v);
            ++drawn;
        }
        ASSERT_GT(drawn, 1000) << name;
        EXPECT_LT(low, 0.1f) << name;
        EXPECT_GT(high, 0.9f) << name;
    }
}

// render --glass: the default scene's three panes, drawn by the forward pass (three draws, sorted)
// after lighting; the saved session names the glass so it renders the same frame again. --glass with
// another scene or a session is refused in one sentence.
TEST(RenderCommand, GlassStandsThreePanesDrawnForward) {
    std::string const out = test::freshTempDir("render_glass");
    std::string const session = out + "/glass.json";
    auto const r = runGbufferLab(
        {"render", "--out", out, "--size", "64x36", "--lights", "4", "--glass", "--save-session", session});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    auto const stats = test::readJsonFile(fs::path(out) / "stats.json");
    ASSERT_TRUE(stats["calls"].contains("forward")) << stats["calls"].dump();
    EXPECT_EQ(stats["calls"]["forward"]["draws"], 3);
    auto const saved = test::readJsonFile(session);
    EXPECT_EQ(saved["scene"]["default_scene_glass"], true);
    EXPECT_EQ(saved["pipeline"]["glass_outline"], false);

    std::string const plainOut = test::freshTempDir("render_no_glass");
    ASSERT_EQ(runGbufferLab({"render", "--out", plainOut, "--size", "64x36", "--lights", "4"}).exitCode, 0);
    auto const plain = test::readJsonFile(fs::path(plainOut) / "stats.json");
    EXPECT_EQ(plain["calls"]["forward"]["draws"], 0) << "no blended surface without --glass";

    auto const withScene = runGbufferLab({"render", "--out", out, "--glass", "--scene", "x.gltf"});
    EXPECT_EQ(withScene.exitCode, 2);
    EXPECT_NE(withScene.output.find("--glass stands its panes in the default scene"), std::string::npos)
        << withScene.output;
    auto const withSession = runGbufferLab({"render", "--out", out, "--glass", "--session", session});
    EXPECT_EQ(withSession.exitCode, 2);
    EXPECT_NE(withSession.output.find("cannot be combined with --session"), std::string::npos) << withSession.output;
}

// stats.json's memory follows the mode that ran (core/frame_memory.h): forward and forward+ write
// no G-buffer, so its bytes are 0 there and bytes_per_pixel counts their own targets; a deferred
// frame keeps its layout's G-buffer bytes.
TEST(RenderCommand, ForwardModesReportTheirOwnBytesPerPixel) {
    auto const statsOf = [](std::string const& mode) {
        std::string const out = test::freshTempDir("render_memory_" + mode);
        auto const r = runGbufferLab(
            {"render", "--out", out, "--size", "64x36", "--lights", "4", "--layout", "packed", "--mode", mode});
        EXPECT_EQ(r.exitCode, 0) << r.output;
        return test::readJsonFile(fs::path(out) / "stats.json");
    };
    auto const quad = statsOf("quad");
    EXPECT_EQ(quad["gbuffer_bytes_per_pixel"], 12);
    EXPECT_EQ(quad["bytes_per_pixel"], 12.0 + 8.0 + 4.0);  // + lit image RGBA16F + its DEPTH24_STENCIL8
    auto const forward = statsOf("forward");
    EXPECT_EQ(forward["gbuffer_bytes_per_pixel"], 0);
    EXPECT_EQ(forward["bytes_per_pixel"], 8.0 + 4.0);
    auto const plus = statsOf("forward+");
    ASSERT_FALSE(plus.contains("fallback_reason")) << plus["fallback_reason"];
    EXPECT_EQ(plus["gbuffer_bytes_per_pixel"], 0);
    auto const& parts = plus["memory"];
    EXPECT_EQ(parts["depth pre-pass DEPTH24_STENCIL8"], 4.0);
    EXPECT_EQ(parts["lit image RGBA16F"], 8.0);
    // 4 x 3 tiles of a count, a depth range and at least one index each, over 64 x 36 pixels.
    EXPECT_GE(parts["tile light lists"].get<double>(), 12 * (4.0 + 8.0 + 4.0) / (64.0 * 36.0));
    EXPECT_DOUBLE_EQ(plus["bytes_per_pixel"].get<double>(), 12.0 + parts["tile light lists"].get<double>());
}
