// The shader-checks build (shaders/shader_checks.glsl): compute shaders check the index of each
// buffer, image and shared-array access against its size, clamp the ones out of range and record
// the first in a small storage buffer. The renderer reads it after each frame and reports what it
// found like a GL error: a message naming the program, the access, the index and the size, and a
// process-wide count that tests compare before and after (as glErrorCount()).
#pragma once

#include "gl/buffer.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gbl {

// Whether renderers of this process build their shaders with the checks: GBL_SHADER_CHECKS=1 or 0
// in the environment, else the build's default (the CMake option GBL_SHADER_CHECKS). The checks
// need storage buffers in compute shaders (OpenGL 4.3); without them nothing is checked.
bool shaderChecksRequested();

// Out-of-range accesses reported in this process so far (every failure of every frame). Only
// ever grows, like glErrorCount().
std::uint64_t shaderCheckFailureCount();
// The report of the latest frame with failures ("" when none yet).
std::string lastShaderCheckReport();

// The names of the CHECK_SITE_ numbers, read from the `#define CHECK_SITE_<NAME> <n>` lines of
// shaders/shader_checks.glsl's text: site n is names[n] ("" where none is defined).
std::vector<std::string> shaderCheckSiteNames(std::string_view checksSource);

// What the buffer holds after a frame.
struct ShaderCheckRecord {
    std::uint32_t failures = 0;
    std::uint32_t program = 0;  // ProgramId
    std::uint32_t site = 0;
    std::int32_t index = 0;
    std::int32_t size = 0;
};

// One sentence for a frame's record: "shader check: 3 out-of-range accesses; the first in program
// lighting_tiled, at sKept (site 4): index 1030 outside [0, 1024)".
std::string describeShaderChecks(ShaderCheckRecord const& r, std::vector<std::string> const& siteNames);

class ShaderChecks {
public:
    // The report buffer, bound at BIND_SSBO_SHADER_CHECKS for every compute shader.
    static ShaderChecks create(std::vector<std::string> siteNames);
    explicit operator bool() const { return bool(buffer_); }

    // Zeroes the record and binds the buffer; call before a frame's compute passes.
    void begin();
    // Reads the record (waits for the GPU). With failures: counts them process-wide, logs the
    // sentence to stderr and returns it.
    std::optional<std::string> collect();

private:
    gl::Buffer buffer_;
    std::vector<std::string> siteNames_;
};

}  // namespace gbl
