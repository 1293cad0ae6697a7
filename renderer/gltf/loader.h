// Loads a glTF 2.0 file (.gltf or .glb) into a CPU SceneData; safe on a worker thread (no GL).
#pragma once

#include "scene/scene_data.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace gbl {

struct GltfLoadOptions {
    // External buffers and images must sit in the scene's folder (or below it) unless this is
    // set; data: URIs are always allowed.
    bool allowOutsideUris = false;

    // Limits against absurd or hostile files. Every refusal names the limit it hit.
    std::size_t maxFileBytes = std::size_t(1) << 30;        // the file itself and each file it reads
    std::size_t maxTriangles = 50'000'000;                  // drawn triangles over all instances
    std::size_t maxVertices = 50'000'000;                   // elements of any one accessor
    std::size_t maxImagePixels = std::size_t(8192) * 8192;  // width * height of one image
    std::size_t maxNodes = 1'000'000;                       // nodes in the file
    std::size_t maxJsonDepth = 64;                          // nesting of the JSON document

    // Called with a fraction in [0, 1] and the stage's name; returning false cancels the load.
    // Called on the loading thread.
    std::function<bool(float fraction, std::string_view stage)> progress;
};

struct GltfLoadResult {
    std::optional<SceneData> scene;  // empty on failure or cancellation, never half-filled
    std::string error;               // one sentence naming the file and the cause when scene is empty
    bool cancelled = false;          // the progress callback asked to stop
};

GltfLoadResult loadGltf(std::filesystem::path const& file, GltfLoadOptions const& options = {});

// The same from bytes already in memory (tests, fuzzing, drag-and-drop of data). `file` names
// the source in messages and its folder is where external URIs are looked up.
GltfLoadResult loadGltfFromMemory(std::span<std::uint8_t const> bytes, std::filesystem::path const& file,
                                  GltfLoadOptions const& options = {});

// Whether this build decodes KHR_draco_mesh_compression (configured with the Draco library).
bool gltfDecodesDraco();

}  // namespace gbl
