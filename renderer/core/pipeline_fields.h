// One table of PipelineSettings' fields: name in files, kind, range, default, help, the Pipeline
// panel's label, section and widget, and the `render` option. The session reader and writer, the
// A/B table, the UI script's `set` / `expect-setting` and its help, the Pipeline panel, the
// `render` and `bench` options and the lesson writer all go through it, so a field has one name and
// one range everywhere. tests/pipeline_fields_test.cpp fails to compile when PipelineSettings gains
// a member, and fails when a member has no entry here.
#pragma once

#include "core/pipeline_settings.h"

#include <array>
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

// The Pipeline panel's sections, top to bottom; each field is drawn in one.
enum class PipelineSection { LightingMode, VolumeCull, DepthCopy, Overlays, Shading };
inline constexpr std::array<std::string_view, 5> kPipelineSectionTitles{
    "Lighting mode", "Volume cull (volumes, prepass)", "Depth copy", "Overlays and views", "Shading"};

// How the Pipeline panel edits a field.
enum class PipelineWidget {
    Radio,           // Choice: one radio button per choice, each with its `choiceHelp` on hover
    Combo,           // Choice: a drop-down list
    ChoiceCheckbox,  // Choice: a checkbox, ticked = choice `checkedChoice`, unticked = the first choice
    Checkbox,        // Toggle
    Slider,          // Number: a slider over [min, max]
    LogSlider,       // Number: the same on a logarithmic scale
    Drag,            // Number: a drag box over [min, max]
    Colour,          // the colour (`rgb`): a colour editor
};

// Every value travels as a double: an enum's index, 0/1, the number.
struct PipelineField {
    std::string_view name{};  // in session files, the A/B table, lesson files and the UI script
    SettingKind kind = SettingKind::Choice;
    std::span<std::string_view const> choices{};  // Choice: the names in enum order
    float min = 0.0f, max = 1.0f;                 // Number: the values files, scripts, A/B, panels and options accept
    std::string_view help{};                      // one line: the option's help, the script's help, docs
    bool optionalInFiles = false;  // sessions written before the field existed leave it out: the default then
    bool sideB = false;            // the A/B table can change it on side B (the view is shared by both sides)
    double (*get)(PipelineSettings const&) = nullptr;
    void (*set)(PipelineSettings&, double) = nullptr;
    // A colour (ambient): files store the RGB triple; get/set read and write its grey level.
    glm::vec3 PipelineSettings::*rgb = nullptr;

    // --- the Pipeline panel
    std::string_view label{};  // the widget's label ("Depth copy"); radio rows show their section's title instead
    PipelineSection section = PipelineSection::Shading;
    PipelineWidget widget = PipelineWidget::Combo;
    std::string_view tooltip{};                      // on hover, where longer than `help`; empty: `help`
    std::span<std::string_view const> choiceHelp{};  // Radio: one line per choice, in enum order
    std::string_view format = "%.2f";                // Number: the value's format
    int checkedChoice = 0;                           // ChoiceCheckbox: the choice a tick stands for
    // Whether the field changes the frame under `s`; greyed out (never hidden) where it does not.
    bool (*applies)(PipelineSettings const&) = nullptr;

    // --- the command line: `render OPTION VALUE` sets the field (empty: no option)
    std::string_view option{};
    // The field's old name, still read from session and lesson files, scripts and the A/B table, and
    // its old option, still accepted by `render` (hidden from --help). Empty for most fields.
    std::string_view oldName{};
    std::string_view oldOption{};

    // The default, from PipelineSettings{}.
    double defaultValue() const { return get(PipelineSettings{}); }
    bool appliesTo(PipelineSettings const& s) const { return !applies || applies(s); }
    std::string_view hoverText() const { return tooltip.empty() ? help : tooltip; }
};

std::span<PipelineField const> pipelineFields();
// The field called `name`, or whose old name is `name` (sessions and lessons keep loading); nullptr.
PipelineField const* findPipelineField(std::string_view name);

// The value as files and scripts write it: a choice's name, "0"/"1", a number ("%g").
std::string fieldScriptText(PipelineField const& f, PipelineSettings const& s);
// A value written that way (a toggle also takes "on"/"off"); nullopt for an unknown name, a toggle
// other than those, text that is not a number, or a number outside [min, max] (NaN included).
std::optional<double> parseFieldValue(PipelineField const& f, std::string const& text);
// Whether a number is inside the field's range (false for NaN and infinities).
bool fieldAccepts(PipelineField const& f, double v);
// What a value of the field must be, for messages: "one of blit, shader or off", "0 or 1 (or off
// or on)", "a number from 0.05 to 16".
std::string fieldValuesText(PipelineField const& f);

}  // namespace gbl
