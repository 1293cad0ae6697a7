// The Frame window's diagram: reads and writes of the declared passes, edges, layout, words.
#include "model/frame_diagram.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace gbl::ui {

namespace {

void addOnce(std::vector<Resource>& out, Resource r) {
    if (std::find(out.begin(), out.end(), r) == out.end()) out.push_back(r);
}

bool contains(std::vector<Resource> const& list, Resource r) {
    return std::find(list.begin(), list.end(), r) != list.end();
}

std::string joined(std::vector<Resource> const& list) {
    std::string out;
    for (std::size_t i = 0; i < list.size(); ++i) out += (i ? ", " : "") + std::string(resourceName(list[i]));
    return out;
}

char const* depthTestWords(DepthTest t) {
    switch (t) {
        case DepthTest::Off:
            return "no depth test";
        case DepthTest::Less:
            return "depth test less (nearer than what is stored)";
        case DepthTest::LessEqual:
            return "depth test less-or-equal";
        case DepthTest::GreaterEqual:
            return "depth test greater-or-equal (behind the stored surface)";
        case DepthTest::Always:
            return "depth test always passes";
    }
    return "?";
}

char const* blendWords(Blend b) {
    switch (b) {
        case Blend::Off:
            return "no blending (replaces)";
        case Blend::Add:
            return "additive blending (ONE, ONE: lights summed)";
        case Blend::Alpha:
            return "alpha blending over what is there";
    }
    return "?";
}

char const* cullWords(FaceCull c) {
    switch (c) {
        case FaceCull::Off:
            return "no face culling";
        case FaceCull::Back:
            return "back faces culled";
        case FaceCull::Front:
            return "front faces culled";
    }
    return "?";
}

char const* stencilWords(StencilUse s) {
    switch (s) {
        case StencilUse::Off:
            return "no stencil";
        case StencilUse::Mark:
            return "stencil marks where depth fails (back faces +1, front faces -1)";
        case StencilUse::ShadeMarked:
            return "stencil shades where the mark is 1 and zeroes it";
        case StencilUse::EqualBits:
            return "stencil passes where the tested bits are set";
        case StencilUse::MarkComplex:
            return "stencil sets the complex bit at every pixel drawn (the complex ones; simple pixels discard)";
        case StencilUse::MarkCovered:
            return "stencil marks 1 at every pixel drawn (the light cubes)";
        case StencilUse::Covered:
            return "stencil passes where the mark is 1 (the light cubes' pixels)";
    }
    return "?";
}

std::string readWrite(char const* what, bool read, bool write) {
    std::string out = std::string(what) + (read ? " tested" : " not tested");
    return out + (write ? ", written" : ", not written");
}

}  // namespace

std::vector<Resource> passInputs(PassDecl const& p) {
    std::vector<Resource> out;
    for (Resource r : p.samples) addOnce(out, r);
    if (p.kind == PassKind::Compute) return out;
    if (p.depthStencil && (p.depthRead || p.stencilRead)) addOnce(out, *p.depthStencil);
    bool const blends =
        std::any_of(p.states.begin(), p.states.end(), [](DrawState const& s) { return s.blend != Blend::Off; });
    if (blends)
        for (Resource r : p.color) addOnce(out, r);
    return out;
}

std::vector<Resource> passOutputs(PassDecl const& p) {
    std::vector<Resource> out;
    if (p.kind == PassKind::Compute) {
        for (Resource r : p.writes) addOnce(out, r);
        return out;
    }
    bool const colour = p.kind == PassKind::Raster &&
                        std::any_of(p.states.begin(), p.states.end(), [](DrawState const& s) { return s.colorWrite; });
    if (colour)
        for (Resource r : p.color) addOnce(out, r);
    if (p.depthStencil && (p.depthWrite || p.stencilWrite)) addOnce(out, *p.depthStencil);
    return out;
}

std::vector<FrameEdge> frameEdges(std::span<PassDecl const> passes) {
    std::vector<FrameEdge> out;
    for (std::size_t to = 0; to < passes.size(); ++to)
        for (Resource r : passInputs(passes[to]))
            for (std::size_t from = to; from-- > 0;)
                if (contains(passOutputs(passes[from]), r)) {
                    out.push_back({int(from), int(to), r});
                    break;
                }
    return out;
}

std::string describeEdge(FrameEdge const& e, std::span<PassDecl const> passes) {
    return std::string(passes[std::size_t(e.from)].name()) + " -> " + std::string(passes[std::size_t(e.to)].name()) +
           " via " + std::string(resourceName(e.resource));
}

std::optional<DebugView> resourceView(Resource r) {
    switch (r) {
        case Resource::GBufferPosition:
            return DebugView::Position;
        case Resource::GBufferNormal:
            return DebugView::Normal;
        case Resource::GBufferAlbedoSpec:
            return DebugView::Albedo;
        case Resource::GBufferEmissive:
            return DebugView::Emissive;
        case Resource::GBufferDepth:
            return DebugView::Depth;
        case Resource::Lighting:
            return DebugView::Lighting;
        case Resource::DiffuseLight:
            return DebugView::DiffuseLight;
        case Resource::SpecularLight:
            return DebugView::SpecularLight;
        case Resource::Coverage:
            return DebugView::Heatmap;
        case Resource::Display:
            return DebugView::Final;
        case Resource::TileBins:
            return DebugView::TileLights;
        // msaa: the viewers show the multisampled G-buffer resolved (the msaa_resolve pass)
        case Resource::MsaaPosition:
            return DebugView::Position;
        case Resource::MsaaNormal:
            return DebugView::Normal;
        case Resource::MsaaAlbedoSpec:
            return DebugView::Albedo;
        case Resource::MsaaEmissive:
            return DebugView::Emissive;
        case Resource::MsaaDepth:
            return DebugView::Depth;
        case Resource::PrepassNormal:  // prepass's thin G-buffer: the normal viewer shows it in prepass frames
            return DebugView::Normal;
        case Resource::ComplexMask:
        case Resource::VolumeDepth:
        case Resource::LitDepth:
        case Resource::Lights:
        case Resource::VolumeInstances:
        case Resource::Materials:
        case Resource::ClusterLists:
        case Resource::Imported:
        case Resource::View:      // a view's own image (drawView), no frame's
        case Resource::Readback:  // the browser's read-back target, no frame's
            break;
    }
    return std::nullopt;
}

std::vector<std::string> describePass(PassDecl const& p) {
    std::vector<std::string> out;
    switch (p.kind) {
        case PassKind::Raster:
            out.push_back("A raster pass: draws into a framebuffer.");
            break;
        case PassKind::Compute:
            out.push_back("A compute pass: dispatches, no framebuffer.");
            break;
        case PassKind::Blit:
            out.push_back("A blit: glBlitFramebuffer copies depth and stencil.");
            break;
    }
    std::string const verb = p.kind == PassKind::Blit ? "Copies from: " : "Samples: ";
    out.push_back(p.samples.empty() ? std::string("Samples nothing.") : verb + joined(p.samples) + ".");
    if (p.kind == PassKind::Compute) {
        out.push_back("Writes: " + (p.writes.empty() ? std::string("nothing") : joined(p.writes)) + ".");
        return out;
    }
    std::string into = p.color.empty() ? std::string("no colour target") : joined(p.color);
    if (p.depthStencil) into += "; depth-stencil " + std::string(resourceName(*p.depthStencil));
    out.push_back("Draws into: " + into + ".");
    if (p.depthStencil)
        out.push_back(readWrite("Depth", p.depthRead, p.depthWrite) + "; " +
                      readWrite("stencil", p.stencilRead, p.stencilWrite) + ".");
    if (p.states.empty() && p.kind == PassKind::Raster) out.push_back("No draws: its targets are only cleared.");
    for (DrawState const& s : p.states) {
        std::string line = std::string(s.what) + ": " + depthTestWords(s.depthTest);
        if (!line.empty() && line[0] >= 'a' && line[0] <= 'z') line[0] = char(line[0] - 'a' + 'A');
        line += s.depthWrite ? ", writes depth" : (s.depthTest != DepthTest::Off ? ", depth read-only" : "");
        line += std::string(", ") + blendWords(s.blend) + ", " + cullWords(s.cull) + ", " + stencilWords(s.stencil);
        if (s.pixels == MsaaPixels::Simple) line += ", simple pixels only (stencil complex bit 0)";
        if (s.pixels == MsaaPixels::Complex) line += ", complex pixels only (stencil complex bit 1)";
        if (!s.colorWrite) line += ", colour writes off";
        out.push_back(line + ".");
    }
    return out;
}

DiagramLayout layoutDiagram(std::span<PassDecl const> passes, std::span<PassBoxText const> text,
                            DiagramMetrics const& m) {
    DiagramLayout out;
    float x = m.pinRadius + 2.0f;
    float bottom = 0.0f;
    for (std::size_t i = 0; i < passes.size(); ++i) {
        PassBoxText const t = i < text.size() ? text[i] : PassBoxText{};
        std::size_t const nIn = passInputs(passes[i]).size(), nOut = passOutputs(passes[i]).size();
        float widestIn = 0.0f, widestOut = 0.0f;
        for (std::size_t k = 0; k < nIn && k < t.inputs.size(); ++k) widestIn = std::max(widestIn, t.inputs[k]);
        for (std::size_t k = 0; k < nOut && k < t.outputs.size(); ++k) widestOut = std::max(widestOut, t.outputs[k]);
        float const side = m.pad + m.pinRadius;
        float const pins = 2.0f * side + widestIn + widestOut + (nIn && nOut ? m.labelGap : 0.0f);
        BoxPlace b;
        b.pos = glm::vec2(x, 0.0f);
        b.size.x = std::ceil(std::max(t.header + 2.0f * m.pad, pins));
        float const rowsTop = m.pad + float(m.headerLines) * m.line;
        b.size.y = rowsTop + float(std::max<std::size_t>({nIn, nOut, 1})) * m.line + m.pad;
        for (std::size_t k = 0; k < nIn; ++k) b.inputs.emplace_back(x, rowsTop + (float(k) + 0.5f) * m.line);
        for (std::size_t k = 0; k < nOut; ++k)
            b.outputs.emplace_back(x + b.size.x, rowsTop + (float(k) + 0.5f) * m.line);
        b.inputLabelX = x + side;
        b.outputLabelRight = x + b.size.x - side;
        bottom = std::max(bottom, b.size.y);
        x += b.size.x + m.columnGap;
        out.boxes.push_back(std::move(b));
    }
    // Lanes: one per writer and resource whose readers are not all next to it, shared by
    // intervals that do not overlap (the earliest free lane first).
    std::vector<FrameEdge> const edges = frameEdges(passes);
    std::map<std::pair<int, int>, int> groupEnd;  // (writer, resource) -> its farthest reader
    for (FrameEdge const& e : edges)
        if (e.to > e.from + 1) {
            int& end = groupEnd[{e.from, int(e.resource)}];
            end = std::max(end, e.to);
        }
    std::vector<std::pair<std::pair<int, int>, int>> groups(groupEnd.begin(), groupEnd.end());
    std::stable_sort(groups.begin(), groups.end(), [](auto const& a, auto const& b) {
        return a.first.first != b.first.first ? a.first.first < b.first.first : a.second < b.second;
    });
    std::vector<int> laneEnds;  // the last box each lane reaches
    std::map<std::pair<int, int>, int> laneOf;
    for (auto const& group : groups) {
        int const start = group.first.first, end = group.second;
        auto const slot = std::find_if(laneEnds.begin(), laneEnds.end(), [start](int e) { return e <= start; });
        int const lane = slot == laneEnds.end() ? int(laneEnds.size()) : int(slot - laneEnds.begin());
        if (slot == laneEnds.end())
            laneEnds.push_back(end);
        else
            *slot = end;
        laneOf[group.first] = lane;
    }
    float const legStep = std::max(2.0f, (m.columnGap * 0.5f - 8.0f) / 6.0f);
    for (FrameEdge const& e : edges) {
        BoxPlace const& from = out.boxes[std::size_t(e.from)];
        BoxPlace const& to = out.boxes[std::size_t(e.to)];
        auto const outs = passOutputs(passes[std::size_t(e.from)]);
        auto const ins = passInputs(passes[std::size_t(e.to)]);
        glm::vec2 const a = from.outputs[std::size_t(std::find(outs.begin(), outs.end(), e.resource) - outs.begin())];
        glm::vec2 const b = to.inputs[std::size_t(std::find(ins.begin(), ins.end(), e.resource) - ins.begin())];
        EdgeRoute r{e, {}, false};
        if (e.to == e.from + 1) {
            float const d = m.columnGap * 0.5f;
            r.points = {a, a + glm::vec2(d, 0.0f), b - glm::vec2(d, 0.0f), b};
            r.curve = true;
        } else {
            int const lane = laneOf[{e.from, int(e.resource)}];
            float const y = bottom + m.laneGap * float(lane + 1);
            float const step = legStep * float(lane % 6);
            float const xo = a.x + 6.0f + m.pinRadius + step, xi = b.x - 6.0f - m.pinRadius - step;
            r.points = {a, {xo, a.y}, {xo, y}, {xi, y}, {xi, b.y}, b};
        }
        out.routes.push_back(std::move(r));
    }
    out.size = glm::vec2(std::max(0.0f, x - m.columnGap + m.pinRadius + 2.0f),
                         bottom + m.laneGap * float(laneEnds.size() + 1));
    return out;
}

}  // namespace gbl::ui
