// One table of ViewerState's settings: the key in session and lesson files, the kind, the range, the
// help line. The session reader and writer and the copy of a viewer's settings out of a session go
// through it, so a setting has one name and one range everywhere (the PipelineSettings table is
// core/pipeline_fields.h). What a viewer learns at run time (image size, last fit, picked pixel,
// region, requests) is not a setting and has no entry. tests/viewer_fields_test.cpp fails to
// compile when ViewerState gains a member, and fails when a setting member has no entry.
#pragma once

#include "model/viewer_state.h"

#include <array>
#include <span>
#include <string_view>

namespace gbl::ui {

inline constexpr std::array<std::string_view, 2> kNormalDisplayNames{"biased", "absolute"};
// The overlay bits (core/view_params.h kOverlay*) in bit order.
inline constexpr std::array<std::string_view, 4> kOverlayNames{"nan", "inf", "negative", "clip"};

enum class ViewerFieldKind {
    Mask,    // a whole number in [min, max]: the channel mask
    Number,  // a finite float in [min, max], > 0 when `positive`
    Toggle,  // a bool
    Choice,  // an enum: one of `names`, in enum order
    Flags,   // a set of bits: a list of `names`, bit i for names[i]
};

// Every value travels as a double: the number, 0/1, an enum's index, the bits.
struct ViewerField {
    std::string_view key;  // in files; a vector's components share it ("center": [x, y])
    int component = -1;    // -1: a scalar; else this component of the key's array
    bool inTools = false;  // written under the viewer's "tools" object (every tool field is optional there)
    ViewerFieldKind kind = ViewerFieldKind::Number;
    float min = 0.0f, max = 1.0f;             // Mask and Number: the values files accept
    bool positive = false;                    // Number: zero is refused too
    std::span<std::string_view const> names;  // Choice and Flags
    bool viewport = true;   // the viewport's tools keep it too (they have no zoom, pan or linear switch)
    std::string_view help;  // one line, for tooltips and docs
    double (*get)(ViewerState const&) = nullptr;
    void (*set)(ViewerState&, double) = nullptr;

    // Whether a value is inside the field's range (false for NaN and infinities).
    bool accepts(double v) const;
};

std::span<ViewerField const> viewerFields();
// The entry with this key (a vector's first component), or nullptr.
ViewerField const* findViewerField(std::string_view key);
// The keys of a viewer's object in files, in table order ("tools" once, where the tools begin).
std::span<std::string_view const> viewerFileKeys();
// The keys of its "tools" object.
std::span<std::string_view const> viewerToolKeys();

// Copies the settings `viewerFields()` lists from one viewer to another, leaving what `to` learnt at
// run time; `viewport` copies only the fields the viewport's tools keep. The stencil view is a depth
// viewer's only: another kind keeps it off, and a depth viewer that turns it on starts the depth's
// range (waiting in otherRange) at the depth viewer's default.
void copyViewerSettings(ViewerState const& from, ViewerState& to, bool viewport = false);

}  // namespace gbl::ui
