// Undo history: steps, merging of drags and quick edits, redo, bounds.
#include "model/undo.h"

#include <gtest/gtest.h>

using namespace gbl;
using namespace gbl::ui;

namespace {

UndoSnapshot start() {
    UndoSnapshot s;
    for (int i = 0; i < 3; ++i) {
        PointLight l;
        l.position = {float(i), 1.0f, 0.0f};
        s.lights.push_back(l);
    }
    return s;
}

UndoSnapshot withX(UndoSnapshot s, int light, float x) {
    s.lights[std::size_t(light)].position.x = x;
    return s;
}

}  // namespace

TEST(Undo, NothingToUndoAtFirst) {
    UndoStack u;
    u.reset(start());
    EXPECT_FALSE(u.canUndo());
    EXPECT_FALSE(u.canRedo());
    EXPECT_FALSE(u.undo(start(), 0.0));
    EXPECT_FALSE(u.redo(start(), 0.0));
    // Observing an unchanged state records nothing.
    EXPECT_FALSE(u.observe(start(), false, 1.0));
    EXPECT_FALSE(u.canUndo());
}

TEST(Undo, OneEditUndoesAndRedoes) {
    UndoStack u;
    u.reset(start());
    UndoSnapshot const edited = withX(start(), 1, 5.0f);
    EXPECT_TRUE(u.observe(edited, false, 1.0));
    EXPECT_EQ(u.undoSteps(), 1u);
    auto const back = u.undo(edited, 2.0);
    ASSERT_TRUE(back);
    EXPECT_TRUE(*back == start());
    EXPECT_TRUE(u.canRedo());
    auto const again = u.redo(*back, 3.0);
    ASSERT_TRUE(again);
    EXPECT_TRUE(*again == edited);
    EXPECT_FALSE(u.canRedo());
}

TEST(Undo, ASliderDragIsOneStep) {
    UndoStack u;
    u.reset(start());
    // Sixty frames of dragging light 0 from x = 0 to x = 6 while the widget is held.
    UndoSnapshot live = start();
    for (int f = 1; f <= 60; ++f) {
        live = withX(live, 0, float(f) * 0.1f);
        EXPECT_FALSE(u.observe(live, true, f / 60.0));
    }
    EXPECT_FALSE(u.canUndo());                 // nothing recorded mid-drag
    EXPECT_TRUE(u.observe(live, false, 1.1));  // released
    EXPECT_EQ(u.undoSteps(), 1u);
    auto const back = u.undo(live, 5.0);
    ASSERT_TRUE(back);
    EXPECT_FLOAT_EQ(back->lights[0].position.x, 0.0f);
    EXPECT_FALSE(u.canUndo());
}

TEST(Undo, QuickEditsOfTheSameThingMergeOthersDoNot) {
    UndoStack u(UndoLimits{200, std::size_t(64) << 20, 0.75});
    u.reset(start());
    UndoSnapshot s = start();
    // Three wheel notches on light 2 within 0.2 s: one step.
    for (int i = 1; i <= 3; ++i) {
        s = withX(s, 2, 2.0f + float(i));
        u.observe(s, false, 10.0 + 0.1 * i);
    }
    EXPECT_EQ(u.undoSteps(), 1u);
    // Light 1 right after: another thing, another step.
    s = withX(s, 1, -4.0f);
    u.observe(s, false, 10.4);
    EXPECT_EQ(u.undoSteps(), 2u);
    // Light 1 again, but after a pause longer than the merge window: a new step.
    s = withX(s, 1, -8.0f);
    u.observe(s, false, 12.0);
    EXPECT_EQ(u.undoSteps(), 3u);
    // Pipeline changes merge with each other, not with light edits.
    s.pipeline.exposure = 2.0f;
    u.observe(s, false, 12.1);
    s.pipeline.exposure = 3.0f;
    u.observe(s, false, 12.2);
    EXPECT_EQ(u.undoSteps(), 4u);

    auto a = u.undo(s, 20.0);  // exposure back to 1 in one go
    ASSERT_TRUE(a);
    EXPECT_EQ(a->pipeline.exposure, 1.0f);
    EXPECT_EQ(a->lights[1].position.x, -8.0f);
    auto b = u.undo(*a, 20.1);  // the second, separate edit of light 1
    ASSERT_TRUE(b);
    EXPECT_EQ(b->lights[1].position.x, -4.0f);
    auto c = u.undo(*b, 20.2);
    ASSERT_TRUE(c);
    EXPECT_EQ(c->lights[1].position.x, 1.0f);
    EXPECT_EQ(c->lights[2].position.x, 5.0f);  // the merged notches are still applied
    auto d = u.undo(*c, 20.3);
    ASSERT_TRUE(d);
    EXPECT_TRUE(*d == start());
}

TEST(Undo, AddingAndDeletingLightsNeverMerge) {
    UndoStack u;
    u.reset(start());
    UndoSnapshot s = start();
    s.lights.push_back(PointLight{});
    u.observe(s, false, 1.0);
    s.lights.push_back(PointLight{});
    u.observe(s, false, 1.05);
    EXPECT_EQ(u.undoSteps(), 2u);
    auto const one = u.undo(s, 2.0);
    ASSERT_TRUE(one);
    EXPECT_EQ(one->lights.size(), 4u);
}

TEST(Undo, AnEditAfterUndoClearsRedo) {
    UndoStack u;
    u.reset(start());
    UndoSnapshot const a = withX(start(), 0, 1.5f);
    u.observe(a, false, 1.0);
    auto const back = u.undo(a, 2.0);
    ASSERT_TRUE(back);
    EXPECT_TRUE(u.canRedo());
    UndoSnapshot const b = withX(*back, 2, 9.0f);
    u.observe(b, false, 3.0);
    EXPECT_FALSE(u.canRedo());
    EXPECT_FALSE(u.redo(b, 4.0));
}

TEST(Undo, UndoRecordsAPendingEditFirst) {
    // Ctrl+Z pressed before the frame that would have recorded the edit: undo still takes
    // back exactly that edit, and redo brings it back.
    UndoStack u;
    u.reset(start());
    UndoSnapshot const pending = withX(start(), 0, 7.0f);
    auto const back = u.undo(pending, 1.0);
    ASSERT_TRUE(back);
    EXPECT_TRUE(*back == start());
    auto const fwd = u.redo(*back, 2.0);
    ASSERT_TRUE(fwd);
    EXPECT_TRUE(*fwd == pending);
}

TEST(Undo, HistoryIsBoundedInSteps) {
    UndoStack u(UndoLimits{5, std::size_t(64) << 20, 0.0});
    u.reset(start());
    UndoSnapshot s = start();
    for (int i = 1; i <= 10; ++i) {
        s = withX(s, 0, float(i));
        u.observe(s, false, double(i));
    }
    EXPECT_EQ(u.undoSteps(), 5u);
    std::optional<UndoSnapshot> cur = s;
    for (int i = 0; i < 5; ++i) cur = u.undo(*cur, 100.0 + i);
    ASSERT_TRUE(cur);
    EXPECT_EQ(cur->lights[0].position.x, 5.0f);  // the oldest kept state
    EXPECT_FALSE(u.undo(*cur, 200.0));
}

TEST(Undo, HistoryIsBoundedInMemory) {
    // 4000 lights are ~320 KB a snapshot; a 1 MB budget keeps only a handful of steps.
    UndoStack u(UndoLimits{1000, std::size_t(1) << 20, 0.0});
    UndoSnapshot s;
    s.lights.assign(4000, PointLight{});
    u.reset(s);
    for (int i = 1; i <= 50; ++i) {
        s.lights[0].position.x = float(i);
        u.observe(s, false, double(i));
    }
    EXPECT_LE(u.bytes(), std::size_t(1) << 20);
    EXPECT_GE(u.undoSteps(), 2u);
    EXPECT_LT(u.undoSteps(), 10u);
    // Undo still works to the oldest kept state.
    std::optional<UndoSnapshot> cur = s;
    std::size_t const steps = u.undoSteps();
    for (std::size_t i = 0; i < steps; ++i) cur = u.undo(*cur, 100.0 + double(i));
    ASSERT_TRUE(cur);
    EXPECT_EQ(cur->lights[0].position.x, float(50 - steps));
}

TEST(Undo, PipelineEditsAreSteps) {
    UndoStack u;
    UndoSnapshot s = start();
    u.reset(s);
    s.pipeline.cull = CullMode::Back;
    u.observe(s, false, 1.0);
    s.pipeline.depthCopy = DepthCopy::Off;
    u.observe(s, false, 5.0);
    auto const a = u.undo(s, 6.0);
    ASSERT_TRUE(a);
    EXPECT_EQ(a->pipeline.depthCopy, DepthCopy::Blit);
    EXPECT_EQ(a->pipeline.cull, CullMode::Back);
    auto const b = u.undo(*a, 7.0);
    ASSERT_TRUE(b);
    EXPECT_EQ(b->pipeline.cull, CullMode::Front);
}

TEST(Undo, EditTargetNamesWhatChanged) {
    UndoSnapshot const a = start();
    EXPECT_EQ(editTarget(a, a), "");
    EXPECT_EQ(editTarget(a, withX(a, 2, 3.0f)), "light 2");
    EXPECT_EQ(editTarget(a, withX(withX(a, 0, 3.0f), 1, 3.0f)), "lights");
    UndoSnapshot p = a;
    p.pipeline.mode = LightingMode::Tiled;
    EXPECT_EQ(editTarget(a, p), "pipeline");
    UndoSnapshot n = a;
    n.lights[1].name = "key";
    EXPECT_EQ(editTarget(a, n), "light 1");
    UndoSnapshot fewer = a;
    fewer.lights.pop_back();
    EXPECT_EQ(editTarget(a, fewer), "lights");
}

TEST(Undo, ResetForgetsTheHistory) {
    UndoStack u;
    u.reset(start());
    u.observe(withX(start(), 0, 2.0f), false, 1.0);
    u.reset(withX(start(), 0, 2.0f));
    EXPECT_FALSE(u.canUndo());
    EXPECT_EQ(u.bytes(), 0u);
}

TEST(Undo, EveryLightFieldAndThePipelineCountAsAChange) {
    // Change detection is the structs' defaulted ==, so each table entry (core/point_light.h),
    // the name and any pipeline switch make an edit with the right target.
    for (LightField const& f : kLightFields) {
        UndoSnapshot after = start();
        f.of(after.lights[1]) += 0.5f;
        EXPECT_EQ(editTarget(start(), after), "light 1") << f.name;
    }
    UndoSnapshot renamed = start();
    renamed.lights[2].name = "key";
    EXPECT_EQ(editTarget(start(), renamed), "light 2");
    UndoSnapshot piped = start();
    piped.pipeline.ambient.g += 0.01f;
    EXPECT_EQ(editTarget(start(), piped), "pipeline");
    piped = start();
    piped.pipeline.normalMaps = !piped.pipeline.normalMaps;
    EXPECT_EQ(editTarget(start(), piped), "pipeline");
    EXPECT_EQ(editTarget(start(), start()), "");
}
