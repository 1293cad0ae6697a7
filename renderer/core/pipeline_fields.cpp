// The PipelineSettings field table.
#include "core/pipeline_fields.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace gbl {

namespace {

template <auto Member, std::size_t N>
constexpr PipelineField choice(std::string_view name, std::array<std::string_view, N> const& names,
                               std::string_view help, bool optionalInFiles, bool sideB) {
    return {name,
            SettingKind::Choice,
            std::span<std::string_view const>(names.data(), names.size()),
            0.0f,
            float(N - 1),
            help,
            optionalInFiles,
            sideB,
            [](PipelineSettings const& s) { return double(int(s.*Member)); },
            [](PipelineSettings& s, double v) {
                using Enum = std::remove_reference_t<decltype(s.*Member)>;
                s.*Member = Enum(int(v));
            }};
}

template <auto Member>
constexpr PipelineField toggle(std::string_view name, std::string_view help, bool optionalInFiles, bool sideB) {
    return {name,
            SettingKind::Toggle,
            {},
            0.0f,
            1.0f,
            help,
            optionalInFiles,
            sideB,
            [](PipelineSettings const& s) { return (s.*Member) ? 1.0 : 0.0; },
            [](PipelineSettings& s, double v) { s.*Member = v != 0.0; }};
}

template <auto Member>
constexpr PipelineField number(std::string_view name, float min, float max, std::string_view help, bool optionalInFiles,
                               bool sideB) {
    return {name,
            SettingKind::Number,
            {},
            min,
            max,
            help,
            optionalInFiles,
            sideB,
            [](PipelineSettings const& s) { return double(s.*Member); },
            [](PipelineSettings& s, double v) { s.*Member = float(v); }};
}

constexpr bool kOptional = true, kRequired = false;
constexpr bool kSideB = true, kSharedView = false;  // kSharedView: both sides of A/B show it alike

// The A/B table shows the sideB rows in this order; its first row is the mode (startAb ticks it).
std::array<PipelineField, 16> const kFields{
    choice<&PipelineSettings::mode>("mode", kLightingModeNames, "How the lights are added: the lighting mode",
                                    kRequired, kSideB),
    choice<&PipelineSettings::cull>("cull", kCullModeNames, "Which faces of a light volume are drawn (volumes mode)",
                                    kRequired, kSideB),
    choice<&PipelineSettings::depthCopy>("blit", kDepthCopyNames,
                                         "How the G-buffer depth reaches the lit target before the forward pass",
                                         kRequired, kSideB),
    choice<&PipelineSettings::tonemap>("tonemap", kTonemapNames, "HDR to display: exposure, Reinhard or clamp",
                                       kRequired, kSideB),
    choice<&PipelineSettings::layout>("layout", kGBufferLayoutNames, "What the G-buffer stores, and how", kOptional,
                                      kSideB),
    toggle<&PipelineSettings::normalMaps>("normal_maps", "Use the materials' normal maps", kRequired, kSideB),
    toggle<&PipelineSettings::lightCubes>("light_cubes", "A small unlit cube at each light, after the depth copy",
                                          kRequired, kSideB),
    toggle<&PipelineSettings::volumeWireframes>("volume_wireframes", "Outline each light's volume", kRequired, kSideB),
    number<&PipelineSettings::shininess>("shininess", 1.0f, 512.0f, "Blinn-Phong specular exponent", kRequired, kSideB),
    number<&PipelineSettings::exposure>("exposure", 0.05f, 16.0f, "Multiplies the HDR frame before tonemapping",
                                        kRequired, kSideB),
    PipelineField{"ambient",
                  SettingKind::Number,
                  {},
                  0.0f,
                  1.0f,
                  "Ambient light: albedo times this colour (the A/B table sets a grey)",
                  kRequired,
                  kSideB,
                  [](PipelineSettings const& s) { return double(s.ambient.x); },
                  [](PipelineSettings& s, double v) { s.ambient = glm::vec3(float(v)); },
                  &PipelineSettings::ambient},
    choice<&PipelineSettings::view>("view", kDebugViewNames, "What the viewport shows", kRequired, kSharedView),
    choice<&PipelineSettings::accumulation>("accumulation", kLightAccumulationNames,
                                            "One lit target, or diffuse and specular targets and a combine pass",
                                            kOptional, kSideB),
    choice<&PipelineSettings::shading>(
        "shading", kShadingModelNames,
        "The lighting equation: gbuffer-lab's (docs/lighting.md) or LearnOpenGL's deferred shader's", kOptional,
        kSideB),
    toggle<&PipelineSettings::wireframesSelectedOnly>(
        "wireframes_selected_only", "The wireframes outline the selected light's volume only", kOptional, kSharedView),
    number<&PipelineSettings::volumeScale>("volume_scale", 0.1f, 4.0f,
                                           "Scales every light volume (1 just encloses the light's radius)", kOptional,
                                           kSideB),
};

}  // namespace

std::span<PipelineField const> pipelineFields() {
    return kFields;
}

PipelineField const* findPipelineField(std::string_view name) {
    for (PipelineField const& f : kFields)
        if (f.name == name) return &f;
    return nullptr;
}

std::string fieldScriptText(PipelineField const& f, PipelineSettings const& s) {
    double const v = f.get(s);
    switch (f.kind) {
        case SettingKind::Choice: {
            std::size_t const i = std::size_t(v);
            return i < f.choices.size() ? std::string(f.choices[i]) : std::string("?");
        }
        case SettingKind::Toggle:
            return v != 0.0 ? "1" : "0";
        case SettingKind::Number:
            break;
    }
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

bool fieldAccepts(PipelineField const& f, double v) {
    return std::isfinite(v) && v >= f.min && v <= f.max;
}

std::optional<double> parseFieldValue(PipelineField const& f, std::string const& text) {
    switch (f.kind) {
        case SettingKind::Choice:
            for (std::size_t i = 0; i < f.choices.size(); ++i)
                if (f.choices[i] == text) return double(i);
            return std::nullopt;
        case SettingKind::Toggle:
            if (text == "1" || text == "on") return 1.0;
            if (text == "0" || text == "off") return 0.0;
            return std::nullopt;
        case SettingKind::Number:
            break;
    }
    char* end = nullptr;
    double const v = std::strtod(text.c_str(), &end);
    if (end == text.c_str() || *end != '\0' || !fieldAccepts(f, v)) return std::nullopt;
    return v;
}

}  // namespace gbl
