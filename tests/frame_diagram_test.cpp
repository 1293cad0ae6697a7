// The Frame window's diagram (issue 24): the edges of the quad, volumes, tiled and forward frames
// (writer pass -> reader pass via resource), the views that show a resource, the plain words of a
// pass's state, and a layout whose boxes, labels and arrows do not overlap.
#include "model/frame_diagram.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

using namespace gbl;
using namespace gbl::ui;

namespace {

std::vector<std::string> edgeList(PipelineSettings const& s) {
    std::vector<PassDecl> const passes = framePasses(s);
    std::vector<std::string> out;
    for (FrameEdge const& e : frameEdges(passes)) out.push_back(describeEdge(e, passes));
    return out;
}

PipelineSettings settings(LightingMode mode) {
    PipelineSettings s;  // classic layout, front-face cull, blit, single target, light cubes
    s.mode = mode;
    return s;
}

// Every label as wide as its name at 7 px a character, the header as the pass name plus a time.
std::vector<PassBoxText> measured(std::vector<PassDecl> const& passes) {
    std::vector<PassBoxText> out;
    for (PassDecl const& p : passes) {
        PassBoxText t;
        t.header = 7.0f * float(p.name().size() + 10);
        for (Resource r : passInputs(p)) t.inputs.push_back(7.0f * float(resourceName(r).size()));
        for (Resource r : passOutputs(p)) t.outputs.push_back(7.0f * float(resourceName(r).size()));
        out.push_back(std::move(t));
    }
    return out;
}

}  // namespace

TEST(FrameDiagram, QuadEdges) {
    std::vector<std::string> const expected{
        "geometry -> lighting via gbuffer.position",
        "geometry -> lighting via gbuffer.normal",
        "geometry -> lighting via gbuffer.albedo_spec",
        "geometry -> lighting via gbuffer.emissive",
        "geometry -> depth_copy via gbuffer.depth",
        "depth_copy -> forward via lighting.depth",
        "lighting -> forward via lighting",
        "geometry -> display via gbuffer.position",
        "geometry -> display via gbuffer.normal",
        "geometry -> display via gbuffer.albedo_spec",
        "geometry -> display via gbuffer.emissive",
        "geometry -> display via gbuffer.depth",
        "forward -> display via lighting",
        // The cubes draw over the display image after the display pass, against the copied depth,
        // and blend the glass over themselves there (reading the display image).
        "depth_copy -> light_cubes via lighting.depth",
        "display -> light_cubes via display",
    };
    EXPECT_EQ(edgeList(settings(LightingMode::Quad)), expected);
}

TEST(FrameDiagram, VolumesEdges) {
    // Classic keeps position, so the volumes test against the G-buffer's own depth-stencil.
    std::vector<std::string> const expected{
        "geometry -> lighting via gbuffer.position",    "geometry -> lighting via gbuffer.normal",
        "geometry -> lighting via gbuffer.albedo_spec", "geometry -> lighting via gbuffer.emissive",
        "geometry -> lighting via gbuffer.depth",       "geometry -> depth_copy via gbuffer.depth",
        "depth_copy -> forward via lighting.depth",     "lighting -> forward via lighting",
        "geometry -> display via gbuffer.position",     "geometry -> display via gbuffer.normal",
        "geometry -> display via gbuffer.albedo_spec",  "geometry -> display via gbuffer.emissive",
        "geometry -> display via gbuffer.depth",        "forward -> display via lighting",
        "depth_copy -> light_cubes via lighting.depth", "display -> light_cubes via display",
    };
    EXPECT_EQ(edgeList(settings(LightingMode::Volumes)), expected);

    // Packed rebuilds position from depth: the volumes test against the copy the blit made.
    PipelineSettings s = settings(LightingMode::Volumes);
    s.layout = GBufferLayout::Packed;
    std::vector<std::string> const packed = edgeList(s);
    EXPECT_NE(std::find(packed.begin(), packed.end(), "geometry -> volume_depth via gbuffer.depth"), packed.end());
    EXPECT_NE(std::find(packed.begin(), packed.end(), "volume_depth -> lighting via volumes.depth"), packed.end());
}

TEST(FrameDiagram, TiledEdges) {
    std::vector<std::string> const expected{
        "geometry -> light_lists via gbuffer.depth", "geometry -> lighting via gbuffer.position",
        "geometry -> lighting via gbuffer.normal",   "geometry -> lighting via gbuffer.albedo_spec",
        "geometry -> lighting via gbuffer.emissive", "light_lists -> lighting via tile_bins",
        "geometry -> depth_copy via gbuffer.depth",  "depth_copy -> forward via lighting.depth",
        "lighting -> forward via lighting",          "geometry -> display via gbuffer.position",
        "geometry -> display via gbuffer.normal",    "geometry -> display via gbuffer.albedo_spec",
        "geometry -> display via gbuffer.emissive",  "geometry -> display via gbuffer.depth",
        "forward -> display via lighting",           "depth_copy -> light_cubes via lighting.depth",
        "display -> light_cubes via display",
    };
    EXPECT_EQ(edgeList(settings(LightingMode::Tiled)), expected);
}

TEST(FrameDiagram, ForwardEdges) {
    // No G-buffer: forward shading writes the lit image and its depth, the blended pass draws over
    // them, and the cubes test against that depth on the display image.
    std::vector<std::string> const expected{
        "forward_shading -> forward via lighting.depth",
        "forward_shading -> forward via lighting",
        "forward -> display via lighting",
        "forward_shading -> light_cubes via lighting.depth",
        "display -> light_cubes via display",
    };
    EXPECT_EQ(edgeList(settings(LightingMode::Forward)), expected);
}

TEST(FrameDiagram, SplitAccumulationAddsTheCombine) {
    PipelineSettings s = settings(LightingMode::Quad);
    s.accumulation = LightAccumulation::Split;
    std::vector<std::string> const edges = edgeList(s);
    for (char const* e : {"lighting -> light_combine via diffuse_light", "lighting -> light_combine via specular_light",
                          "lighting -> display via diffuse_light", "light_combine -> forward via lighting"})
        EXPECT_NE(std::find(edges.begin(), edges.end(), e), edges.end()) << e;
}

TEST(FrameDiagram, ResourcesWithAViewShowIt) {
    EXPECT_EQ(resourceView(Resource::GBufferNormal), DebugView::Normal);
    EXPECT_EQ(resourceView(Resource::Lighting), DebugView::Lighting);
    EXPECT_EQ(resourceView(Resource::Display), DebugView::Final);
    EXPECT_EQ(resourceView(Resource::Lights), std::nullopt);
    EXPECT_EQ(resourceView(Resource::LitDepth), std::nullopt);
}

// prepass (issue 48): the thin G-buffer's normal target opens the normal view, and the display of a
// prepass frame reads the thin G-buffer (its views show it), not the layout's, which it never drew.
TEST(FrameDiagram, PrepassThinGBufferOpensTheNormalViewAndFeedsTheDisplay) {
    EXPECT_EQ(resourceView(Resource::PrepassNormal), DebugView::Normal);
    std::vector<std::string> const edges = edgeList(settings(LightingMode::Prepass));
    for (char const* e :
         {"prepass_geometry -> display via prepass.normal_exp", "prepass_geometry -> display via lighting.depth"})
        EXPECT_NE(std::find(edges.begin(), edges.end(), e), edges.end()) << e;
    for (std::string const& e : edges) EXPECT_EQ(e.find("gbuffer."), std::string::npos) << e;
    std::vector<std::string> const quad = edgeList(settings(LightingMode::Quad));
    EXPECT_NE(std::find(quad.begin(), quad.end(), "geometry -> display via gbuffer.normal"), quad.end());
    for (std::string const& e : quad) EXPECT_EQ(e.find("prepass."), std::string::npos) << e;
}

TEST(FrameDiagram, PassStateInPlainWords) {
    std::vector<PassDecl> const passes = framePasses(settings(LightingMode::Volumes));
    std::vector<std::string> const words = describePass(passes[1]);  // lighting
    ASSERT_GE(words.size(), 5u);
    EXPECT_EQ(words[0], "A raster pass: draws into a framebuffer.");
    EXPECT_EQ(words[2], "Draws into: lighting; depth-stencil gbuffer.depth.");
    EXPECT_EQ(words[3], "Depth tested, not written; stencil not tested, not written.");
    EXPECT_EQ(words[5],
              "Volumes: back faces: depth test greater-or-equal (behind the stored surface), depth read-only, additive "
              "blending (ONE, ONE: lights summed), front faces culled, no stencil.");
}

TEST(FrameDiagram, BoxesLabelsAndLanesDoNotOverlap) {
    // The heat map adds the coverage pass; the final view adds the overlays after the display pass.
    for (DebugView view : {DebugView::Heatmap, DebugView::Final})
        for (LightingMode mode : {LightingMode::Quad, LightingMode::Volumes, LightingMode::Tiled, LightingMode::Forward,
                                  LightingMode::Clustered}) {
            PipelineSettings s = settings(mode);
            s.volumeWireframes = true;
            s.view = view;
            std::vector<PassDecl> const passes = framePasses(s);
            std::vector<PassBoxText> const text = measured(passes);
            DiagramMetrics const m;
            DiagramLayout const d = layoutDiagram(passes, text, m);
            ASSERT_EQ(d.boxes.size(), passes.size());
            float lowest = 0.0f;
            for (std::size_t i = 0; i < d.boxes.size(); ++i) {
                BoxPlace const& b = d.boxes[i];
                SCOPED_TRACE(std::string(kLightingModeNames[std::size_t(mode)]) + " " + std::string(passes[i].name()));
                if (i > 0) {
                    EXPECT_GE(b.pos.x, d.boxes[i - 1].pos.x + d.boxes[i - 1].size.x + m.columnGap - 0.01f);
                }
                EXPECT_GE(b.size.x, text[i].header + 2.0f * m.pad);
                // Input labels end before output labels start, on every row.
                float widestIn = 0.0f, widestOut = 0.0f;
                for (float w : text[i].inputs) widestIn = std::max(widestIn, w);
                for (float w : text[i].outputs) widestOut = std::max(widestOut, w);
                EXPECT_LE(b.inputLabelX + widestIn, b.outputLabelRight - widestOut + 0.01f);
                EXPECT_GE(b.inputLabelX, b.pos.x);
                EXPECT_LE(b.outputLabelRight, b.pos.x + b.size.x);
                // Pins below the header, inside the box.
                for (glm::vec2 p : b.inputs) {
                    EXPECT_EQ(p.x, b.pos.x);
                    EXPECT_GE(p.y, b.pos.y + m.pad + float(m.headerLines) * m.line);
                    EXPECT_LE(p.y, b.pos.y + b.size.y);
                }
                EXPECT_EQ(b.inputs.size(), passInputs(passes[i]).size());
                EXPECT_EQ(b.outputs.size(), passOutputs(passes[i]).size());
                EXPECT_GE(d.size.x, b.pos.x + b.size.x);
                lowest = std::max(lowest, b.pos.y + b.size.y);
            }
            EXPECT_EQ(d.routes.size(), frameEdges(passes).size());
            // Arrows start on an output pin and end on an input pin; those that skip passes run below
            // every box, and their legs stay in the gaps between boxes.
            for (EdgeRoute const& r : d.routes) {
                ASSERT_GE(r.points.size(), 4u);
                BoxPlace const& from = d.boxes[std::size_t(r.edge.from)];
                BoxPlace const& to = d.boxes[std::size_t(r.edge.to)];
                EXPECT_EQ(r.points.front().x, from.pos.x + from.size.x);
                EXPECT_EQ(r.points.back().x, to.pos.x);
                if (r.curve) continue;
                EXPECT_GT(r.points[2].y, lowest);
                EXPECT_LE(r.points[2].y, d.size.y);
                EXPECT_GT(r.points[1].x, from.pos.x + from.size.x);
                EXPECT_LT(r.points[1].x, d.boxes[std::size_t(r.edge.from) + 1].pos.x);
                EXPECT_LT(r.points[4].x, to.pos.x);
                EXPECT_GT(r.points[4].x,
                          d.boxes[std::size_t(r.edge.to) - 1].pos.x + d.boxes[std::size_t(r.edge.to) - 1].size.x);
            }
        }
}
