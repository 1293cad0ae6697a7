// The glTF scene builder's lights: KHR_lights_punctual point (and spot) lights placed by their nodes.
#include "gltf/scene_builder_parts.h"

#include "core/light_math.h"
#include "gltf/mapping.h"

namespace gbl::gltf {

void SceneBuilder::addLights(std::vector<std::pair<int, glm::mat4>> const& placed) {
    Json const* ext = member(doc_, "extensions");
    Json const* punctual = ext ? member(*ext, "KHR_lights_punctual") : nullptr;
    Json const* lights = punctual ? member(*punctual, "lights") : nullptr;
    if (lights) requireKind(*lights, Kind::Array, "KHR_lights_punctual.lights");
    Json const* nodes = member(doc_, "nodes");
    for (auto const& [node, world] : placed) {
        Json const* nodeExt = nodes ? member((*nodes)[std::size_t(node)], "extensions") : nullptr;
        Json const* ref = nodeExt ? member(*nodeExt, "KHR_lights_punctual") : nullptr;
        if (!ref) continue;
        std::string const who = "node " + std::to_string(node);
        requireKind(*ref, Kind::Object, who + "'s KHR_lights_punctual");
        Json const* li = member(*ref, "light");
        if (!li) continue;
        requireKind(*li, Kind::Index, who + "'s KHR_lights_punctual.light");
        std::uint64_t const l = li->get<std::uint64_t>();
        if (!lights || l >= lights->size())
            fail(who + " refers to light " + std::to_string(l) + ", but the file has " +
                 num(lights ? lights->size() : 0));
        Json const& light = (*lights)[l];
        std::string const lw = "light " + std::to_string(l);
        requireKind(light, Kind::Object, lw);
        std::string type = "point";
        if (Json const* t = member(light, "type"))
            requireKind(*t, Kind::String, lw + ".type"), type = t->get<std::string>();
        glm::vec3 color(1.0f);
        if (Json const* c = member(light, "color")) {
            requireKind(*c, Kind::NumberArray, lw + ".color");
            if (c->size() != 3) fail(lw + ".color has " + num(c->size()) + " numbers; expected 3");
            color = glm::vec3((*c)[0].get<float>(), (*c)[1].get<float>(), (*c)[2].get<float>());
        }
        float intensity = 1.0f, range = 0.0f;
        if (Json const* i = member(light, "intensity"))
            requireKind(*i, Kind::Number, lw + ".intensity"), intensity = i->get<float>();
        if (Json const* r = member(light, "range"))
            requireKind(*r, Kind::Number, lw + ".range"), range = r->get<float>();
        std::string name = "light " + std::to_string(l);
        if (Json const* nm = member(light, "name"); nm && nm->is_string()) name = nm->get<std::string>();
        if (type == "directional") {
            scene_.warnings.push_back(lw + " is directional; only point lights are loaded, so it is skipped");
            continue;
        }
        if (type == "spot")
            scene_.warnings.push_back(lw + " is a spot light; it is loaded as a point light without its cone");
        else if (type != "point") {
            scene_.warnings.push_back(lw + " has an unknown type '" + printable(type, 20) + "'; skipped");
            continue;
        }
        std::string why;
        auto pl = pointLightFromGltf(glm::vec3(world[3]), color, intensity, range, name, &why);
        if (!pl) {
            scene_.warnings.push_back(lw + " is skipped because " + why);
            continue;
        }
        if (lightRadius(*pl).kind == RadiusKind::Zero)
            scene_.warnings.push_back(lw + " is too dim to reach the light threshold; it lights nothing");
        scene_.lights.push_back(std::move(*pl));
    }
}

}  // namespace gbl::gltf
