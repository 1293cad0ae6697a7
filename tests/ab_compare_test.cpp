// The A/B field table, side B and the scrubber's steps: plain values, no GL.
#include "model/ab_compare.h"
#include "model/ab_accumulate.h"

#include <gtest/gtest.h>

#include <set>

using namespace gbl;
using namespace gbl::ui;

namespace {
std::size_t fieldIndex(std::string_view name) {
    auto const fields = abFields();
    for (std::size_t i = 0; i < fields.size(); ++i)
        if (fields[i].name == name) return i;
    ADD_FAILURE() << "no A/B field " << name;
    return 0;
}
}  // namespace

TEST(AbCompare, EveryFieldRoundTripsThroughItsAccessors) {
    std::set<std::string_view> names;
    for (AbField const& f : abFields()) {
        EXPECT_TRUE(names.insert(f.name).second) << "duplicate " << f.name;
        PipelineSettings s;
        double const before = f.get(s);
        // A value other than the default: the next choice, the other state, a number in range.
        double const other = f.kind == AbFieldKind::Choice   ? double((int(before) + 1) % int(f.choices.size()))
                             : f.kind == AbFieldKind::Toggle ? (before != 0.0 ? 0.0 : 1.0)
                                                             : double(f.min + (f.max - f.min) * 0.25f);
        f.set(s, other);
        EXPECT_NEAR(f.get(s), other, 1e-6) << f.name;
        EXPECT_FALSE(s == PipelineSettings{}) << f.name << " must change the settings it names";
        EXPECT_EQ(differingFields(PipelineSettings{}, s), std::vector<std::string_view>{f.name});
    }
}

TEST(AbCompare, SideBTakesOnlyTheTickedFields) {
    PipelineSettings a;
    a.mode = LightingMode::Quad;
    a.shininess = 16.0f;
    AbState ab;
    ab.b.mode = LightingMode::Volumes;
    ab.b.cull = CullMode::Back;
    ab.b.shininess = 64.0f;
    ab.overrides[fieldIndex("mode")] = true;
    ab.overrides[fieldIndex("cull")] = true;
    PipelineSettings const b = sideB(ab, a);
    EXPECT_EQ(b.mode, LightingMode::Volumes);
    EXPECT_EQ(b.cull, CullMode::Back);
    EXPECT_EQ(b.shininess, 16.0f);  // not ticked: follows A
    EXPECT_EQ(describeAb(a, b), "mode quad | volumes, cull front | back");
    EXPECT_EQ(describeAb(a, a), "A and B are the same settings");
    EXPECT_EQ(fieldText(abFields()[fieldIndex("shininess")], b), "16");
}

TEST(AbCompare, ScriptValuesSetAndTickAField) {
    AbState ab;
    EXPECT_TRUE(setAbField(ab, "cull", "stencil"));
    EXPECT_TRUE(setAbField(ab, "shininess", "64"));
    EXPECT_TRUE(setAbField(ab, "normal_maps", "0"));
    EXPECT_FALSE(setAbField(ab, "cull", "sideways"));
    EXPECT_FALSE(setAbField(ab, "shininess", "1000"));  // past the slider's range
    EXPECT_FALSE(setAbField(ab, "colour", "1"));
    PipelineSettings const b = sideB(ab, PipelineSettings{});
    EXPECT_EQ(b.cull, CullMode::Stencil);
    EXPECT_EQ(b.shininess, 64.0f);
    EXPECT_FALSE(b.normalMaps);
    EXPECT_EQ(differingFields(PipelineSettings{}, b).size(), 3u);
    // Turning A/B on keeps what was ticked; on a fresh state it ticks the mode, to another one.
    startAb(ab, PipelineSettings{});
    EXPECT_EQ(sideB(ab, PipelineSettings{}).mode, LightingMode::Quad);
    AbState fresh;
    startAb(fresh, PipelineSettings{});
    EXPECT_TRUE(fresh.enabled);
    EXPECT_EQ(sideB(fresh, PipelineSettings{}).mode, LightingMode::Volumes);
}

TEST(AbCompare, NormalAngleNeedsTheLayoutTicked) {
    AbState ab;
    EXPECT_FALSE(abComparesLayout(ab));
    EXPECT_TRUE(setAbField(ab, "cull", "stencil"));
    EXPECT_FALSE(abComparesLayout(ab));  // another field ticked: still no layout to compare
    EXPECT_TRUE(setAbField(ab, "layout", "classic"));
    EXPECT_TRUE(abComparesLayout(ab));
    EXPECT_EQ(sideB(ab, PipelineSettings{}).layout, GBufferLayout::Classic);
}

TEST(Accumulate, ArrowStepsStayWithinTheLightList) {
    AccumulateState a;
    stepAccumulation(a, -1, 32);
    EXPECT_EQ(a.count, 0);
    for (int i = 0; i < 40; ++i) stepAccumulation(a, 1, 32);
    EXPECT_EQ(a.count, 32);
    stepAccumulation(a, -1, 32);
    EXPECT_EQ(a.count, 31);
    stepAccumulation(a, 0, 4);  // lights removed under the scrubber
    EXPECT_EQ(a.count, 4);
}
