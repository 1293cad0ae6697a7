// glTF 2.0 loading: a strict JSON pre-check (gltf_precheck), tinygltf parsing with our own file
// access and OpenImageIO images, then the scene builder's validation of every index and byte range.
#include "gltf/loader.h"

#include "gltf/failure.h"
#include "gltf/precheck.h"
#include "gltf/scene_builder.h"

#include <tiny_gltf.h>

#include <cctype>
#include <climits>
#include <cstring>
#include <fstream>
#include <new>

namespace gbl {

using namespace gltf;  // the loader's internals, shared by its source files

namespace {

namespace fs = std::filesystem;

// ---------------------------------------------------------------------------------------------
// File access for tinygltf: only the scene's folder, within the size limit

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

std::string fsExpandFilePath(std::string const& path, void*) {
    return path;
}

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

bool fsWriteWholeFile(std::string*, std::string const&, std::vector<unsigned char> const&, void*) {
    return false;
}

// Keeps the encoded bytes of URI images for the builder (see ImageStash).
bool stashImage(tinygltf::Image* image, int index, std::string*, std::string*, int, int, unsigned char const* bytes,
                int size, void* user) {
    // For bufferView images tinygltf passes a pointer it has not range-checked: never read it here.
    if (image->bufferView >= 0) return true;
    if (bytes && size > 0) static_cast<ImageStash*>(user)->encoded[index].assign(bytes, bytes + size);
    return true;
}

// A binary glTF with another JSON chunk and the same BIN chunk.
std::vector<std::uint8_t> rebuildGlb(std::string const& json, Glb const& glb) {
    auto u32 = [](std::vector<std::uint8_t>& out, std::uint32_t v) {
        for (int i = 0; i < 4; ++i) out.push_back(std::uint8_t(v >> (8 * i)));
    };
    std::size_t const jsonLength = (json.size() + 3) / 4 * 4, binLength = (glb.bin.size() + 3) / 4 * 4;
    std::vector<std::uint8_t> out = {'g', 'l', 'T', 'F'};
    u32(out, 2);
    u32(out, std::uint32_t(12 + 8 + jsonLength + (glb.hasBin ? 8 + binLength : 0)));
    u32(out, std::uint32_t(jsonLength));
    u32(out, 0x4E4F534Au);
    out.insert(out.end(), json.begin(), json.end());
    out.resize(20 + jsonLength, ' ');  // JSON chunks are padded with spaces
    if (glb.hasBin) {
        u32(out, std::uint32_t(binLength));
        u32(out, 0x004E4942u);
        out.insert(out.end(), glb.bin.begin(), glb.bin.end());
        out.resize(out.size() + (binLength - glb.bin.size()), 0);
    }
    return out;
}

// ---------------------------------------------------------------------------------------------
// Reading, parsing and the one-sentence error

SceneData loadFromBytes(std::span<std::uint8_t const> data, fs::path const& file, GltfLoadOptions const& options,
                        Progress& progress) {
    if (data.empty()) fail("the file is empty");
    if (data.size() > options.maxFileBytes)
        fail("the file is " + num(data.size()) + " bytes, more than the limit of " + num(options.maxFileBytes) +
             " bytes");
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
        if (i == data.size() || data[i] != '{') fail("it is not a glTF file (neither a JSON object nor binary glTF)");
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
    precheck(doc, glb ? &*glb : nullptr, fsState.folder, options);

    // Draco primitives keep their indices in the Draco data; tinygltf must not see their empty accessors.
    std::string patchedJson;
    std::vector<std::uint8_t> patchedGlb;
    if (std::optional<Json> const patched = withoutDracoIndices(doc)) {
        patchedJson = patched->dump();
        if (glb) {
            patchedGlb = rebuildGlb(patchedJson, *glb);
            data = patchedGlb;
        } else {
            jsonText = std::span(reinterpret_cast<std::uint8_t const*>(patchedJson.data()), patchedJson.size());
        }
    }

    tinygltf::TinyGLTF loader;
    ImageStash stash;
    loader.SetImageLoader(&stashImage, &stash);
    loader.SetFsCallbacks({&fsFileExists, &fsExpandFilePath, &fsReadWholeFile, &fsWriteWholeFile, &fsState});
    tinygltf::Model model;
    std::string err, warn;
    std::string const baseDir = fsState.folder.string();
    bool const ok =
        isGlb ? loader.LoadBinaryFromMemory(&model, &err, &warn, data.data(), unsigned(data.size()), baseDir)
              : loader.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<char const*>(jsonText.data()),
                                           unsigned(jsonText.size()), baseDir);
    if (!fsState.failure.empty()) fail(fsState.failure);
    if (!ok) {
        std::string first = err.substr(0, err.find('\n'));
        fail("tinygltf rejected it (" + printable(first.empty() ? std::string("no reason given") : first, 160) + ")");
    }
    progress.report(0.1f, "parsing");

    SceneData scene = buildScene(model, doc, stash, options, progress);
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