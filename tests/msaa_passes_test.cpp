// The msaa volumes' declared passes (docs/msaa.md): the volumes light the single-sample lit image over
// its depth-stencil, once per draw group whatever the sample count, and edges and per-sample share
// the complex pixels' draws, which test no depth.
#include "core/frame_passes.h"
#include "core/msaa.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

using namespace gbl;

namespace {

PipelineSettings volumes(Msaa msaa, MsaaLighting lighting, CullMode cull,
                         GBufferLayout layout = GBufferLayout::Classic) {
    PipelineSettings s;
    s.mode = LightingMode::Volumes;
    s.msaa = msaa;
    s.msaaLighting = lighting;
    s.cull = cull;
    s.layout = layout;
    s.lightCubes = false;
    return s;
}

std::vector<std::string> names(std::vector<PassDecl> const& passes) {
    std::vector<std::string> out;
    for (PassDecl const& p : passes) out.emplace_back(p.name());
    return out;
}

PassDecl lighting(PipelineSettings const& s) {
    for (PassDecl const& p : framePasses(s, false))
        if (p.id == PassId::Lighting) return p;
    ADD_FAILURE() << "no lighting pass";
    return {};
}

std::vector<DrawState> kept(std::vector<DrawState> const& states, MsaaPixels pixels) {
    std::vector<DrawState> out;
    std::copy_if(states.begin(), states.end(), std::back_inserter(out),
                 [&](DrawState const& d) { return d.pixels == pixels; });
    return out;
}

constexpr CullMode kCulls[] = {CullMode::Back, CullMode::Front, CullMode::None, CullMode::Flip, CullMode::Stencil};

}  // namespace

// The multisampled depth resolved into the lit target's depth (its stencil keeps msaa_edges' complex
// bit), the volumes drawn there, and no multisampled lit image to resolve, in every layout.
TEST(MsaaPassesTest, VolumesLightTheSingleSampleLitImageOverTheResolvedDepth) {
    for (GBufferLayout layout : {GBufferLayout::Classic, GBufferLayout::Packed})
        for (MsaaLighting l : {MsaaLighting::PerSample, MsaaLighting::Edges}) {
            std::vector<PassDecl> const passes = framePasses(volumes(Msaa::X4, l, CullMode::Stencil, layout), false);
            EXPECT_EQ(names(passes), (std::vector<std::string>{"geometry", "msaa_edges", "volume_depth", "lighting",
                                                               "msaa_resolve", "depth_copy", "forward", "display"}));
            PassDecl const& depth = passes[2];
            EXPECT_EQ(depth.samples, std::vector{Resource::MsaaDepth});
            EXPECT_EQ(depth.depthStencil, Resource::LitDepth);
            EXPECT_TRUE(depth.depthWrite);
            EXPECT_FALSE(depth.stencilWrite) << "the complex bit stays";
            PassDecl const& lit = passes[3];
            EXPECT_EQ(lit.color, std::vector{Resource::Lighting});
            EXPECT_EQ(lit.depthStencil, Resource::LitDepth);
            EXPECT_TRUE(lit.stencilRead);
            EXPECT_TRUE(feedbackLoops(passes).empty());
        }
}

// Each group drawn once, whatever the sample count (the shader loops over the samples); the simple
// pixels' groups are the msaa off frame's volume groups, depth-tested, and the complex pixels' the
// faces of msaaComplexCull with no depth test, the same in both strategies.
TEST(MsaaPassesTest, VolumesDrawEachGroupOnceAndBothStrategiesShareTheComplexDraws) {
    for (CullMode cull : kCulls) {
        std::string const what(enumName(kCullModeNames, cull));
        std::vector<DrawState> off = lighting(volumes(Msaa::Off, MsaaLighting::Edges, cull)).states;
        off.erase(off.begin());  // the ambient term
        std::vector<DrawState> const edges = lighting(volumes(Msaa::X4, MsaaLighting::Edges, cull)).states;
        std::vector<DrawState> const perSample = lighting(volumes(Msaa::X4, MsaaLighting::PerSample, cull)).states;
        for (Msaa n : {Msaa::X2, Msaa::X8}) {
            EXPECT_EQ(lighting(volumes(n, MsaaLighting::Edges, cull)).states, edges) << what;
            EXPECT_EQ(lighting(volumes(n, MsaaLighting::PerSample, cull)).states, perSample) << what;
        }
        std::vector<DrawState> simple = kept(edges, MsaaPixels::Simple);
        ASSERT_FALSE(simple.empty()) << what;
        simple.erase(simple.begin());  // the ambient term of the simple pixels
        ASSERT_EQ(simple.size(), off.size()) << what;
        for (std::size_t i = 0; i < off.size(); ++i) {
            DrawState want = off[i];
            want.pixels = MsaaPixels::Simple;
            EXPECT_EQ(simple[i], want) << what << " group " << i;
        }
        std::vector<DrawState> complex = kept(edges, MsaaPixels::Complex);
        ASSERT_GE(complex.size(), 2u) << what << ": the ambient term and the volumes";
        complex.erase(complex.begin());  // the ambient term (per-sample's covers every pixel)
        EXPECT_EQ(complex, kept(perSample, MsaaPixels::Complex)) << what << ": the same draws, so the same values";
        for (std::size_t i = 0; i < complex.size(); ++i) {
            EXPECT_EQ(complex[i].depthTest, DepthTest::Off) << what;
            EXPECT_EQ(complex[i].stencil, StencilUse::Off) << what << ": no cull stencil over the complex bit";
            EXPECT_EQ(complex[i].blend, Blend::Add) << what;
        }
        // stencil's mark needs the depth test: its complex pixels draw the back faces, as front's.
        FaceCull const faces = cull == CullMode::Stencil || cull == CullMode::Front ? FaceCull::Front
                               : cull == CullMode::Back                             ? FaceCull::Back
                                                                                    : complex.back().cull;
        EXPECT_EQ(complex.back().cull, faces) << what;
        EXPECT_EQ(msaaComplexCull(cull), cull == CullMode::Stencil ? CullMode::Front : cull);
    }
}
