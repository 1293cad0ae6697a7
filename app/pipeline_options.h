// The command-line options of core/pipeline_fields.h's rows: one `render` option per field that
// names one, with the field's help, its values checked by CLI11 (IsMember over the enum's names,
// or the field's range) and its default from PipelineSettings{}; `bench` checks its lists of
// modes, cull modes and layouts against the same names.
#pragma once

#include "core/pipeline_fields.h"

#include <CLI/CLI.hpp>

#include <optional>
#include <set>
#include <string>
#include <vector>

namespace gbl {

// Each field's value as its option takes it, for PipelineSettings{} ("quad", "on", "0.03"), in
// pipelineFields() order: what `render` starts from and --help shows as the default.
std::vector<std::string> defaultPipelineText();

// Checks one value of `f`: a choice's name (CLI11's IsMember over its names), 0/1/off/on, or a
// number in the field's range. The error is "'VALUE' is not one of NAMES" (CLI11 puts the option
// in front), the help shows the names or the range.
CLI::Validator fieldValidator(PipelineField const& f);

// Adds an option for every field that names one, bound to `text[i]` (text is resized to the table,
// its values defaultPipelineText()'s unless already set); a field's old option (--blit) is a second
// name of its option, which the help marks as the old one.
void addPipelineOptions(CLI::App& sub, std::vector<std::string>& text);
// Adds to `given` the option of every field given on `sub`'s command line (under either name).
void notePipelineOptionsGiven(CLI::App const& sub, std::set<std::string>& given);

// PipelineSettings{} with every field set from `text` (pipelineFields() order); nullopt and one
// sentence in `error` for a value the field does not take.
std::optional<PipelineSettings> pipelineFromText(std::vector<std::string> const& text, std::string* error);
// `into` with the fields whose option is in `given` taken from `from` (options override a session).
void applyGivenOptions(PipelineSettings& into, PipelineSettings const& from, std::set<std::string> const& given);
// The first pipeline option in `given`, or nullopt (for commands where the step or file sets them).
std::optional<std::string> firstPipelineOptionGiven(std::set<std::string> const& given);

}  // namespace gbl

namespace gbl {

// A list option's values as `f`'s enum (bench's --modes, --cull); nullopt and "OPTION: 'x' is not
// one of ..." in `error` for a name that is not one of the field's.
template <class Enum>
std::optional<std::vector<Enum>> choiceList(PipelineField const& f, std::vector<std::string> const& names,
                                            std::string const& option, std::string* error) {
    std::vector<Enum> out;
    for (std::string const& name : names) {
        std::optional<double> const v = f.kind == SettingKind::Choice ? parseFieldValue(f, name) : std::nullopt;
        if (!v) {
            *error = option + ": '" + name + "' is not " + fieldValuesText(f);
            return std::nullopt;
        }
        out.push_back(Enum(int(*v)));
    }
    return out;
}

}  // namespace gbl
