// Editing operations on the light list (add, duplicate, delete, validated edits, random lights,
// attenuation presets), kept free of ImGui so they can be tested on the CPU.
#pragma once

#include "core/point_light.h"
#include "scene/scene_data.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace gbl::ui {

// More lights than this make the editor a slide show on llvmpipe; requests past it are clamped
// with a message.
inline constexpr int kMaxEditorLights = 4096;

// The widely used table of (Kc, Kl, Kq) triples. `range` is the distance the classic table files
// each triple under; the radius a light really gets depends on its brightness and threshold
// (lightRadius), so the editor names presets by presetRadius, never by `range`.
struct AttenuationPreset {
    int range;
    float kc, kl, kq;
};
inline constexpr std::array<AttenuationPreset, 12> kAttenuationPresets{{
    {7, 1.0f, 0.7f, 1.8f},
    {13, 1.0f, 0.35f, 0.44f},
    {20, 1.0f, 0.22f, 0.20f},
    {32, 1.0f, 0.14f, 0.07f},
    {50, 1.0f, 0.09f, 0.032f},
    {65, 1.0f, 0.07f, 0.017f},
    {100, 1.0f, 0.045f, 0.0075f},
    {160, 1.0f, 0.027f, 0.0028f},
    {200, 1.0f, 0.022f, 0.0019f},
    {325, 1.0f, 0.014f, 0.0007f},
    {600, 1.0f, 0.007f, 0.0002f},
    {3250, 1.0f, 0.0014f, 0.000007f},
}};

// Index of the preset whose (Kc, Kl, Kq) equal the light's, or -1.
int matchingPreset(PointLight const& light);
void applyPreset(PointLight& light, AttenuationPreset const& preset);
// The radius (lightRadius) `light` gets with the preset's terms: what the preset is named by.
float presetRadius(PointLight const& light, AttenuationPreset const& preset);
// "radius 10.3": the preset's name for this light, the radius to one decimal.
std::string presetLabel(PointLight const& light, AttenuationPreset const& preset);

// Result of an operation that may refuse: the index it produced (or -1) and why it refused.
struct EditResult {
    int index = -1;
    std::string message;  // empty on success
};

EditResult addLight(std::vector<PointLight>& lights, glm::vec3 position);
EditResult duplicateLight(std::vector<PointLight>& lights, int index);
// Returns the index to select afterwards (the next light, or the previous when it was last).
int deleteLight(std::vector<PointLight>& lights, int index);

// Replaces lights[index] with `edited` only when validateLight accepts it; otherwise the light
// stays as it was and the message says why.
std::optional<std::string> applyLightEdit(std::vector<PointLight>& lights, int index, PointLight const& edited);

// Adds `count` lights spread over `bounds` with saturated colours and a preset that suits the
// scene size. Deterministic for a given seed, which advances so the next batch differs.
// Clamped to kMaxEditorLights; the message says so when it clamps.
EditResult addRandomLights(std::vector<PointLight>& lights, int count, Bounds const& bounds, std::uint32_t& seed);

}  // namespace gbl::ui
