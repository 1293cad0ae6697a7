// Loading the UI font with the glyph ranges the program prints.
#include "panels/fonts.h"

#include <cstdio>

#ifndef GBL_UI_FONT_PATH
#define GBL_UI_FONT_PATH "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"
#endif

namespace gbl::ui {

namespace {
// ImGui's built-in font, at `pixels` (it is drawn for 13: other sizes are scaled, blurrier).
void addDefaultFont(ImFontAtlas& atlas, float pixels) {
    ImFontConfig config;
    config.SizePixels = pixels;
    atlas.AddFontDefault(&config);
}
}  // namespace

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

std::optional<std::string> loadUiFont(char const* path, float pixels) {
    ImFontAtlas* atlas = ImGui::GetIO().Fonts;
    // ImGui would assert on a missing file: look first.
    if (std::FILE* f = std::fopen(path, "rb")) {
        std::fclose(f);
        ImFontConfig config;
        config.OversampleH = 2;  // the 1.86 default is 3: a smaller atlas, the same look at 1x
        if (atlas->AddFontFromFileTTF(path, pixels, &config, uiGlyphRanges())) return std::nullopt;
        atlas->Clear();
        addDefaultFont(*atlas, pixels);
        return "The UI font " + std::string(path) +
               " could not be read; using ImGui's built-in font, which shows non-ASCII characters as \"?\".";
    }
    addDefaultFont(*atlas, pixels);
    return "The UI font " + std::string(path) +
           " is missing (apt install fonts-dejavu-core); using ImGui's built-in font, which shows non-ASCII "
           "characters as \"?\".";
}

std::optional<std::string> applyUiScale(ImGuiStyle const& base, float uiScale, float contentScale, char const* path) {
    float const scale = uiScale * (contentScale > 0.0f ? contentScale : 1.0f);
    ImGuiStyle style = base;  // a fresh copy: scaling the current style again would compound
    if (scale != 1.0f) style.ScaleAllSizes(scale);
#if IMGUI_VERSION_NUM >= 19200
    style.FontScaleMain = uiScale;
    style.FontScaleDpi = contentScale;
    ImGui::GetStyle() = style;
    (void)path;
    return std::nullopt;
#else
    ImGui::GetStyle() = style;
    ImGui::GetIO().FontGlobalScale = contentScale > 0.0f ? contentScale : 1.0f;
    ImGui::GetIO().Fonts->Clear();
    return loadUiFont(path, kUiFontPixels * uiScale);
#endif
}

float uiScaleFactor() {
    return ImGui::GetFontSize() / kUiFontPixels;
}

}  // namespace gbl::ui
