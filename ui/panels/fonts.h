// The UI font: DejaVu Sans (Debian's fonts-dejavu-core) with the glyphs the lessons, the docs
// strings and the units use, or ImGui's built-in font where the file is missing.
#pragma once

#include <imgui.h>

#include <optional>
#include <string>

namespace gbl::ui {

// The font file the build found (CMake's GBL_UI_FONT), or Debian's path.
char const* uiFontPath();

// Zero-terminated pairs of first, last code point: Latin-1 (· × ° ± ² ³ ¹ ÷), Greek (Σ θ π),
// punctuation (— – … ›), super- and subscripts (⁻ ⁶ ⁸), arrows (→ ⇔), mathematical operators
// (− ≤ ≥ ≈ √ ∑) and the ceiling/floor brackets (⌈ ⌉ ⌊ ⌋), and the modifier letters (ᵏ).
ImWchar const* uiGlyphRanges();

// Loads the UI font at `pixels` from `path`; nullopt when it loaded, else one sentence saying the
// built-in font is used instead (that font has ASCII only: other characters print as "?").
std::optional<std::string> loadUiFont(char const* path, float pixels = 13.0f);

}  // namespace gbl::ui
