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
inline constexpr float kUiFontPixels = 13.0f;
std::optional<std::string> loadUiFont(char const* path, float pixels = kUiFontPixels);

// Applies a UI scale (model/ui_scale.h) to the current context: `base` (the unscaled style)
// scaled by uiScale * contentScale replaces the style, never the style scaled again; the font
// atlas is rebuilt at kUiFontPixels * uiScale from `path` (ImGui 1.92 sizes fonts itself: only the
// scale is set). With ImGui before 1.92 the caller must recreate the renderer backend's font
// texture before the next frame (ImGui_ImplOpenGL3_DestroyDeviceObjects). Call between frames.
// Returns loadUiFont's warning, if any.
std::optional<std::string> applyUiScale(ImGuiStyle const& base, float uiScale, float contentScale, char const* path);

// The scale the UI is drawn at now (UI scale times monitor content scale), from the font's size:
// layout sizes given in pixels at scale 1 are multiplied by this.
float uiScaleFactor();

}  // namespace gbl::ui
