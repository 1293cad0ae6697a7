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
                                  volumeWireframes, glassOutline, wireframesSelectedOnly, normalMaps, ambient, exposure,
                                  shininess, volumeScale, msaa, msaaLighting, prepassLights] = PipelineSettings{};
    constexpr std::size_t kMembers = 20;
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

// Every row carries what its users draw and parse: a label, a section, a widget that edits its
// kind, a tooltip, and the `render` option named after it (dashes for underscores), or none where
// the command line has no use for it.
TEST(PipelineFields, EveryRowHasItsWidgetAndOption) {
    std::set<std::string_view> options;
    for (PipelineField const& f : pipelineFields()) {
        EXPECT_FALSE(f.label.empty()) << f.name << " has no label";
        EXPECT_LT(std::size_t(f.section), kPipelineSectionTitles.size()) << f.name;
        EXPECT_FALSE(f.hoverText().empty()) << f.name << " has no tooltip";
        switch (f.widget) {
            case PipelineWidget::Radio:
                EXPECT_EQ(f.kind, SettingKind::Choice) << f.name;
                EXPECT_EQ(f.choiceHelp.size(), f.choices.size()) << f.name << ": one tooltip per radio button";
                for (std::size_t i = 0; i < f.choiceHelp.size() && i < f.choices.size(); ++i) {
                    EXPECT_EQ(f.choiceHelp[i].rfind(std::string(f.choices[i]) + ": ", 0), 0u)
                        << f.name << ": the tooltip of " << f.choices[i] << " is another choice's";
                }
                break;
            case PipelineWidget::Combo:
                EXPECT_EQ(f.kind, SettingKind::Choice) << f.name;
                break;
            case PipelineWidget::ChoiceCheckbox:
                EXPECT_EQ(f.kind, SettingKind::Choice) << f.name;
                EXPECT_GT(f.checkedChoice, 0) << f.name << ": unticked is the first choice, ticked another";
                EXPECT_LT(std::size_t(f.checkedChoice), f.choices.size()) << f.name;
                break;
            case PipelineWidget::Checkbox:
                EXPECT_EQ(f.kind, SettingKind::Toggle) << f.name;
                break;
            case PipelineWidget::Slider:
            case PipelineWidget::LogSlider:
            case PipelineWidget::Drag:
                EXPECT_EQ(f.kind, SettingKind::Number) << f.name;
                EXPECT_EQ(f.rgb, nullptr) << f.name << ": a colour is edited as a colour";
                EXPECT_GT(f.max, f.min) << f.name;
                break;
            case PipelineWidget::Colour:
                EXPECT_NE(f.rgb, nullptr) << f.name;
                break;
        }
        if (f.name == "view") {
            // render's --view writes extra debug views beside the final image: it is not this field.
            EXPECT_TRUE(f.option.empty());
            continue;
        }
        std::string expected = "--" + std::string(f.name);
        for (char& ch : expected)
            if (ch == '_') ch = '-';
        EXPECT_EQ(f.option, expected) << f.name;
        EXPECT_TRUE(options.insert(f.option).second) << f.option << " twice";
    }
    // The row the old option and key belong to.
    EXPECT_EQ(options.size(), pipelineFields().size() - 1);
}

// The depth copy has one name, `depth_copy`, the pass's; `blit` (the setting's name until then) still
// finds it, so old sessions, lessons and scripts keep working.
TEST(PipelineFields, TheDepthCopyIsFoundUnderItsOldNameToo) {
    PipelineField const* copy = findPipelineField("depth_copy");
    ASSERT_TRUE(copy);
    EXPECT_EQ(findPipelineField("blit"), copy);
    EXPECT_EQ(copy->oldName, "blit");
    EXPECT_EQ(copy->option, "--depth-copy");
    EXPECT_EQ(copy->oldOption, "--blit");
    EXPECT_EQ(copy->label, "Depth copy");
    EXPECT_EQ(kPipelineSectionTitles[std::size_t(copy->section)], "Depth copy");
    PipelineSettings s;
    copy->set(s, *parseFieldValue(*copy, "shader"));
    EXPECT_EQ(s.depthCopy, DepthCopy::Shader);
}

TEST(PipelineFields, ValuesTextListsWhatAFieldTakes) {
    EXPECT_EQ(fieldValuesText(*findPipelineField("depth_copy")), "one of blit, shader or off");
    EXPECT_EQ(fieldValuesText(*findPipelineField("mode")),
              "one of quad, volumes, tiled, forward, clustered, forward+ or prepass");
    EXPECT_EQ(fieldValuesText(*findPipelineField("exposure")), "a number from 0.05 to 16");
    EXPECT_EQ(fieldValuesText(*findPipelineField("normal_maps")), "0 or 1 (or off or on)");
}

// Greyed out, never hidden: the volumes' rows apply in volumes mode only, the selected-only toggle
// with the wireframes on.
TEST(PipelineFields, RowsSayWhenTheyApply) {
    PipelineSettings s;
    s.mode = LightingMode::Quad;
    s.volumeWireframes = false;
    EXPECT_FALSE(findPipelineField("cull")->appliesTo(s));
    EXPECT_FALSE(findPipelineField("volume_scale")->appliesTo(s));
    EXPECT_FALSE(findPipelineField("wireframes_selected_only")->appliesTo(s));
    EXPECT_TRUE(findPipelineField("exposure")->appliesTo(s));
    s.mode = LightingMode::Volumes;
    s.volumeWireframes = true;
    EXPECT_TRUE(findPipelineField("cull")->appliesTo(s));
    EXPECT_TRUE(findPipelineField("volume_scale")->appliesTo(s));
    EXPECT_TRUE(findPipelineField("wireframes_selected_only")->appliesTo(s));
}

}  // namespace
