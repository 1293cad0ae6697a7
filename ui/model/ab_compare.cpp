// The A/B field table and side B.
#include "model/ab_compare.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace gbl::ui {

namespace {

template <auto Member>
AbField choice(std::string_view name, auto const& names) {
    return {name,
            AbFieldKind::Choice,
            std::span<std::string_view const>(names.data(), names.size()),
            0.0f,
            float(names.size() - 1),
            [](PipelineSettings const& s) { return double(int(s.*Member)); },
            [](PipelineSettings& s, double v) {
                using Enum = std::remove_reference_t<decltype(s.*Member)>;
                s.*Member = Enum(int(v));
            }};
}

template <auto Member>
AbField toggle(std::string_view name) {
    return {name,
            AbFieldKind::Toggle,
            {},
            0.0f,
            1.0f,
            [](PipelineSettings const& s) { return (s.*Member) ? 1.0 : 0.0; },
            [](PipelineSettings& s, double v) { s.*Member = v != 0.0; }};
}

template <auto Member>
AbField number(std::string_view name, float min, float max) {
    return {name,
            AbFieldKind::Number,
            {},
            min,
            max,
            [](PipelineSettings const& s) { return double(s.*Member); },
            [](PipelineSettings& s, double v) { s.*Member = float(v); }};
}

// The one list of what B can change. `view` is left out: both sides show the same view.
std::array<AbField, 11> const kFields{
    choice<&PipelineSettings::mode>("mode", kLightingModeNames),
    choice<&PipelineSettings::cull>("cull", kCullModeNames),
    choice<&PipelineSettings::depthCopy>("blit", kDepthCopyNames),
    choice<&PipelineSettings::tonemap>("tonemap", kTonemapNames),
    choice<&PipelineSettings::layout>("layout", kGBufferLayoutNames),
    toggle<&PipelineSettings::normalMaps>("normal_maps"),
    toggle<&PipelineSettings::lightCubes>("light_cubes"),
    toggle<&PipelineSettings::volumeWireframes>("volume_wireframes"),
    number<&PipelineSettings::shininess>("shininess", 1.0f, 256.0f),
    number<&PipelineSettings::exposure>("exposure", 0.05f, 8.0f),
    AbField{"ambient",
            AbFieldKind::Number,
            {},
            0.0f,
            0.3f,
            [](PipelineSettings const& s) { return double(s.ambient.x); },
            [](PipelineSettings& s, double v) { s.ambient = glm::vec3(float(v)); }},
};

}  // namespace

std::span<AbField const> abFields() {
    return kFields;
}

void startAb(AbState& state, PipelineSettings const& a) {
    state.enabled = true;
    if (std::find(state.overrides.begin(), state.overrides.end(), true) != state.overrides.end()) return;
    state.b = a;
    state.b.mode = a.mode == LightingMode::Volumes ? LightingMode::Quad : LightingMode::Volumes;
    state.overrides[0] = true;  // kFields[0] is the mode
}

bool setAbField(AbState& state, std::string_view field, std::string const& value) {
    for (std::size_t i = 0; i < kFields.size(); ++i) {
        AbField const& f = kFields[i];
        if (f.name != field) continue;
        double v = 0.0;
        switch (f.kind) {
            case AbFieldKind::Choice: {
                auto const it = std::find(f.choices.begin(), f.choices.end(), value);
                if (it == f.choices.end()) return false;
                v = double(it - f.choices.begin());
                break;
            }
            case AbFieldKind::Toggle:
                if (value != "0" && value != "1") return false;
                v = value == "1" ? 1.0 : 0.0;
                break;
            case AbFieldKind::Number: {
                char* end = nullptr;
                v = std::strtod(value.c_str(), &end);
                if (end == value.c_str() || *end != '\0' || v < f.min || v > f.max) return false;
                break;
            }
        }
        f.set(state.b, v);
        if (i < state.overrides.size()) state.overrides[i] = true;
        return true;
    }
    return false;
}

PipelineSettings sideB(AbState const& state, PipelineSettings const& a) {
    PipelineSettings b = a;
    for (std::size_t i = 0; i < kFields.size() && i < state.overrides.size(); ++i)
        if (state.overrides[i]) kFields[i].set(b, kFields[i].get(state.b));
    return b;
}

std::vector<std::string_view> differingFields(PipelineSettings const& a, PipelineSettings const& b) {
    std::vector<std::string_view> out;
    for (AbField const& f : kFields)
        if (f.get(a) != f.get(b)) out.push_back(f.name);
    return out;
}

std::string fieldText(AbField const& f, PipelineSettings const& s) {
    double const v = f.get(s);
    switch (f.kind) {
        case AbFieldKind::Choice: {
            std::size_t const i = std::size_t(v);
            return i < f.choices.size() ? std::string(f.choices[i]) : std::string("?");
        }
        case AbFieldKind::Toggle:
            return v != 0.0 ? "on" : "off";
        case AbFieldKind::Number:
            break;
    }
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
}

std::string describeAb(PipelineSettings const& a, PipelineSettings const& b) {
    std::string out;
    for (AbField const& f : kFields) {
        if (f.get(a) == f.get(b)) continue;
        if (!out.empty()) out += ", ";
        out += std::string(f.name) + " " + fieldText(f, a) + " | " + fieldText(f, b);
    }
    return out.empty() ? std::string("A and B are the same settings") : out;
}

bool abComparesLayout(AbState const& state) {
    std::span<AbField const> const fields = abFields();
    for (std::size_t i = 0; i < fields.size() && i < state.overrides.size(); ++i)
        if (fields[i].name == "layout") return state.overrides[i];
    return false;
}

}  // namespace gbl::ui
