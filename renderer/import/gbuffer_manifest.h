// The G-buffer manifest (docs/import.md): how another program's attachments, camera and lights are
// stored, read from versioned JSON and validated with a message naming the first bad field.
#pragma once

#include "core/gbuffer_layout.h"     // NormalEncoding, the same three encodings the layouts store
#include "core/pipeline_settings.h"  // ShadingModel
#include "core/point_light.h"

#include <glm/glm.hpp>

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gbl {

inline constexpr std::string_view kManifestFormat = "gbuffer-lab-gbuffer";
// Bump when a field changes meaning or a required field is added.
inline constexpr int kManifestVersion = 1;

enum class Space { World, View };
enum class ColorEncoding { Linear, Srgb };
enum class DepthConvention { Window, Ndc, Linear };
enum class RawType { Float, Half, Uint8 };

inline constexpr std::array<std::string_view, 2> kSpaceNames{"world", "view"};
inline constexpr std::array<std::string_view, 3> kNormalEncodingNames{"float", "biased", "octahedral"};
inline constexpr std::array<std::string_view, 2> kColorEncodingNames{"linear", "srgb"};
inline constexpr std::array<std::string_view, 3> kDepthConventionNames{"window", "ndc", "linear"};
inline constexpr std::array<std::string_view, 3> kRawTypeNames{"float", "half", "uint8"};
inline constexpr std::array<std::string_view, 3> kManifestPresetNames{"learnopengl", "newcastle", "gbuffer-lab"};

// A headerless file of float32, float16 or uint8 samples, rows top to bottom, channels interleaved.
struct RawFormat {
    RawType type = RawType::Float;
    int width = 0;
    int height = 0;
    int channels = 0;
};

// One image file and the channels of it that hold a quantity.
struct ImageRef {
    std::string path;           // resolved against the manifest's folder
    std::string field;          // the manifest field that named it, for messages ("normal")
    std::vector<int> channels;  // indices into the file's channels (r = 0 ... a = 3)
    std::optional<RawFormat> raw;
};

struct PositionSpec {
    ImageRef image;
    Space space = Space::World;
    // A channel that is 0 where nothing was drawn (gbuffer-lab's position.exr has w = 1 where drawn).
    std::optional<int> coverageChannel;
};

struct NormalSpec {
    ImageRef image;
    NormalEncoding encoding = NormalEncoding::Float;
    Space space = Space::World;
};

struct AlbedoSpec {
    ImageRef image;
    ColorEncoding encoding = ColorEncoding::Linear;
};

// Emitted radiance (docs/lighting.md: added once, after the lights), stored linear or sRGB and
// multiplied by `scale` after decoding (a program that stores emission / k in an 8-bit target gives k).
struct EmissiveSpec {
    ImageRef image;  // three channels
    ColorEncoding encoding = ColorEncoding::Linear;
    float scale = 1.0f;
};

struct DepthSpec {
    ImageRef image;  // one channel
    DepthConvention convention = DepthConvention::Window;
    float nearPlane = 0.0f;  // given, or the camera's
    float farPlane = 0.0f;
};

// The camera as matrices (OpenGL conventions: view space looks down -z, clip z in [-w, w]).
struct CameraMatrices {
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    glm::vec3 position{0.0f};        // the eye, from the inverse view matrix
    std::optional<float> nearPlane;  // given in the manifest or read from a perspective projection
    std::optional<float> farPlane;
    // > 0: the camera was given as position/target/fov and `projection` is built on load, when the
    // images' aspect ratio is known (cameraForSize); 0: the projection was given.
    float fovYDegrees = 0.0f;
};

// The camera for a frame of width x height: builds the projection of a fov-given camera.
CameraMatrices cameraForSize(CameraMatrices camera, int width, int height);

struct GBufferManifest {
    std::string label;                     // the manifest's file name: the start of every message
    std::string preset;                    // "" or a name of kManifestPresetNames
    std::optional<PositionSpec> position;  // nullopt with positionFromDepth: rebuilt from depth
    bool positionFromDepth = false;
    NormalSpec normal;
    std::optional<AlbedoSpec> albedo;
    std::optional<ImageRef> specular;      // one channel
    std::optional<EmissiveSpec> emissive;  // absent: emission 0
    std::optional<ImageRef> occlusion;     // one channel, ambient occlusion in [0, 1]; absent: 1
    std::optional<DepthSpec> depth;
    std::optional<ImageRef> lit;  // the program's own lit output, rgb
    std::optional<CameraMatrices> camera;
    std::vector<PointLight> lights;
    bool flipY = false;  // rows are bottom-up in the files (glReadPixels) and are turned over on load
    float shininess = 32.0f;
    ShadingModel shading = ShadingModel::GbufferLab;  // the re-light's equation ("shading")
};

// The re-light's settings a manifest gives: its shininess and shading model, and with the
// learnopengl model the ambient light that text's lighting shader hard-codes.
void applyManifestShading(float shininess, ShadingModel shading, PipelineSettings& settings);

struct ManifestLoad {
    std::optional<GBufferManifest> manifest;  // whole, or nothing
    std::string error;                        // "<file>: <field> <what is wrong>" when manifest is empty
};

// Parses and validates a manifest. `label` starts every message; relative file names resolve
// against `dir`. Reads no file: a missing image is found by loadGBuffer.
ManifestLoad parseManifest(std::string_view text, std::string const& label, std::string const& dir);
// Reads a manifest file, or a folder: its manifest.json when it has one, else a `render --out`
// folder of gbuffer-lab's own (camera.json, lights.json, position.exr ...) as the gbuffer-lab preset.
ManifestLoad loadManifest(std::string const& path);

}  // namespace gbl
