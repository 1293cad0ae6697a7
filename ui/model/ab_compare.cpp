// The A/B field table and side B.
#include "model/ab_compare.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <optional>

namespace gbl::ui {

namespace {

std::vector<AbField> sideBFields() {
    std::vector<AbField> out;
    for (PipelineField const& f : pipelineFields())
        if (f.sideB) out.push_back(f);
    return out;
}

}  // namespace

std::span<AbField const> abFields() {
    static std::vector<AbField> const fields = sideBFields();  // built on first use: AbState's default needs it
    return fields;
}

void startAb(AbState& state, PipelineSettings const& a) {
    state.enabled = true;
    if (std::find(state.overrides.begin(), state.overrides.end(), true) != state.overrides.end()) return;
    state.b = a;
    state.b.mode = a.mode == LightingMode::Volumes ? LightingMode::Quad : LightingMode::Volumes;
    state.overrides[0] = true;  // abFields()[0] is the mode
}

bool setAbField(AbState& state, std::string_view field, std::string const& value) {
    std::span<AbField const> const fields = abFields();
    PipelineField const* named = findPipelineField(field);  // an old name ("blit") too
    for (std::size_t i = 0; i < fields.size(); ++i) {
        AbField const& f = fields[i];
        if (!named || f.name != named->name) continue;
        std::optional<double> const v = parseFieldValue(f, value);
        if (!v) return false;
        f.set(state.b, *v);
        if (i < state.overrides.size()) state.overrides[i] = true;
        return true;
    }
    return false;
}

PipelineSettings sideB(AbState const& state, PipelineSettings const& a) {
    PipelineSettings b = a;
    std::span<AbField const> const fields = abFields();
    for (std::size_t i = 0; i < fields.size() && i < state.overrides.size(); ++i)
        if (state.overrides[i]) fields[i].set(b, fields[i].get(state.b));
    return b;
}

std::vector<std::string_view> differingFields(PipelineSettings const& a, PipelineSettings const& b) {
    std::vector<std::string_view> out;
    for (AbField const& f : abFields())
        if (f.get(a) != f.get(b)) out.push_back(f.name);
    return out;
}

std::string fieldText(AbField const& f, PipelineSettings const& s) {
    double const v = f.get(s);
    if (f.kind == AbFieldKind::Toggle) return v != 0.0 ? "on" : "off";
    if (f.kind == AbFieldKind::Choice) return fieldScriptText(f, s);
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
}

std::string describeAb(PipelineSettings const& a, PipelineSettings const& b) {
    std::string out;
    for (AbField const& f : abFields()) {
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
