// Parsing of command-line values shared by the sub-commands.
#pragma once

#include <optional>
#include <string>

namespace gbl {

struct Size2 {
    int width = 0;
    int height = 0;
};

// Largest frame the commands accept on either side (GL_MAX_TEXTURE_SIZE is at least 16384 on
// the drivers we target; larger requests are refused rather than attempted).
inline constexpr int kMaxFrameSide = 16384;

// "1280x720" -> {1280, 720}. Returns an error sentence for anything else, 0 or over the limit.
std::optional<Size2> parseSize(std::string const& text, std::string* error);

}  // namespace gbl
