// Light list edits: every change goes through validateLight so a bad value never reaches the GPU.
#include "model/light_list.h"

#include "core/light_math.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

namespace gbl::ui {

int matchingPreset(PointLight const& light) {
    for (std::size_t i = 0; i < kAttenuationPresets.size(); ++i) {
        auto const& p = kAttenuationPresets[i];
        if (light.kc == p.kc && light.kl == p.kl && light.kq == p.kq) return int(i);
    }
    return -1;
}

void applyPreset(PointLight& light, AttenuationPreset const& preset) {
    light.kc = preset.kc;
    light.kl = preset.kl;
    light.kq = preset.kq;
}

float presetRadius(PointLight const& light, AttenuationPreset const& preset) {
    PointLight withPreset = light;
    applyPreset(withPreset, preset);
    return lightRadius(withPreset).radius;
}

std::string presetLabel(PointLight const& light, AttenuationPreset const& preset) {
    char text[48];
    std::snprintf(text, sizeof text, "radius %.1f", presetRadius(light, preset));
    return text;
}

namespace {
std::string limitMessage() {
    return "the editor holds at most " + std::to_string(kMaxEditorLights) + " lights";
}

std::string uniqueName(std::vector<PointLight> const& lights) {
    return "light " + std::to_string(lights.size());
}
}  // namespace

EditResult addLight(std::vector<PointLight>& lights, glm::vec3 position) {
    if (int(lights.size()) >= kMaxEditorLights) return {-1, limitMessage()};
    PointLight light;
    light.position = position;
    applyPreset(light, kAttenuationPresets[1]);
    light.name = uniqueName(lights);
    lights.push_back(light);
    return {int(lights.size()) - 1, {}};
}

EditResult duplicateLight(std::vector<PointLight>& lights, int index) {
    if (index < 0 || index >= int(lights.size())) return {-1, "no light selected to duplicate"};
    if (int(lights.size()) >= kMaxEditorLights) return {-1, limitMessage()};
    PointLight copy = lights[std::size_t(index)];
    // Offset the copy so it is visible as a second cube rather than hidden inside the first.
    copy.position += glm::vec3(0.5f, 0.0f, 0.0f);
    copy.name = (copy.name.empty() ? uniqueName(lights) : copy.name) + " copy";
    lights.insert(lights.begin() + index + 1, copy);
    return {index + 1, {}};
}

int deleteLight(std::vector<PointLight>& lights, int index) {
    if (index < 0 || index >= int(lights.size())) return -1;
    lights.erase(lights.begin() + index);
    if (lights.empty()) return -1;
    return std::min(index, int(lights.size()) - 1);
}

std::optional<std::string> applyLightEdit(std::vector<PointLight>& lights, int index, PointLight const& edited) {
    if (index < 0 || index >= int(lights.size())) return "no light selected";
    if (auto error = validateLight(edited)) return "not applied: " + *error;
    lights[std::size_t(index)] = edited;
    return std::nullopt;
}

EditResult addRandomLights(std::vector<PointLight>& lights, int count, Bounds const& bounds, std::uint32_t& seed) {
    EditResult result;
    if (count <= 0) return {-1, "the number of lights to add must be at least 1"};
    int const room = kMaxEditorLights - int(lights.size());
    if (count > room) {
        result.message = "added " + std::to_string(std::max(room, 0)) + " of " + std::to_string(count) +
                         " lights: " + limitMessage();
        count = std::max(room, 0);
    }
    std::mt19937 rng(seed);
    seed = rng();
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);

    // Pick the preset whose range is closest to a third of the scene size: enough to light a
    // neighbourhood, small enough that many lights stay cheap in the volume pass.
    float const wanted = std::max(glm::length(bounds.max - bounds.min) / 3.0f, 1.0f);
    AttenuationPreset preset = kAttenuationPresets[0];
    for (auto const& p : kAttenuationPresets)
        if (std::abs(float(p.range) - wanted) < std::abs(float(preset.range) - wanted)) preset = p;

    glm::vec3 const lo = bounds.min, size = bounds.max - bounds.min;
    for (int i = 0; i < count; ++i) {
        PointLight light;
        // Lights start in the lower half of the scene: that is where the surfaces are.
        light.position = lo + glm::vec3(unit(rng), 0.05f + 0.45f * unit(rng), unit(rng)) * size;
        // Fully saturated hue with one channel at 1, so Imax (and the radius) is predictable.
        float const h = unit(rng) * 6.0f;
        float const f = h - std::floor(h);
        int const sector = int(h) % 6;
        glm::vec3 const rgb[6] = {{1, f, 0}, {1 - f, 1, 0}, {0, 1, f}, {0, 1 - f, 1}, {f, 0, 1}, {1, 0, 1 - f}};
        light.color = glm::mix(glm::vec3(1.0f), rgb[sector], 0.8f);
        light.intensity = 0.5f + unit(rng);
        applyPreset(light, preset);
        light.name = uniqueName(lights);
        lights.push_back(light);
    }
    result.index = count > 0 ? int(lights.size()) - 1 : -1;
    return result;
}

}  // namespace gbl::ui
