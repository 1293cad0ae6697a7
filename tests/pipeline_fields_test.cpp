// core/pipeline_fields.h: one entry per PipelineSettings member, each editing its own member, with
// its default inside its range, and values parsed as files and scripts write them.
#include "core/pipeline_fields.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

using namespace gbl;

namespace {

// A value of `f` other than its default (the next choice, the other toggle, a number in range).
double otherValue(PipelineField const& f, double now) {
    switch (f.kind) {
        case SettingKind::Choice:
            return double((int(now) + 1) % int(f.choices.size()));
        case SettingKind::Toggle:
            return now != 0.0 ? 0.0 : 1.0;
        case SettingKind::Number:
            break;
    }
    return now == double(f.max) ? double(f.min) : double(f.max);
}

TEST(PipelineFields, OneEntryPerMemberEachEditingItsOwn) {
    // Fails to compile when PipelineSettings gains or loses a member: add its entry to the table in
    // core/pipeline_fields.cpp, then update the count here.
    [[maybe_unused]] auto const& [mode, cull, depthCopy, tonemap, view, layout, accumulation, shading, lightCubes,
                                  volumeWireframes, wireframesSelectedOnly, normalMaps, ambient, exposure, shininess,
                                  volumeScale] = PipelineSettings{};
    constexpr std::size_t kMembers = 16;
    std::span<PipelineField const> const fields = pipelineFields();
    ASSERT_EQ(fields.size(), kMembers);

    std::set<std::string_view> names;
    for (PipelineField const& f : fields) {
        EXPECT_TRUE(names.insert(f.name).second) << f.name << " is in the table twice";
        PipelineSettings s;
        double const before = f.get(s);
        double const other = otherValue(f, before);
        f.set(s, other);
        EXPECT_NE(s, PipelineSettings{}) << f.name << " changes nothing";
        EXPECT_EQ(f.get(s), double(float(other))) << f.name << " does not read back what it wrote";
        // It changed its own member only: every other entry still reads its default.
        for (PipelineField const& g : fields) {
            if (&g != &f) {
                EXPECT_EQ(g.get(s), g.defaultValue()) << f.name << " also changed " << g.name;
            }
        }
    }
}

TEST(PipelineFields, DefaultsLieInTheirRanges) {
    for (PipelineField const& f : pipelineFields()) {
        EXPECT_TRUE(fieldAccepts(f, f.defaultValue())) << f.name;
        EXPECT_FALSE(f.help.empty()) << f.name << " has no help line";
        if (f.kind == SettingKind::Choice) {
            EXPECT_FALSE(f.choices.empty()) << f.name;
        }
        // Text written for the default parses back to it.
        auto const back = parseFieldValue(f, fieldScriptText(f, PipelineSettings{}));
        ASSERT_TRUE(back) << f.name;
        EXPECT_EQ(float(*back), float(f.defaultValue())) << f.name;
    }
}

TEST(PipelineFields, ParseRefusesUnknownNamesAndOutOfRange) {
    PipelineField const* mode = findPipelineField("mode");
    PipelineField const* shininess = findPipelineField("shininess");
    PipelineField const* cubes = findPipelineField("light_cubes");
    ASSERT_TRUE(mode && shininess && cubes);
    EXPECT_EQ(parseFieldValue(*mode, "tiled"), double(int(LightingMode::Tiled)));
    EXPECT_FALSE(parseFieldValue(*mode, "tiles"));
    EXPECT_EQ(parseFieldValue(*shininess, "64"), 64.0);
    EXPECT_EQ(parseFieldValue(*shininess, "512"), 512.0);
    EXPECT_FALSE(parseFieldValue(*shininess, "513"));
    EXPECT_FALSE(parseFieldValue(*shininess, "0.5"));
    EXPECT_FALSE(parseFieldValue(*shininess, "nan"));
    EXPECT_FALSE(parseFieldValue(*shininess, "64x"));
    EXPECT_EQ(parseFieldValue(*cubes, "off"), 0.0);
    EXPECT_EQ(parseFieldValue(*cubes, "1"), 1.0);
    EXPECT_FALSE(parseFieldValue(*cubes, "2"));
    EXPECT_FALSE(findPipelineField("cubes")) << "the script's old name is gone: light_cubes everywhere";
}

TEST(PipelineFields, AmbientIsAColourWhoseGreyTheTableEdits) {
    PipelineField const* ambient = findPipelineField("ambient");
    ASSERT_TRUE(ambient && ambient->rgb);
    PipelineSettings s;
    ambient->set(s, 0.25);
    EXPECT_EQ(s.ambient, glm::vec3(0.25f));
    EXPECT_EQ(&(s.*ambient->rgb), &s.ambient);
}

}  // namespace
