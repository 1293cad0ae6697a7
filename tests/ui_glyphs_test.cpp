// Every character the UI can show is in the UI font's glyph ranges (issue 26): the lesson files'
// strings and the UI sources' text, so a new "⇔" in a lesson fails here, not as "?" on screen; and
// the font file itself (DejaVu Sans) has a glyph for every character of the lessons and glossary.
#include "panels/fonts.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

using namespace gbl::ui;
namespace fs = std::filesystem;

namespace {

std::string readFile(fs::path const& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// Code points of UTF-8 text; a malformed byte is returned as 0xFFFD.
std::vector<char32_t> codePoints(std::string const& text) {
    std::vector<char32_t> out;
    for (std::size_t i = 0; i < text.size();) {
        unsigned char const c = static_cast<unsigned char>(text[i]);
        int const extra = c < 0x80 ? 0 : (c >> 5) == 0x6 ? 1 : (c >> 4) == 0xE ? 2 : (c >> 3) == 0x1E ? 3 : -1;
        if (extra < 0 || i + std::size_t(extra) >= text.size()) {
            out.push_back(0xFFFD);
            ++i;
            continue;
        }
        char32_t cp = extra == 0 ? c : extra == 1 ? (c & 0x1F) : extra == 2 ? (c & 0x0F) : (c & 0x07);
        for (int k = 1; k <= extra; ++k) cp = (cp << 6) | (static_cast<unsigned char>(text[i + std::size_t(k)]) & 0x3F);
        out.push_back(cp);
        i += std::size_t(extra) + 1;
    }
    return out;
}

bool inRanges(char32_t cp) {
    if (cp == '\n' || cp == '\t' || cp == '\r') return true;  // layout, not glyphs
    for (ImWchar const* r = uiGlyphRanges(); r[0] != 0; r += 2)
        if (cp >= r[0] && cp <= r[1]) return true;
    return false;
}

void collectStrings(nlohmann::json const& j, std::string& out) {
    if (j.is_string()) {
        out += j.get<std::string>();
        out += '\n';
    } else if (j.is_array() || j.is_object()) {
        for (auto const& item : j) collectStrings(item, out);
    }
}

// "U+21D4 in FILE" for each character of `text` outside the ranges.
void expectCovered(std::string const& text, std::string const& where) {
    for (char32_t cp : codePoints(text))
        EXPECT_TRUE(inRanges(cp)) << "U+" << std::hex << std::uppercase << std::uint32_t(cp) << " in " << where
                                  << ": add its block to uiGlyphRanges (ui/panels/fonts.cpp)";
}

}  // namespace

TEST(UiGlyphs, RangesAreSortedPairsEndingInZero) {
    ImWchar const* r = uiGlyphRanges();
    int pairs = 0;
    for (; r[0] != 0; r += 2, ++pairs) EXPECT_LE(r[0], r[1]);
    EXPECT_GT(pairs, 1);
}

TEST(UiGlyphs, TheOnesTheIssueNamedAreIn) {
    for (char32_t cp : codePoints("Σ − → ≤ ≥ ⇔ … — · ² θ π"))
        EXPECT_TRUE(inRanges(cp)) << std::hex << std::uint32_t(cp);
}

TEST(UiGlyphs, EveryLessonStringIsCovered) {
    int files = 0;
    for (auto const& entry : fs::directory_iterator(fs::path(GBL_SOURCE_DIR) / "assets" / "lessons")) {
        if (entry.path().extension() != ".json") continue;
        ++files;
        std::string text;
        collectStrings(nlohmann::json::parse(readFile(entry.path())), text);
        expectCovered(text, entry.path().filename().string());
    }
    EXPECT_GT(files, 0);
}

TEST(UiGlyphs, EveryGlossaryStringIsCovered) {
    fs::path const path = fs::path(GBL_SOURCE_DIR) / "assets" / "glossary.json";
    std::string text;
    collectStrings(nlohmann::json::parse(readFile(path)), text);
    expectCovered(text, "glossary.json");
    EXPECT_GT(text.size(), 100u);
}

TEST(UiGlyphs, EveryCharacterOfTheUiSourcesIsCovered) {
    // Whole files, comments included: stricter than the strings alone, and simpler.
    int files = 0;
    for (char const* folder : {"ui", "app"})
        for (auto const& entry : fs::recursive_directory_iterator(fs::path(GBL_SOURCE_DIR) / folder)) {
            fs::path const& p = entry.path();
            if (p.extension() != ".cpp" && p.extension() != ".h") continue;
            ++files;
            expectCovered(readFile(p), p.lexically_relative(GBL_SOURCE_DIR).string());
        }
    EXPECT_GT(files, 10);
}

// ImGui 1.92 loads glyphs as they are drawn, from the whole font: what matters is that the file has
// them. Every lesson and glossary character, asked of the font ImGui loads (loadUiFont).
TEST(UiGlyphs, TheUiFontHasEveryLessonAndGlossaryCharacter) {
    if (!fs::exists(uiFontPath())) GTEST_SKIP() << uiFontPath() << " is not installed (fonts-dejavu-core)";
    ImGui::CreateContext();
    ASSERT_EQ(loadUiFont(uiFontPath()), std::nullopt);
    ImFont* font = ImGui::GetIO().Fonts->Fonts[0];
    std::string text;
    for (auto const& entry : fs::directory_iterator(fs::path(GBL_SOURCE_DIR) / "assets" / "lessons"))
        if (entry.path().extension() == ".json") collectStrings(nlohmann::json::parse(readFile(entry.path())), text);
    collectStrings(nlohmann::json::parse(readFile(fs::path(GBL_SOURCE_DIR) / "assets" / "glossary.json")), text);
    int checked = 0;
    for (char32_t cp : codePoints(text)) {
        if (cp < 0x20) continue;  // line breaks and tabs: layout, not glyphs
        ++checked;
        EXPECT_TRUE(font->IsGlyphInFont(ImWchar(cp)))
            << "U+" << std::hex << std::uppercase << std::uint32_t(cp) << " is not in " << uiFontPath();
    }
    EXPECT_GT(checked, 1000);
    ImGui::DestroyContext();
}
