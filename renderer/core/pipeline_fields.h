// One table of PipelineSettings' fields: name in files, kind, range, default, help. The session
// reader and writer, the A/B table, the UI script's `set` / `expect-setting`, the Pipeline panel's
// ranges and the lesson writer all go through it, so a field has one name and one range everywhere.
// tests/pipeline_fields_test.cpp fails to compile when PipelineSettings gains a member, and fails
// when a member has no entry here.
#pragma once

#include "core/pipeline_settings.h"

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace gbl {

enum class SettingKind {
    Choice,  // an enum: one of `choices`, in enum order
    Toggle,  // a bool
    Number,  // a float in [min, max]
};

// Every value travels as a double: an enum's index, 0/1, the number.
struct PipelineField {
    std::string_view name;  // in session files, the A/B table, lesson files and the UI script
    SettingKind kind = SettingKind::Choice;
    std::span<std::string_view const> choices;  // Choice: the names in enum order
    float min = 0.0f, max = 1.0f;               // Number: the values files, scripts, A/B and panels accept
    std::string_view help;                      // one line, for tooltips and docs
    bool optionalInFiles = false;  // sessions written before the field existed leave it out: the default then
    bool sideB = false;            // the A/B table can change it on side B (the view is shared by both sides)
    double (*get)(PipelineSettings const&) = nullptr;
    void (*set)(PipelineSettings&, double) = nullptr;
    // A colour (ambient): files store the RGB triple; get/set read and write its grey level.
    glm::vec3 PipelineSettings::*rgb = nullptr;

    // The default, from PipelineSettings{}.
    double defaultValue() const { return get(PipelineSettings{}); }
};

std::span<PipelineField const> pipelineFields();
PipelineField const* findPipelineField(std::string_view name);

// The value as files and scripts write it: a choice's name, "0"/"1", a number ("%g").
std::string fieldScriptText(PipelineField const& f, PipelineSettings const& s);
// A value written that way (a toggle also takes "on"/"off"); nullopt for an unknown name, a toggle
// other than those, text that is not a number, or a number outside [min, max] (NaN included).
std::optional<double> parseFieldValue(PipelineField const& f, std::string const& text);
// Whether a number is inside the field's range (false for NaN and infinities).
bool fieldAccepts(PipelineField const& f, double v);

}  // namespace gbl
