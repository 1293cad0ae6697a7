// Lesson file fields (lesson_file_fields.h): the readers every part of a lesson file goes through,
// and a step's claim and A/B comparison.
#include "session/lesson_file_fields.h"

#include "core/pipeline_fields.h"
#include "model/lesson_claims.h"
#include "model/lesson_text.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <span>
#include <utility>

namespace gbl::ui::lesson_fields {

[[noreturn]] void fail(std::string const& field, std::string const& what) {
    throw FieldError(field + " " + what);
}

void knownFields(json const& j, std::string const& path, std::initializer_list<std::string_view> known) {
    if (!j.is_object()) fail(path, "must be an object");
    for (auto it = j.begin(); it != j.end(); ++it)
        if (std::find(known.begin(), known.end(), std::string_view(it.key())) == known.end())
            fail(path.empty() ? it.key() : path + "." + it.key(), "is not a known field");
}

std::string text(json const& j, std::string const& key, std::string const& path, bool required) {
    auto it = j.find(key);
    std::string const field = path + "." + key;
    if (it == j.end()) {
        if (required) fail(field, "is missing");
        return {};
    }
    if (!it->is_string()) fail(field, "must be a string");
    std::string s = it->get<std::string>();
    if (required && s.find_first_not_of(" \t\n") == std::string::npos) fail(field, "must not be empty");
    if (auto bad = unknownPlaceholder(s)) {
        std::string list;
        for (auto p : kLessonPlaceholders) list += (list.empty() ? "" : ", ") + std::string(p);
        fail(field, "uses the unknown placeholder " + *bad + " (known: " + list + ")");
    }
    return s;
}

int integer(json const& j, std::string const& field, int lo, int hi) {
    if (!j.is_number_integer() || j.get<long long>() < lo || j.get<long long>() > hi)
        fail(field, "must be a whole number from " + std::to_string(lo) + " to " + std::to_string(hi) + " (got " +
                        j.dump() + ")");
    return int(j.get<long long>());
}

float number(json const& j, std::string const& field, float lo, float hi) {
    if (!j.is_number() || !std::isfinite(j.get<double>()) || j.get<double>() < lo || j.get<double>() > hi)
        fail(field, "must be a number from " + json(lo).dump() + " to " + json(hi).dump() + " (got " + j.dump() + ")");
    return j.get<float>();
}

void mergePipeline(json& into, json const& patch) {
    if (into.is_object() && patch.is_object())
        for (PipelineField const& f : pipelineFields()) {
            if (f.oldName.empty()) continue;
            if (patch.contains(f.oldName)) into.erase(std::string(f.name));
            if (patch.contains(f.name)) into.erase(std::string(f.oldName));
        }
    into.merge_patch(patch);
}

namespace {

Attachment attachmentNamed(json const& j, std::string const& field) {
    static constexpr std::array<std::pair<std::string_view, Attachment>, 5> names{
        {{"position", Attachment::Position},
         {"normal", Attachment::Normal},
         {"albedo_spec", Attachment::AlbedoSpec},
         {"depth", Attachment::Depth},
         {"lighting", Attachment::Lighting}}};
    if (j.is_string())
        for (auto const& [name, a] : names)
            if (j.get<std::string>() == name) return a;
    fail(field, "must be one of position, normal, albedo_spec, depth or lighting (got " + j.dump() + ")");
}

// A comparing claim's optional "image": "lighting" (the default, the light sum) or "final" (the display
// image, which alone shows the light cubes and wireframes).
Attachment comparedImage(json const& c, std::string const& path) {
    auto it = c.find("image");
    if (it == c.end()) return Attachment::Lighting;
    if (it->is_string() && it->get<std::string>() == "lighting") return Attachment::Lighting;
    if (it->is_string() && it->get<std::string>() == "final") return Attachment::Final;
    fail(path + ".image", "must be lighting or final (got " + it->dump() + ")");
}

}  // namespace

LessonClaim readClaim(json const& c, std::string const& path, json const& state, LessonStep const& step) {
    if (!c.is_object()) fail(path, "must be an object");
    auto kindIt = c.find("kind");
    if (kindIt == c.end()) fail(path + ".kind", "is missing");
    std::string names;
    for (ClaimKindInfo const& k : claimKinds()) names += (names.empty() ? "" : ", ") + std::string(k.name);
    if (!kindIt->is_string()) fail(path + ".kind", "must be one of " + names);
    ClaimKindInfo const* info = findClaimKind(kindIt->get<std::string>());
    if (!info) fail(path + ".kind", "must be one of " + names + " (got " + kindIt->dump() + ")");
    // Every key is the kind's (claimKinds()): a misspelt or misplaced field is named, not ignored.
    for (auto const& item : c.items()) {
        std::string const& key = item.key();
        auto const has = [&key](std::span<std::string_view const> fields) {
            return std::find(fields.begin(), fields.end(), key) != fields.end();
        };
        if (key != "kind" && !has(info->fields) && !has(info->optionalFields))
            fail(path + "." + key, "is not a field of a " + std::string(info->name) + " claim");
    }
    auto const kind = std::optional<ClaimKind>(info->kind);
    LessonClaim claim;
    claim.kind = *kind;
    auto need = [&](char const* key) -> json const& {
        auto it = c.find(key);
        if (it == c.end()) fail(path + "." + key, "is missing (a " + kindIt->get<std::string>() + " claim needs it)");
        return *it;
    };
    if (info->atPixel && !step.state.pixel)
        fail(path + ".kind", "is a claim about the step's pixel, and the step has no pixel");
    // The kind's numbers, each within its range (claimNumberFields()); an optional one left out
    // keeps its default.
    for (ClaimNumberField const& f : claimNumberFields()) {
        bool const required = std::find(info->fields.begin(), info->fields.end(), f.name) != info->fields.end();
        auto it = c.find(f.name);
        if (required) need(std::string(f.name).c_str());
        if (it != c.end()) claim.*f.member = number(*it, path + "." + std::string(f.name), f.min, f.max);
    }
    switch (*kind) {
        case ClaimKind::LosesLight:
            claim.light = integer(need("light"), path + ".light", 0, int(step.state.lights.size()) - 1);
            break;
        case ClaimKind::SameImage:
            claim.image = comparedImage(c, path);
            break;
        case ClaimKind::FewerLitPixels:
            break;
        case ClaimKind::PositionError:
            if (claim.atLeast > claim.bound)  // its range ends at the bound: the same message, that end
                number(c["at_least"], path + ".at_least", findClaimNumberField("at_least")->min, claim.bound);
            if (auto it = c.find("mark"); it != c.end()) {
                if (!it->is_boolean()) fail(path + ".mark", "must be true or false");
                claim.mark = it->get<bool>();
            }
            break;
        case ClaimKind::TileCountMatchesCpu:
            if (step.state.pipeline.mode != LightingMode::Tiled || step.state.pipeline.view != DebugView::TileLights)
                fail(path + ".kind", "needs pipeline.mode \"tiled\" and pipeline.view \"tile_lights\"");
            if (auto it = c.find("most"); it != c.end()) {
                if (!it->is_boolean()) fail(path + ".most", "must be true or false");
                claim.most = it->get<bool>();
            }
            break;
        case ClaimKind::ExecutedExceedsLit:
            if (step.state.pipeline.view != DebugView::Heatmap) fail(path + ".kind", "needs pipeline.view \"heatmap\"");
            if (claim.maxFraction <= claim.minFraction)
                fail(path + ".max_fraction", "must be greater than min_fraction");
            break;
        case ClaimKind::AttachmentEquals: {
            claim.attachment = attachmentNamed(need("attachment"), path + ".attachment");
            json const& v = need("value");
            // null skips a component: [null, 0, null] says only "y is 0".
            if (!v.is_array() || v.empty() || v.size() > 4)
                fail(path + ".value", "must be an array of 1 to 4 numbers (null skips a component)");
            claim.compare = 0;
            for (std::size_t i = 0; i < v.size(); ++i) {
                if (v[i].is_null()) continue;
                claim.value[int(i)] = number(v[i], path + ".value[" + std::to_string(i) + "]", -1e6f, 1e6f);
                claim.compare |= 1u << i;
            }
            if (!claim.compare) fail(path + ".value", "must compare at least one component");
            break;
        }
        case ClaimKind::DiffersFrom:
            if (claim.maxFraction <= claim.minFraction)
                fail(path + ".max_fraction", "must be greater than min_fraction");
            claim.image = comparedImage(c, path);
            break;
        case ClaimKind::FewerEvaluations:
            if (step.state.pipeline.view != DebugView::Heatmap) fail(path + ".kind", "needs pipeline.view \"heatmap\"");
            if (claim.maxFraction <= claim.minFraction)
                fail(path + ".max_fraction", "must be greater than min_fraction");
            break;
        case ClaimKind::ComplexShare:
            if (step.state.pipeline.msaa == Msaa::Off) fail(path + ".kind", "needs pipeline.msaa 2, 4 or 8");
            if (claim.maxFraction <= claim.minFraction)
                fail(path + ".max_fraction", "must be greater than min_fraction");
            break;
        case ClaimKind::MatchesCpu:
            if (auto it = c.find("reached"); it != c.end())
                claim.reached = integer(*it, path + ".reached", 0, int(step.state.lights.size()));
            break;
    }
    if (claimNeedsReference(claim)) {
        // The reference is the step's pipeline with these settings changed, read like the step.
        json const& ref = need("reference");
        if (!ref.is_object()) fail(path + ".reference", "must be an object of pipeline settings");
        json s = state;
        if (!s.contains("pipeline") || !s["pipeline"].is_object()) s["pipeline"] = json::object();
        mergePipeline(s["pipeline"], ref);
        glm::vec3 ignored;
        bool has = false;
        try {
            claim.reference = readState(s, "@", &ignored, &has).pipeline;
        } catch (FieldError const& e) {
            std::string what = e.what();
            if (what.rfind("@.pipeline.", 0) == 0) what = path + ".reference." + what.substr(11);
            throw FieldError(what);
        }
    }
    return claim;
}

// "ab": {"view": "split" | "diff", "b": {FIELD: VALUE, ...}}: the A/B comparison the step opens,
// B being the step's pipeline with the named fields of the A/B table (abFields) changed.
LessonAb readAb(json const& j, std::string const& path, PipelineSettings const& a) {
    knownFields(j, path, {"view", "b"});
    LessonAb ab;
    if (auto it = j.find("view"); it != j.end()) {
        std::string const v = it->is_string() ? it->get<std::string>() : "";
        if (v != "split" && v != "diff") fail(path + ".view", "must be split or diff (got " + it->dump() + ")");
        ab.view = v == "diff" ? AbView::Diff : AbView::Split;
    }
    auto b = j.find("b");
    if (b == j.end() || !b->is_object() || b->empty())
        fail(path + ".b", "must be an object naming at least one field side B changes");
    AbState scratch;
    scratch.b = a;
    for (auto it = b->begin(); it != b->end(); ++it) {
        json const& v = it.value();
        std::string const value = v.is_string()    ? v.get<std::string>()
                                  : v.is_boolean() ? (v.get<bool>() ? "1" : "0")
                                                   : v.dump();
        if (!setAbField(scratch, it.key(), value))
            fail(path + ".b." + it.key(),
                 "is not a field of the A/B table, or " + v.dump() + " is not one of its values");
    }
    ab.b = scratch.b;
    ab.overrides = scratch.overrides;
    return ab;
}

// "light_by_light": {"light": I, "only": BOOL}: the scrubber the step opens, at light I.
LessonLightByLight readLightByLight(json const& j, std::string const& path, int lightCount) {
    if (!j.is_object()) fail(path, "must be an object: {\"light\": INDEX, \"only\": true}");
    knownFields(j, path, {"light", "only"});
    auto const light = j.find("light");
    if (light == j.end()) fail(path + ".light", "is missing (the index of the light the scrubber stops at)");
    LessonLightByLight out;
    out.light = integer(*light, path + ".light", 0, lightCount - 1);
    if (auto it = j.find("only"); it != j.end()) {
        if (!it->is_boolean()) fail(path + ".only", "must be true or false");
        out.only = it->get<bool>();
    }
    return out;
}

}  // namespace gbl::ui::lesson_fields
