// The declared passes of a frame: the feedback-loop check over every combination of settings, the
// check shown to fail on the wiring it replaced, the sequences of a few frames, stops and clears.
// What each pass draws into and samples, mode by mode: frame_pass_targets_test.
#include "frame_pass_checks.h"

#include "core/gbuffer_layout.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

using namespace gbl;
using namespace gbl::test;

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
