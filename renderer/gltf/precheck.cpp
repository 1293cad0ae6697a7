// The glTF loader's JSON pre-check: types, URIs and limits, before tinygltf reads anything else.
#include "gltf/precheck.h"

#include "gltf/draco.h"
#include "gltf/failure.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <iterator>
#include <optional>

namespace gbl::gltf {

namespace fs = std::filesystem;

namespace {

std::uint32_t readU32(std::uint8_t const* p) {
    std::uint32_t v;
    std::memcpy(&v, p, 4);
    return v;  // glTF is little-endian, as is every platform we build for
}

// glTF URIs are percent-encoded; tinygltf decodes them the same way before opening files.
std::string decodeUri(std::string const& uri) {
    auto hex = [](char c) -> int {
        if (c >= '0' && c <= '9') return c - '0';
        if (c >= 'a' && c <= 'f') return c - 'a' + 10;
        if (c >= 'A' && c <= 'F') return c - 'A' + 10;
        return 0;
    };
    std::string out;
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '+')
            out += ' ';
        else if (uri[i] == '%' && i + 2 < uri.size()) {
            out += char(hex(uri[i + 1]) * 16 + hex(uri[i + 2]));
            i += 2;
        } else
            out += uri[i];
    }
    return out;
}

char const* typeName(Json const& v) {
    return v.type_name();
}

struct FieldRule {
    char const* collection;
    char const* key;
    Kind kind;
};

// The properties whose types tinygltf would otherwise ignore silently or misread.
constexpr FieldRule kFieldRules[] = {
    {"accessors", "bufferView", Kind::Index},
    {"accessors", "byteOffset", Kind::Index},
    {"accessors", "componentType", Kind::Index},
    {"accessors", "count", Kind::Index},
    {"accessors", "type", Kind::String},
    {"accessors", "normalized", Kind::Bool},
    {"accessors", "sparse", Kind::Object},
    {"buffers", "byteLength", Kind::Index},
    {"cameras", "type", Kind::String},
    {"cameras", "perspective", Kind::Object},
    {"cameras", "orthographic", Kind::Object},
    {"buffers", "uri", Kind::String},
    {"bufferViews", "buffer", Kind::Index},
    {"bufferViews", "byteOffset", Kind::Index},
    {"bufferViews", "byteLength", Kind::Index},
    {"bufferViews", "byteStride", Kind::Index},
    {"images", "uri", Kind::String},
    {"images", "bufferView", Kind::Index},
    {"images", "mimeType", Kind::String},
    {"materials", "pbrMetallicRoughness", Kind::Object},
    {"materials", "normalTexture", Kind::Object},
    {"materials", "alphaMode", Kind::String},
    {"materials", "alphaCutoff", Kind::Number},
    {"materials", "doubleSided", Kind::Bool},
    {"materials", "extensions", Kind::Object},

    {"meshes", "primitives", Kind::Array},
    {"nodes", "mesh", Kind::Index},
    {"nodes", "camera", Kind::Index},
    {"nodes", "children", Kind::IndexArray},
    {"nodes", "matrix", Kind::NumberArray},
    {"nodes", "translation", Kind::NumberArray},
    {"nodes", "rotation", Kind::NumberArray},
    {"nodes", "scale", Kind::NumberArray},
    {"nodes", "extensions", Kind::Object},
    {"scenes", "nodes", Kind::IndexArray},
    {"textures", "source", Kind::Index},
    {"textures", "sampler", Kind::Index},
};

constexpr char const* kCollections[] = {"accessors", "animations", "buffers", "bufferViews", "cameras",
                                        "images",    "materials",  "meshes",  "nodes",       "samplers",
                                        "scenes",    "skins",      "textures"};

// Extensions whose absence changes what the file means; anything else required is refused.
constexpr char const* kSupportedRequired[] = {"KHR_lights_punctual",   "KHR_materials_specular",
                                              "KHR_mesh_quantization", "KHR_materials_emissive_strength",
                                              "KHR_texture_transform", "KHR_draco_mesh_compression"};

std::size_t base64DecodedSize(std::string const& uri) {
    auto const comma = uri.find(',');
    if (comma == std::string::npos) return 0;
    std::size_t n = 0;
    for (std::size_t i = comma + 1; i < uri.size(); ++i)
        if (uri[i] != '=' && !std::isspace(static_cast<unsigned char>(uri[i]))) ++n;
    return n * 3 / 4;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Paths: what counts as "inside the scene's folder"

bool isInside(fs::path const& folder, fs::path const& p) {
    std::error_code ec;
    fs::path const target = fs::weakly_canonical(p, ec);
    if (ec) return false;
    auto f = folder.begin(), t = target.begin();
    for (; f != folder.end(); ++f, ++t) {
        if (f->empty()) continue;  // trailing separator
        if (t == target.end() || *f != *t) return false;
    }
    return true;
}

// ---------------------------------------------------------------------------------------------
// Binary containers and JSON

Glb splitGlb(std::span<std::uint8_t const> data) {
    if (data.size() < 20) fail("the binary glTF header is truncated");
    std::uint32_t const version = readU32(data.data() + 4), length = readU32(data.data() + 8);
    if (version != 2) fail("binary glTF version " + std::to_string(version) + " is not supported (only 2)");
    if (length > data.size())
        fail("the binary glTF is truncated: its header says " + std::to_string(length) + " bytes but the file has " +
             num(data.size()));
    std::size_t pos = 12;
    Glb glb;
    bool first = true;
    while (pos + 8 <= length) {
        std::uint32_t const chunkLength = readU32(data.data() + pos), type = readU32(data.data() + pos + 4);
        pos += 8;
        if (chunkLength > length - pos) fail("a binary glTF chunk runs past the end of the file");
        std::span<std::uint8_t const> const chunk = data.subspan(pos, chunkLength);
        if (first) {
            if (type != 0x4E4F534Au) fail("the first binary glTF chunk is not JSON");
            glb.json = chunk;
            first = false;
        } else if (type == 0x004E4942u && !glb.hasBin) {
            glb.bin = chunk;
            glb.hasBin = true;
        }
        pos += chunkLength;
    }
    if (first) fail("the binary glTF has no JSON chunk");
    return glb;
}

Json parseJson(std::span<std::uint8_t const> text, std::size_t maxDepth) {
    auto const limitDepth = [maxDepth](int depth, Json::parse_event_t, Json&) {
        if (std::size_t(depth) > maxDepth) fail("the JSON nests deeper than the limit of " + num(maxDepth) + " levels");
        return true;
    };
    try {
        return Json::parse(text.begin(), text.end(), limitDepth, true);
    } catch (Json::exception const& e) {  // parse_error, and out_of_range for a number like 1e400
        std::string what = e.what();
        auto const at = what.find("at line");
        if (at != std::string::npos) what = what.substr(at);
        fail("the JSON is malformed (" + printable(what, 160) + ")");
    }
}

// ---------------------------------------------------------------------------------------------
// Types and the whole-document check

void requireKind(Json const& v, Kind kind, std::string const& where) {
    auto const isIndex = [](Json const& x) {
        return x.is_number_unsigned() || (x.is_number_integer() && x.get<std::int64_t>() >= 0);
    };
    bool ok = false;
    char const* want = "";
    switch (kind) {
        case Kind::Index:
            ok = isIndex(v), want = "a non-negative integer";
            break;
        case Kind::Number:
            ok = v.is_number(), want = "a number";
            break;
        case Kind::String:
            ok = v.is_string(), want = "a string";
            break;
        case Kind::Bool:
            ok = v.is_boolean(), want = "true or false";
            break;
        case Kind::Object:
            ok = v.is_object(), want = "an object";
            break;
        case Kind::Array:
            ok = v.is_array(), want = "an array";
            break;
        case Kind::IndexArray:
            ok = v.is_array() && std::all_of(v.begin(), v.end(), isIndex), want = "an array of non-negative integers";
            break;
        case Kind::NumberArray:
            ok = v.is_array() && std::all_of(v.begin(), v.end(), [](Json const& x) { return x.is_number(); }),
            want = "an array of numbers";
            break;
    }
    if (!ok) fail(where + " must be " + want + " but is " + (v.is_array() || v.is_object() ? "a " : "") + typeName(v));
}

Json const* member(Json const& object, char const* key) {
    if (!object.is_object()) return nullptr;
    auto const it = object.find(key);
    return it == object.end() ? nullptr : &*it;
}

std::optional<Json> withoutDracoIndices(Json const& doc) {
    Json const* meshes = member(doc, "meshes");
    Json const* accessors = member(doc, "accessors");
    if (!meshes) return std::nullopt;
    std::optional<Json> out;
    for (std::size_t m = 0; m < meshes->size(); ++m) {
        Json const* prims = member((*meshes)[m], "primitives");
        for (std::size_t p = 0; prims && p < prims->size(); ++p) {
            Json const& prim = (*prims)[p];
            Json const* ext = member(prim, "extensions");
            Json const* indices = member(prim, "indices");
            if (!ext || !member(*ext, "KHR_draco_mesh_compression") || !indices) continue;
            std::uint64_t const a = indices->get<std::uint64_t>();
            bool const hasData = accessors && a < accessors->size() && member((*accessors)[a], "bufferView");
            if (hasData) continue;
            if (!out) out = doc;
            (*out)["meshes"][m]["primitives"][p].erase("indices");
        }
    }
    return out;
}

void precheck(Json const& doc, Glb const* glb, fs::path const& folder, GltfLoadOptions const& options) {
    if (!doc.is_object()) fail("the JSON root is " + std::string(typeName(doc)) + ", not an object, so it is not glTF");
    Json const* asset = member(doc, "asset");
    Json const* version = asset ? member(*asset, "version") : nullptr;
    if (!version || !version->is_string()) fail("it has no asset.version string, so it is not a glTF 2.0 file");
    std::string const v = version->get<std::string>();
    if (v.rfind("2.", 0) != 0) fail("it is glTF version '" + printable(v, 20) + "'; only glTF 2.0 is supported");

    if (Json const* req = member(doc, "extensionsRequired")) {
        requireKind(*req, Kind::Array, "extensionsRequired");
        for (auto const& e : *req) {
            requireKind(e, Kind::String, "extensionsRequired[]");
            std::string const name = e.get<std::string>();
            if (name == "KHR_draco_mesh_compression" && !gltfDecodesDraco())
                fail("it requires the extension KHR_draco_mesh_compression, but " + std::string(kNoDracoReason));
            if (std::find(std::begin(kSupportedRequired), std::end(kSupportedRequired), name) ==
                std::end(kSupportedRequired))
                fail("it requires the extension " + printable(name, 60) + ", which this loader does not support");
        }
    }
    if (Json const* scene = member(doc, "scene")) requireKind(*scene, Kind::Index, "'scene'");

    for (char const* c : kCollections) {
        Json const* arr = member(doc, c);
        if (!arr) continue;
        requireKind(*arr, Kind::Array, std::string("'") + c + "'");
        for (std::size_t i = 0; i < arr->size(); ++i)
            requireKind((*arr)[i], Kind::Object, std::string(c) + "[" + num(i) + "]");
    }
    for (auto const& rule : kFieldRules) {
        Json const* arr = member(doc, rule.collection);
        if (!arr) continue;
        for (std::size_t i = 0; i < arr->size(); ++i)
            if (Json const* f = member((*arr)[i], rule.key))
                requireKind(*f, rule.kind, std::string(rule.collection) + "[" + num(i) + "]." + rule.key);
    }
    if (Json const* meshes = member(doc, "meshes")) {
        for (std::size_t m = 0; m < meshes->size(); ++m) {
            Json const* prims = member((*meshes)[m], "primitives");
            if (!prims) fail("meshes[" + num(m) + "] has no primitives");
            for (std::size_t p = 0; p < prims->size(); ++p) {
                std::string const where = "meshes[" + num(m) + "].primitives[" + num(p) + "]";
                Json const& prim = (*prims)[p];
                requireKind(prim, Kind::Object, where);
                Json const* attrs = member(prim, "attributes");
                if (!attrs) fail(where + " has no attributes");
                requireKind(*attrs, Kind::Object, where + ".attributes");
                for (auto it = attrs->begin(); it != attrs->end(); ++it)
                    requireKind(*it, Kind::Index, where + ".attributes." + printable(it.key(), 40));
                for (char const* key : {"indices", "material", "mode"})
                    if (Json const* f = member(prim, key)) requireKind(*f, Kind::Index, where + "." + key);
                if (Json const* f = member(prim, "extensions")) requireKind(*f, Kind::Object, where + ".extensions");
            }
        }
    }

    if (Json const* nodes = member(doc, "nodes"); nodes && nodes->size() > options.maxNodes)
        fail("it has " + num(nodes->size()) + " nodes, more than the limit of " + num(options.maxNodes));

    // URIs: refuse any that leave the folder before anything is read through them.
    auto checkUri = [&](std::string const& uri, std::string const& what) -> std::optional<fs::path> {
        if (tinygltf::IsDataURI(uri) || uri.rfind("data:", 0) == 0) return std::nullopt;
        fs::path const decoded = fs::path(decodeUri(uri));
        fs::path const full = (folder / decoded).lexically_normal();
        if (!options.allowOutsideUris && (decoded.is_absolute() || decoded.has_root_name() ||
                                          uri.find("://") != std::string::npos || !isInside(folder, full)))
            fail(what + " URI '" + printable(uri, 80) +
                 "' leaves the scene's folder, which is refused (allow with --allow-outside-uris)");
        return full;
    };
    if (Json const* images = member(doc, "images"))
        for (std::size_t i = 0; i < images->size(); ++i)
            if (Json const* uri = member((*images)[i], "uri"))
                checkUri(uri->get<std::string>(), "image " + num(i) + "'s");
    if (Json const* buffers = member(doc, "buffers")) {
        for (std::size_t i = 0; i < buffers->size(); ++i) {
            Json const& b = (*buffers)[i];
            std::string const what = "buffer " + num(i);
            Json const* len = member(b, "byteLength");
            if (!len) fail(what + " has no byteLength");
            std::uint64_t const byteLength = len->get<std::uint64_t>();
            if (byteLength == 0) fail(what + " has byteLength 0");
            if (byteLength > options.maxFileBytes)
                fail(what + " declares " + std::to_string(byteLength) + " bytes, more than the limit of " +
                     num(options.maxFileBytes) + " bytes");
            Json const* uriJson = member(b, "uri");
            if (!uriJson) {
                if (!glb) fail(what + " has no uri, which only a binary glTF may omit");
                if (i != 0 || !glb->hasBin) fail(what + " has no uri and the binary glTF has no BIN chunk for it");
                if (glb->bin.size() < byteLength)
                    fail(what + " is short: it declares " + std::to_string(byteLength) +
                         " bytes but the BIN chunk holds " + num(glb->bin.size()));
                continue;
            }
            std::string const uri = uriJson->get<std::string>();
            auto const path = checkUri(uri, what + "'s");
            if (!path) {
                if (!tinygltf::IsDataURI(uri)) fail(what + " has a data: URI that is not base64 buffer data");
                std::size_t const have = base64DecodedSize(uri);
                if (have != byteLength)
                    fail(what + "'s data: URI holds " + num(have) + " bytes but its byteLength is " +
                         std::to_string(byteLength) + (have < byteLength ? " (short buffer)" : ""));
                continue;
            }
            std::error_code ec;
            if (!fs::is_regular_file(*path, ec))
                fail(what + " refers to '" + printable(uri, 80) + "', which does not exist");
            std::uintmax_t const size = fs::file_size(*path, ec);
            if (ec) fail(what + " file '" + printable(uri, 80) + "' cannot be read");
            if (size != byteLength)
                fail(what + " file '" + printable(uri, 80) + "' holds " + std::to_string(size) +
                     " bytes but its byteLength is " + std::to_string(byteLength) +
                     (size < byteLength ? " (short buffer)" : ""));
        }
    }
}

}  // namespace gbl::gltf
