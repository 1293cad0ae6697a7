// Reading a parsed JSON document field by field, each error naming the field it is about
// ("lights[2].kq must be a finite number >= 0 (got -1)"): the phrasing session files
// (docs/sessions.md) and G-buffer manifests (docs/import.md) share, and the one writer of a light
// (lightJson). Header-only and included by the readers and writers alone, which link nlohmann-json
// themselves; gbl_core itself reads no JSON.
#pragma once

#include "core/frame_types.h"
#include "core/light_math.h"
#include "core/point_light.h"

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace gbl::json_fields {

using nlohmann::json;

// Thrown inside a reader only; the reader's parse function turns it into its returned message.
struct FieldError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

[[noreturn]] inline void fail(std::string const& field, std::string const& what) {
    throw FieldError(field + " " + what);
}

inline std::string typeName(json const& j) {
    if (j.is_number()) return "a number";
    if (j.is_boolean()) return "true/false";
    if (j.is_null()) return "null";
    if (j.is_object()) return "an object";
    if (j.is_array()) return "an array";
    return "a string";
}

// "a, b or c".
inline std::string joinNames(std::span<std::string_view const> names) {
    std::string s;
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (i) s += i + 1 == names.size() ? " or " : ", ";
        s += names[i];
    }
    return s;
}

// One JSON object being read. Every field must be one of `known`: a typo ("intesity") is
// reported as the unknown field it is, before the "missing" message it would also cause.
class Object {
public:
    Object(json const& j, std::string path, std::vector<std::string_view> const& known)
        : j_(j), path_(std::move(path)) {
        if (!j_.is_object()) fail(path_, "must be an object (got " + typeName(j_) + ")");
        for (auto it = j_.begin(); it != j_.end(); ++it)
            if (std::find(known.begin(), known.end(), std::string_view(it.key())) == known.end())
                fail(field(it.key()), "is not a known field");
    }
    std::string field(std::string_view key) const {
        return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
    }
    json const& required(std::string_view key) const {
        auto it = j_.find(key);
        if (it == j_.end()) fail(field(key), "is missing");
        return *it;
    }
    json const* optional(std::string_view key) const {
        auto it = j_.find(key);
        return it == j_.end() ? nullptr : &*it;
    }

private:
    json const& j_;
    std::string path_;
};

enum class Bound { Any, NonNegative, Positive };

inline float number(json const& j, std::string const& field, Bound bound = Bound::Any) {
    char const* const want = bound == Bound::NonNegative ? "must be a finite number >= 0"
                             : bound == Bound::Positive  ? "must be a finite number > 0"
                                                         : "must be a finite number";
    if (!j.is_number()) fail(field, std::string(want) + " (got " + typeName(j) + ")");
    // The renderer works in float: 1e300 is a finite double but no finite float (and narrowing
    // it would be undefined behaviour), so the range is checked in double first.
    double const d = j.get<double>();
    if (!std::isfinite(d) || std::abs(d) > double(std::numeric_limits<float>::max()) ||
        (bound == Bound::NonNegative && d < 0.0) || (bound == Bound::Positive && float(d) <= 0.0f))
        fail(field, std::string(want) + " (got " + j.dump() + ")");
    return float(d);
}

inline float numberIn(json const& j, std::string const& field, float lo, float hi) {
    float const v = number(j, field);
    if (v < lo || v > hi) {
        std::ostringstream s;
        s << "must be between " << lo << " and " << hi << " (got " << j.dump() << ")";
        fail(field, s.str());
    }
    return v;
}

inline int integer(json const& j, std::string const& field, int lo, int hi) {
    std::string const want = "must be a whole number from " + std::to_string(lo) + " to " + std::to_string(hi);
    if (!j.is_number_integer()) fail(field, want + " (got " + (j.is_number() ? j.dump() : typeName(j)) + ")");
    auto const v = j.get<long long>();
    if (v < lo || v > hi) fail(field, want + " (got " + j.dump() + ")");
    return int(v);
}

inline bool boolean(json const& j, std::string const& field) {
    if (!j.is_boolean()) fail(field, "must be true or false (got " + typeName(j) + ")");
    return j.get<bool>();
}

inline std::string string(json const& j, std::string const& field) {
    if (!j.is_string()) fail(field, "must be a string (got " + typeName(j) + ")");
    return j.get<std::string>();
}

// The index of the name `j` holds among `names`.
inline std::size_t choiceIndex(json const& j, std::string const& field, std::span<std::string_view const> names) {
    std::string const want = "must be one of " + joinNames(names);
    if (!j.is_string()) fail(field, want + " (got " + typeName(j) + ")");
    auto const it = std::find(names.begin(), names.end(), j.get<std::string>());
    if (it == names.end()) fail(field, want + " (got " + j.dump() + ")");
    return std::size_t(it - names.begin());
}

template <class Enum, std::size_t N>
Enum enumeration(json const& j, std::string const& field, std::array<std::string_view, N> const& names) {
    return static_cast<Enum>(choiceIndex(j, field, names));
}

template <int N>
glm::vec<N, float> vector(json const& j, std::string const& field, Bound bound = Bound::Any) {
    if (!j.is_array() || j.size() != std::size_t(N))
        fail(field, "must be an array of " + std::to_string(N) + " numbers");
    glm::vec<N, float> v;
    for (int i = 0; i < N; ++i) v[i] = number(j[std::size_t(i)], field + "[" + std::to_string(i) + "]", bound);
    return v;
}

// The keys of a light in session files, in the order they are written: its name, its kind, then
// kLightFields' file keys (a vector's three components share one key).
inline std::vector<std::string_view> lightFileKeys() {
    std::vector<std::string_view> keys{"name", "kind"};
    for (LightField const& f : kLightFields)
        if (keys.back() != f.fileKey) keys.push_back(f.fileKey);
    return keys;
}

// One light as session files write it (docs/sessions.md), at `path` ("lights[3]"). The numbers
// come from kLightFields: its file key, its range, whether older files may leave it out.
inline PointLight readLight(json const& j, std::string const& path) {
    Object o(j, path, lightFileKeys());
    PointLight l;
    if (json const* name = o.optional("name")) l.name = string(*name, o.field("name"));
    // Optional (sessions written before light kinds load as point lights with the defaults).
    if (json const* kind = o.optional("kind")) l.kind = enumeration<LightKind>(*kind, o.field("kind"), kLightKindNames);
    for (std::size_t i = 0; i < kLightFields.size(); i += kLightFields[i].vector ? 3 : 1) {
        LightField const& f = kLightFields[i];
        json const* v = f.optionalInFiles ? o.optional(f.fileKey) : &o.required(f.fileKey);
        if (!v) continue;
        std::string const at = o.field(f.fileKey);
        Bound const bound = f.positive                                ? Bound::Positive
                            : f.range == LightFieldRange::NonNegative ? Bound::NonNegative
                                                                      : Bound::Any;
        if (f.vector) {
            l.*f.vector = vector<3>(*v, at, bound);
            if (f.range == LightFieldRange::Direction && glm::dot(l.*f.vector, l.*f.vector) <= 0.0f)
                fail(at, "must not be the zero vector");
        } else if (f.range == LightFieldRange::ConeAngle) {
            l.*f.scalar = numberIn(*v, at, 0.0f, kMaxSpotConeDeg);
        } else {
            l.*f.scalar = number(*v, at, bound);
        }
    }
    // The rules that involve more than one field (Kc = Kl = Kq = 0) come from the one validator
    // the editor and the renderer use too.
    if (auto err = validateLight(l)) fail(path + ":", *err);
    return l;
}

// One light as session files write it: readLight's keys in lightFileKeys' order.
template <class Json>
Json lightJson(PointLight const& l) {
    Json out = Json::object();
    out["name"] = l.name;
    out["kind"] = lightKindName(l.kind);
    for (LightField const& f : kLightFields) {
        std::string const key(f.fileKey);
        if (f.vector)
            out[key][std::size_t(f.component)] = f.of(l);
        else
            out[key] = f.of(l);
    }
    return out;
}

// stats.json's "calls" (render --out, the editor's Export all): per pass what it issued,
// {"draws": N, "dispatches": M, "triangles": T} (gl/draw_count.h), a pass that ran twice summed.
inline json passCallsJson(std::span<PassCalls const> calls) {
    json out = json::object();
    for (PassCalls const& c : calls) {
        json& entry = out[c.name];
        if (entry.is_null())
            entry = {{"draws", std::uint64_t(0)}, {"dispatches", std::uint64_t(0)}, {"triangles", std::uint64_t(0)}};
        entry["draws"] = entry["draws"].get<std::uint64_t>() + c.draws;
        entry["dispatches"] = entry["dispatches"].get<std::uint64_t>() + c.dispatches;
        entry["triangles"] = entry["triangles"].get<std::uint64_t>() + c.triangles;
    }
    return out;
}

}  // namespace gbl::json_fields
