// UI script commands of the viewer tools: the G-buffer viewers' and the viewport's tools, the
// viewers' pin and diff, and the viewport's "Pin lit" / "Diff" row, with checks of what they show.
#include "script/script_run.h"

#include <cstdio>
#include <cstdlib>

namespace gbl::ui {

namespace {

// A viewer and its data: a G-buffer viewer by name, or "viewport" for the viewport's tools.
struct ViewerRef {
    ViewerState* viewer = nullptr;
    ViewerData* data = nullptr;
    int index = -1;  // kViewportViewer for the viewport
};

// The viewer named by word 1, or an empty ref after a failed check.
ViewerRef viewerRef(CommandCall const& c) {
    EditorState& s = c.host.state;
    if (c.w[1] == "viewport") {
        // As the next frame would: the viewer takes the kind of the view shown now.
        followViewportView(s.viewportTools, s.pipeline.view);
        return {&s.viewportTools.viewer, &s.viewportTools.data, kViewportViewer};
    }
    for (std::size_t i = 0; i < kViewerNames.size(); ++i)
        if (kViewerNames[i] == c.w[1]) return {&s.gbuffer.viewers[i], &s.gbuffer.data[i], int(i)};
    c.check(false, "no viewer " + c.w[1] + " (position normal albedo specular depth viewport)");
    return {};
}

// "on" / "off" in word n; nullopt after a failed check.
std::optional<bool> onOff(CommandCall const& c, std::size_t n) {
    if (c.w[n] == "on") return true;
    if (c.w[n] == "off") return false;
    c.check(false, "expected on or off, got " + c.w[n]);
    return std::nullopt;
}

// Compares x with the command's CMP and value words (=, <, >, <=, >=).
bool compare(CommandCall const& c, double x, std::size_t cmpWord, bool* known) {
    double const y = number(c.w[cmpWord + 1]);
    std::string const& op = c.w[cmpWord];
    *known = true;
    if (op == "=") return x == y;
    if (op == "<") return x < y;
    if (op == ">") return x > y;
    if (op == "<=") return x <= y;
    if (op == ">=") return x >= y;
    *known = false;
    return false;
}

void viewerToolCommand(CommandCall const& c) {
    ViewerRef const r = viewerRef(c);
    if (!r.viewer) return;
    std::optional<bool> const on = onOff(c, 3);
    if (!on) return;
    GBufferPanelState& panel = c.host.state.gbuffer;
    ViewerState& v = *r.viewer;
    auto overlay = [&](unsigned bit) { v.overlays = *on ? v.overlays | bit : v.overlays & ~bit; };
    std::string const& tool = c.w[2];
    if (tool == "histogram")
        v.showHistogram = *on;
    else if (tool == "nan")
        overlay(kOverlayNaN);
    else if (tool == "inf")
        overlay(kOverlayInf);
    else if (tool == "negative")
        overlay(kOverlayNegative);
    else if (tool == "clip")
        overlay(kOverlayClip);
    else if (tool == "stencil") {
        if (v.kind != ViewerKind::Depth || r.index == kViewportViewer)
            return c.check(false, "only the depth viewer shows the stencil");
        setShowStencil(v, *on);  // as its "stencil" checkbox
    } else if (tool == "diff")
        v.showDiff = *on;  // the Diff toggle (enabled once pinned)
    else if (tool == "magnifier") {
        panel.showMagnifier = *on;
        panel.activeViewer = r.index;
        if (*on && !v.picked) v.picked = glm::ivec2(c.host.renderer.width() / 2, c.host.renderer.height() / 2);
    } else
        return c.check(false, "unknown tool " + tool + " (histogram nan inf negative clip stencil diff magnifier)");
}

void viewerColormapCommand(CommandCall const& c) {
    ViewerRef const r = viewerRef(c);
    if (!r.viewer) return;
    auto const map = enumFromName<Colormap>(kColormapNames, c.w[2]);
    if (!map) return c.check(false, "no colormap " + c.w[2] + " (grey turbo viridis)");
    r.viewer->colormap = *map;
}

void viewerRangeCommand(CommandCall const& c) {
    ViewerRef const r = viewerRef(c);
    if (!r.viewer) return;
    float const lo = number(c.w[2]), hi = number(c.w[3]);
    if (!(hi > lo)) return c.check(false, "the white point must be above the black point");
    r.viewer->rangeMin = lo;
    r.viewer->rangeMax = hi;
    r.viewer->autoFit = false;
}

void expectViewerStatCommand(CommandCall const& c) {
    ViewerRef const r = viewerRef(c);
    if (!r.viewer) return;
    ViewerData const& d = *r.data;
    if (d.frame < 0) return c.check(false, "no statistics yet: turn a tool of this viewer on and wait a frame");
    ImageStats const& s = d.stats;
    std::string const& stat = c.w[2];
    double const x = number(c.w[3]);
    char detail[200];
    std::snprintf(detail, sizeof detail, "min %.5g max %.5g mean %.5g, NaN %ld Inf %ld negative %ld of %ld pixels",
                  s.shown.min, s.shown.max, s.shown.mean, s.nanPixels, s.infPixels, s.negativePixels, s.pixels);
    if (stat == "nan") return c.check(double(s.nanPixels) == x, detail);
    if (stat == "inf") return c.check(double(s.infPixels) == x, detail);
    if (stat == "negative") return c.check(double(s.negativePixels) == x, detail);
    if (stat == "min-below") return c.check(s.shown.finite > 0 && s.shown.min < x, detail);
    if (stat == "max-above") return c.check(s.shown.finite > 0 && s.shown.max > x, detail);
    if (stat == "max-below") return c.check(s.shown.finite > 0 && s.shown.max < x, detail);
    if (stat == "min-equals") return c.check(s.shown.finite > 0 && double(s.shown.min) == x, detail);
    if (stat == "max-equals") return c.check(s.shown.finite > 0 && double(s.shown.max) == x, detail);
    if (stat == "pixels-above") return c.check(double(s.pixels) > x, detail);
    c.check(false, "unknown statistic " + stat +
                       " (nan inf negative min-below max-above max-below min-equals max-equals pixels-above)");
}

// One statistic of a diff, as the viewer's or the viewport's row shows it.
void expectDiff(CommandCall const& c, DiffStats const& d, bool shown) {
    if (!shown) return c.check(false, "no diff shown: pin, turn Diff on and wait a frame");
    if (!d.comparable) return c.check(false, "the pinned image has another size");
    std::string const& stat = c.w[c.w.size() - 3];
    double const x = stat == "max"      ? double(d.max)
                     : stat == "mean"   ? d.mean
                     : stat == "over"   ? double(d.overThreshold)
                     : stat == "pixels" ? double(d.pixels)
                     : stat == "nan"    ? double(d.nanPixels)
                                        : -1.0;
    if (x < 0.0) return c.check(false, "unknown diff statistic " + stat + " (max mean over pixels nan)");
    bool known = false;
    bool const ok = compare(c, x, c.w.size() - 2, &known);
    if (!known) return c.check(false, "unknown comparison " + c.w[c.w.size() - 2] + " (= < > <= >=)");
    char detail[200];
    std::snprintf(detail, sizeof detail, "max %.6g at %d,%d mean %.6g over %ld of %ld NaN/Inf %ld", double(d.max),
                  d.maxAt.x, d.maxAt.y, d.mean, d.overThreshold, d.pixels, d.nanPixels);
    c.check(ok, detail);
}

void litDiffCommand(CommandCall const& c) {
    LitPin& pin = c.host.state.litPin;
    if (!pin.pinned) return c.check(false, "Diff is disabled until the lit frame is pinned (pin-lit)");
    if (std::optional<bool> const on = onOff(c, 1)) pin.showDiff = *on;
}

void litDiffThresholdCommand(CommandCall const& c) {
    float const t = number(c.w[1]);
    if (!(t >= 0.0f)) return c.check(false, "the threshold must be a number >= 0");
    c.host.state.litPin.diffThreshold = t;
}

void litDiffModeCommand(CommandCall const& c) {
    if (c.w[1] != "abs" && c.w[1] != "rel") return c.check(false, "expected abs or rel");
    c.host.state.litPin.diffMode = c.w[1] == "rel" ? DiffMode::Relative : DiffMode::Absolute;
}

// The sample selector of a viewer (msaa, issue 47): "all" or a sample below the frame's count.
void viewerSampleCommand(CommandCall const& c) {
    ViewerRef const r = viewerRef(c);
    if (!r.viewer) return;
    if (c.w[2] == "all") {
        r.viewer->sample = -1;
        return;
    }
    int const samples = c.host.state.gbuffer.msaaSamples, k = std::atoi(c.w[2].c_str());
    if (samples <= 0) return c.check(false, "the frame shown ran without msaa: only all is offered");
    if (!viewerSampleSlot(r.viewer->kind)) return c.check(false, "the " + c.w[1] + " viewer shows all samples only");
    if (c.w[2].find_first_not_of("0123456789") != std::string::npos || k >= samples)
        return c.check(false, "no sample " + c.w[2] + " (all, or 0 to " + std::to_string(samples - 1) + ")");
    r.viewer->sample = k;
}

void msaaViewCommand(CommandCall const& c) {
    std::optional<bool> const on = onOff(c, 2);
    if (!on) return;
    MsaaViewState& m = c.host.state.viewport.msaa;
    if (c.w[1] == "complex")
        m.complexOverlay = *on;
    else if (c.w[1] == "samples")
        m.samplesHeat = *on;
    else
        c.check(false, "unknown msaa view " + c.w[1] + " (complex samples)");
}

constexpr ScriptCommandSpec kViewerCommands[] = {
    {"viewer-tool", "VIEWER TOOL on|off",
     "a viewer's tool (VIEWER: position normal albedo specular depth, or viewport for the\n"
     "viewport's tools): histogram nan inf negative clip stencil (depth) diff magnifier",
     viewerToolCommand},
    {"viewer-sample", "VIEWER all|K",
     "the viewer's sample selector while the frame ran msaa: all (resolved) or sample K (position\n"
     "normal albedo specular, or viewport)",
     viewerSampleCommand},
    {"msaa-view", "complex|samples on|off",
     "the viewport's msaa views: the complex-pixel overlay, the samples-that-differ heat map", msaaViewCommand},
    {"expect-msaa-samples", "N",
     "the frame shown ran msaa with N samples per pixel (0: without), and with N > 0 its complex share is known",
     [](CommandCall const& c) {
         MsaaViewState const& m = c.host.state.viewport.msaa;
         std::string const share = m.complexShare ? std::to_string(*m.complexShare) : std::string("none");
         c.check(m.samples == int(number(c.w[1])) && (m.samples == 0 || m.complexShare.has_value()),
                 "samples " + std::to_string(m.samples) + ", complex share " + share);
     }},
    {"wait-msaa-view", "complex|samples SECONDS",
     "run frames until the viewport's msaa view is on and drawn (a real click may turn it on; fails after SECONDS)",
     [](CommandCall const& c) {
         MsaaViewState const& m = c.host.state.viewport.msaa;
         bool const complex = c.w[1] == "complex";
         if (!complex && c.w[1] != "samples")
             return c.check(false, "unknown msaa view " + c.w[1] + " (complex samples)");
         c.waitUntil([&m, complex] { return complex ? m.overlayTexture != 0 : m.heatTexture != 0; }, number(c.w[2]));
     }},
    {"expect-inspector-samples", "N",
     "the pixel inspector lists N msaa samples of its pixel (0: the frame ran without msaa)",
     [](CommandCall const& c) {
         std::size_t const n = c.host.state.inspector.msaaSamples.size();
         c.check(double(n) == number(c.w[1]), std::to_string(n) + " samples listed");
     }},
    {"viewer-colormap", "VIEWER MAP", "the viewer's colormap: grey turbo viridis", viewerColormapCommand},
    {"viewer-range", "VIEWER MIN MAX", "the viewer's black and white points (auto-fit off)", viewerRangeCommand},
    {"viewer-pin", "VIEWER", "the viewer's Pin button: keep its current values (read at the next frame)",
     [](CommandCall const& c) {
         if (ViewerRef const r = viewerRef(c); r.viewer) r.viewer->pinRequested = true;
     }},
    {"viewport-tools", "on|off", "the viewport's Tools toggle (shown while it shows a G-buffer attachment)",
     [](CommandCall const& c) {
         if (std::optional<bool> const on = onOff(c, 1)) c.host.state.viewportTools.open = *on;
     }},
    {"expect-viewer-stat", "VIEWER STAT X",
     "the viewer's statistics: nan|inf|negative X (pixel counts equal X), min-below X,\n"
     "max-above X, max-below X, min-equals X, max-equals X, pixels-above X (needs a tool on and a frame)",
     expectViewerStatCommand},
    {"expect-viewer-diff", "VIEWER STAT CMP X",
     "the viewer's diff statistics as its row shows them: max|mean|over|pixels|nan, CMP = < > <= >=",
     [](CommandCall const& c) {
         if (ViewerRef const r = viewerRef(c); r.viewer)
             expectDiff(c, r.data->diff, r.viewer->showDiff && r.data->pinned.has_value());
     }},
    {"pin-lit", "", "the viewport's \"Pin lit\" button: keep the lit HDR frame (read at the next frame)",
     [](CommandCall const& c) { c.host.state.litPin.pinRequested = true; }},
    {"lit-diff", "on|off", "the viewport's \"Diff\" checkbox (enabled once the lit frame is pinned)", litDiffCommand},
    {"lit-diff-threshold", "X", "the lit diff's threshold (applies at once)", litDiffThresholdCommand},
    {"lit-diff-mode", "abs|rel", "the lit diff's \"rel\" checkbox", litDiffModeCommand},
    {"wait-lit-diff", "SECONDS",
     "run frames until the lit frame is pinned and its diff shown (a real click may do it; fails after SECONDS)",
     [](CommandCall const& c) {
         LitPin const& pin = c.host.state.litPin;
         c.waitUntil([&pin] { return pin.pinned && pin.showDiff && pin.diff.comparable; }, number(c.w[1]));
     }},
    {"expect-lit-pinned", "", "a lit frame is pinned",
     [](CommandCall const& c) {
         c.check(c.host.state.litPin.pinned.has_value(),
                 "pinned at frame " + std::to_string(c.host.state.litPin.pinnedFrame));
     }},
    {"expect-lit-diff", "STAT CMP X",
     "the lit diff's statistics as the viewport's row shows them: max|mean|over|pixels|nan, CMP = < > <= >=",
     [](CommandCall const& c) {
         LitPin const& pin = c.host.state.litPin;
         expectDiff(c, pin.diff, pin.showDiff && pin.pinned.has_value());
     }},
    {"expect-ab-diff", "STAT CMP X",
     "the A/B diff's statistics as the viewport shows them (lit, or degrees with ab-metric normal-angle)",
     [](CommandCall const& c) {
         AbState const& ab = c.host.state.ab;
         bool const angle = ab.metric == AbMetric::NormalAngle;
         expectDiff(c, angle ? ab.normalDiff : ab.pin.diff, ab.enabled && ab.view == AbView::Diff);
     }},
};

}  // namespace

std::span<ScriptCommandSpec const> viewerCommands() {
    return kViewerCommands;
}

}  // namespace gbl::ui
