// Reading the glossary file and finding its terms in lesson text.
#include "session/glossary_file.h"

#include "session/atomic_file.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <stdexcept>
#include <utility>

namespace gbl::ui {

using nlohmann::json;

namespace {

std::string lower(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = char(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

bool wordChar(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || (static_cast<unsigned char>(c) & 0x80);
}

// Where `word` first occurs in `text` (both lower case) as a whole word; npos when it does not.
std::size_t findWord(std::string const& text, std::string const& word) {
    for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) {
        bool const startOk = at == 0 || !wordChar(text[at - 1]);
        std::size_t const end = at + word.size();
        bool const endOk = end >= text.size() || !wordChar(text[end]);
        if (startOk && endOk) return at;
    }
    return std::string::npos;
}

std::string stringField(json const& j, char const* key, std::string const& path) {
    auto it = j.find(key);
    if (it == j.end()) throw std::runtime_error(path + "." + key + " is missing");
    if (!it->is_string() || it->get<std::string>().find_first_not_of(" \t\n") == std::string::npos)
        throw std::runtime_error(path + "." + key + " must be a string that is not empty");
    return it->get<std::string>();
}

}  // namespace

Glossary parseGlossary(std::string_view text, std::string const& fileLabel) {
    Glossary g;
    try {
        json const j = json::parse(text.begin(), text.end());
        if (!j.is_object() || j.value("format", "") != kGlossaryFormat)
            throw std::runtime_error("format must be \"" + std::string(kGlossaryFormat) + "\"");
        if (j.value("version", 0) != kGlossaryVersion)
            throw std::runtime_error("version must be " + std::to_string(kGlossaryVersion));
        auto terms = j.find("terms");
        if (terms == j.end() || !terms->is_array() || terms->empty())
            throw std::runtime_error("terms must be an array of at least one term");
        for (std::size_t i = 0; i < terms->size(); ++i) {
            json const& t = (*terms)[i];
            std::string const path = "terms[" + std::to_string(i) + "]";
            if (!t.is_object()) throw std::runtime_error(path + " must be an object");
            for (auto it = t.begin(); it != t.end(); ++it)
                if (it.key() != "term" && it.key() != "aliases" && it.key() != "definition")
                    throw std::runtime_error(path + "." + it.key() + " is not a known field");
            GlossaryTerm term;
            term.term = stringField(t, "term", path);
            term.definition = stringField(t, "definition", path);
            if (auto a = t.find("aliases"); a != t.end()) {
                if (!a->is_array()) throw std::runtime_error(path + ".aliases must be an array of strings");
                for (auto const& s : *a) {
                    if (!s.is_string() || s.get<std::string>().empty())
                        throw std::runtime_error(path + ".aliases must be an array of strings");
                    term.aliases.push_back(s.get<std::string>());
                }
            }
            for (auto const& other : g.terms)
                if (lower(other.term) == lower(term.term))
                    throw std::runtime_error(path + ".term \"" + term.term + "\" is listed twice");
            g.terms.push_back(std::move(term));
        }
    } catch (json::exception const& e) {
        g.terms.clear();
        g.error = fileLabel + ": not valid JSON: " + e.what();
    } catch (std::runtime_error const& e) {
        g.terms.clear();
        g.error = fileLabel + ": " + e.what();
    }
    return g;
}

Glossary loadGlossary(std::string const& path) {
    std::string error;
    auto text = readWholeFile(path, &error);
    if (!text) return {{}, "cannot read the glossary: " + error};
    return parseGlossary(*text, path);
}

std::string defaultGlossaryPath() {
    if (char const* env = std::getenv("GBL_GLOSSARY"); env && *env) return env;
    return GBL_GLOSSARY_PATH;
}

std::vector<int> glossaryTermsIn(Glossary const& glossary, std::string_view text) {
    std::string const t = lower(text);
    std::vector<std::pair<std::size_t, int>> found;
    for (std::size_t i = 0; i < glossary.terms.size(); ++i) {
        GlossaryTerm const& term = glossary.terms[i];
        std::size_t first = findWord(t, lower(term.term));
        for (auto const& a : term.aliases) first = std::min(first, findWord(t, lower(a)));
        if (first != std::string::npos) found.emplace_back(first, int(i));
    }
    std::sort(found.begin(), found.end());
    std::vector<int> out;
    for (auto const& f : found) out.push_back(f.second);
    return out;
}

}  // namespace gbl::ui
