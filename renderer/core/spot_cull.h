// The cone half of the tiled and clustered light tests (CPU twin of coneMayTouchSphere in
// shaders/light_fetch.glsl): after the sphere test, a spot is kept only when its cone may meet a
// sphere around the tile's (or cluster's) pixels. Conservative: never drops a lit pixel.
#pragma once

#include "core/light_math.h"
#include "core/tile_math.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace gbl {

// False only when the sphere (centre, radius) cannot meet the cone with apex `apex`, unit `axis`
// and half-angle acos(cosOuter) <= 90 degrees. In the plane through the axis and the centre, the
// cone's side is the line at the outer angle; its signed distance cosOuter * across - along *
// sinOuter is a lower bound on the distance to the solid cone, and nothing of the cone lies more
// than `radius` behind the apex.
inline bool sphereMayTouchCone(glm::vec3 centre, float radius, glm::vec3 apex, glm::vec3 axis, float cosOuter) {
    glm::vec3 const v = centre - apex;
    float const along = glm::dot(v, axis);
    float const across = glm::length(v - along * axis);
    float const sinOuter = std::sqrt(std::max(1.0f - cosOuter * cosOuter, 0.0f));
    float const slack = radius * 1.0001f + 1e-4f;  // as the shader
    return along >= -slack && cosOuter * across - along * sinOuter <= slack;
}

// The same test for a light in view space (`view` the camera's view matrix): true for lights
// without a cone.
inline bool lightConeMayTouchSphere(PointLight const& light, glm::mat4 const& view, glm::vec3 centreView,
                                    float radius) {
    if (light.kind != LightKind::Spot) return true;
    glm::vec3 const apex = glm::vec3(view * glm::vec4(light.position, 1.0f));
    glm::vec3 const axis = glm::mat3(view) * lightDirection(light);
    return sphereMayTouchCone(centreView, radius, apex, axis, spotCone(light).cosOuter);
}

// A sphere (xyz centre, w radius) around the view-space frustum piece whose far-plane corners are
// `farCorners`, between view depths minDepth and maxDepth (lighting_tiled.comp's tile sphere).
inline glm::vec4 frustumPieceSphere(std::array<glm::vec3, 4> const& farCorners, float minDepth, float maxDepth) {
    float const farDepth = -farCorners[0].z;
    glm::vec3 const mean = (farCorners[0] + farCorners[1] + farCorners[2] + farCorners[3]) * 0.25f;
    glm::vec3 const centre = mean * ((minDepth + maxDepth) * 0.5f / farDepth);
    float radius = 0.0f;
    for (glm::vec3 const& c : farCorners)
        for (float d : {minDepth, maxDepth}) radius = std::max(radius, glm::distance(centre, c * (d / farDepth)));
    return {centre, radius};
}

// The far-plane corners (view space) of a tile, as lighting_tiled.comp unprojects them:
// bottom-left, bottom-right, top-left, top-right.
inline std::array<glm::vec3, 4> tileFarCorners(glm::mat4 const& inverseProjection, int width, int height,
                                               PixelRect const& rect) {
    auto unproject = [&](int px, int py) {
        glm::vec4 const v = inverseProjection * glm::vec4(2.0f * float(px) / float(width) - 1.0f,
                                                          2.0f * float(py) / float(height) - 1.0f, 1.0f, 1.0f);
        return glm::vec3(v) / v.w;
    };
    return {unproject(rect.x0, rect.y0), unproject(rect.x1, rect.y0), unproject(rect.x0, rect.y1),
            unproject(rect.x1, rect.y1)};
}

}  // namespace gbl
