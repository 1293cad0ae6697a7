// Shared by the glTF loader's source files only: how a load fails or is cancelled, message helpers.
#pragma once

#include "gltf/loader.h"

#include <algorithm>
#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <utility>

namespace gbl::gltf {

// Thrown inside the loader only; loadGltf turns it into the one-sentence error.
struct LoadFailure {
    std::string cause;
};
struct LoadCancelled {};

[[noreturn]] inline void fail(std::string cause) {
    throw LoadFailure{std::move(cause)};
}

inline std::string num(std::size_t v) {
    return std::to_string(v);
}

// Keeps messages to one readable line: no control bytes, no multi-kilobyte data URIs.
inline std::string printable(std::string_view s, std::size_t maxLen = 120) {
    std::string out;
    for (char c : s) {
        if (out.size() >= maxLen) {
            out += "...";
            break;
        }
        unsigned char const u = static_cast<unsigned char>(c);
        out += (u < 0x20 || u == 0x7f) ? ' ' : c;
    }
    while (!out.empty() && (out.back() == ' ' || out.back() == '.')) out.pop_back();
    return out;
}

// Reports progress to the caller's callback; a `false` from it cancels the load.
class Progress {
public:
    explicit Progress(GltfLoadOptions const& o) : callback_(o.progress) {}
    void report(float fraction, std::string_view stage) {
        if (callback_ && !callback_(std::clamp(fraction, 0.0f, 1.0f), stage)) throw LoadCancelled{};
    }

private:
    std::function<bool(float, std::string_view)> const& callback_;
};

}  // namespace gbl::gltf
