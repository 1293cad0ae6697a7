// One call's GL state from the retracer (`-D CALL --dump-format=json`): uniforms, shaders, images.
#pragma once

#include "core/frame_types.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace gbl::capture {

struct DumpedImage {
    std::string format;    // the GL internal format the retracer names, e.g. GL_RGBA16F
    std::string encoded;   // the bytes as dumped: a PNG, or apitrace's float PNM (PF, PX, Pf)
    bool isFloat = false;  // the PNM kind: decode() gives its floats
    int width = 0, height = 0;
    FloatImage decode() const;  // rows top to bottom, as the retracer writes them
};

struct StateDump {
    nlohmann::json uniforms;                         // name -> value, as the retracer lists them
    std::map<std::string, std::string> shaders;      // GL_FRAGMENT_SHADER -> source
    std::map<int, DumpedImage> textures;             // texture unit -> its 2D level 0
    std::map<std::string, DumpedImage> framebuffer;  // GL_COLOR_ATTACHMENT0, GL_DEPTH_ATTACHMENT, GL_BACK, ...
};

// The retracer's JSON carries shader sources with raw line breaks; this escapes them first.
std::optional<StateDump> parseStateDump(std::string const& dump, std::string* error);

// Runs the retracer on `trace` at `call` (EGL traces: eglretrace on Mesa's surfaceless platform).
std::optional<StateDump> dumpState(std::string const& retracer, std::string const& trace, std::uint64_t call,
                                   std::string* error);

}  // namespace gbl::capture
