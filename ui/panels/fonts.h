// The UI font: DejaVu Sans (Debian's fonts-dejavu-core) with the glyphs the lessons, the docs
// strings and the units use, or ImGui's built-in font where the file is missing.
#pragma once

#include <imgui.h>

#include <optional>
#include <string>

namespace gbl::ui {

// The font file the build found (CMake's GBL_UI_FONT), or Debian's path.
char const* uiFontPath();

// Zero-terminated pairs of first, last code point of the blocks the program prints: Latin-1 (· × °
// ± ² ³ ¹ ÷), Greek (Σ θ π), punctuation (— – … ›), super- and subscripts (⁻ ⁶ ⁸), arrows (→ ⇔),
// mathematical operators (− ≤ ≥ ≈ √ ∑), the ceiling/floor brackets (⌈ ⌉ ⌊ ⌋) and the modifier
// letters (ᵏ). ImGui 1.92 loads glyphs when first drawn, so the font is loaded with no ranges; these
// are the blocks ui_glyphs_test checks the lessons, the glossary and the font file against.
ImWchar const* uiGlyphRanges();

// Loads the UI font from `path` into the current context's atlas, once, before the first frame (ImGui
// 1.92 sizes it as drawn: style.FontSizeBase and the scales choose the size). nullopt when it loaded,
// else one sentence saying ImGui's built-in font is used instead (ASCII only: other characters print
// as "?").
inline constexpr float kUiFontPixels = 13.0f;
std::optional<std::string> loadUiFont(char const* path);

// Applies a UI scale (model/ui_scale.h) to the current context: `base` (the unscaled style)
// scaled by uiScale * contentScale replaces the style, never the style scaled again; the text is
// kUiFontPixels times uiScale (style.FontScaleMain) times contentScale (style.FontScaleDpi). The
// font is not reloaded: ImGui bakes glyphs at the new size and the renderer backend updates its
// textures itself (ImGuiBackendFlags_RendererHasTextures). Call between frames.
void applyUiScale(ImGuiStyle const& base, float uiScale, float contentScale);

// The scale the UI is drawn at now (UI scale times monitor content scale), from the font's size:
// layout sizes given in pixels at scale 1 are multiplied by this.
float uiScaleFactor();

}  // namespace gbl::ui
