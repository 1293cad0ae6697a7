// The checks of an imported G-buffer (docs/import.md, "Checks"): each finding counts its pixels,
// marks them in a mask and names the likely bug in one sentence.
#pragma once

#include "import/imported_gbuffer.h"

#include <cstdint>
#include <string>
#include <vector>

namespace gbl {

struct GBufferFinding {
    std::string check;       // "normal_not_unit", ... (docs/import.md lists them)
    std::string attachment;  // the manifest field it concerns
    std::size_t pixels = 0;
    double share = 0.0;  // pixels / the geometry pixels (nan_inf, no_background: / every pixel of the frame)
    std::string cause;   // one sentence naming the likely bug
    bool heuristic = false;
    std::vector<std::uint8_t> mask;  // width * height, 1 where the finding applies
};

// What one attachment's storage can hold: its step, and for normals the highlight error it causes.
struct PrecisionNote {
    std::string attachment;
    std::string storage;  // "8-bit unsigned", ...
    double step = 0.0;    // storageStep(): one level, or one ulp at 1
    // Normals only: the largest error of (N.H)^shininess over the highlight that the normal's
    // quantisation causes, as a fraction of the peak (0 for other attachments).
    double highlightError = 0.0;
    double shininess = 0.0;  // the manifest's, which highlightError is worked out at (normals only)
};

struct GBufferCheckReport {
    int width = 0;
    int height = 0;
    std::size_t geometryPixels = 0;    // neither background nor NaN/Inf
    std::size_t backgroundPixels = 0;  // by the markers
    std::vector<GBufferFinding> findings;
    std::vector<PrecisionNote> precision;
};

// Highlight error over (N.H)^s, as a fraction of its peak, when the normal is off by `angle` radians.
double highlightError(double angle, double shininess);
// Largest angle a normal stored with `step` per component (in the stored range) may be off by.
double normalAngleError(NormalEncoding encoding, double step);

GBufferCheckReport checkGBuffer(ImportedGBuffer const& g);

// One line for a precision note, as `check` prints it and the editor's Checks list shows it:
// "normal: 8-bit unsigned, step 0.00392; a highlight of shininess 32 moves by up to 1.3 % of its peak".
std::string precisionLine(PrecisionNote const& note);

}  // namespace gbl
