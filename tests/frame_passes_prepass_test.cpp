// prepass's declared passes with `prepass_lights: volumes` (core/frame_passes_prepass.cpp): a copy of
// the thin depth-stencil, then a light pass with the volumes' states of each cull mode over it, and
// no feedback loop in any layout, cull mode or view.
#include "core/frame_passes.h"
#include "core/pipeline_fields.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

using namespace gbl;

namespace {

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

PipelineSettings prepassVolumes(CullMode cull) {
    PipelineSettings s;
    s.mode = LightingMode::Prepass;
    s.prepassLights = PrepassLights::Volumes;
    s.cull = cull;
    s.lightCubes = false;
    return s;
}

}  // namespace

TEST(FramePassesPrepass, TheVolumesLightPassTestsACopyOfTheThinDepthWithTheCullModesStates) {
    for (std::size_t cull = 0; cull < kCullModeNames.size(); ++cull) {
        PipelineSettings const s = prepassVolumes(CullMode(cull));
        std::vector<PassDecl> const passes = framePasses(s);
        ASSERT_EQ(names(passes), (std::vector<std::string>{"prepass_geometry", "volume_depth", "lighting",
                                                           "prepass_shading", "forward", "display"}))
            << kCullModeNames[cull];
        PassDecl const& copy = passes[1];
        EXPECT_EQ(copy.kind, PassKind::Blit);
        EXPECT_EQ(copy.samples, std::vector<Resource>{Resource::LitDepth});
        EXPECT_EQ(copy.depthStencil, Resource::VolumeDepth);
        PassDecl const& light = passes[2];
        EXPECT_EQ(light.samples, (std::vector<Resource>{Resource::PrepassNormal, Resource::LitDepth, Resource::Lights,
                                                        Resource::VolumeInstances}));
        EXPECT_EQ(light.color, (std::vector<Resource>{Resource::DiffuseLight, Resource::SpecularLight}));
        EXPECT_EQ(light.clears, light.color);
        EXPECT_EQ(light.depthStencil, Resource::VolumeDepth);
        EXPECT_EQ(light.depthRead, CullMode(cull) != CullMode::None);
        EXPECT_EQ(light.stencilWrite, CullMode(cull) == CullMode::Stencil);
        // The directional lights full screen (no blending: the first write after the clear), then the
        // volumes mode's own groups for this cull mode, every one added.
        PipelineSettings volumes = s;
        volumes.mode = LightingMode::Volumes;
        std::vector<PassDecl> const volumesPasses = framePasses(volumes);
        std::vector<DrawState> const& own = find(volumesPasses, PassId::Lighting).states;
        ASSERT_EQ(light.states.size(), own.size());
        EXPECT_EQ(light.states[0].what, "directional lights");
        EXPECT_EQ(light.states[0].blend, Blend::Off);
        for (std::size_t g = 1; g < own.size(); ++g) EXPECT_EQ(light.states[g], own[g]) << kCullModeNames[cull];
    }
    // Full screen (the default): the one draw, no copy.
    PipelineSettings s = prepassVolumes(CullMode::Front);
    s.prepassLights = PrepassLights::Quad;
    EXPECT_EQ(names(framePasses(s)),
              (std::vector<std::string>{"prepass_geometry", "lighting", "prepass_shading", "forward", "display"}));
}

TEST(FramePassesPrepass, NoVolumesFrameSamplesWhatItDrawsInto) {
    int frames = 0;
    for (std::size_t layout = 0; layout < kGBufferLayoutNames.size(); ++layout)
        for (std::size_t cull = 0; cull < kCullModeNames.size(); ++cull)
            for (DebugView view : {DebugView::Final, DebugView::Heatmap, DebugView::TileLights})
                for (bool overlays : {false, true}) {
                    PipelineSettings s = prepassVolumes(CullMode(cull));
                    s.layout = GBufferLayout(layout);
                    s.view = view;
                    s.lightCubes = s.volumeWireframes = overlays;
                    for (FeedbackLoop const& l : feedbackLoops(framePasses(s)))
                        ADD_FAILURE() << kGBufferLayoutNames[layout] << " " << kCullModeNames[cull] << ": "
                                      << passName(l.pass) << " samples " << resourceName(l.resource);
                    ++frames;
                }
    EXPECT_EQ(frames, 4 * 5 * 3 * 2);
}

// The setting: its session key, option and names, greyed out outside prepass; the cull mode and the
// volume scale apply to prepass with volumes too.
TEST(FramePassesPrepass, ThePrepassLightsSettingAndTheCullModeApplyWhereVolumesAreDrawn) {
    PipelineField const* f = findPipelineField("prepass_lights");
    ASSERT_NE(f, nullptr);
    EXPECT_EQ(f->option, "--prepass-lights");
    EXPECT_TRUE(f->optionalInFiles);  // sessions written before it keep loading
    EXPECT_EQ(parseFieldValue(*f, "volumes"), 1.0);
    EXPECT_FALSE(parseFieldValue(*f, "spheres"));
    PipelineSettings s;
    EXPECT_FALSE(f->appliesTo(s));
    s.mode = LightingMode::Prepass;
    EXPECT_TRUE(f->appliesTo(s));
    EXPECT_FALSE(findPipelineField("cull")->appliesTo(s));
    s.prepassLights = PrepassLights::Volumes;
    EXPECT_TRUE(findPipelineField("cull")->appliesTo(s));
    EXPECT_TRUE(findPipelineField("volume_scale")->appliesTo(s));
    EXPECT_TRUE(drawsLightVolumes(s));
    s.mode = LightingMode::Quad;  // the setting is prepass's alone
    EXPECT_FALSE(drawsLightVolumes(s));
}
