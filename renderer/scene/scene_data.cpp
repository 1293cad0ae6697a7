// Whole-scene queries over the CPU scene description.
#include "scene/scene_data.h"

#include <limits>

namespace gbl {

std::size_t SceneData::triangleCount() const {
    std::size_t n = 0;
    for (auto const& inst : instances)
        if (inst.mesh >= 0 && std::size_t(inst.mesh) < meshes.size()) n += meshes[inst.mesh].indices.size() / 3;
    return n;
}

Bounds SceneData::bounds() const {
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    bool any = false;
    for (auto const& inst : instances) {
        if (inst.mesh < 0 || std::size_t(inst.mesh) >= meshes.size()) continue;
        for (auto const& v : meshes[inst.mesh].vertices) {
            glm::vec3 const p = glm::vec3(inst.model * glm::vec4(v.position, 1.0f));
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
            any = true;
        }
    }
    if (!any) return {};
    return {lo, hi};
}

}  // namespace gbl
