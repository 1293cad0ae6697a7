// Finds a deferred renderer's two passes in one frame of an `apitrace dump` listing (no GL, no replay).
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace gbl::capture {

// The calls the scan follows; `apitrace dump --grep` is given this so the listing stays short.
extern char const* const kScanCallsRegex;

struct TraceScan {
    int frames = 0;  // swaps seen (a frame ends with one)
    std::optional<std::uint64_t> lastGeometryDraw, lightingDraw;
    unsigned gbufferFramebuffer = 0;
    std::map<std::string, unsigned> gbufferAttachments;  // "GL_COLOR_ATTACHMENT0" -> texture
    std::map<std::string, int> sampledAttachments;       // what the lighting draw has bound of them -> unit
    std::string error;                                   // one sentence when the frame has no deferred passes
};

// Scans the listing for frame `frame` (counted from 0). `error` names what is missing.
TraceScan scanTrace(std::string const& listing, int frame);

}  // namespace gbl::capture
