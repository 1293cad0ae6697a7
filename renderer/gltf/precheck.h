// The glTF loader's JSON pre-check and the JSON helpers it shares with the scene builder.
#pragma once

#include "gltf/loader.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>

namespace gbl::gltf {

using Json = nlohmann::json;

// The JSON and BIN chunks of a binary glTF (.glb).
struct Glb {
    std::span<std::uint8_t const> json;
    std::span<std::uint8_t const> bin;
    bool hasBin = false;
};

// Splits a .glb into its chunks after checking the header and every chunk length.
Glb splitGlb(std::span<std::uint8_t const> data);

// Parses JSON text, refusing malformed text and nesting deeper than maxDepth.
Json parseJson(std::span<std::uint8_t const> text, std::size_t maxDepth);

enum class Kind { Index, Number, String, Bool, Object, Array, IndexArray, NumberArray };

// Fails with "<where> must be <kind> but is <actual type>" unless v has the kind.
void requireKind(Json const& v, Kind kind, std::string const& where);

// The member `key` of an object, or null when absent or when `object` is not an object.
Json const* member(Json const& object, char const* key);

// True when p (made canonical) lies in the canonical `folder` or below it.
bool isInside(std::filesystem::path const& folder, std::filesystem::path const& p);

// The document without the "indices" of Draco-compressed primitives whose index accessor has no
// buffer view (their indices are in the Draco data), or nullopt when there are none: tinygltf 2.7
// refuses such accessors as indices. Call after precheck().
std::optional<Json> withoutDracoIndices(Json const& doc);

// Checks the document before tinygltf sees it: asset version, required extensions, the types
// of the properties tinygltf would silently misread, node count, buffer sizes, and that no
// URI leaves `folder` (the canonical scene folder) unless options.allowOutsideUris.
void precheck(Json const& doc, Glb const* glb, std::filesystem::path const& folder, GltfLoadOptions const& options);

}  // namespace gbl::gltf
