// Bad session files: one clear message per kind of bad field, naming it; the light limit; text that
// is not JSON; every truncation and byte flip; missing files. Round trips and atomic writes:
// session_test.
#include "run_command.h"
#include "session/session.h"
#include "session_samples.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <functional>
#include <string>
#include <vector>

using namespace gbl;
using namespace gbl::ui;
using gbl::test::richSession;
using nlohmann::json;

namespace {

struct BadCase {
    char const* what;
    std::function<void(json&)> edit;
    std::string message;  // the whole expected message
};

}  // namespace

TEST(Session, EveryKindOfBadFieldGetsOneMessageNamingIt) {
    std::vector<BadCase> const cases{
        // unknown fields, at every level
        {"unknown top-level field", [](json& j) { j["colour_grading"] = true; },
         "s.json: colour_grading is not a known field"},
        {"typo in a light field", [](json& j) { j["lights"][2]["intesity"] = 2; },
         "s.json: lights[2].intesity is not a known field"},
        {"unknown pipeline field", [](json& j) { j["pipeline"]["ssao"] = true; },
         "s.json: pipeline.ssao is not a known field"},
        {"unknown viewer", [](json& j) { j["viewers"]["emission"] = j["viewers"]["albedo"]; },
         "s.json: viewers.emission is not a known field"},
        // missing required fields
        {"missing camera.near", [](json& j) { j["camera"].erase("near"); }, "s.json: camera.near is missing"},
        {"missing kq", [](json& j) { j["lights"][1].erase("kq"); }, "s.json: lights[1].kq is missing"},
        {"missing lights", [](json& j) { j.erase("lights"); }, "s.json: lights is missing"},
        {"missing viewer", [](json& j) { j["viewers"].erase("depth"); }, "s.json: viewers.depth is missing"},
        {"missing format", [](json& j) { j.erase("format"); }, "s.json: format is missing"},
        // wrong types
        {"kq as a string", [](json& j) { j["lights"][3]["kq"] = "1.8"; },
         "s.json: lights[3].kq must be a finite number >= 0 (got a string)"},
        {"bool as a number", [](json& j) { j["pipeline"]["light_cubes"] = 1; },
         "s.json: pipeline.light_cubes must be true or false (got a number)"},
        {"lights as an object", [](json& j) { j["lights"] = json::object(); },
         "s.json: lights must be an array (got an object)"},
        {"light as an array", [](json& j) { j["lights"][0] = json::array(); },
         "s.json: lights[0] must be an object (got an array)"},
        {"short vector",
         [](json& j) {
             j["camera"]["position"] = {1, 2};
         },
         "s.json: camera.position must be an array of 3 numbers"},
        {"vector element", [](json& j) { j["lights"][4]["color"][1] = true; },
         "s.json: lights[4].color[1] must be a finite number >= 0 (got true/false)"},
        {"fractional mask", [](json& j) { j["viewers"]["albedo"]["channel_mask"] = 1.5; },
         "s.json: viewers.albedo.channel_mask must be a whole number from 0 to 15 (got 1.5)"},
        // NaN, infinity, negative: JSON writers turn NaN into null; 1e39 is finite as a double
        // but infinite as the float the renderer uses.
        {"NaN written as null", [](json& j) { j["lights"][3]["kq"] = nullptr; },
         "s.json: lights[3].kq must be a finite number >= 0 (got null)"},
        {"float overflow", [](json& j) { j["lights"][3]["intensity"] = 1e39; },
         "s.json: lights[3].intensity must be a finite number >= 0 (got 1e+39)"},
        {"negative kq", [](json& j) { j["lights"][3]["kq"] = -0.5; },
         "s.json: lights[3].kq must be a finite number >= 0 (got -0.5)"},
        {"negative colour", [](json& j) { j["lights"][0]["color"][2] = -1; },
         "s.json: lights[0].color[2] must be a finite number >= 0 (got -1)"},
        {"zero threshold", [](json& j) { j["lights"][0]["threshold"] = 0; },
         "s.json: lights[0].threshold must be a finite number > 0 (got 0)"},
        {"infinite position", [](json& j) { j["lights"][1]["position"][0] = -1e300; },
         "s.json: lights[1].position[0] must be a finite number (got -1e+300)"},
        {"no attenuation at all",
         [](json& j) {
             j["lights"][2]["kc"] = 0;
             j["lights"][2]["kl"] = 0;
             j["lights"][2]["kq"] = 0;
         },
         "s.json: lights[2]: light attenuation Kc, Kl and Kq cannot all be 0 (infinite brightness at the light)"},
        {"unknown light kind", [](json& j) { j["lights"][0]["kind"] = "area"; },
         "s.json: lights[0].kind must be one of point, spot or directional (got \"area\")"},
        {"zero direction",
         [](json& j) {
             j["lights"][1]["direction"] = {0, 0, 0};
         },
         "s.json: lights[1].direction must not be the zero vector"},
        {"non-finite direction", [](json& j) { j["lights"][1]["direction"][2] = nullptr; },
         "s.json: lights[1].direction[2] must be a finite number (got null)"},
        {"cone past 90 degrees", [](json& j) { j["lights"][1]["outer_cone_deg"] = 120; },
         "s.json: lights[1].outer_cone_deg must be between 0 and 90 (got 120)"},
        {"inner wider than outer",
         [](json& j) {
             j["lights"][1]["inner_cone_deg"] = 40;
             j["lights"][1]["outer_cone_deg"] = 30;
         },
         "s.json: lights[1]: light parameter inner_cone_deg must not exceed outer_cone_deg (40.000000 > 30.000000)"},
        {"negative exposure", [](json& j) { j["pipeline"]["exposure"] = -1; },
         "s.json: pipeline.exposure must be between 0.05 and 16 (got -1)"},
        // The ranges of core/pipeline_fields.h, the same as the Pipeline panel's and the A/B table's.
        {"shininess past the panel's range", [](json& j) { j["pipeline"]["shininess"] = 1000; },
         "s.json: pipeline.shininess must be between 1 and 512 (got 1000)"},
        {"ambient above one",
         [](json& j) {
             j["pipeline"]["ambient"] = {0.1, 2.0, 0.1};
         },
         "s.json: pipeline.ambient[1] must be between 0 and 1 (got 2.0)"},
        {"the script's old name", [](json& j) { j["pipeline"]["cubes"] = true; },
         "s.json: pipeline.cubes is not a known field"},
        // out of range
        {"far before near", [](json& j) { j["camera"]["far"] = 0.001; },
         "s.json: camera.far must be greater than camera.near"},
        {"pitch past the pole", [](json& j) { j["camera"]["pitch_degrees"] = 90; },
         "s.json: camera.pitch_degrees must be between -89 and 89 (got 90)"},
        {"zoom out of range", [](json& j) { j["viewers"]["normal"]["zoom"] = 0.5; },
         "s.json: viewers.normal.zoom must be between 1 and 256 (got 0.5)"},
        {"empty remap range",
         [](json& j) { j["viewers"]["position"]["range_max"] = j["viewers"]["position"]["range_min"]; },
         "s.json: viewers.position.range_max must be greater than viewers.position.range_min"},
        {"light count", [](json& j) { j["scene"]["default_scene_lights"] = 262145; },
         "s.json: scene.default_scene_lights must be a whole number from 0 to 262144 (got 262145)"},
        // enums
        {"unknown mode", [](json& j) { j["pipeline"]["mode"] = "raytraced"; },
         "s.json: pipeline.mode must be one of quad, volumes, tiled, forward, clustered, forward+ or prepass (got "
         "\"raytraced\")"},
        {"unknown depth copy", [](json& j) { j["pipeline"]["depth_copy"] = "copy"; },
         "s.json: pipeline.depth_copy must be one of blit, shader or off (got \"copy\")"},
        // the depth copy's old key names the field as the file does, and is one field with the new one
        {"unknown blit",
         [](json& j) {
             j["pipeline"].erase("depth_copy");
             j["pipeline"]["blit"] = "copy";
         },
         "s.json: pipeline.blit must be one of blit, shader or off (got \"copy\")"},
        {"old and new key", [](json& j) { j["pipeline"]["blit"] = "off"; },
         "s.json: pipeline.blit is the old name of pipeline.depth_copy: give only one of them"},
        {"no depth copy", [](json& j) { j["pipeline"].erase("depth_copy"); }, "s.json: pipeline.depth_copy is missing"},
        {"enum by number", [](json& j) { j["pipeline"]["cull"] = 1; },
         "s.json: pipeline.cull must be one of back, front, none, flip or stencil (got a number)"},
        {"unknown normal display", [](json& j) { j["viewers"]["normal"]["normal_display"] = "signed"; },
         "s.json: viewers.normal.normal_display must be one of biased or absolute (got \"signed\")"},
        // viewer tools
        {"unknown colormap", [](json& j) { j["viewers"]["depth"]["tools"]["colormap"] = "jet"; },
         "s.json: viewers.depth.tools.colormap must be one of grey, turbo or viridis (got \"jet\")"},
        {"unknown overlay",
         [](json& j) {
             j["viewers"]["albedo"]["tools"]["overlays"] = {"nan", "zebra"};
         },
         "s.json: viewers.albedo.tools.overlays[1] must be one of nan, inf, negative or clip (got \"zebra\")"},
        {"overlays as bits", [](json& j) { j["viewers"]["albedo"]["tools"]["overlays"] = 3; },
         "s.json: viewers.albedo.tools.overlays must be an array of names out of nan, inf, negative or clip (got a "
         "number)"},
        {"histogram as text", [](json& j) { j["viewers"]["normal"]["tools"]["histogram"] = "yes"; },
         "s.json: viewers.normal.tools.histogram must be true or false (got a string)"},
        {"stencil on another viewer", [](json& j) { j["viewers"]["position"]["tools"]["stencil"] = true; },
         "s.json: viewers.position.tools.stencil must be false: only the depth viewer shows the stencil"},
        {"unknown tool", [](json& j) { j["viewers"]["depth"]["tools"]["zebra"] = true; },
         "s.json: viewers.depth.tools.zebra is not a known field"},
        {"sync as a number", [](json& j) { j["viewer_tools"]["sync"] = 1; },
         "s.json: viewer_tools.sync must be true or false (got a number)"},
        {"viewport zoom out of range", [](json& j) { j["viewer_tools"]["viewport"]["viewer"]["zoom"] = 0; },
         "s.json: viewer_tools.viewport.viewer.zoom must be between 1 and 256 (got 0)"},
        {"viewport stencil", [](json& j) { j["viewer_tools"]["viewport"]["viewer"]["tools"]["stencil"] = true; },
         "s.json: viewer_tools.viewport.viewer.tools.stencil must be false: only the depth viewer shows the stencil"},
        // versions and format
        {"newer version", [](json& j) { j["version"] = 2; },
         "s.json: version 2 is not supported; this program reads version 1 (the file comes from a newer gbuffer-lab)"},
        {"older version", [](json& j) { j["version"] = 0; },
         "s.json: version 0 is not supported; this program reads version 1"},
        {"version as text", [](json& j) { j["version"] = "1"; }, "s.json: version must be a whole number (got \"1\")"},
        {"another format", [](json& j) { j["format"] = "blender-scene"; },
         "s.json: format must be \"gbuffer-lab-session\" (got \"blender-scene\"); this is not a gbuffer-lab session"},
        // a newer file's new fields do not hide its version
        {"newer version with new fields",
         [](json& j) {
             j["version"] = 3;
             j["shadows"] = true;
         },
         "s.json: version 3 is not supported; this program reads version 1 (the file comes from a newer gbuffer-lab)"},
        {"not an object",
         [](json& j) {
             j = json::array({1, 2});
         },
         "s.json: the file must hold a JSON object (got an array)"},
    };
    for (auto const& c : cases) {
        json j = json::parse(sessionToJson(richSession()));
        c.edit(j);
        SessionLoad const r = parseSession(j.dump(2), "s.json");
        EXPECT_FALSE(r.session) << c.what;
        EXPECT_EQ(r.error, c.message) << c.what;
    }
}

TEST(Session, TooManyLightsAreRefusedWithTheLimit) {
    Session s;
    s.lights.assign(std::size_t(kMaxLights) + 1, PointLight{});
    SessionLoad const r = parseSession(sessionToJson(s), "big.json");
    EXPECT_FALSE(r.session);
    EXPECT_EQ(r.error, "big.json: lights holds 262145 lights; the limit is 262144");
    s.lights.resize(std::size_t(kMaxLights));
    SessionLoad const ok = parseSession(sessionToJson(s), "big.json");
    ASSERT_TRUE(ok.session) << ok.error;
    EXPECT_EQ(ok.session->lights.size(), std::size_t(kMaxLights));
}

TEST(Session, TextThatIsNotJsonNamesTheFileAndPlace) {
    for (std::string const text : {"", "{", "{\"format\": \"gbuffer-lab-session\", \"version\": 1,}", "{\"kq\": NaN}",
                                   "{\"kq\": 1e999}", "\xff\xfe"}) {
        SessionLoad const r = parseSession(text, "broken.json");
        EXPECT_FALSE(r.session) << text;
        EXPECT_EQ(r.error.rfind("broken.json: not valid JSON: ", 0), 0u) << r.error;
        EXPECT_EQ(r.error.find("[json.exception"), std::string::npos) << r.error;
    }
}

TEST(Session, EveryTruncationAndByteFlipFailsCleanly) {
    // Whatever a crash or a stray editor leaves in the file, parsing ends with a message or a
    // valid session, never a crash (ASan/UBSan runs check the "never").
    std::string const text = sessionToJson(richSession());
    // Every prefix up to the closing brace (the text ends in "}\n"; without the newline it is whole).
    ASSERT_EQ(text.substr(text.size() - 2), "}\n");
    for (std::size_t n = 0; n < text.size() - 1; n += 7) {
        SessionLoad const r = parseSession(std::string_view(text).substr(0, n), "t.json");
        EXPECT_FALSE(r.session) << n;
        EXPECT_FALSE(r.error.empty());
    }
    int accepted = 0;
    for (std::size_t i = 0; i < text.size(); i += 5) {
        for (char c : {'\0', '-', '9', '"', '}', 'e'}) {
            std::string t = text;
            t[i] = c;
            SessionLoad const r = parseSession(t, "t.json");
            EXPECT_NE(bool(r.session), !r.error.empty());
            accepted += bool(r.session);
        }
    }
    // Some flips stay valid (a digit for a digit); most must not.
    EXPECT_GT(accepted, 0);
}

TEST(Session, MissingFileAndDirectoryAreMessages) {
    std::string const dir = test::freshTempDir("session_missing");
    SessionLoad const a = loadSession(dir + "/nope.json");
    EXPECT_FALSE(a.session);
    EXPECT_NE(a.error.find(dir + "/nope.json"), std::string::npos) << a.error;
    SessionLoad const b = loadSession(dir);
    EXPECT_FALSE(b.session);
    EXPECT_NE(b.error.find("is a directory"), std::string::npos) << b.error;
}
