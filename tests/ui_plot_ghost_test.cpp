// The attenuation plot's ghost (model/lights_state.h): the light as it was when a drag of one of
// its attenuation fields began, kept through the drag and after it while the light is unchanged.
#include "core/light_math.h"
#include "model/lights_state.h"

#include <gtest/gtest.h>

using namespace gbl;
using namespace gbl::ui;

namespace {

PointLight lightWithKq(float kq) {
    PointLight l;
    l.kq = kq;
    return l;
}

// One frame of the panel: the selected light `before` this frame's edit, `now` after it.
void frame(LightsPanelState& s, bool dragging, PointLight const& before, PointLight const& now) {
    trackPlotGhost(s, dragging, before, now);
}

}  // namespace

TEST(LightsPanelGhost, CapturedOnDragStartKeptThroughTheDrag) {
    LightsPanelState s;
    s.selected = 2;
    PointLight const start = lightWithKq(1.0f);
    frame(s, false, start, start);
    EXPECT_FALSE(s.plotGhost);
    EXPECT_EQ(shownPlotGhost(s, start), nullptr);

    // The press: the field is held, nothing changed yet. The ghost is the light as it was, but
    // draws nothing while it equals the light.
    frame(s, true, start, start);
    ASSERT_TRUE(s.plotGhost);
    EXPECT_EQ(s.plotGhostOf, 2);
    EXPECT_EQ(shownPlotGhost(s, start), nullptr);

    // The drag moves Kq over several frames: the ghost stays the light before the drag.
    PointLight prev = start;
    for (float kq : {1.5f, 2.0f, 3.0f}) {
        PointLight const now = lightWithKq(kq);
        frame(s, true, prev, now);
        prev = now;
        PointLight const* ghost = shownPlotGhost(s, now);
        ASSERT_NE(ghost, nullptr);
        EXPECT_EQ(ghost->kq, 1.0f);
        EXPECT_EQ(lightRadius(*ghost).radius, lightRadius(start).radius);
        EXPECT_GT(lightRadius(*ghost).radius, lightRadius(now).radius);
    }
}

TEST(LightsPanelGhost, KeptAfterTheDragUntilTheLightChangesOtherwise) {
    LightsPanelState s;
    s.selected = 0;
    PointLight const start = lightWithKq(1.0f), dragged = lightWithKq(2.0f);
    frame(s, true, start, start);
    frame(s, true, start, dragged);  // the release frame still belongs to the drag
    frame(s, false, dragged, dragged);
    frame(s, false, dragged, dragged);
    ASSERT_NE(shownPlotGhost(s, dragged), nullptr);
    EXPECT_EQ(shownPlotGhost(s, dragged)->kq, 1.0f);

    // A position change (animation, the gizmo) does not touch the curve: the ghost stays.
    PointLight moved = dragged;
    moved.position.x += 1.0f;
    frame(s, false, dragged, moved);
    EXPECT_NE(shownPlotGhost(s, moved), nullptr);

    // Any other change of the curve (undo, a preset, a script) drops it.
    PointLight undone = moved;
    undone.kq = 1.0f;
    frame(s, false, moved, undone);
    EXPECT_FALSE(s.plotGhost);
    EXPECT_EQ(shownPlotGhost(s, undone), nullptr);
}

TEST(LightsPanelGhost, ANewDragStartsFromWhereTheLastOneEnded) {
    LightsPanelState s;
    s.selected = 0;
    PointLight const a = lightWithKq(1.0f), b = lightWithKq(2.0f), c = lightWithKq(4.0f);
    frame(s, true, a, b);
    frame(s, false, b, b);
    frame(s, true, b, c);
    ASSERT_NE(shownPlotGhost(s, c), nullptr);
    EXPECT_EQ(shownPlotGhost(s, c)->kq, 2.0f);
}

TEST(LightsPanelGhost, DroppedWhenAnotherLightIsSelected) {
    LightsPanelState s;
    s.selected = 0;
    PointLight const a = lightWithKq(1.0f), b = lightWithKq(2.0f);
    frame(s, true, a, b);
    frame(s, false, b, b);
    ASSERT_TRUE(s.plotGhost);
    s.selected = 1;
    EXPECT_EQ(shownPlotGhost(s, b), nullptr);  // not this light's, even before the next frame
    frame(s, false, b, b);
    EXPECT_FALSE(s.plotGhost);
}

TEST(LightsPanelGhost, EveryAttenuationInputCounts) {
    PointLight const base;
    EXPECT_TRUE(sameAttenuation(base, base));
    PointLight l = base;
    l.position = {1, 2, 3};
    l.name = "other";
    EXPECT_TRUE(sameAttenuation(base, l));
    for (char const* field : {"kc", "kl", "kq", "intensity", "threshold", "r", "g", "b"}) {
        PointLight changed = base;
        findLightField(field)->of(changed) += 0.5f;
        EXPECT_FALSE(sameAttenuation(base, changed)) << field;
    }
}
