// The glTF scene builder's lights: KHR_lights_punctual point, spot and directional lights placed
// by their nodes (spots and directional lights shine along the node's -Z axis).
#include "gltf/scene_builder_parts.h"

#include "core/light_math.h"
#include "gltf/mapping.h"

#include <glm/gtc/constants.hpp>

#include <cmath>

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
        if (type != "point" && type != "spot" && type != "directional") {
            scene_.warnings.push_back(lw + " has an unknown type '" + printable(type, 20) + "'; skipped");
            continue;
        }
        // A directional light's intensity is in lux, a point's in candela; both are mapped by the
        // same 1/pi (our Lambert term has no 1/pi), and a directional light ignores range.
        std::string why;
        auto pl =
            pointLightFromGltf(glm::vec3(world[3]), color, intensity, type == "directional" ? 0.0f : range, name, &why);
        if (!pl) {
            scene_.warnings.push_back(lw + " is skipped because " + why);
            continue;
        }
        glm::vec3 const minusZ = -glm::vec3(world[2]);
        if (type != "point") {
            if (!(glm::dot(minusZ, minusZ) > 0.0f) || !std::isfinite(minusZ.x + minusZ.y + minusZ.z)) {
                scene_.warnings.push_back(lw + " is skipped because its node's transform gives it no direction");
                continue;
            }
            pl->direction = glm::normalize(minusZ);
        }
        if (type == "directional") {
            pl->kind = LightKind::Directional;
            scene_.lights.push_back(std::move(*pl));
            continue;
        }
        if (type == "spot") {
            // Angles in radians in the file, 0 <= inner < outer <= pi/2 (defaults 0 and pi/4).
            float inner = 0.0f, outer = glm::quarter_pi<float>();
            if (Json const* sp = member(light, "spot")) {
                requireKind(*sp, Kind::Object, lw + ".spot");
                if (Json const* a = member(*sp, "innerConeAngle"))
                    requireKind(*a, Kind::Number, lw + ".spot.innerConeAngle"), inner = a->get<float>();
                if (Json const* a = member(*sp, "outerConeAngle"))
                    requireKind(*a, Kind::Number, lw + ".spot.outerConeAngle"), outer = a->get<float>();
            }
            pl->kind = LightKind::Spot;
            pl->innerConeDeg = glm::degrees(inner);
            pl->outerConeDeg = glm::degrees(outer);
            if (auto bad = validateLight(*pl)) {
                scene_.warnings.push_back(lw + " is skipped because its spot cone is unusable: " + *bad);
                continue;
            }
        }
        if (lightRadius(*pl).kind == RadiusKind::Zero)
            scene_.warnings.push_back(lw + " is too dim to reach the light threshold; it lights nothing");
        scene_.lights.push_back(std::move(*pl));
    }
}

}  // namespace gbl::gltf
