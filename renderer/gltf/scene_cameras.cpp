// The glTF scene builder's cameras: perspective cameras placed by their nodes, offered as views.
#include "gltf/scene_builder_parts.h"

#include "gltf/mapping.h"

#include <cmath>

namespace gbl::gltf {

void SceneBuilder::addCameras(std::vector<std::pair<int, glm::mat4>> const& placed, Bounds const& bounds) {
    // For infinite projections: as far as the framing camera would see, from wherever the file's camera is.
    float const sceneFar = frameBounds(bounds).farPlane;
    for (auto const& [node, world] : placed) {
        int const c = model_.nodes[std::size_t(node)].camera;
        if (c < 0) continue;
        std::string const who = "node " + std::to_string(node);
        if (std::size_t(c) >= model_.cameras.size())
            fail(who + " refers to camera " + std::to_string(c) + ", but the file has " + num(model_.cameras.size()));
        auto const& src = model_.cameras[std::size_t(c)];
        std::string const name = src.name.empty() ? "camera " + std::to_string(c) : printable(src.name, 60);
        if (src.type != "perspective") {
            scene_.warnings.push_back(name + " (" + who + ") is " +
                                      (src.type == "orthographic" ? std::string("orthographic")
                                                                  : "of type '" + printable(src.type, 20) + "'") +
                                      "; the renderer has only perspective cameras, so it is not offered as a view");
            continue;
        }
        auto const& p = src.perspective;
        bool const sane = std::isfinite(p.yfov) && p.yfov > 0.0 && p.yfov < 3.14159 && std::isfinite(p.znear) &&
                          p.znear > 0.0 && std::isfinite(p.zfar) && std::isfinite(p.aspectRatio);
        if (!sane) {
            scene_.warnings.push_back(name + " (" + who +
                                      ") has a yfov outside (0, pi) or a znear that is not positive; not offered");
            continue;
        }
        Camera const cam = cameraFromGltf(world, float(p.yfov), float(p.znear), float(p.zfar), sceneFar);
        scene_.cameras.push_back({name, cam, p.aspectRatio > 0.0 ? float(p.aspectRatio) : 0.0f});
    }
}

}  // namespace gbl::gltf
