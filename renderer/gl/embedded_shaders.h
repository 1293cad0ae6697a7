// The shader sources compiled into the binary (generated from shaders/ at build time).
#pragma once

#include <span>

namespace gbl {

struct EmbeddedShader {
    char const* name;  // file name inside shaders/, e.g. "geometry.frag"
    char const* source;
};

std::span<EmbeddedShader const> embeddedShaders();

// The shaders/ folder of the source tree this binary was built from (for hot reload).
char const* shaderSourceDir();

}  // namespace gbl
