// Loading the UI font with the glyph ranges the program prints.
#include "panels/fonts.h"

#include <cstdio>

#ifndef GBL_UI_FONT_PATH
#define GBL_UI_FONT_PATH "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"
#endif

namespace gbl::ui {

char const* uiFontPath() {
    return GBL_UI_FONT_PATH;
}

ImWchar const* uiGlyphRanges() {
    static ImWchar const ranges[] = {
        0x0020, 0x00FF,  // Basic Latin and Latin-1
        0x0370, 0x03FF,  // Greek
        0x1D00, 0x1DBF,  // phonetic extensions (the modifier letters: superscript k)
        0x2000, 0x206F,  // general punctuation
        0x2070, 0x209F,  // superscripts and subscripts
        0x2190, 0x21FF,  // arrows
        0x2200, 0x22FF,  // mathematical operators
        0x2300, 0x23FF,  // miscellaneous technical
        0,
    };
    return ranges;
}

std::optional<std::string> loadUiFont(char const* path) {
    ImFontAtlas* atlas = ImGui::GetIO().Fonts;
    // ImGui would assert on a missing file: look first.
    std::string why = " is missing (apt install fonts-dejavu-core)";
    if (std::FILE* f = std::fopen(path, "rb")) {
        std::fclose(f);
        if (atlas->AddFontFromFileTTF(path, kUiFontPixels)) return std::nullopt;
        atlas->Clear();
        why = " could not be read";
    }
    atlas->AddFontDefault();
    return "The UI font " + std::string(path) + why +
           "; using ImGui's built-in font, which shows non-ASCII characters as \"?\".";
}

void applyUiScale(ImGuiStyle const& base, float uiScale, float contentScale) {
    float const dpi = contentScale > 0.0f ? contentScale : 1.0f;
    ImGuiStyle style = base;  // a fresh copy: scaling the current style again would compound
    if (uiScale * dpi != 1.0f) style.ScaleAllSizes(uiScale * dpi);
    style.FontSizeBase = kUiFontPixels;
    style.FontScaleMain = uiScale;
    style.FontScaleDpi = dpi;
    ImGui::GetStyle() = style;
}

float uiScaleFactor() {
    return ImGui::GetFontSize() / kUiFontPixels;
}

}  // namespace gbl::ui
