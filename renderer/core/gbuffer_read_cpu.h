// The C++ twin of shaders/gbuffer_read.glsl's decoding (and gbuffer_encoding.glsl's decodeNormal):
// a stored normal back to a unit normal, a window depth back to a world position. Tests decode
// exported raw samples with it to check what the GPU decoded.
#pragma once

#include "core/gbuffer_layout.h"
#include "core/octahedral.h"

#include <glm/glm.hpp>

namespace gbl {

// The unit normal from what the layout's normal attachment stores.
inline glm::vec3 decodeStoredNormal(NormalEncoding e, glm::vec4 stored) {
    switch (e) {
        case NormalEncoding::Octahedral:
            return octDecode(glm::vec2(stored) * 2.0f - 1.0f);
        case NormalEncoding::Biased:
            return glm::normalize(glm::vec3(stored) * 2.0f - 1.0f);
        case NormalEncoding::Float:
            break;
    }
    return glm::normalize(glm::vec3(stored));
}

// The world position whose window depth is `depth` at `at` (0..1) inside pixel `px` (GL's
// bottom-left rows) of a width x height frame, through the inverse view-projection.
inline glm::vec3 positionFromWindowDepth(glm::mat4 const& inverseViewProj, glm::ivec2 px, glm::vec2 at, int width,
                                         int height, float depth) {
    glm::vec2 const ndc = (glm::vec2(px) + at) / glm::vec2(float(width), float(height)) * 2.0f - 1.0f;
    glm::vec4 const world = inverseViewProj * glm::vec4(ndc, depth * 2.0f - 1.0f, 1.0f);
    return glm::vec3(world) / world.w;
}

}  // namespace gbl
