// The glossary: deferred-shading terms and their definitions, read from assets/glossary.json, and
// which of them a piece of lesson text uses (the Lessons window lists them under the step).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace gbl::ui {

inline constexpr std::string_view kGlossaryFormat = "gbuffer-lab-glossary";
inline constexpr int kGlossaryVersion = 1;

struct GlossaryTerm {
    std::string term;                  // as listed: "NDC"
    std::vector<std::string> aliases;  // other spellings found in text: "normalized device coordinates"
    std::string definition;
};

struct Glossary {
    std::vector<GlossaryTerm> terms;  // in file order
    std::string error;                // "<file>: <field> <what is wrong>" when the file failed
};

Glossary parseGlossary(std::string_view text, std::string const& fileLabel);
Glossary loadGlossary(std::string const& path);
// assets/glossary.json of the source tree, or $GBL_GLOSSARY when set.
std::string defaultGlossaryPath();

// The terms `text` mentions (the term or an alias as a whole word, ignoring case), each once, in
// the order of their first mention.
std::vector<int> glossaryTermsIn(Glossary const& glossary, std::string_view text);

}  // namespace gbl::ui
