// Command-line value parsing.
#include "cli_values.h"

#include <charconv>

namespace gbl {

std::optional<Size2> parseSize(std::string const& text, std::string* error) {
    auto const x = text.find('x');
    Size2 s;
    auto parse = [](std::string_view part, int& out) {
        auto [ptr, ec] = std::from_chars(part.data(), part.data() + part.size(), out);
        return ec == std::errc() && ptr == part.data() + part.size();
    };
    std::string_view const all(text);
    if (x == std::string::npos || !parse(all.substr(0, x), s.width) || !parse(all.substr(x + 1), s.height)) {
        *error = "--size must look like 1280x720, got '" + text + "'";
        return std::nullopt;
    }
    if (s.width <= 0 || s.height <= 0) {
        *error = "--size must be at least 1x1, got '" + text + "'";
        return std::nullopt;
    }
    if (s.width > kMaxFrameSide || s.height > kMaxFrameSide) {
        *error = "--size is limited to " + std::to_string(kMaxFrameSide) + " on each side, got '" + text + "'";
        return std::nullopt;
    }
    return s;
}

}  // namespace gbl
