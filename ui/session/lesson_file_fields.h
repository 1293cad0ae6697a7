// Reading lesson files, the parts lesson_file.cpp and lesson_file_fields.cpp share: field readers
// that throw FieldError with a message naming the field, a step's whole state, and a step's claim
// and A/B comparison. Internal to ui/session; the API is session/lesson_file.h.
#pragma once

#include "model/lesson_state.h"
#include "session/lesson_file.h"
#include "session/session.h"

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <initializer_list>
#include <stdexcept>
#include <string>
#include <string_view>

namespace gbl::ui::lesson_fields {

using nlohmann::json;

// "FIELD WHAT", e.g. "steps[0].claim.kind is missing"; parseLesson prefixes the file.
struct FieldError : std::runtime_error {
    using std::runtime_error::runtime_error;
};
[[noreturn]] void fail(std::string const& field, std::string const& what);

// `j` is an object whose keys are all in `known`.
void knownFields(json const& j, std::string const& path, std::initializer_list<std::string_view> known);
// j[key] as text (required: present and not blank), its {placeholders} all known.
std::string text(json const& j, std::string const& key, std::string const& path, bool required = true);
int integer(json const& j, std::string const& field, int lo, int hi);
float number(json const& j, std::string const& field, float lo, float hi);

// Merges a "pipeline" object over another: a field the patch names under its old name ("blit")
// replaces the field of its new name ("depth_copy") and the other way round, so the session reader
// sees each field once, under the name the lesson wrote (which its messages then name).
void mergePipeline(json& into, json const& patch);

// A step's whole state: the session the default scene starts with, patched by the lesson's setup
// and the step, then read by parseSession so every session rule applies (lesson_file.cpp).
Session readState(json const& state, std::string const& path, glm::vec3* lookAt, bool* hasLookAt);

// "claim": one kind of claimKinds() with that kind's fields; `state` is the step's merged state
// (a reference is its pipeline with the claim's changes), `step` the step read so far.
LessonClaim readClaim(json const& c, std::string const& path, json const& state, LessonStep const& step);
// "ab": {"view", "b"}: the A/B comparison the step opens, B being `a` with the named fields changed.
LessonAb readAb(json const& j, std::string const& path, PipelineSettings const& a);
// "light_by_light": {"light", "only"}: the light-by-light scrubber the step opens.
LessonLightByLight readLightByLight(json const& j, std::string const& path, int lightCount);

}  // namespace gbl::ui::lesson_fields
