// glTF 2.0 loading: a strict JSON pre-check, tinygltf parsing with our own file access and
// OpenImageIO images, then our own validation of every index and byte range before use.
#include "gltf_loader.h"

#include "gltf_geometry.h"
#include "gltf_images.h"
#include "gltf_mapping.h"
#include "light_math.h"

#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <algorithm>
#include <cctype>
#include <climits>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <new>
#include <set>

namespace gbl {

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

// Thrown inside the loader only; loadGltf turns it into the one-sentence error.
struct LoadFailure {
    std::string cause;
};
struct LoadCancelled {};

[[noreturn]] void fail(std::string cause) { throw LoadFailure{std::move(cause)}; }

std::string num(std::size_t v) { return std::to_string(v); }

// Keeps messages to one readable line: no control bytes, no multi-kilobyte data URIs.
std::string printable(std::string_view s, std::size_t maxLen = 120) {
    std::string out;
    for (char c : s) {
        if (out.size() >= maxLen) {
            out += "...";
            break;
        }
        unsigned char const u = static_cast<unsigned char>(c);
        out += (u < 0x20 || u == 0x7f) ? ' ' : c;
    }
    while (!out.empty() && (out.back() == ' ' || out.back() == '.')) out.pop_back();
    return out;
}

// ---------------------------------------------------------------------------------------------
// Progress and cancellation

class Progress {
public:
    explicit Progress(GltfLoadOptions const& o) : callback_(o.progress) {}
    void report(float fraction, std::string_view stage) {
        if (callback_ && !callback_(std::clamp(fraction, 0.0f, 1.0f), stage)) throw LoadCancelled{};
    }

private:
    std::function<bool(float, std::string_view)> const& callback_;
};

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
        if (uri[i] == '+') out += ' ';
        else if (uri[i] == '%' && i + 2 < uri.size()) {
            out += char(hex(uri[i + 1]) * 16 + hex(uri[i + 2]));
            i += 2;
        } else out += uri[i];
    }
    return out;
}

struct FsState {
    fs::path folder;  // canonical scene folder
    bool allowOutside = false;
    std::size_t maxFileBytes = 0;
    std::string failure;  // first refusal, reported instead of tinygltf's "file not found"
};

bool fsFileExists(std::string const& path, void* user) {
    auto* st = static_cast<FsState*>(user);
    fs::path const p(path);
    // tinygltf also tries the working directory with a relative path; only the scene's folder counts.
    if (!p.is_absolute()) return false;
    if (!st->allowOutside && !isInside(st->folder, p)) {
        if (st->failure.empty())
            st->failure = "the URI of '" + printable(path) +
                          "' leaves the scene's folder, which is refused (allow with --allow-outside-uris)";
        return false;
    }
    std::error_code ec;
    return fs::is_regular_file(p, ec);
}

std::string fsExpandFilePath(std::string const& path, void*) { return path; }

bool fsReadWholeFile(std::vector<unsigned char>* out, std::string* err, std::string const& path, void* user) {
    auto* st = static_cast<FsState*>(user);
    if (!fsFileExists(path, user)) {
        if (err) *err = "not found";
        return false;
    }
    std::error_code ec;
    std::uintmax_t const size = fs::file_size(path, ec);
    if (ec) {
        if (err) *err = ec.message();
        return false;
    }
    if (size > st->maxFileBytes) {
        if (st->failure.empty())
            st->failure = "'" + printable(path) + "' is " + std::to_string(size) + " bytes, more than the limit of " +
                          num(st->maxFileBytes) + " bytes";
        return false;
    }
    std::ifstream in(path, std::ios::binary);
    out->resize(std::size_t(size));
    if (!in || (size > 0 && !in.read(reinterpret_cast<char*>(out->data()), std::streamsize(size)))) {
        if (err) *err = "read error";
        return false;
    }
    return true;
}

bool fsWriteWholeFile(std::string*, std::string const&, std::vector<unsigned char> const&, void*) { return false; }

// Encoded image bytes, kept by image index: decoding happens later, once every byte range
// has been checked, with progress reported per image.
struct ImageStash {
    std::map<int, std::vector<std::uint8_t>> encoded;
};

bool stashImage(tinygltf::Image* image, int index, std::string*, std::string*, int, int, unsigned char const* bytes,
                int size, void* user) {
    // For bufferView images tinygltf passes a pointer it has not range-checked: never read it here.
    if (image->bufferView >= 0) return true;
    if (bytes && size > 0) static_cast<ImageStash*>(user)->encoded[index].assign(bytes, bytes + size);
    return true;
}

// ---------------------------------------------------------------------------------------------
// JSON pre-check: types, URIs and limits, before tinygltf reads anything else.

struct Glb {
    std::span<std::uint8_t const> json;
    std::span<std::uint8_t const> bin;
    bool hasBin = false;
};

std::uint32_t readU32(std::uint8_t const* p) {
    std::uint32_t v;
    std::memcpy(&v, p, 4);
    return v;  // glTF is little-endian, as is every platform we build for
}

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
        if (std::size_t(depth) > maxDepth)
            fail("the JSON nests deeper than the limit of " + num(maxDepth) + " levels");
        return true;
    };
    try {
        return Json::parse(text.begin(), text.end(), limitDepth, true);
    } catch (Json::parse_error const& e) {
        std::string what = e.what();
        auto const at = what.find("at line");
        if (at != std::string::npos) what = what.substr(at);
        fail("the JSON is malformed (" + printable(what, 160) + ")");
    }
}

char const* typeName(Json const& v) { return v.type_name(); }

enum class Kind { Index, Number, String, Bool, Object, Array, IndexArray, NumberArray };

void requireKind(Json const& v, Kind kind, std::string const& where) {
    auto const isIndex = [](Json const& x) {
        return x.is_number_unsigned() || (x.is_number_integer() && x.get<std::int64_t>() >= 0);
    };
    bool ok = false;
    char const* want = "";
    switch (kind) {
    case Kind::Index: ok = isIndex(v), want = "a non-negative integer"; break;
    case Kind::Number: ok = v.is_number(), want = "a number"; break;
    case Kind::String: ok = v.is_string(), want = "a string"; break;
    case Kind::Bool: ok = v.is_boolean(), want = "true or false"; break;
    case Kind::Object: ok = v.is_object(), want = "an object"; break;
    case Kind::Array: ok = v.is_array(), want = "an array"; break;
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

struct FieldRule {
    char const* collection;
    char const* key;
    Kind kind;
};

// The properties whose types tinygltf would otherwise ignore silently or misread.
constexpr FieldRule kFieldRules[] = {
    {"accessors", "bufferView", Kind::Index},   {"accessors", "byteOffset", Kind::Index},
    {"accessors", "componentType", Kind::Index}, {"accessors", "count", Kind::Index},
    {"accessors", "type", Kind::String},         {"accessors", "normalized", Kind::Bool},
    {"accessors", "sparse", Kind::Object},       {"buffers", "byteLength", Kind::Index},
    {"buffers", "uri", Kind::String},            {"bufferViews", "buffer", Kind::Index},
    {"bufferViews", "byteOffset", Kind::Index},  {"bufferViews", "byteLength", Kind::Index},
    {"bufferViews", "byteStride", Kind::Index},  {"images", "uri", Kind::String},
    {"images", "bufferView", Kind::Index},       {"images", "mimeType", Kind::String},
    {"materials", "pbrMetallicRoughness", Kind::Object}, {"materials", "normalTexture", Kind::Object},
    {"materials", "alphaMode", Kind::String},    {"materials", "alphaCutoff", Kind::Number},
    {"materials", "doubleSided", Kind::Bool},    {"materials", "extensions", Kind::Object},
    {"meshes", "primitives", Kind::Array},       {"nodes", "mesh", Kind::Index},
    {"nodes", "children", Kind::IndexArray},     {"nodes", "matrix", Kind::NumberArray},
    {"nodes", "translation", Kind::NumberArray}, {"nodes", "rotation", Kind::NumberArray},
    {"nodes", "scale", Kind::NumberArray},       {"nodes", "extensions", Kind::Object},
    {"scenes", "nodes", Kind::IndexArray},       {"textures", "source", Kind::Index},
    {"textures", "sampler", Kind::Index},
};

constexpr char const* kCollections[] = {"accessors", "animations", "buffers", "bufferViews", "cameras",
                                        "images",    "materials",  "meshes",  "nodes",       "samplers",
                                        "scenes",    "skins",      "textures"};

// Extensions whose absence changes what the file means; anything else required is refused.
constexpr char const* kSupportedRequired[] = {"KHR_lights_punctual", "KHR_materials_specular",
                                              "KHR_mesh_quantization", "KHR_materials_emissive_strength"};

Json const* member(Json const& object, char const* key) {
    if (!object.is_object()) return nullptr;
    auto const it = object.find(key);
    return it == object.end() ? nullptr : &*it;
}

std::size_t base64DecodedSize(std::string const& uri) {
    auto const comma = uri.find(',');
    if (comma == std::string::npos) return 0;
    std::size_t n = 0;
    for (std::size_t i = comma + 1; i < uri.size(); ++i)
        if (uri[i] != '=' && !std::isspace(static_cast<unsigned char>(uri[i]))) ++n;
    return n * 3 / 4;
}

void precheck(Json const& doc, Glb const* glb, FsState const& fsState, GltfLoadOptions const& options) {
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
            }
        }
    }

    if (Json const* nodes = member(doc, "nodes"); nodes && nodes->size() > options.maxNodes)
        fail("it has " + num(nodes->size()) + " nodes, more than the limit of " + num(options.maxNodes));

    // URIs: refuse any that leave the folder before anything is read through them.
    auto checkUri = [&](std::string const& uri, std::string const& what) -> std::optional<fs::path> {
        if (tinygltf::IsDataURI(uri) || uri.rfind("data:", 0) == 0) return std::nullopt;
        fs::path const decoded = fs::path(decodeUri(uri));
        fs::path const full = (fsState.folder / decoded).lexically_normal();
        if (!fsState.allowOutside && (decoded.is_absolute() || decoded.has_root_name() ||
                                      uri.find("://") != std::string::npos || !isInside(fsState.folder, full)))
            fail(what + " URI '" + printable(uri, 80) +
                 "' leaves the scene's folder, which is refused (allow with --allow-outside-uris)");
        return full;
    };
    if (Json const* images = member(doc, "images"))
        for (std::size_t i = 0; i < images->size(); ++i)
            if (Json const* uri = member((*images)[i], "uri")) checkUri(uri->get<std::string>(), "image " + num(i) + "'s");
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
                    fail(what + " is short: it declares " + std::to_string(byteLength) + " bytes but the BIN chunk holds " +
                         num(glb->bin.size()));
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

// ---------------------------------------------------------------------------------------------
// Accessors: every byte range checked before it is read

std::size_t componentSize(int type) {
    switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
    }
}

int componentCount(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    case TINYGLTF_TYPE_MAT2: return 4;
    case TINYGLTF_TYPE_MAT3: return 9;
    case TINYGLTF_TYPE_MAT4: return 16;
    default: return 0;
    }
}

double readComponent(std::uint8_t const* p, int type, bool normalized) {
    switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
        std::int8_t v;
        std::memcpy(&v, p, 1);
        return normalized ? std::max(double(v) / 127.0, -1.0) : double(v);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? double(*p) / 255.0 : double(*p);
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
        std::int16_t v;
        std::memcpy(&v, p, 2);
        return normalized ? std::max(double(v) / 32767.0, -1.0) : double(v);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        std::uint16_t v;
        std::memcpy(&v, p, 2);
        return normalized ? double(v) / 65535.0 : double(v);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
        std::uint32_t v;
        std::memcpy(&v, p, 4);
        return double(v);
    }
    default: {
        float v;
        std::memcpy(&v, p, 4);
        return double(v);
    }
    }
}

class ModelReader {
public:
    ModelReader(tinygltf::Model const& model, GltfLoadOptions const& options) : model_(model), options_(options) {
        for (std::size_t i = 0; i < model.bufferViews.size(); ++i) bufferView(int(i), "bufferView " + num(i));
    }

    // The bytes of a buffer view, after checking it lies inside its buffer.
    std::span<std::uint8_t const> bufferView(int index, std::string const& who) const {
        if (index < 0 || std::size_t(index) >= model_.bufferViews.size())
            fail(who + " refers to buffer view " + std::to_string(index) + ", but the file has " +
                 num(model_.bufferViews.size()));
        auto const& bv = model_.bufferViews[std::size_t(index)];
        if (bv.buffer < 0 || std::size_t(bv.buffer) >= model_.buffers.size())
            fail("buffer view " + std::to_string(index) + " refers to buffer " + std::to_string(bv.buffer) +
                 ", but the file has " + num(model_.buffers.size()));
        auto const& data = model_.buffers[std::size_t(bv.buffer)].data;
        if (bv.byteOffset > data.size() || bv.byteLength > data.size() - bv.byteOffset)
            fail("buffer view " + std::to_string(index) + " covers bytes " + num(bv.byteOffset) + " to " +
                 std::to_string(std::uint64_t(bv.byteOffset) + bv.byteLength) + " but buffer " +
                 std::to_string(bv.buffer) + " holds only " + num(data.size()));
        return {data.data() + bv.byteOffset, bv.byteLength};
    }

    // count * components values as double, normalised integers mapped to [0,1] / [-1,1].
    std::vector<double> read(int index, std::string const& who, int wantComponents = 0) const {
        if (index < 0 || std::size_t(index) >= model_.accessors.size())
            fail(who + " refers to accessor " + std::to_string(index) + ", but the file has " +
                 num(model_.accessors.size()));
        auto const& acc = model_.accessors[std::size_t(index)];
        std::string const name = "accessor " + std::to_string(index);
        int const comps = componentCount(acc.type);
        std::size_t const csize = componentSize(acc.componentType);
        if (comps == 0 || csize == 0) fail(name + " has an unknown type or component type");
        if (wantComponents && comps != wantComponents)
            fail(name + " (" + who + ") has " + std::to_string(comps) + " components per element; expected " +
                 std::to_string(wantComponents));
        if (acc.count > options_.maxVertices)
            fail(name + " has " + num(acc.count) + " elements, more than the limit of " + num(options_.maxVertices));
        std::size_t const elem = csize * std::size_t(comps);
        std::vector<double> out(acc.count * std::size_t(comps), 0.0);
        if (acc.bufferView >= 0 && acc.count > 0) {
            auto const bytes = bufferView(acc.bufferView, name);
            std::size_t const declared = model_.bufferViews[std::size_t(acc.bufferView)].byteStride;
            std::size_t const stride = declared ? declared : elem;
            if (stride < elem)
                fail("buffer view " + std::to_string(acc.bufferView) + " has byteStride " + num(stride) + ", less than the " +
                     num(elem) + "-byte elements of " + name);
            // 128-bit so that a hostile count or stride cannot wrap around and pass the check.
            unsigned __int128 const end =
                (unsigned __int128)acc.byteOffset + (unsigned __int128)(acc.count - 1) * stride + elem;
            if (end > bytes.size())
                fail(name + " reads bytes up to " + std::to_string(std::uint64_t(std::min<unsigned __int128>(end, UINT64_MAX))) +
                     " but buffer view " + std::to_string(acc.bufferView) + " holds only " + num(bytes.size()));
            for (std::size_t i = 0; i < acc.count; ++i) {
                std::uint8_t const* p = bytes.data() + acc.byteOffset + i * stride;
                for (int c = 0; c < comps; ++c)
                    out[i * std::size_t(comps) + std::size_t(c)] =
                        readComponent(p + std::size_t(c) * csize, acc.componentType, acc.normalized);
            }
        }
        if (acc.sparse.isSparse) applySparse(acc, name, comps, csize, out);
        return out;
    }

private:
    void applySparse(tinygltf::Accessor const& acc, std::string const& name, int comps, std::size_t csize,
                     std::vector<double>& out) const {
        auto const& sp = acc.sparse;
        if (sp.count < 0 || std::size_t(sp.count) > acc.count)
            fail(name + " has " + std::to_string(sp.count) + " sparse values but only " + num(acc.count) + " elements");
        std::size_t const n = std::size_t(sp.count);
        std::size_t const isize = componentSize(sp.indices.componentType);
        if (isize == 0 || sp.indices.componentType == TINYGLTF_COMPONENT_TYPE_BYTE ||
            sp.indices.componentType == TINYGLTF_COMPONENT_TYPE_SHORT || sp.indices.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT)
            fail(name + " has sparse indices of an invalid component type");
        auto const ib = bufferView(sp.indices.bufferView, name + " sparse indices");
        auto const vb = bufferView(sp.values.bufferView, name + " sparse values");
        std::size_t const elem = csize * std::size_t(comps);
        if (sp.indices.byteOffset < 0 || sp.values.byteOffset < 0 || std::size_t(sp.indices.byteOffset) > ib.size() ||
            n > (ib.size() - std::size_t(sp.indices.byteOffset)) / isize ||
            std::size_t(sp.values.byteOffset) > vb.size() || n > (vb.size() - std::size_t(sp.values.byteOffset)) / elem)
            fail(name + " has sparse data that runs past the end of its buffer views");
        for (std::size_t i = 0; i < n; ++i) {
            double const target =
                readComponent(ib.data() + std::size_t(sp.indices.byteOffset) + i * isize, sp.indices.componentType, false);
            if (target >= double(acc.count))
                fail(name + " has a sparse index " + std::to_string(std::uint64_t(target)) + " past its " + num(acc.count) +
                     " elements");
            std::uint8_t const* p = vb.data() + std::size_t(sp.values.byteOffset) + i * elem;
            for (int c = 0; c < comps; ++c)
                out[std::size_t(target) * std::size_t(comps) + std::size_t(c)] =
                    readComponent(p + std::size_t(c) * csize, acc.componentType, acc.normalized);
        }
    }

    tinygltf::Model const& model_;
    GltfLoadOptions const& options_;
};

// ---------------------------------------------------------------------------------------------
// The scene builder: nodes, meshes, materials, images, lights

glm::mat4 localTransform(tinygltf::Node const& n, std::size_t index) {
    std::string const who = "node " + num(index);
    if (!n.matrix.empty()) {
        if (n.matrix.size() != 16) fail(who + "'s matrix has " + num(n.matrix.size()) + " numbers; expected 16");
        glm::mat4 m;
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) m[c][r] = float(n.matrix[std::size_t(c * 4 + r)]);
        return m;
    }
    auto check = [&](std::vector<double> const& v, std::size_t want, char const* what) {
        if (!v.empty() && v.size() != want)
            fail(who + "'s " + what + " has " + num(v.size()) + " numbers; expected " + num(want));
    };
    check(n.translation, 3, "translation");
    check(n.rotation, 4, "rotation");
    check(n.scale, 3, "scale");
    glm::mat4 m(1.0f);
    if (!n.translation.empty())
        m = glm::translate(m, glm::vec3(float(n.translation[0]), float(n.translation[1]), float(n.translation[2])));
    if (!n.rotation.empty()) {
        glm::quat q(float(n.rotation[3]), float(n.rotation[0]), float(n.rotation[1]), float(n.rotation[2]));
        float const len = glm::length(q);
        m *= (len > 0.0f && std::isfinite(len)) ? glm::mat4_cast(q / len) : glm::mat4(1.0f);
    }
    if (!n.scale.empty()) m = glm::scale(m, glm::vec3(float(n.scale[0]), float(n.scale[1]), float(n.scale[2])));
    return m;
}

bool finiteMatrix(glm::mat4 const& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

class SceneBuilder {
public:
    SceneBuilder(tinygltf::Model const& model, Json const& doc, ImageStash& stash, GltfLoadOptions const& options,
                 Progress& progress)
        : model_(model), doc_(doc), stash_(stash), options_(options), progress_(progress), reader_(model, options) {}

    SceneData build() {
        std::vector<std::pair<int, glm::mat4>> const placed = placeNodes();

        // Materials first: their images dominate the time, and primitives need to know about normal maps.
        std::set<int> usedMaterials;
        for (auto const& [node, world] : placed) {
            int const meshIndex = model_.nodes[std::size_t(node)].mesh;
            if (meshIndex < 0) continue;
            if (std::size_t(meshIndex) >= model_.meshes.size())
                fail("node " + std::to_string(node) + " refers to mesh " + std::to_string(meshIndex) + ", but the file has " +
                     num(model_.meshes.size()));
            for (auto const& prim : model_.meshes[std::size_t(meshIndex)].primitives) {
                if (prim.material >= 0 && std::size_t(prim.material) >= model_.materials.size())
                    fail("mesh " + std::to_string(meshIndex) + " refers to material " + std::to_string(prim.material) +
                         ", but the file has " + num(model_.materials.size()));
                if (prim.material >= 0) usedMaterials.insert(prim.material);
            }
        }
        imagesToDecode_ = countImages(usedMaterials);
        progress_.report(0.1f, "decoding images");
        for (int m : usedMaterials) material(m);

        progress_.report(0.6f, "building meshes");
        std::map<int, std::vector<int>> meshParts;  // glTF mesh -> our meshes (one per primitive)
        std::size_t drawn = 0;
        std::size_t done = 0;
        for (auto const& [node, world] : placed) {
            int const meshIndex = model_.nodes[std::size_t(node)].mesh;
            if (meshIndex < 0) continue;
            auto it = meshParts.find(meshIndex);
            if (it == meshParts.end()) {
                it = meshParts.emplace(meshIndex, buildMesh(meshIndex)).first;
                progress_.report(0.6f + 0.3f * float(++done) / float(std::max<std::size_t>(placed.size(), 1)),
                                 "building meshes");
            }
            for (int part : it->second) {
                drawn += scene_.meshes[std::size_t(part)].indices.size() / 3;
                if (drawn > options_.maxTriangles)
                    fail("its instances draw more than the limit of " + num(options_.maxTriangles) + " triangles");
                scene_.instances.push_back({part, world});
            }
        }

        progress_.report(0.95f, "lights and camera");
        addLights(placed);
        Bounds const bounds = scene_.bounds();
        if (scene_.instances.empty()) scene_.warnings.push_back("the scene has no triangles to draw");
        if (scene_.lights.empty()) scene_.lights = generateLightsForBounds(bounds);
        scene_.camera = frameBounds(bounds);
        return std::move(scene_);
    }

private:
    // Validates the node graph (a forest: in-range children, one parent each, no cycles) and
    // returns the nodes of the chosen scene with their world matrices.
    std::vector<std::pair<int, glm::mat4>> placeNodes() {
        std::size_t const n = model_.nodes.size();
        std::vector<int> parent(n, -1);
        for (std::size_t i = 0; i < n; ++i) {
            for (int c : model_.nodes[i].children) {
                if (c < 0 || std::size_t(c) >= n)
                    fail("node " + num(i) + " lists child " + std::to_string(c) + ", but the file has " + num(n) + " nodes");
                if (std::size_t(c) == i) fail("node " + num(i) + " is its own child (the node graph is recursive)");
                if (parent[std::size_t(c)] >= 0)
                    fail("node " + std::to_string(c) + " has two parents (nodes " + std::to_string(parent[std::size_t(c)]) +
                         " and " + num(i) + "); glTF node graphs must be trees");
                parent[std::size_t(c)] = int(i);
            }
        }
        // With one parent each, a cycle is a chain of parents that comes back on itself.
        std::vector<char> state(n, 0);  // 0 unvisited, 1 on the current chain, 2 known acyclic
        for (std::size_t start = 0; start < n; ++start) {
            std::vector<int> chain;
            int cur = int(start);
            while (cur >= 0 && state[std::size_t(cur)] == 0) {
                state[std::size_t(cur)] = 1;
                chain.push_back(cur);
                cur = parent[std::size_t(cur)];
            }
            if (cur >= 0 && state[std::size_t(cur)] == 1)
                fail("node " + std::to_string(cur) + " is its own ancestor (the node graph is recursive)");
            for (int c : chain) state[std::size_t(c)] = 2;
        }

        std::vector<int> roots;
        if (!model_.scenes.empty()) {
            int s = model_.defaultScene;
            if (s < 0) s = 0;
            if (std::size_t(s) >= model_.scenes.size())
                fail("its default scene is " + std::to_string(s) + ", but the file has " + num(model_.scenes.size()));
            roots = model_.scenes[std::size_t(s)].nodes;
        } else {
            for (std::size_t i = 0; i < n; ++i)
                if (parent[i] < 0) roots.push_back(int(i));
        }
        std::vector<std::pair<int, glm::mat4>> placed;
        std::vector<char> visited(n, 0);
        std::vector<std::pair<int, glm::mat4>> stack;
        for (auto it = roots.rbegin(); it != roots.rend(); ++it) {
            if (*it < 0 || std::size_t(*it) >= n)
                fail("the scene lists node " + std::to_string(*it) + ", but the file has " + num(n) + " nodes");
            stack.push_back({*it, glm::mat4(1.0f)});
        }
        while (!stack.empty()) {
            auto const [node, parentWorld] = stack.back();
            stack.pop_back();
            if (visited[std::size_t(node)]) {
                scene_.warnings.push_back("node " + std::to_string(node) + " is reached twice from the scene; drawn once");
                continue;
            }
            visited[std::size_t(node)] = 1;
            glm::mat4 const world = parentWorld * localTransform(model_.nodes[std::size_t(node)], std::size_t(node));
            if (!finiteMatrix(world)) fail("node " + std::to_string(node) + " has a NaN or infinite transform");
            placed.push_back({node, world});
            auto const& children = model_.nodes[std::size_t(node)].children;
            for (auto c = children.rbegin(); c != children.rend(); ++c) stack.push_back({*c, world});
        }
        return placed;
    }

    // --- images and materials -----------------------------------------------------------

    int textureSource(int texture, std::string const& who) {
        if (texture < 0) return -1;
        if (std::size_t(texture) >= model_.textures.size())
            fail(who + " refers to texture " + std::to_string(texture) + ", but the file has " + num(model_.textures.size()));
        int const source = model_.textures[std::size_t(texture)].source;
        if (source < 0) {
            scene_.warnings.push_back(who + " uses texture " + std::to_string(texture) +
                                      ", which has no image this loader can read; ignored");
            return -1;
        }
        if (std::size_t(source) >= model_.images.size())
            fail("texture " + std::to_string(texture) + " refers to image " + std::to_string(source) + ", but the file has " +
                 num(model_.images.size()));
        return source;
    }

    std::size_t countImages(std::set<int> const& materials) {
        std::set<int> images;
        for (int m : materials) {
            auto const& mat = model_.materials[std::size_t(m)];
            std::string const who = "material " + std::to_string(m);
            for (int t : {mat.pbrMetallicRoughness.baseColorTexture.index, mat.normalTexture.index,
                          mat.pbrMetallicRoughness.metallicRoughnessTexture.index})
                if (int s = textureSource(t, who); s >= 0) images.insert(s);
        }
        return std::max<std::size_t>(images.size(), 1);
    }

    // The decoded image, or null (with a warning) when it is missing or unreadable.
    ImageData const* decoded(int image) {
        auto found = decoded_.find(image);
        if (found != decoded_.end()) return found->second ? &*found->second : nullptr;
        auto const& src = model_.images[std::size_t(image)];
        std::string const label = "image " + std::to_string(image) + (src.uri.empty() || src.uri.rfind("data:", 0) == 0
                                                                           ? std::string()
                                                                           : " ('" + printable(src.uri, 80) + "')");
        std::span<std::uint8_t const> bytes;
        if (src.bufferView >= 0) {
            bytes = reader_.bufferView(src.bufferView, "image " + std::to_string(image));
        } else if (auto it = stash_.encoded.find(image); it != stash_.encoded.end()) {
            bytes = it->second;
        }
        std::optional<ImageData> result;
        if (bytes.empty()) {
            scene_.warnings.push_back(label + " is missing; a placeholder texture is shown instead");
        } else {
            DecodedImage d = decodeImage(bytes, src.name.empty() ? label : src.name,
                                         src.mimeType.empty() ? std::string_view(src.uri) : std::string_view(src.mimeType),
                                         options_.maxImagePixels);
            if (d.overLimit) fail(label + ": " + d.error);
            if (!d.image) scene_.warnings.push_back(label + " cannot be used (" + d.error + "); a placeholder texture is shown instead");
            result = std::move(d.image);
        }
        ++imagesDecoded_;
        progress_.report(0.1f + 0.5f * float(imagesDecoded_) / float(imagesToDecode_), "decoding images");
        auto const& stored = decoded_.emplace(image, std::move(result)).first->second;
        return stored ? &*stored : nullptr;
    }

    // Index into scene_.images for a glTF image used as colour (sRGB) or as data (linear).
    int sceneImage(int image, bool srgb) {
        auto const key = std::make_pair(image, srgb);
        if (auto it = sceneImages_.find(key); it != sceneImages_.end()) return it->second;
        ImageData const* img = decoded(image);
        ImageData copy = img ? *img : placeholderImage("placeholder for image " + std::to_string(image));
        copy.srgb = srgb;
        scene_.images.push_back(std::move(copy));
        int const index = int(scene_.images.size() - 1);
        sceneImages_.emplace(key, index);
        return index;
    }

    int material(int index) {
        if (auto it = materials_.find(index); it != materials_.end()) return it->second;
        auto const& src = model_.materials[std::size_t(index)];
        std::string const who = "material " + std::to_string(index);
        Material mat;
        mat.name = src.name.empty() ? who : src.name;
        auto const& pbr = src.pbrMetallicRoughness;
        if (pbr.baseColorFactor.size() == 4)
            mat.baseColorFactor = glm::clamp(glm::vec4(float(pbr.baseColorFactor[0]), float(pbr.baseColorFactor[1]),
                                                       float(pbr.baseColorFactor[2]), float(pbr.baseColorFactor[3])),
                                             0.0f, 1.0f);
        else if (!pbr.baseColorFactor.empty())
            scene_.warnings.push_back(who + "'s baseColorFactor does not have 4 numbers; white is used");
        auto noteTexCoord = [&](int texCoord, char const* what) {
            if (texCoord != 0)
                scene_.warnings.push_back(who + "'s " + what + " uses TEXCOORD_" + std::to_string(texCoord) +
                                          "; only TEXCOORD_0 is loaded");
        };
        if (int s = textureSource(pbr.baseColorTexture.index, who); s >= 0) {
            mat.baseColorTexture = sceneImage(s, true);
            noteTexCoord(pbr.baseColorTexture.texCoord, "base colour texture");
        }
        if (int s = textureSource(src.normalTexture.index, who); s >= 0) {
            mat.normalTexture = sceneImage(s, false);
            mat.normalScale = std::isfinite(src.normalTexture.scale) ? float(src.normalTexture.scale) : 1.0f;
            noteTexCoord(src.normalTexture.texCoord, "normal texture");
        }

        // Specular intensity: docs/gltf.md, "glTF materials and lights".
        float weight = 1.0f;
        int specularImage = -1;
        Json const* specExt = nullptr;
        if (Json const* mats = member(doc_, "materials"); mats && std::size_t(index) < mats->size())
            if (Json const* ext = member((*mats)[std::size_t(index)], "extensions"))
                specExt = member(*ext, "KHR_materials_specular");
        if (specExt) {
            requireKind(*specExt, Kind::Object, who + "'s KHR_materials_specular");
            if (Json const* f = member(*specExt, "specularFactor")) {
                requireKind(*f, Kind::Number, who + "'s specularFactor");
                weight = f->get<float>();
            }
            if (Json const* f = member(*specExt, "specularColorFactor")) {
                requireKind(*f, Kind::NumberArray, who + "'s specularColorFactor");
                float strongest = 0.0f;
                for (auto const& c : *f) strongest = std::max(strongest, c.get<float>());
                if (!f->empty()) weight *= strongest;
            }
            if (Json const* t = member(*specExt, "specularTexture")) {
                requireKind(*t, Kind::Object, who + "'s specularTexture");
                if (Json const* i = member(*t, "index")) {
                    requireKind(*i, Kind::Index, who + "'s specularTexture.index");
                    specularImage = textureSource(int(std::min<std::uint64_t>(i->get<std::uint64_t>(), INT_MAX)), who);
                }
            }
        }
        float const metallic = float(pbr.metallicFactor), roughness = float(pbr.roughnessFactor);
        int const mrImage = textureSource(pbr.metallicRoughnessTexture.index, who);
        ImageData const* mr = mrImage >= 0 ? decoded(mrImage) : nullptr;
        ImageData const* sp = specularImage >= 0 ? decoded(specularImage) : nullptr;
        if (mr || sp) {
            // Bake once per distinct input: many materials share one texture set.
            std::string const key = std::to_string(mr ? mrImage : -1) + "/" + std::to_string(sp ? specularImage : -1) + "/" +
                                    std::to_string(metallic) + "/" + std::to_string(roughness) + "/" + std::to_string(weight);
            auto it = bakes_.find(key);
            if (it == bakes_.end()) {
                scene_.images.push_back(
                    bakeSpecularImage(mr, sp, metallic, roughness, weight, mat.name + " specular (baked)"));
                it = bakes_.emplace(key, int(scene_.images.size() - 1)).first;
            }
            mat.specularTexture = it->second;
            mat.specularFactor = 1.0f;
        } else {
            mat.specularFactor = specularFromMetallicRoughness(metallic, roughness, weight);
        }

        if (src.alphaMode == "MASK") mat.alphaMode = AlphaMode::Mask;
        else if (src.alphaMode == "BLEND") mat.alphaMode = AlphaMode::Blend;
        else if (src.alphaMode != "OPAQUE" && !src.alphaMode.empty())
            scene_.warnings.push_back(who + " has an unknown alphaMode '" + printable(src.alphaMode, 20) + "'; drawn opaque");
        mat.alphaCutoff = std::isfinite(src.alphaCutoff) ? float(src.alphaCutoff) : 0.5f;
        mat.doubleSided = src.doubleSided;

        scene_.materials.push_back(std::move(mat));
        int const ours = int(scene_.materials.size() - 1);
        materials_.emplace(index, ours);
        return ours;
    }

    // --- meshes -------------------------------------------------------------------------

    std::vector<int> buildMesh(int meshIndex) {
        auto const& mesh = model_.meshes[std::size_t(meshIndex)];
        std::vector<int> parts;
        for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
            auto const& prim = mesh.primitives[p];
            std::string const who = "mesh " + std::to_string(meshIndex) + " primitive " + num(p);
            if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != -1) {
                static constexpr char const* kModes[] = {"points", "lines", "line loops", "line strips",
                                                         "triangles", "triangle strips", "triangle fans"};
                std::string const mode = prim.mode >= 0 && prim.mode <= 6 ? kModes[prim.mode] : "an unknown mode";
                scene_.warnings.push_back(who + " draws " + mode + "; only triangle lists are loaded, so it is skipped");
                continue;
            }
            auto attr = [&](char const* name) {
                auto it = prim.attributes.find(name);
                return it == prim.attributes.end() ? -1 : it->second;
            };
            int const posAccessor = attr("POSITION");
            if (posAccessor < 0) {
                scene_.warnings.push_back(who + " has no POSITION attribute; skipped");
                continue;
            }
            MeshData out;
            out.name = (mesh.name.empty() ? "mesh " + std::to_string(meshIndex) : mesh.name) +
                       (mesh.primitives.size() > 1 ? " #" + num(p) : "");
            out.material = prim.material >= 0 ? material(prim.material) : -1;

            std::vector<double> const pos = reader_.read(posAccessor, who + " POSITION", 3);
            std::size_t const n = pos.size() / 3;
            for (std::size_t i = 0; i < pos.size(); ++i)
                if (!std::isfinite(float(pos[i])))
                    fail(who + " has a NaN or infinite position at vertex " + num(i / 3));
            out.vertices.resize(n);
            for (std::size_t i = 0; i < n; ++i)
                out.vertices[i].position = glm::vec3(float(pos[3 * i]), float(pos[3 * i + 1]), float(pos[3 * i + 2]));

            auto sameCount = [&](std::vector<double> const& v, int comps, char const* what) {
                if (v.size() / std::size_t(comps) != n)
                    fail(who + " has " + num(v.size() / std::size_t(comps)) + " " + what + " values for " + num(n) + " positions");
            };
            bool haveNormals = false;
            if (int a = attr("NORMAL"); a >= 0) {
                std::vector<double> const v = reader_.read(a, who + " NORMAL", 3);
                sameCount(v, 3, "NORMAL");
                haveNormals = true;
                for (std::size_t i = 0; i < n && haveNormals; ++i) {
                    glm::vec3 const nn = glm::vec3(float(v[3 * i]), float(v[3 * i + 1]), float(v[3 * i + 2]));
                    float const len = glm::length(nn);
                    if (!(len > 0.0f) || !std::isfinite(len)) haveNormals = false;
                    else out.vertices[i].normal = nn / len;
                }
                if (!haveNormals) scene_.warnings.push_back(who + " has zero or non-finite normals; flat normals are used");
            }
            if (int a = attr("TEXCOORD_0"); a >= 0) {
                std::vector<double> const v = reader_.read(a, who + " TEXCOORD_0", 2);
                sameCount(v, 2, "TEXCOORD_0");
                bool bad = false;
                for (std::size_t i = 0; i < n; ++i) {
                    glm::vec2 uv = glm::vec2(float(v[2 * i]), float(v[2 * i + 1]));
                    if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) uv = glm::vec2(0.0f), bad = true;
                    out.vertices[i].uv = uv;
                }
                if (bad) scene_.warnings.push_back(who + " has non-finite texture coordinates; they are set to 0");
            }
            bool haveTangents = false;
            if (int a = attr("TANGENT"); a >= 0 && haveNormals) {
                std::vector<double> const v = reader_.read(a, who + " TANGENT", 4);
                sameCount(v, 4, "TANGENT");
                haveTangents = true;
                for (std::size_t i = 0; i < n && haveTangents; ++i) {
                    glm::vec3 const t = glm::vec3(float(v[4 * i]), float(v[4 * i + 1]), float(v[4 * i + 2]));
                    float const len = glm::length(t);
                    if (!(len > 0.0f) || !std::isfinite(len) || !std::isfinite(float(v[4 * i + 3]))) haveTangents = false;
                    else out.vertices[i].tangent = glm::vec4(t / len, v[4 * i + 3] < 0.0 ? -1.0f : 1.0f);
                }
                if (!haveTangents) scene_.warnings.push_back(who + " has zero or non-finite tangents; they are generated");
            }

            if (prim.indices >= 0) {
                auto const& acc = model_.accessors.at(std::size_t(prim.indices));  // range checked by tinygltf
                if (acc.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                    acc.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                    acc.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
                    fail(who + "'s indices are not unsigned 8, 16 or 32-bit integers");
                std::vector<double> const idx = reader_.read(prim.indices, who + " indices", 1);
                out.indices.resize(idx.size());
                for (std::size_t i = 0; i < idx.size(); ++i) {
                    if (idx[i] >= double(n))
                        fail(who + " has index " + std::to_string(std::uint64_t(idx[i])) + " at position " + num(i) +
                             ", but only " + num(n) + " vertices");
                    out.indices[i] = std::uint32_t(idx[i]);
                }
            } else {
                out.indices.resize(n);
                for (std::size_t i = 0; i < n; ++i) out.indices[i] = std::uint32_t(i);
            }
            if (out.indices.size() % 3 != 0) {
                scene_.warnings.push_back(who + " has " + num(out.indices.size()) +
                                          " indices, not a multiple of 3; the incomplete triangle is dropped");
                out.indices.resize(out.indices.size() - out.indices.size() % 3);
            }
            uniqueTriangles_ += out.indices.size() / 3;
            if (uniqueTriangles_ > options_.maxTriangles)
                fail("it has more than the limit of " + num(options_.maxTriangles) + " triangles");
            if (out.indices.empty()) {
                scene_.warnings.push_back(who + " has no triangles; skipped");
                continue;
            }
            if (!haveNormals) generateFlatNormals(out);
            bool const normalMapped =
                prim.material >= 0 && scene_.materials[std::size_t(out.material)].normalTexture >= 0;
            if (normalMapped && !haveTangents) generateTangents(out);
            scene_.meshes.push_back(std::move(out));
            parts.push_back(int(scene_.meshes.size() - 1));
        }
        return parts;
    }

    // --- lights -------------------------------------------------------------------------

    void addLights(std::vector<std::pair<int, glm::mat4>> const& placed) {
        Json const* ext = member(doc_, "extensions");
        Json const* punctual = ext ? member(*ext, "KHR_lights_punctual") : nullptr;
        Json const* lights = punctual ? member(*punctual, "lights") : nullptr;
        if (lights) requireKind(*lights, Kind::Array, "KHR_lights_punctual.lights");
        Json const* nodes = member(doc_, "nodes");
        for (auto const& [node, world] : placed) {
            Json const* nodeExt = nodes ? member((*nodes)[std::size_t(node)], "extensions") : nullptr;
            Json const* ref = nodeExt ? member(*nodeExt, "KHR_lights_punctual") : nullptr;
            if (!ref) continue;
            std::string const who = "node " + std::to_string(node);
            requireKind(*ref, Kind::Object, who + "'s KHR_lights_punctual");
            Json const* li = member(*ref, "light");
            if (!li) continue;
            requireKind(*li, Kind::Index, who + "'s KHR_lights_punctual.light");
            std::uint64_t const l = li->get<std::uint64_t>();
            if (!lights || l >= lights->size())
                fail(who + " refers to light " + std::to_string(l) + ", but the file has " +
                     num(lights ? lights->size() : 0));
            Json const& light = (*lights)[l];
            std::string const lw = "light " + std::to_string(l);
            requireKind(light, Kind::Object, lw);
            std::string type = "point";
            if (Json const* t = member(light, "type")) requireKind(*t, Kind::String, lw + ".type"), type = t->get<std::string>();
            glm::vec3 color(1.0f);
            if (Json const* c = member(light, "color")) {
                requireKind(*c, Kind::NumberArray, lw + ".color");
                if (c->size() != 3) fail(lw + ".color has " + num(c->size()) + " numbers; expected 3");
                color = glm::vec3((*c)[0].get<float>(), (*c)[1].get<float>(), (*c)[2].get<float>());
            }
            float intensity = 1.0f, range = 0.0f;
            if (Json const* i = member(light, "intensity")) requireKind(*i, Kind::Number, lw + ".intensity"), intensity = i->get<float>();
            if (Json const* r = member(light, "range")) requireKind(*r, Kind::Number, lw + ".range"), range = r->get<float>();
            std::string name = "light " + std::to_string(l);
            if (Json const* nm = member(light, "name"); nm && nm->is_string()) name = nm->get<std::string>();
            if (type == "directional") {
                scene_.warnings.push_back(lw + " is directional; only point lights are loaded, so it is skipped");
                continue;
            }
            if (type == "spot")
                scene_.warnings.push_back(lw + " is a spot light; it is loaded as a point light without its cone");
            else if (type != "point") {
                scene_.warnings.push_back(lw + " has an unknown type '" + printable(type, 20) + "'; skipped");
                continue;
            }
            std::string why;
            auto pl = pointLightFromGltf(glm::vec3(world[3]), color, intensity, range, name, &why);
            if (!pl) {
                scene_.warnings.push_back(lw + " is skipped because " + why);
                continue;
            }
            if (lightRadius(*pl).kind == RadiusKind::Zero)
                scene_.warnings.push_back(lw + " is too dim to reach the light threshold; it lights nothing");
            scene_.lights.push_back(std::move(*pl));
        }
    }

    tinygltf::Model const& model_;
    Json const& doc_;
    ImageStash& stash_;
    GltfLoadOptions const& options_;
    Progress& progress_;
    ModelReader reader_;
    SceneData scene_;
    std::map<int, std::optional<ImageData>> decoded_;
    std::map<std::pair<int, bool>, int> sceneImages_;
    std::map<int, int> materials_;
    std::map<std::string, int> bakes_;
    std::size_t imagesToDecode_ = 1, imagesDecoded_ = 0;
    std::size_t uniqueTriangles_ = 0;
};

// ---------------------------------------------------------------------------------------------

SceneData loadFromBytes(std::span<std::uint8_t const> data, fs::path const& file, GltfLoadOptions const& options,
                        Progress& progress) {
    if (data.empty()) fail("the file is empty");
    if (data.size() > options.maxFileBytes)
        fail("the file is " + num(data.size()) + " bytes, more than the limit of " + num(options.maxFileBytes) + " bytes");
    if (data.size() > UINT_MAX) fail("the file is larger than 4 GiB, which tinygltf cannot read");

    bool const isGlb = data.size() >= 4 && std::memcmp(data.data(), "glTF", 4) == 0;
    std::optional<Glb> glb;
    std::span<std::uint8_t const> jsonText = data;
    if (isGlb) {
        glb = splitGlb(data);
        jsonText = glb->json;
    } else {
        std::size_t i = 0;
        if (data.size() >= 3 && data[0] == 0xEF && data[1] == 0xBB && data[2] == 0xBF) i = 3;  // UTF-8 BOM
        while (i < data.size() && std::isspace(data[i])) ++i;
        if (i == data.size() || data[i] != '{')
            fail("it is not a glTF file (neither a JSON object nor binary glTF)");
        jsonText = data.subspan(i);
    }

    FsState fsState;
    std::error_code ec;
    fs::path const absolute = fs::absolute(file, ec);
    fsState.folder = fs::weakly_canonical(absolute.parent_path(), ec);
    if (ec) fsState.folder = absolute.parent_path().lexically_normal();
    fsState.allowOutside = options.allowOutsideUris;
    fsState.maxFileBytes = options.maxFileBytes;

    progress.report(0.02f, "parsing");
    Json const doc = parseJson(jsonText, options.maxJsonDepth);
    precheck(doc, glb ? &*glb : nullptr, fsState, options);

    tinygltf::TinyGLTF loader;
    ImageStash stash;
    loader.SetImageLoader(&stashImage, &stash);
    loader.SetFsCallbacks({&fsFileExists, &fsExpandFilePath, &fsReadWholeFile, &fsWriteWholeFile, &fsState});
    tinygltf::Model model;
    std::string err, warn;
    std::string const baseDir = fsState.folder.string();
    bool const ok = isGlb ? loader.LoadBinaryFromMemory(&model, &err, &warn, data.data(), unsigned(data.size()), baseDir)
                          : loader.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<char const*>(jsonText.data()),
                                                       unsigned(jsonText.size()), baseDir);
    if (!fsState.failure.empty()) fail(fsState.failure);
    if (!ok) {
        std::string first = err.substr(0, err.find('\n'));
        fail("tinygltf rejected it (" + printable(first.empty() ? std::string("no reason given") : first, 160) + ")");
    }
    progress.report(0.1f, "parsing");

    SceneBuilder builder(model, doc, stash, options, progress);
    SceneData scene = builder.build();
    scene.source = file.string();
    progress.report(1.0f, "done");
    return scene;
}

GltfLoadResult run(fs::path const& file, GltfLoadOptions const& options,
                   std::function<SceneData(Progress&)> const& load) {
    GltfLoadResult result;
    Progress progress(options);
    std::string const name = "Cannot load '" + file.string() + "': ";
    try {
        result.scene = load(progress);
    } catch (LoadFailure const& f) {
        result.error = name + f.cause + ".";
    } catch (LoadCancelled const&) {
        result.cancelled = true;
        result.error = "Loading '" + file.string() + "' was cancelled.";
    } catch (std::bad_alloc const&) {
        result.error = name + "it needs more memory than is available.";
    } catch (std::exception const& e) {
        result.error = name + "unexpected failure (" + printable(e.what()) + ").";
    }
    if (!result.error.empty()) result.scene.reset();
    return result;
}

}  // namespace

GltfLoadResult loadGltf(fs::path const& file, GltfLoadOptions const& options) {
    return run(file, options, [&](Progress& progress) {
        progress.report(0.0f, "reading");
        std::error_code ec;
        auto const status = fs::status(file, ec);
        if (!fs::exists(status)) fail("the file does not exist");
        if (fs::is_directory(status)) fail("it is a folder, not a file");
        std::uintmax_t const size = fs::file_size(file, ec);
        if (ec) fail("its size cannot be read (" + ec.message() + ")");
        if (size > options.maxFileBytes)
            fail("the file is " + std::to_string(size) + " bytes, more than the limit of " + num(options.maxFileBytes) +
                 " bytes");
        std::ifstream in(file, std::ios::binary);
        if (!in) fail("the file cannot be opened for reading");
        std::vector<std::uint8_t> bytes(static_cast<std::size_t>(size));
        if (size > 0 && !in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(size)))
            fail("the file cannot be read");
        return loadFromBytes(bytes, file, options, progress);
    });
}

GltfLoadResult loadGltfFromMemory(std::span<std::uint8_t const> bytes, fs::path const& file,
                                  GltfLoadOptions const& options) {
    return run(file, options, [&](Progress& progress) { return loadFromBytes(bytes, file, options, progress); });
}

}  // namespace gbl
