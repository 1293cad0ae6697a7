// The order the forward pass draws blended surfaces in: back to front, per object, by view depth.
// Pure math, no GL: drawScene uses it and the CPU tests check it.
#pragma once

#include <glm/glm.hpp>

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <span>
#include <vector>

namespace gbl {

// Indices of `centers` (world-space object centres), farthest first by view depth: the clip-space
// w of viewProj * centre, which is the distance along the view axis for a perspective projection.
// Equal depths keep their list order (stable), so the same scene always draws the same way.
inline std::vector<std::size_t> backToFrontOrder(std::span<glm::vec3 const> centers, glm::mat4 const& viewProj) {
    std::vector<float> depth(centers.size());
    for (std::size_t i = 0; i < centers.size(); ++i) depth[i] = (viewProj * glm::vec4(centers[i], 1.0f)).w;
    std::vector<std::size_t> order(centers.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return depth[a] > depth[b]; });
    return order;
}

}  // namespace gbl
