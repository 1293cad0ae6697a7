// Defaults of the G-buffer viewers and the view each one asks for.
#include "model/viewer_state.h"

#include "core/depth.h"

namespace gbl::ui {

std::array<ViewerState, 5> GBufferPanelState::defaultViewers() {
    std::array<ViewerState, 5> v;
    for (std::size_t i = 0; i < v.size(); ++i) v[i].kind = ViewerKind(i);
    // Positions are world units, not colours: start with a range that shows a scene of a few
    // tens of units and refit to the data.
    v[0].rangeMin = -20.0f;
    v[0].rangeMax = 20.0f;
    v[0].autoFit = true;
    v[3].channelMask = 0x1;  // specular is one value, drawn as grey
    v[4].channelMask = 0x1;
    v[4].autoFit = true;
    return v;
}

ViewerState ViewportTools::defaultViewer() {
    ViewerState v;
    v.autoFit = true;  // the viewport switches between attachments of very different ranges
    return v;
}

std::optional<ViewerKind> viewerKindOfView(DebugView view) {
    switch (view) {
        case DebugView::Position:
            return ViewerKind::Position;
        case DebugView::Normal:
            return ViewerKind::Normal;
        case DebugView::Albedo:
            return ViewerKind::Albedo;
        case DebugView::Specular:
            return ViewerKind::Specular;
        case DebugView::Depth:
        case DebugView::DepthLinear:
            return ViewerKind::Depth;
        case DebugView::Lighting:
            return ViewerKind::Lighting;
        default:
            return std::nullopt;
    }
}

bool followViewportView(ViewportTools& tools, DebugView view) {
    std::optional<ViewerKind> const kind = viewerKindOfView(view);
    if (!kind) return false;
    ViewerState& v = tools.viewer;
    if (v.kind != *kind) {
        // Another attachment: its own channels and a fresh fit, not the last one's range.
        v.kind = *kind;
        v.channelMask = *kind == ViewerKind::Specular || *kind == ViewerKind::Depth ? 0x1u : 0x7u;
        v.lastFitFrame = -1;
        v.region.reset();
        v.picked.reset();
        v.showDiff = false;
        tools.data = ViewerData{};
    }
    if (*kind == ViewerKind::Depth) v.linearDepth = view == DebugView::DepthLinear;
    v.showStencil = false;  // the viewport's depth views are depths; the stencil is in the G-buffer window
    return true;
}

void setShowStencil(ViewerState& viewer, bool on) {
    if (viewer.showStencil == on) return;
    viewer.showStencil = on;
    glm::vec2 const shown(viewer.rangeMin, viewer.rangeMax);
    viewer.rangeMin = viewer.otherRange.x;
    viewer.rangeMax = viewer.otherRange.y;
    viewer.otherRange = shown;
    viewer.lastFitFrame = -1;  // auto-fit refits the new values at once
}

DebugView viewerDebugView(ViewerState const& viewer) {
    switch (viewer.kind) {
        case ViewerKind::Position:
            return DebugView::Position;
        case ViewerKind::Normal:
            return DebugView::Normal;
        case ViewerKind::Albedo:
            return DebugView::Albedo;
        case ViewerKind::Specular:
            return DebugView::Specular;
        case ViewerKind::Depth:
            return viewer.linearDepth ? DebugView::DepthLinear : DebugView::Depth;
        case ViewerKind::Lighting:
            return DebugView::Lighting;
    }
    return DebugView::Final;
}

ViewParams viewerParams(ViewerState const& viewer) {
    ViewParams p;
    p.view = viewerDebugView(viewer);
    p.channelMask = viewer.channelMask == 0 ? 0x7u : viewer.channelMask;
    p.rangeMin = viewer.rangeMin;
    p.rangeMax = viewer.rangeMax;
    p.normalDisplay = viewer.normalDisplay;
    p.colormap = viewer.colormap;
    p.overlays = viewer.overlays;
    return p;
}

Attachment viewerAttachment(ViewerKind kind) {
    switch (kind) {
        case ViewerKind::Position:
            return Attachment::Position;
        case ViewerKind::Normal:
            return Attachment::Normal;
        case ViewerKind::Albedo:
        case ViewerKind::Specular:
            return Attachment::AlbedoSpec;
        case ViewerKind::Depth:
            return Attachment::Depth;
        case ViewerKind::Lighting:
            return Attachment::Lighting;
    }
    return Attachment::Position;
}

Attachment viewerAttachment(ViewerState const& viewer) {
    return viewer.kind == ViewerKind::Depth && viewer.showStencil ? Attachment::Stencil : viewerAttachment(viewer.kind);
}

FloatImage viewerValues(ViewerState const& viewer, FloatImage const& attachment, float nearPlane, float farPlane) {
    if (viewer.kind == ViewerKind::Depth && viewer.showStencil && attachment.channels == 1) {
        FloatImage out{attachment.width, attachment.height, 4, {}};
        out.pixels.reserve(attachment.pixels.size() * 4);
        for (float const s : attachment.pixels) out.pixels.insert(out.pixels.end(), {s, s, 0.0f, 1.0f});
        return out;
    }
    if (viewer.kind != ViewerKind::Depth || attachment.channels != 1) return attachment;
    FloatImage out{attachment.width, attachment.height, 4, {}};
    out.pixels.reserve(attachment.pixels.size() * 4);
    for (float const d : attachment.pixels) {
        out.pixels.push_back(viewer.linearDepth ? linearDepth(d, nearPlane, farPlane) : d);
        out.pixels.push_back(d);
        out.pixels.push_back(0.0f);
        out.pixels.push_back(d < 1.0f ? 1.0f : 0.0f);  // the cleared depth is background
    }
    return out;
}

unsigned viewerStatsMask(ViewerState const& viewer) {
    switch (viewer.kind) {
        case ViewerKind::Specular:
            return 0x8u;
        case ViewerKind::Depth:
            return 0x1u;
        default:
            return viewer.channelMask == 0 ? 0x7u : viewer.channelMask;
    }
}

RangeSkip viewerSkip(ViewerKind kind) {
    // The lit frame's alpha is no coverage mark: every pixel counts (the background is lit black).
    return kind == ViewerKind::Albedo || kind == ViewerKind::Specular || kind == ViewerKind::Lighting
               ? RangeSkip::None
               : RangeSkip::ZeroAlpha;
}

std::string noGBufferNote(LightingMode mode, ViewerKind kind) {
    if (shadesForward(mode)) return "forward and forward+ write no G-buffer";
    if (mode == LightingMode::Prepass && kind == ViewerKind::Albedo)
        return "prepass keeps no albedo: its thin G-buffer holds normal, exponent and depth; the second geometry "
               "pass reads albedo from the materials";
    return {};
}

std::string thinGBufferSource(LightingMode mode, ViewerKind kind) {
    if (mode != LightingMode::Prepass) return {};
    switch (kind) {
        case ViewerKind::Position:
            return "rebuilt from the lit depth";
        case ViewerKind::Normal:
            return "prepass.normal_exp xyz";
        case ViewerKind::Specular:
            return "exponent: prepass.normal_exp w";
        case ViewerKind::Depth:
            return "lit depth (thin pass)";
        case ViewerKind::Albedo:
        case ViewerKind::Lighting:
            break;
    }
    return {};
}

}  // namespace gbl::ui
