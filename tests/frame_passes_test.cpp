// The declared passes of a frame: the feedback-loop check over every combination of settings, the
// check shown to fail on the wiring it replaced, and the sequences of a few frames.
#include "core/frame_passes.h"

#include "core/gbuffer_layout.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

using namespace gbl;

namespace {

std::string describe(std::vector<FeedbackLoop> const& loops) {
    std::string out;
    for (FeedbackLoop const& l : loops)
        out += std::string(passName(l.pass)) + " samples " + std::string(resourceName(l.resource)) + "; ";
    return out;
}

std::vector<std::string> names(std::vector<PassDecl> const& passes) {
    std::vector<std::string> out;
    for (PassDecl const& p : passes) out.emplace_back(p.name());
    return out;
}

PassDecl const& find(std::vector<PassDecl> const& passes, PassId id) {
    for (PassDecl const& p : passes)
        if (p.id == id) return p;
    throw std::runtime_error("no pass " + std::string(passName(id)));
}

}  // namespace

TEST(FramePasses, NoCombinationSamplesWhatItDrawsInto) {
    int frames = 0;
    for (std::size_t mode = 0; mode < kLightingModeNames.size(); ++mode)
        for (std::size_t layout = 0; layout < kGBufferLayoutNames.size(); ++layout)
            for (std::size_t cull = 0; cull < kCullModeNames.size(); ++cull)
                for (std::size_t acc = 0; acc < kLightAccumulationNames.size(); ++acc)
                    for (std::size_t copy = 0; copy < kDepthCopyNames.size(); ++copy)
                        for (DebugView view :  // the overlays are drawn on the first two only
                             {DebugView::Final, DebugView::Lighting, DebugView::Heatmap, DebugView::TileLights})
                            for (bool overlays : {false, true})
                                for (bool imported : {false, true}) {
                                    PipelineSettings s;
                                    s.mode = LightingMode(mode);
                                    s.layout = GBufferLayout(layout);
                                    s.cull = CullMode(cull);
                                    s.accumulation = LightAccumulation(acc);
                                    s.depthCopy = DepthCopy(copy);
                                    s.view = view;
                                    s.lightCubes = s.volumeWireframes = overlays;
                                    if (imported) s = importedSettings(s);
                                    auto const passes = framePasses(s, s.volumeWireframes, imported);
                                    EXPECT_EQ(describe(feedbackLoops(passes)), "")
                                        << kLightingModeNames[mode] << " " << kGBufferLayoutNames[layout] << " "
                                        << kCullModeNames[cull] << " " << kLightAccumulationNames[acc] << " "
                                        << kDepthCopyNames[copy] << (imported ? " imported" : "");
                                    ++frames;
                                }
    EXPECT_EQ(frames, int(kLightingModeNames.size()) * 4 * 5 * 2 * 3 * 4 * 2 * 2);
}

// Re-lighting an imported G-buffer: the import pass writes the layout's targets in the geometry
// pass's place, no scene is drawn (no blended forward pass), forward mode becomes the quad pass and
// the light cubes go, each with its reason.
TEST(FramePasses, AnImportedFrameRunsTheImportPassInsteadOfTheGeometry) {
    PipelineSettings s;
    s.layout = GBufferLayout::Packed;
    s.mode = LightingMode::Volumes;
    auto const passes = framePasses(importedSettings(s), false, true);
    EXPECT_EQ(names(passes), (std::vector<std::string>{"import", "volume_depth", "lighting", "depth_copy", "display"}));
    PassDecl const& imp = find(passes, PassId::Import);
    EXPECT_EQ(imp.samples, std::vector<Resource>{Resource::Imported});
    EXPECT_EQ(imp.color, (std::vector<Resource>{Resource::GBufferNormal, Resource::GBufferAlbedoSpec}));
    EXPECT_EQ(imp.depthStencil, Resource::GBufferDepth);
    ASSERT_EQ(imp.states.size(), 1u);
    EXPECT_EQ(imp.states[0].depthTest, DepthTest::Always);
    EXPECT_TRUE(imp.states[0].depthWrite);
    std::string why;
    s.mode = LightingMode::Forward;
    s.lightCubes = true;
    PipelineSettings const r = importedSettings(s, &why);
    EXPECT_EQ(r.mode, LightingMode::Quad);
    EXPECT_FALSE(r.lightCubes);
    EXPECT_NE(why.find("forward shading draws the scene's meshes"), std::string::npos) << why;
    EXPECT_NE(why.find("light cubes"), std::string::npos) << why;
}

TEST(FramePasses, TheOldVolumeWiringIsALoop) {
    // Before the volume depth copy: in the layouts that rebuild position, the volumes pass sampled
    // the G-buffer's depth (to rebuild position) while that texture was volumeFbo's depth-stencil,
    // and in stencil cull it also wrote its stencil.
    for (GBufferLayout layout : {GBufferLayout::Packed, GBufferLayout::Naive8, GBufferLayout::Rgb10a2}) {
        PipelineSettings s;
        s.mode = LightingMode::Volumes;
        s.cull = CullMode::Stencil;
        s.layout = layout;
        s.view = DebugView::Heatmap;
        std::vector<PassDecl> old = framePasses(s);
        std::erase_if(old, [](PassDecl const& p) { return p.id == PassId::VolumeDepth; });
        for (PassDecl& p : old)
            if (p.depthStencil == Resource::VolumeDepth) p.depthStencil = Resource::GBufferDepth;
        EXPECT_EQ(feedbackLoops(old), (std::vector<FeedbackLoop>{{PassId::Lighting, Resource::GBufferDepth},
                                                                 {PassId::Coverage, Resource::GBufferDepth}}))
            << kGBufferLayoutNames[std::size_t(layout)];
    }
}

TEST(FramePasses, ALoopInAnyPassIsReported) {
    // A colour attachment sampled (the lit image read while drawn into), and a blit whose source is
    // its own destination; a compute pass has no framebuffer, so it cannot loop.
    PassDecl raster;
    raster.id = PassId::Forward;
    raster.samples = {Resource::Lights, Resource::Lighting};
    raster.color = {Resource::Lighting};
    PassDecl blit;
    blit.id = PassId::DepthCopy;
    blit.kind = PassKind::Blit;
    blit.samples = {Resource::LitDepth};
    blit.depthStencil = Resource::LitDepth;
    PassDecl compute;
    compute.id = PassId::Lighting;
    compute.kind = PassKind::Compute;
    compute.samples = {Resource::Lighting};
    compute.writes = {Resource::Lighting};
    std::vector<PassDecl> const passes{raster, blit, compute};
    EXPECT_EQ(feedbackLoops(passes), (std::vector<FeedbackLoop>{{PassId::Forward, Resource::Lighting},
                                                                {PassId::DepthCopy, Resource::LitDepth}}));
}

TEST(FramePasses, VolumesCopyDepthOnlyWhereTheLightingSamplesIt) {
    PipelineSettings s;
    s.mode = LightingMode::Volumes;
    s.lightCubes = false;
    EXPECT_EQ(names(framePasses(s)),
              (std::vector<std::string>{"geometry", "lighting", "depth_copy", "forward", "display"}));
    EXPECT_EQ(find(framePasses(s), PassId::Lighting).depthStencil, Resource::GBufferDepth);
    s.layout = GBufferLayout::Packed;
    auto const packed = framePasses(s);
    EXPECT_EQ(names(packed),
              (std::vector<std::string>{"geometry", "volume_depth", "lighting", "depth_copy", "forward", "display"}));
    EXPECT_EQ(find(packed, PassId::Lighting).depthStencil, Resource::VolumeDepth);
    EXPECT_EQ(find(packed, PassId::VolumeDepth).samples, std::vector<Resource>{Resource::GBufferDepth});
}

TEST(FramePasses, SequencesFollowTheSettings) {
    PipelineSettings s;  // quad, cubes on
    EXPECT_EQ(names(framePasses(s)),
              (std::vector<std::string>{"geometry", "lighting", "depth_copy", "forward", "display", "light_cubes"}));
    s.mode = LightingMode::Tiled;
    s.accumulation = LightAccumulation::Split;
    s.view = DebugView::Lighting;
    EXPECT_EQ(names(framePasses(s, true)),
              (std::vector<std::string>{"geometry", "light_lists", "lighting", "light_combine", "depth_copy", "forward",
                                        "display", "light_cubes", "wireframes"}));
    s.view = DebugView::Heatmap;  // a view of counts, not of the lit image: no overlays on it
    EXPECT_EQ(names(framePasses(s, true)),
              (std::vector<std::string>{"geometry", "light_lists", "lighting", "light_combine", "depth_copy", "forward",
                                        "coverage", "display"}));
    s.mode = LightingMode::Forward;  // split is refused there
    s.view = DebugView::Final;
    s.lightCubes = false;
    EXPECT_EQ(names(framePasses(s)), (std::vector<std::string>{"forward_shading", "forward", "display"}));
}

TEST(FramePasses, EachPassDeclaresItsStateAndTheStencilCullMarksTheStencil) {
    PipelineSettings s;
    s.mode = LightingMode::Volumes;
    s.cull = CullMode::Stencil;
    PassDecl const lighting = find(framePasses(s), PassId::Lighting);
    EXPECT_TRUE(lighting.stencilRead && lighting.stencilWrite);
    EXPECT_FALSE(lighting.depthWrite);
    ASSERT_EQ(lighting.states.size(), 3u);  // ambient, mark, shade
    EXPECT_EQ(lighting.states[1].stencil, StencilUse::Mark);
    EXPECT_FALSE(lighting.states[1].colorWrite);
    EXPECT_EQ(lighting.states[2].blend, Blend::Add);
    s.cull = CullMode::Front;
    PassDecl const front = find(framePasses(s), PassId::Lighting);
    EXPECT_FALSE(front.stencilWrite);
    EXPECT_EQ(front.states.back().depthTest, DepthTest::GreaterEqual);
    EXPECT_EQ(front.states.back().cull, FaceCull::Front);
}

TEST(FramePasses, NamesRoundTripAndLightingWorkIsDeclared) {
    for (std::size_t i = 0; i < kPassNames.size(); ++i) EXPECT_EQ(passFromName(kPassNames[i]), PassId(i));
    EXPECT_EQ(passFromName("viewers"), std::nullopt);  // the editor's own timer, not a frame pass
    EXPECT_TRUE(countsAsLighting(PassId::LightLists));
    EXPECT_TRUE(countsAsLighting(PassId::ForwardShading));
    EXPECT_FALSE(countsAsLighting(PassId::Geometry));
    EXPECT_FALSE(countsAsLighting(PassId::Display));
}

TEST(FramePasses, StoppingKeepsThePassesUpToTheStopThenTheDisplay) {
    PipelineSettings s;
    s.mode = LightingMode::Volumes;
    s.lightCubes = true;
    std::vector<PassDecl> const all = framePasses(s, false);
    EXPECT_EQ(names(passesUntil(all, PassId::Geometry)), (std::vector<std::string>{"geometry", "display"}));
    EXPECT_EQ(names(passesUntil(all, PassId::Lighting)), (std::vector<std::string>{"geometry", "lighting", "display"}));
    // The overlays follow the display pass: stopping after it leaves them out, after one keeps the display.
    EXPECT_EQ(names(passesUntil(all, PassId::Display)),
              (std::vector<std::string>{"geometry", "lighting", "depth_copy", "forward", "display"}));
    EXPECT_EQ(passesUntil(all, PassId::LightCubes), all);
    EXPECT_EQ(passesUntil(all, PassId::Wireframes), all) << "a pass the frame does not run stops nothing";
    std::vector<PassDecl> const wired = framePasses(s, true);
    EXPECT_EQ(names(passesUntil(wired, PassId::LightCubes)),
              (std::vector<std::string>{"geometry", "lighting", "depth_copy", "forward", "display", "light_cubes"}));
}

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

TEST(FramePasses, AStopOutsideTheFrameIsOneSentenceNamingItsPasses) {
    PipelineSettings s;
    s.lightCubes = false;
    std::vector<PassDecl> const all = framePasses(s, false);
    EXPECT_EQ(stopAfterError("lighting", all), std::nullopt);
    EXPECT_EQ(stopAfterError("light_lists", all),
              "cannot stop after 'light_lists': this frame does not run it; this frame's passes are geometry, "
              "lighting, depth_copy, forward and display");
    std::optional<std::string> const unknown = stopAfterError("tonemap", all);
    ASSERT_TRUE(unknown);
    EXPECT_NE(unknown->find("no pass has that name"), std::string::npos) << *unknown;
    EXPECT_EQ(unknown->find('\n'), std::string::npos) << *unknown;
}

// The clears are declared with the pass they precede (the executor does them): each target a pass
// overwrites only in part, the unused G-buffer of a forward frame, the light targets of a frame that
// does not split (an earlier split frame's sums would show in its views), and, in a stopped frame,
// what the skipped passes would have drawn.
TEST(FramePasses, ClearsAreDeclaredWithThePassTheyPrecede) {
    PipelineSettings s;
    s.mode = LightingMode::Quad;
    std::vector<PassDecl> const quad = framePasses(s);
    EXPECT_EQ(find(quad, PassId::Geometry).clears,
              (std::vector<Resource>{Resource::GBufferPosition, Resource::GBufferNormal, Resource::GBufferAlbedoSpec,
                                     Resource::GBufferEmissive, Resource::GBufferDepth, Resource::DiffuseLight,
                                     Resource::SpecularLight}));
    EXPECT_EQ(find(quad, PassId::Lighting).clears, std::vector<Resource>{Resource::Lighting});
    EXPECT_EQ(find(quad, PassId::DepthCopy).clears, std::vector<Resource>{Resource::LitDepth});
    EXPECT_TRUE(find(quad, PassId::Display).clears.empty());

    s.accumulation = LightAccumulation::Split;
    std::vector<PassDecl> const split = framePasses(s);
    EXPECT_EQ(find(split, PassId::Lighting).clears,
              (std::vector<Resource>{Resource::DiffuseLight, Resource::SpecularLight}));
    EXPECT_EQ(find(split, PassId::Geometry).clears.size(), 5u) << "the split frame keeps its light targets";

    s.mode = LightingMode::Forward;  // no G-buffer: cleared, so its views show it unused
    std::vector<PassDecl> const forwardFrame = framePasses(s);
    PassDecl const& forward = find(forwardFrame, PassId::ForwardShading);
    for (Resource r : {Resource::GBufferNormal, Resource::GBufferDepth, Resource::Lighting, Resource::LitDepth,
                       Resource::DiffuseLight})
        EXPECT_NE(std::find(forward.clears.begin(), forward.clears.end(), r), forward.clears.end()) << resourceName(r);

    s.mode = LightingMode::Volumes;
    s.accumulation = LightAccumulation::Single;
    std::vector<PassDecl> const stopped = passesUntil(framePasses(s), PassId::Geometry);
    PassDecl const& first = stopped.front();
    for (Resource r : {Resource::Lighting, Resource::LitDepth, Resource::SpecularLight, Resource::Coverage})
        EXPECT_NE(std::find(first.clears.begin(), first.clears.end(), r), first.clears.end()) << resourceName(r);
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
