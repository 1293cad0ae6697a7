// The declared passes of a frame, mode by mode: what each draws into and samples. The overlays on
// the display image, forward+ and prepass, a viewer's own image, the glass, the read-backs. The
// loop check over every combination, sequences, stops and clears: frame_passes_test.
#include "frame_pass_checks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

using namespace gbl;
using namespace gbl::test;

TEST(FramePasses, OverlaysDrawOnTheDisplayAgainstTheSceneDepthAndLeaveTheLitImageTheLightSum) {
    // Issue 24: the cubes and wireframes used to draw into the lit image, so lighting.exr and the
    // light-by-light sum held them. Now only shading draws into the lit image; the overlays draw
    // into the display image, after the display pass, against the depth they tested before.
    for (std::size_t mode = 0; mode < kLightingModeNames.size(); ++mode)
        for (std::size_t copy = 0; copy < kDepthCopyNames.size(); ++copy) {
            PipelineSettings s;
            s.mode = LightingMode(mode);
            s.depthCopy = DepthCopy(copy);
            s.lightCubes = true;
            std::vector<PassDecl> const passes = framePasses(s, true);
            std::string const name = std::string(kLightingModeNames[mode]) + " " + std::string(kDepthCopyNames[copy]);
            ASSERT_GE(passes.size(), 3u) << name;
            EXPECT_EQ(passes[passes.size() - 3].id, PassId::Display) << name;
            PassDecl const& cubes = find(passes, PassId::LightCubes);
            PassDecl const& wires = find(passes, PassId::Wireframes);
            for (PassDecl const* p : {&cubes, &wires}) {
                EXPECT_EQ(p->color, std::vector<Resource>{Resource::Display}) << name << " " << p->name();
                EXPECT_TRUE(p->depthRead) << name << " " << p->name();
            }
            // The cubes test against the lit target's depth: the depth-copy step's copy of the scene
            // (none when it is off: they show through walls), or forward mode's own depth.
            EXPECT_EQ(cubes.depthStencil, Resource::LitDepth) << name;
            EXPECT_TRUE(cubes.depthWrite) << name;
            // The wireframes test against the scene's depth with or without the copy step.
            // The forward modes and prepass draw the scene's depth into the lit target themselves.
            bool const ownDepth = shadesForward(s.mode) || s.mode == LightingMode::Prepass;
            EXPECT_EQ(wires.depthStencil, ownDepth ? Resource::LitDepth : Resource::GBufferDepth) << name;
            EXPECT_FALSE(wires.depthWrite) << name;
            for (PassDecl const& p : passes) {
                bool const lit = std::find(p.color.begin(), p.color.end(), Resource::Lighting) != p.color.end();
                EXPECT_FALSE(lit && (p.id == PassId::LightCubes || p.id == PassId::Wireframes)) << name;
            }
        }
    // The G-buffer and count views show data, not the lit image: no overlays over them.
    PipelineSettings s;
    s.view = DebugView::Normal;
    s.lightCubes = true;
    EXPECT_EQ(names(framePasses(s, true)),
              (std::vector<std::string>{"geometry", "lighting", "depth_copy", "forward", "display"}));
}

TEST(FramePasses, ForwardPlusIsADepthPrepassTheTiledListsAndAForwardPassAtThatDepth) {
    PipelineSettings s;
    s.mode = LightingMode::ForwardPlus;
    s.lightCubes = false;
    s.accumulation = LightAccumulation::Split;  // refused, as forward refuses it: no G-buffer to combine
    std::vector<PassDecl> const passes = framePasses(s, false);
    EXPECT_EQ(names(passes),
              (std::vector<std::string>{"depth_prepass", "light_lists", "forward_shading", "forward", "display"}));
    PassDecl const& pre = find(passes, PassId::DepthPrepass);
    EXPECT_EQ(pre.color, std::vector<Resource>{Resource::Lighting});
    EXPECT_EQ(pre.depthStencil, Resource::LitDepth);
    ASSERT_EQ(pre.states.size(), 2u);  // single-sided, double-sided materials
    EXPECT_EQ(pre.states[1].cull, FaceCull::Off);
    for (DrawState const& state : pre.states) {
        EXPECT_FALSE(state.colorWrite);
        EXPECT_TRUE(state.depthWrite);
        EXPECT_EQ(state.depthTest, DepthTest::Less);
    }
    // No G-buffer: every attachment cleared, so the viewers show it unused.
    for (Resource r : {Resource::GBufferPosition, Resource::GBufferNormal, Resource::GBufferDepth, Resource::Lighting,
                       Resource::LitDepth, Resource::DiffuseLight})
        EXPECT_NE(std::find(pre.clears.begin(), pre.clears.end(), r), pre.clears.end()) << resourceName(r);
    // The lists are binned from the pre-pass depth, and the shading reads them.
    PassDecl const& lists = find(passes, PassId::LightLists);
    EXPECT_EQ(lists.kind, PassKind::Compute);
    EXPECT_EQ(lists.samples.front(), Resource::LitDepth);
    EXPECT_EQ(lists.writes, std::vector<Resource>{Resource::TileBins});
    PassDecl const& shading = find(passes, PassId::ForwardShading);
    EXPECT_NE(std::find(shading.samples.begin(), shading.samples.end(), Resource::TileBins), shading.samples.end());
    ASSERT_EQ(shading.states.size(), 2u);
    for (DrawState const& state : shading.states) {
        EXPECT_EQ(state.depthTest, DepthTest::LessEqual);
        EXPECT_FALSE(state.depthWrite);
    }
    EXPECT_TRUE(countsAsLighting(PassId::DepthPrepass));
    EXPECT_TRUE(feedbackLoops(passes).empty());
    // The blended surfaces read the lists too (their own, binned from the near plane); forward's do not.
    PassDecl const& blended = find(passes, PassId::Forward);
    EXPECT_NE(std::find(blended.samples.begin(), blended.samples.end(), Resource::TileBins), blended.samples.end());
    PipelineSettings f = s;
    f.mode = LightingMode::Forward;
    std::vector<PassDecl> const forwardPasses = framePasses(f, false);
    PassDecl const& forwardBlended = find(forwardPasses, PassId::Forward);
    EXPECT_EQ(std::find(forwardBlended.samples.begin(), forwardBlended.samples.end(), Resource::TileBins),
              forwardBlended.samples.end());
    // Its heat views count the frame's own lists over the pre-pass depth.
    s.view = DebugView::Heatmap;
    std::vector<PassDecl> const heat = framePasses(s, false);
    PassDecl const& counts = find(heat, PassId::Coverage);
    EXPECT_EQ(counts.kind, PassKind::Compute);
    EXPECT_EQ(counts.samples.front(), Resource::LitDepth);
}

TEST(FramePasses, PrepassIsAThinGBufferALightPassAndASecondGeometryPass) {
    PipelineSettings s;
    s.mode = LightingMode::Prepass;
    s.lightCubes = false;
    s.accumulation = LightAccumulation::Split;  // ignored: prepass always sums into the two light targets
    std::vector<PassDecl> const passes = framePasses(s, false);
    EXPECT_EQ(names(passes),
              (std::vector<std::string>{"prepass_geometry", "lighting", "prepass_shading", "forward", "display"}));
    // The thin G-buffer: normal and exponent, with the lit target's depth, written and tested.
    PassDecl const& thin = find(passes, PassId::ThinGBuffer);
    EXPECT_EQ(thin.color, std::vector<Resource>{Resource::PrepassNormal});
    EXPECT_EQ(thin.depthStencil, Resource::LitDepth);
    ASSERT_EQ(thin.states.size(), 2u);  // single-sided, double-sided materials
    EXPECT_EQ(thin.states[0].cull, FaceCull::Back);
    EXPECT_EQ(thin.states[1].cull, FaceCull::Off);
    for (DrawState const& state : thin.states) {
        EXPECT_TRUE(state.depthWrite);
        EXPECT_EQ(state.depthTest, DepthTest::Less);
    }
    // The layout's G-buffer is not drawn: cleared, so its viewers show it unused.
    for (Resource r : {Resource::GBufferPosition, Resource::GBufferNormal, Resource::GBufferAlbedoSpec,
                       Resource::GBufferDepth, Resource::PrepassNormal, Resource::LitDepth, Resource::Lighting})
        EXPECT_NE(std::find(thin.clears.begin(), thin.clears.end(), r), thin.clears.end()) << resourceName(r);
    // The light pass reads the thin G-buffer and its depth, and writes the two light targets.
    PassDecl const& light = find(passes, PassId::Lighting);
    EXPECT_EQ(light.samples, (std::vector<Resource>{Resource::PrepassNormal, Resource::LitDepth, Resource::Lights}));
    EXPECT_EQ(light.color, (std::vector<Resource>{Resource::DiffuseLight, Resource::SpecularLight}));
    EXPECT_EQ(light.clears, light.color);
    EXPECT_FALSE(light.depthStencil.has_value());  // the depth is sampled, so it cannot be attached
    // The second geometry pass reads the light at its pixel, tested against the thin depth.
    PassDecl const& shading = find(passes, PassId::PrepassShading);
    EXPECT_EQ(shading.color, std::vector<Resource>{Resource::Lighting});
    EXPECT_EQ(shading.depthStencil, Resource::LitDepth);
    EXPECT_NE(std::find(shading.samples.begin(), shading.samples.end(), Resource::DiffuseLight), shading.samples.end());
    ASSERT_EQ(shading.states.size(), thin.states.size());
    for (std::size_t i = 0; i < shading.states.size(); ++i) {
        EXPECT_EQ(shading.states[i].cull, thin.states[i].cull);
        EXPECT_EQ(shading.states[i].depthTest, DepthTest::LessEqual);
        EXPECT_FALSE(shading.states[i].depthWrite);
    }
    EXPECT_TRUE(countsAsLighting(PassId::PrepassShading));
    EXPECT_TRUE(feedbackLoops(passes).empty());
    // An imported G-buffer has no meshes to draw twice: the quad pass lights it.
    std::string why;
    EXPECT_EQ(importedSettings(s, &why).mode, LightingMode::Quad);
    EXPECT_EQ(why, "prepass draws the scene's meshes twice and an imported G-buffer has none, so the quad pass ran");
}

// drawView's list: a count view recounts (after the volumes' depth copy where the layout has one),
// then the view pass draws into the view's own image, never the display.
TEST(FramePasses, AViewRecountsThenDrawsIntoItsOwnImage) {
    PipelineSettings s;
    s.mode = LightingMode::Volumes;
    s.layout = GBufferLayout::Packed;
    s.view = DebugView::Heatmap;
    std::vector<PassDecl> const heat = viewPasses(s);
    EXPECT_EQ(names(heat), (std::vector<std::string>{"volume_depth", "coverage", "display"}));
    EXPECT_EQ(heat.back().color, std::vector<Resource>{Resource::View});
    s.view = DebugView::Normal;
    EXPECT_EQ(names(viewPasses(s)), std::vector<std::string>{"display"});
    EXPECT_TRUE(feedbackLoops(heat).empty());
}

// Blended surfaces go forward: the forward pass comes after lighting and the depth copy, blends
// alpha over the lit image depth-tested against the lit target's depth without writing it; the glass
// outline, when asked for, hatches over the display (any view) and over a viewer's own image.
TEST(FramePasses, TheGlassGoesForwardAfterLightingAndTheOutlineOverEveryView) {
    PipelineSettings s;
    std::vector<std::string> const n = names(framePasses(s));
    auto const at = [&](char const* name) { return std::find(n.begin(), n.end(), name) - n.begin(); };
    EXPECT_LT(at("lighting"), at("depth_copy"));
    EXPECT_LT(at("depth_copy"), at("forward"));
    EXPECT_LT(at("forward"), at("display"));
    PassDecl const forward = find(framePasses(s), PassId::Forward);
    EXPECT_EQ(forward.color, std::vector{Resource::Lighting});
    EXPECT_EQ(forward.depthStencil, Resource::LitDepth);
    EXPECT_TRUE(forward.depthRead);
    EXPECT_FALSE(forward.depthWrite);
    ASSERT_EQ(forward.states.size(), 2u);  // single-sided, double-sided (the panes are double-sided)
    for (DrawState const& state : forward.states) {
        EXPECT_EQ(state.blend, Blend::Alpha);
        EXPECT_EQ(state.depthTest, DepthTest::Less);
        EXPECT_FALSE(state.depthWrite);
    }
    EXPECT_EQ(forward.states[1].cull, FaceCull::Off);
    EXPECT_EQ(std::count(n.begin(), n.end(), "glass_outline"), 0) << "off by default";
    s.glassOutline = true;
    s.view = DebugView::Albedo;  // a view without the overlays still gets the outline
    std::vector<PassDecl> const frame = framePasses(s);
    EXPECT_EQ(frame.back().id, PassId::GlassOutline);
    EXPECT_EQ(frame.back().color, std::vector{Resource::Display});
    std::vector<PassDecl> const view = viewPasses(s);
    EXPECT_EQ(view.back().id, PassId::GlassOutline);
    EXPECT_EQ(view.back().color, std::vector{Resource::View});
    EXPECT_TRUE(feedbackLoops(frame).empty());
}

// The browser's read-backs (renderer_readback.cpp): the depth one samples the G-buffer's depth into
// the read-back target; the stencil one attaches that depth-stencil without sampling it (no feedback
// loop) and has one additive group per bit plane, testing exactly that bit.
TEST(FramePasses, TheReadbacksAreDeclaredWithOneGroupPerStencilBit) {
    PassDecl const depth = readbackPass(false);
    EXPECT_EQ(depth.name(), "readback_depth");
    EXPECT_EQ(depth.samples, std::vector<Resource>{Resource::GBufferDepth});
    EXPECT_EQ(depth.color, std::vector<Resource>{Resource::Readback});
    EXPECT_FALSE(depth.depthStencil.has_value());
    ASSERT_EQ(depth.states.size(), 1u);
    EXPECT_EQ(depth.states[0].stencil, StencilUse::Off);

    PassDecl const stencil = readbackPass(true);
    EXPECT_EQ(stencil.name(), "readback_stencil");
    EXPECT_TRUE(stencil.samples.empty());
    EXPECT_EQ(stencil.depthStencil, Resource::GBufferDepth);
    EXPECT_TRUE(stencil.stencilRead);
    EXPECT_FALSE(stencil.stencilWrite);
    ASSERT_EQ(stencil.states.size(), 8u);
    for (int bit = 0; bit < 8; ++bit) {
        DrawState const& s = stencil.states[std::size_t(bit)];
        EXPECT_EQ(s.stencil, StencilUse::EqualBits) << bit;
        EXPECT_EQ(s.stencilRef, 1 << bit) << bit;
        EXPECT_EQ(s.blend, Blend::Add) << bit;  // the bit planes' constants are summed
        EXPECT_EQ(s.depthTest, DepthTest::Off) << bit;
        EXPECT_FALSE(s.depthWrite) << bit;
    }
    std::vector<PassDecl> const both{depth, stencil};
    EXPECT_TRUE(feedbackLoops(both).empty());
}

// The light cubes mark their pixels in the lit depth's stencil, then the blended surfaces are drawn
// over them there (docs/transparency.md): three groups, the cubes' first.
TEST(FramePasses, TheLightCubesDrawTheGlassOverThemselves) {
    PipelineSettings s;
    s.lightCubes = true;
    std::vector<PassDecl> const passes = framePasses(s, false);
    PassDecl const& cubes = find(passes, PassId::LightCubes);
    ASSERT_EQ(cubes.states.size(), 3u);
    EXPECT_EQ(cubes.states[0].stencil, StencilUse::MarkCovered);
    EXPECT_TRUE(cubes.states[0].depthWrite);
    EXPECT_EQ(cubes.states[0].blend, Blend::Off);
    for (std::size_t i : {1u, 2u}) {
        EXPECT_EQ(cubes.states[i].stencil, StencilUse::Covered);
        EXPECT_EQ(cubes.states[i].blend, Blend::Alpha);
        EXPECT_EQ(cubes.states[i].depthTest, DepthTest::Less);
        EXPECT_FALSE(cubes.states[i].depthWrite);
    }
    EXPECT_EQ(cubes.states[2].cull, FaceCull::Off);  // double-sided glass
    EXPECT_TRUE(cubes.stencilRead && cubes.stencilWrite);
    EXPECT_EQ(cubes.depthStencil, Resource::LitDepth);
    EXPECT_NE(std::find(cubes.samples.begin(), cubes.samples.end(), Resource::Materials), cubes.samples.end());
    EXPECT_TRUE(feedbackLoops(passes).empty());
}
