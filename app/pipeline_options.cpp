// Command-line options from the pipeline field table.
#include "pipeline_options.h"

#include <cstdio>

namespace gbl {

std::vector<std::string> defaultPipelineText() {
    std::vector<std::string> text;
    PipelineSettings const defaults;
    for (PipelineField const& f : pipelineFields())
        text.push_back(f.kind == SettingKind::Toggle ? (f.get(defaults) != 0.0 ? "on" : "off")
                                                     : fieldScriptText(f, defaults));
    return text;
}

CLI::Validator fieldValidator(PipelineField const& f) {
    std::string const want = fieldValuesText(f);
    if (f.kind == SettingKind::Number) {
        char range[64];
        std::snprintf(range, sizeof range, "[%g, %g]", double(f.min), double(f.max));
        PipelineField const* field = &f;  // the table lives as long as the program
        return CLI::Validator(
            [field, want](std::string& in) {
                return parseFieldValue(*field, in) ? std::string() : "'" + in + "' is not " + want;
            },
            range);
    }
    std::vector<std::string> names;
    if (f.kind == SettingKind::Choice)
        names.assign(f.choices.begin(), f.choices.end());
    else
        names = {"off", "on", "0", "1"};
    CLI::Validator const member = CLI::IsMember(names);  // a Validator: IsMember's own copy is a template
    std::string const description = member.get_description();
    return CLI::Validator(
        [member, want](std::string& in) {
            std::string value = in;
            return member(value).empty() ? std::string() : "'" + in + "' is not " + want;
        },
        description);
}

void addPipelineOptions(CLI::App& sub, std::vector<std::string>& text) {
    std::span<PipelineField const> const fields = pipelineFields();
    if (text.size() != fields.size()) text = defaultPipelineText();
    for (std::size_t i = 0; i < fields.size(); ++i) {
        PipelineField const& f = fields[i];
        if (f.option.empty()) continue;
        // The old option is a second name of the same option, so it is checked and counted alike;
        // the help says it is the old one.
        std::string const names = std::string(f.option) + (f.oldOption.empty() ? "" : "," + std::string(f.oldOption));
        std::string const help =
            std::string(f.help) + (f.oldOption.empty() ? "" : " (" + std::string(f.oldOption) + ": its old name)");
        sub.add_option(names, text[i], help)
            ->check(fieldValidator(f))
            ->type_name(f.kind == SettingKind::Number ? "FLOAT" : "TEXT")
            ->capture_default_str();
    }
}

void notePipelineOptionsGiven(CLI::App const& sub, std::set<std::string>& given) {
    for (PipelineField const& f : pipelineFields()) {
        if (f.option.empty()) continue;
        if (sub.count(std::string(f.option)) > 0) given.insert(std::string(f.option));
    }
}

std::optional<PipelineSettings> pipelineFromText(std::vector<std::string> const& text, std::string* error) {
    std::span<PipelineField const> const fields = pipelineFields();
    PipelineSettings settings;
    for (std::size_t i = 0; i < fields.size() && i < text.size(); ++i) {
        PipelineField const& f = fields[i];
        std::optional<double> const v = parseFieldValue(f, text[i]);
        if (!v) {
            std::string const name = f.option.empty() ? std::string(f.name) : std::string(f.option);
            *error = name + " must be " + fieldValuesText(f) + ", got '" + text[i] + "'";
            return std::nullopt;
        }
        f.set(settings, *v);
    }
    return settings;
}

void applyGivenOptions(PipelineSettings& into, PipelineSettings const& from, std::set<std::string> const& given) {
    for (PipelineField const& f : pipelineFields())
        if (!f.option.empty() && given.count(std::string(f.option))) {
            if (f.rgb)
                into.*f.rgb = from.*f.rgb;
            else
                f.set(into, f.get(from));
        }
}

std::optional<std::string> firstPipelineOptionGiven(std::set<std::string> const& given) {
    for (PipelineField const& f : pipelineFields())
        if (!f.option.empty() && given.count(std::string(f.option))) return std::string(f.option);
    return std::nullopt;
}

}  // namespace gbl
