// Viewer tools: read-back scheduling, statistics, fits, pin and diff.
#include "model/viewer_tools.h"

#include "model/colormap.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <utility>

namespace gbl::ui {

bool viewerNeedsData(GBufferPanelState const& panel, std::size_t i) {
    ViewerState const& v = panel.viewers[i];
    bool const magnifier = panel.showMagnifier && panel.activeViewer == int(i);
    return viewerToolsNeedData(v) || magnifier;
}

bool viewerToolsNeedData(ViewerState const& v) {
    // The stencil has no view pass: its picture is made from the values.
    bool const stencil = v.kind == ViewerKind::Depth && v.showStencil;
    return v.showHistogram || v.overlays != 0 || v.region || v.showDiff || v.percentileFitRequested ||
           v.regionFitRequested || v.pinRequested || stencil || v.sample >= 0;
}

unsigned viewerValuesKey(ViewerState const& viewer) {
    return unsigned(viewer.kind) | (viewer.linearDepth ? 8u : 0u) | (viewer.cameraClipPlanes ? 16u : 0u) |
           (viewer.kind == ViewerKind::Depth && viewer.showStencil ? 32u : 0u) | (unsigned(viewer.sample + 1) << 6);
}

bool viewerDataDue(ViewerState const& viewer, ViewerData const& data, long frame) {
    // A fit or a pin acts on the newest frame, not on values up to half a second old.
    if (viewer.percentileFitRequested || viewer.pinRequested) return true;
    return data.frame < 0 || frame - data.frame >= kViewerDataInterval || data.key != viewerValuesKey(viewer);
}

ValueRange readableRange(ViewerState const& viewer, FloatImage const& values) {
    float const low = viewer.kind == ViewerKind::Lighting ? 0.0f : 1.0f;
    return percentileRange(values, viewerStatsMask(viewer), low, 99.0f, {}, viewerSkip(viewer.kind));
}

ValueRange stripViewerRange(ViewerState const& viewer, FloatImage const& attachment, bool asked, float nearPlane,
                            float farPlane) {
    if (viewer.kind == ViewerKind::Depth && viewer.showStencil) {
        ValueRange r = fitRange(attachment, 0x1, RangeSkip::None);
        r.max = std::max(r.max, r.min + 1.0f);
        return r;
    }
    if (asked) {
        if (viewer.kind == ViewerKind::Depth)  // raw window depths: the far plane is the background
            return fitRange(attachment, 0x1, RangeSkip::FarDepth, viewer.linearDepth, nearPlane, farPlane);
        unsigned const mask = viewer.kind == ViewerKind::Specular ? 0x8u : (viewer.channelMask & 0x7u);
        return fitRange(attachment, mask, viewerSkip(viewer.kind));
    }
    return readableRange(viewer, viewerValues(viewer, attachment, nearPlane, farPlane));
}

bool autoFitDue(ViewerState const& viewer, ViewerData const& data, glm::vec2 clipPlanes, long frame, bool rendered) {
    if (!viewer.autoFit) return false;
    if (viewer.lastFitFrame < 0) return true;
    if (data.autoFitFor != std::make_pair(viewerValuesKey(viewer), clipPlanes)) return true;
    return rendered && frame - viewer.lastFitFrame >= 60;
}

void setViewerValues(ViewerState& viewer, ViewerData& data, FloatImage values, long frame) {
    data.values = std::move(values);
    data.frame = frame;
    data.key = viewerValuesKey(viewer);
    data.computedFor.reset();
    unsigned const mask = viewerStatsMask(viewer);
    RangeSkip const skip = viewerSkip(viewer.kind);
    if (viewer.percentileFitRequested) {
        viewer.percentileFitRequested = false;
        ValueRange const r = percentileRange(data.values, mask, 1.0f, 99.0f, {}, skip);
        if (r.samples > 0 && viewerRemaps(viewer.kind)) {
            viewer.rangeMin = r.min;
            viewer.rangeMax = r.max;
            viewer.autoFit = false;  // auto-fit would undo the fit within a second
        }
    }
    if (viewer.pinRequested) {
        viewer.pinRequested = false;
        data.pinned = data.values;
        data.pinnedFrame = frame;
    }
    updateViewerStats(viewer, data);
}

bool updateViewerStats(ViewerState& viewer, ViewerData& data) {
    if (data.frame < 0) return false;
    unsigned const mask = viewerStatsMask(viewer);
    RangeSkip const skip = viewerSkip(viewer.kind);
    if (viewer.regionFitRequested) {
        viewer.regionFitRequested = false;
        ImageStats const r = imageStats(data.values, mask, viewer.region, skip);
        if (r.shown.finite > 0 && viewerRemaps(viewer.kind)) {
            viewer.rangeMin = r.shown.min;
            viewer.rangeMax = std::max(r.shown.max, r.shown.min + 1e-6f);
            viewer.autoFit = false;
        }
    }
    StatsInputs const in{mask, viewer.rangeMin, viewer.rangeMax, viewer.region, viewer.diffThreshold, viewer.diffMode};
    if (data.computedFor == in) return false;
    bool const newValues = !data.computedFor || data.computedFor->mask != mask;
    data.computedFor = in;
    data.stats = imageStats(data.values, mask, {}, skip);
    data.regionStats = viewer.region ? imageStats(data.values, mask, viewer.region, skip) : ImageStats{};
    data.clip = clipCounts(data.values, mask, viewer.rangeMin, viewer.rangeMax, {}, skip);
    // The histogram spans the data (0.1-99.9 %, so a few outliers do not squash it) and the
    // black/white points, so both are always on it.
    if (newValues || data.histogram.bins.empty() || viewer.rangeMin < data.histLo || viewer.rangeMax > data.histHi) {
        ValueRange const span = percentileRange(data.values, mask, 0.1f, 99.9f, {}, skip);
        float lo = span.samples > 0 ? span.min : 0.0f, hi = span.samples > 0 ? span.max : 1.0f;
        if (viewerRemaps(viewer.kind)) {
            lo = std::min(lo, viewer.rangeMin);
            hi = std::max(hi, viewer.rangeMax);
        }
        float const pad = (hi - lo) * 0.02f;
        data.histLo = lo - pad;
        data.histHi = std::max(hi + pad, data.histLo + 1e-6f);
    }
    data.histogram = histogram(data.values, mask, data.histLo, data.histHi, 128, {}, skip);
    bool const diffable = data.pinned && viewer.showDiff;
    data.diff =
        diffable ? diffImages(data.values, *data.pinned, mask, viewer.diffThreshold, viewer.diffMode) : DiffStats{};
    return diffable;
}

std::vector<std::uint8_t> diffHeatmap(DiffStats const& diff, float scale) {
    std::vector<std::uint8_t> rgba;
    rgba.reserve(diff.diff.pixels.size() * 4);
    auto byte = [](float v) { return std::uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); };
    for (float const d : diff.diff.pixels) {
        // Exactly equal stays black, so "nothing changed" reads at a glance.
        glm::vec3 const c = !std::isfinite(d) ? glm::vec3(1.0f, 0.0f, 1.0f)
                            : d == 0.0f       ? glm::vec3(0.0f)
                                              : colormap(Colormap::Turbo, scale > 0.0f ? d / scale : 1.0f);
        rgba.insert(rgba.end(), {byte(c.r), byte(c.g), byte(c.b), 255});
    }
    return rgba;
}

glm::vec3 shownTexelColour(ViewerState const& v, FloatImage const& values, int x, int y) {
    auto remap = [&](float value) {
        if (!viewerRemaps(v.kind)) return value;
        return (value - v.rangeMin) / std::max(v.rangeMax - v.rangeMin, 1e-20f);
    };
    // Normals are shown as directions (biased or absolute), as the view pass does.
    auto shown = [&](float value) {
        if (v.kind != ViewerKind::Normal) return remap(value);
        return v.normalDisplay == NormalDisplay::Absolute ? std::abs(value) : value * 0.5f + 0.5f;
    };
    unsigned const mask = viewerStatsMask(v);
    glm::vec3 c{0.0f};
    bool nan = false, inf = false, negative = false, below = false, above = false;
    for (int ch = 0; ch < 4; ++ch) {
        if (!(mask & (1u << ch))) continue;
        float const raw = values.at(x, y, ch);
        nan = nan || std::isnan(raw);
        inf = inf || std::isinf(raw);
        if (std::isnan(raw)) continue;
        negative = negative || raw < 0.0f;
        float const t = shown(raw);
        below = below || t < 0.0f;
        above = above || t > 1.0f;
    }
    if (std::popcount(mask) == 1) {
        c = colormap(v.colormap, shown(values.at(x, y, std::countr_zero(mask))));
    } else {
        for (int ch = 0; ch < 3; ++ch)
            if (mask & (1u << ch)) c[ch] = std::clamp(shown(values.at(x, y, ch)), 0.0f, 1.0f);
    }
    // Overlays win, in the shader's order (shaders/view_tools.glsl, viewTools).
    if ((v.overlays & kOverlayNaN) && nan) return {1.0f, 0.0f, 1.0f};
    if ((v.overlays & kOverlayInf) && inf) return {0.0f, 1.0f, 0.0f};
    if ((v.overlays & kOverlayNegative) && negative) return {0.0f, 1.0f, 1.0f};
    if ((v.overlays & kOverlayClip) && below && viewerRemaps(v.kind)) return {0.0f, 0.0f, 1.0f};
    if ((v.overlays & kOverlayClip) && above && viewerRemaps(v.kind)) return {1.0f, 0.0f, 0.0f};
    return glm::clamp(c, glm::vec3(0.0f), glm::vec3(1.0f));
}

std::vector<std::uint8_t> viewerPicture(ViewerState const& viewer, FloatImage const& values) {
    std::vector<std::uint8_t> rgba;
    rgba.reserve(std::size_t(values.width) * std::size_t(values.height) * 4);
    auto byte = [](float v) { return std::uint8_t(std::lround(v * 255.0f)); };
    for (int y = 0; y < values.height; ++y)
        for (int x = 0; x < values.width; ++x) {
            glm::vec3 const c = shownTexelColour(viewer, values, x, y);
            rgba.insert(rgba.end(), {byte(c.r), byte(c.g), byte(c.b), 255});
        }
    return rgba;
}

void syncViewers(GBufferPanelState& panel, std::size_t from) {
    for (auto& v : panel.viewers) {
        v.zoom = panel.viewers[from].zoom;
        v.center = panel.viewers[from].center;
    }
}

bool litPinDue(LitPin const& pin, long frame) {
    if (pin.pinRequested) return true;
    if (!pin.showDiff) return false;
    // Diff just turned on: at once, unless the frame size changed since the pin (then it waits).
    bool const sameSize =
        pin.pinned && pin.values.width == pin.pinned->width && pin.values.height == pin.pinned->height;
    if (pin.pinned && !pin.diff.comparable && sameSize) return true;
    return pin.frame < 0 || frame - pin.frame >= kViewerDataInterval;
}

void setLitValues(LitPin& pin, FloatImage lighting, long frame) {
    pin.values = std::move(lighting);
    pin.frame = frame;
    if (pin.pinRequested) {
        pin.pinRequested = false;
        pin.pinned = pin.values;
        pin.pinnedFrame = frame;
        pin.pinnedName.clear();
    }
    unsigned const rgb = 0x7;
    pin.stats = imageStats(pin.values, rgb, {}, RangeSkip::None);
    pin.diff = pin.pinned && pin.showDiff ? diffImages(pin.values, *pin.pinned, rgb, pin.diffThreshold, pin.diffMode)
                                          : DiffStats{};
    pin.diffFor = std::pair(pin.diffThreshold, pin.diffMode);
}

bool updateLitDiff(LitPin& pin) {
    if (!pin.pinned || !pin.showDiff || pin.frame < 0) return false;
    if (pin.diffFor == std::pair(pin.diffThreshold, pin.diffMode)) return false;
    pin.diff = diffImages(pin.values, *pin.pinned, 0x7, pin.diffThreshold, pin.diffMode);
    pin.diffFor = std::pair(pin.diffThreshold, pin.diffMode);
    return true;
}

std::string storedFloatText(float value) {
    std::uint32_t bits = 0;
    std::memcpy(&bits, &value, sizeof bits);
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.9g (bits 0x%08x)", double(value), unsigned(bits));
    return buf;
}

}  // namespace gbl::ui
