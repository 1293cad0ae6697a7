// The ViewerState field table.
#include "model/viewer_fields.h"

#include "core/view_params.h"

#include <cmath>
#include <limits>
#include <vector>

namespace gbl::ui {

namespace {

static_assert(kOverlayNaN == 1 && kOverlayInf == 2 && kOverlayNegative == 4 && kOverlayClip == 8,
              "kOverlayNames lists the overlay bits in order");

constexpr float kHuge = std::numeric_limits<float>::max();

template <auto Member>
constexpr ViewerField number(std::string_view key, float min, float max, bool positive, bool viewport,
                             std::string_view help) {
    return {key,
            -1,
            false,
            ViewerFieldKind::Number,
            min,
            max,
            positive,
            {},
            viewport,
            help,
            [](ViewerState const& v) { return double(v.*Member); },
            [](ViewerState& v, double x) { v.*Member = float(x); }};
}

template <auto Member>
constexpr ViewerField toggle(std::string_view key, bool inTools, bool viewport, std::string_view help) {
    return {key,
            -1,
            inTools,
            ViewerFieldKind::Toggle,
            0.0f,
            1.0f,
            false,
            {},
            viewport,
            help,
            [](ViewerState const& v) { return (v.*Member) ? 1.0 : 0.0; },
            [](ViewerState& v, double x) { v.*Member = x != 0.0; }};
}

template <auto Member, std::size_t N>
constexpr ViewerField choice(std::string_view key, bool inTools, std::array<std::string_view, N> const& names,
                             std::string_view help) {
    return {key,
            -1,
            inTools,
            ViewerFieldKind::Choice,
            0.0f,
            float(N - 1),
            false,
            std::span<std::string_view const>(names.data(), names.size()),
            true,
            help,
            [](ViewerState const& v) { return double(int(v.*Member)); },
            [](ViewerState& v, double x) {
                using Enum = std::remove_reference_t<decltype(v.*Member)>;
                v.*Member = Enum(int(x));
            }};
}

template <int Component>
constexpr ViewerField centre() {
    return {"center",
            Component,
            false,
            ViewerFieldKind::Number,
            0.0f,
            1.0f,
            false,
            {},
            false,
            "image point (0..1, top-left origin) at the middle of the viewer when zoomed",
            [](ViewerState const& v) { return double(v.center[Component]); },
            [](ViewerState& v, double x) { v.center[Component] = float(x); }};
}

constexpr bool kViewportToo = true, kViewersOnly = false, kTools = true, kNotTools = false;

std::array<ViewerField, 16> const kFields{{
    {"channel_mask",
     -1,
     kNotTools,
     ViewerFieldKind::Mask,
     0.0f,
     15.0f,
     false,
     {},
     kViewportToo,
     "channels shown: bit 0 = R, 1 = G, 2 = B, 3 = A",
     [](ViewerState const& v) { return double(v.channelMask); },
     [](ViewerState& v, double x) { v.channelMask = unsigned(x); }},
    number<&ViewerState::rangeMin>("range_min", -kHuge, kHuge, false, kViewportToo, "value shown black"),
    number<&ViewerState::rangeMax>("range_max", -kHuge, kHuge, false, kViewportToo,
                                   "value shown white; above range_min"),
    toggle<&ViewerState::autoFit>("auto_fit", kNotTools, kViewportToo,
                                  "refit the range to the data about once a second"),
    choice<&ViewerState::normalDisplay>("normal_display", kNotTools, kNormalDisplayNames,
                                        "normals as 0.5 n + 0.5 (biased) or |n| (absolute)"),
    toggle<&ViewerState::linearDepth>("linear_depth", kNotTools, kViewersOnly,
                                      "depth viewer: eye distance instead of window depth"),
    toggle<&ViewerState::cameraClipPlanes>("camera_clip_planes", kNotTools, kViewportToo,
                                           "linearise depth with the camera's near and far planes"),
    number<&ViewerState::nearPlane>("near", 0.0f, kHuge, true, kViewportToo,
                                    "near plane for linear depth when not the camera's"),
    number<&ViewerState::farPlane>("far", 0.0f, kHuge, true, kViewportToo,
                                   "far plane for linear depth when not the camera's; above near"),
    number<&ViewerState::zoom>("zoom", 1.0f, 256.0f, false, kViewersOnly,
                               "1 = the whole image fits the viewer; up to 256 screen pixels per texel"),
    centre<0>(),
    centre<1>(),
    choice<&ViewerState::colormap>("colormap", kTools, kColormapNames, "colours of a single shown channel"),
    {"overlays", -1, kTools, ViewerFieldKind::Flags, 0.0f, 15.0f, false,
     std::span<std::string_view const>(kOverlayNames.data(), kOverlayNames.size()), kViewportToo,
     "mark NaN, Inf, negative and clipped pixels", [](ViewerState const& v) { return double(v.overlays); },
     [](ViewerState& v, double x) { v.overlays = unsigned(x); }},
    toggle<&ViewerState::showHistogram>("histogram", kTools, kViewportToo, "histogram under the image"),
    toggle<&ViewerState::showStencil>("stencil", kTools, kViewportToo,
                                      "depth viewer: the stencil bits instead of the depth"),
}};

// The keys of a viewer's object (tools = false: "tools" once, where the tool fields begin) or of its
// "tools" object, in table order, a vector's key once.
std::vector<std::string_view> fileKeys(bool tools) {
    std::vector<std::string_view> out;
    for (ViewerField const& f : kFields) {
        if (tools && !f.inTools) continue;
        std::string_view const key = !tools && f.inTools ? std::string_view("tools") : f.key;
        if (out.empty() || out.back() != key) out.push_back(key);
    }
    return out;
}

}  // namespace

bool ViewerField::accepts(double v) const {
    if (!std::isfinite(v)) return false;
    switch (kind) {
        case ViewerFieldKind::Toggle:
            return v == 0.0 || v == 1.0;
        case ViewerFieldKind::Choice:
            return v == std::floor(v) && v >= 0.0 && v < double(names.size());
        case ViewerFieldKind::Flags:
            return v == std::floor(v) && v >= 0.0 && v < double(1u << names.size());
        case ViewerFieldKind::Mask:
            return v == std::floor(v) && v >= double(min) && v <= double(max);
        case ViewerFieldKind::Number:
            break;
    }
    return v >= double(min) && v <= double(max) && (!positive || float(v) > 0.0f);
}

std::span<ViewerField const> viewerFields() {
    return kFields;
}

ViewerField const* findViewerField(std::string_view key) {
    for (ViewerField const& f : kFields)
        if (f.key == key) return &f;
    return nullptr;
}

std::span<std::string_view const> viewerFileKeys() {
    static std::vector<std::string_view> const k = fileKeys(false);
    return k;
}

std::span<std::string_view const> viewerToolKeys() {
    static std::vector<std::string_view> const k = fileKeys(true);
    return k;
}

void copyViewerSettings(ViewerState const& from, ViewerState& to, bool viewport) {
    bool const stencilBefore = to.showStencil;
    for (ViewerField const& f : kFields)
        if (!viewport || f.viewport) f.set(to, f.get(from));
    if (to.kind != ViewerKind::Depth) {
        to.showStencil = false;
    } else if (to.showStencil && !stencilBefore) {
        // The range copied is the stencil's; the depth's waits in otherRange, at its default.
        ViewerState const depth = GBufferPanelState::defaultViewers()[std::size_t(ViewerKind::Depth)];
        to.otherRange = glm::vec2(depth.rangeMin, depth.rangeMax);
    }
}

}  // namespace gbl::ui
