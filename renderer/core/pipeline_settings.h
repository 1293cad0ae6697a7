// Every switch of the deferred pipeline the user can flip, as plain values.
#pragma once

#include <glm/glm.hpp>

#include <array>
#include <optional>
#include <string_view>

namespace gbl {

// ForwardPlus: a depth pre-pass, tiled's light lists, then forward shading reading its tile's list.
// Prepass (deferred lighting, docs/deferred_lighting.md): a thin G-buffer (normal and specular
// exponent, depth), the lights summed into diffuse and specular light, then the scene drawn again
// applying its materials to them.
enum class LightingMode { Quad, Volumes, Tiled, Forward, Clustered, ForwardPlus, Prepass };
enum class CullMode { Back, Front, None, Flip, Stencil };
// How the G-buffer depth reaches the lit target before the forward pass: the depth copy
// (setting `depth_copy`, pass `depth_copy`, option --depth-copy).
enum class DepthCopy { Blit, Shader, Off };
// Values match TONEMAP_* in shaders/view_constants.glsl.
enum class Tonemap { Exposure, Reinhard, Clamp };
// How the G-buffer stores a surface; each value has one description in core/gbuffer_layout.h.
enum class GBufferLayout { Classic, Packed, Naive8, Rgb10a2 };
// The lighting equation (docs/lighting.md): gbuffer-lab's own, or the one LearnOpenGL's deferred
// shading chapter writes (its 8.1 lighting shader: attenuation 1/(Kc + Kl d + Kq d^2) with no
// window, specular not gated by N.L), so a G-buffer of a program of that text re-lights as that
// program lit it. Values match SHADING_* in shaders/lighting.glsl.
enum class ShadingModel { GbufferLab, LearnOpenGl };
// The ambient light LearnOpenGL's deferred lighting shader hard-codes (0.1 * albedo); opening a
// G-buffer whose manifest asks for the learnopengl shading sets it.
inline constexpr float kLearnOpenGlAmbient = 0.1f;
// The specular exponent that shader hard-codes: a manifest with that shading and no "shininess".
inline constexpr float kLearnOpenGlShininess = 16.0f;
// Where the lighting modes add their lights (docs/lighting.md, "Accumulation targets"): one lit
// target, or diffuse and specular light in two targets that a combine pass finishes.
enum class LightAccumulation { Single, Split };
// Multisampling of the G-buffer (docs/msaa.md): off, or 2, 4 or 8 samples per pixel.
enum class Msaa { Off, X2, X4, X8 };
// How a multisampled G-buffer is lit (docs/msaa.md): its attributes resolved (averaged) first, which
// is wrong on purpose (silhouettes halo); every sample lit and the results averaged; or the complex
// pixels (samples that differ) found in a pass of their own and lit per sample, the others once.
enum class MsaaLighting { ResolveFirst, PerSample, Edges };
// How prepass's light pass reaches the pixels (docs/deferred_lighting.md): one full-screen draw that
// sums every light at every pixel, or the light volumes with the cull mode (`cull`), each added.
enum class PrepassLights { Quad, Volumes };

// What the final image shows. Values match the VIEW_* constants in shaders/view_constants.glsl
// (shader_constants_test checks them).
enum class DebugView {
    Final = 0,
    Lighting = 1,
    Position = 2,
    Normal = 3,
    Albedo = 4,
    Specular = 5,
    Depth = 6,
    DepthLinear = 7,
    Heatmap = 8,
    TileLights = 9,
    // The current layout's colour attachments 0, 1, 2 exactly as stored (core/gbuffer_layout.h
    // lists them); Position and Normal above show the decoded values for every layout.
    Raw0 = 10,
    Raw1 = 11,
    Raw2 = 12,
    Raw3 = 13,  // classic's fourth colour attachment (emissive_ao); zero in the others (and raw2 in packed)
    // The emissive attachment decoded: emitted radiance (rgb), and ambient occlusion as grey.
    Emissive = 14,
    Occlusion = 15,
    // The accumulation targets of `accumulation: split` (zero in single frames): sum of
    // N.L * attenuation * colour, and of specular * (N.H)^shininess * attenuation * colour.
    DiffuseLight = 16,
    SpecularLight = 17,
    // Each pixel's exponential depth slice of the clustered grid (core/cluster_math.h), one
    // colour per slice (clusterSliceColor) with a swatch legend along the bottom.
    ClusterSlices = 18,
};

struct PipelineSettings {
    LightingMode mode = LightingMode::Quad;
    CullMode cull = CullMode::Front;
    DepthCopy depthCopy = DepthCopy::Blit;
    Tonemap tonemap = Tonemap::Exposure;
    DebugView view = DebugView::Final;
    GBufferLayout layout = GBufferLayout::Classic;
    LightAccumulation accumulation = LightAccumulation::Single;
    ShadingModel shading = ShadingModel::GbufferLab;
    bool lightCubes = true;
    bool volumeWireframes = false;
    bool glassOutline = false;  // hatch where the blended (forward-drawn) surfaces are, on every view
    // The wireframes outline the selected light's volume only: 32 outlines at once bury the frame.
    bool wireframesSelectedOnly = true;
    bool normalMaps = true;
    glm::vec3 ambient{0.03f};
    float exposure = 1.0f;
    float shininess = 32.0f;
    // Multiplies the scale that makes a light volume enclose its radius (1 = just enclosing).
    // Below 1 the sphere's faces cut the light off: the volumes lesson shows it.
    float volumeScale = 1.0f;
    Msaa msaa = Msaa::Off;
    MsaaLighting msaaLighting = MsaaLighting::Edges;
    PrepassLights prepassLights = PrepassLights::Quad;

    // Every member, floats compared with ==: what undo's change detection wants.
    bool operator==(PipelineSettings const&) const = default;
};

// Names used on the command line and in session files, in enum order.
inline constexpr std::array<std::string_view, 7> kLightingModeNames{"quad",      "volumes",  "tiled",  "forward",
                                                                    "clustered", "forward+", "prepass"};
inline constexpr std::array<std::string_view, 5> kCullModeNames{"back", "front", "none", "flip", "stencil"};
inline constexpr std::array<std::string_view, 3> kDepthCopyNames{"blit", "shader", "off"};
inline constexpr std::array<std::string_view, 3> kTonemapNames{"exposure", "reinhard", "clamp"};
inline constexpr std::array<std::string_view, 4> kGBufferLayoutNames{"classic", "packed", "naive8", "rgb10a2"};
inline constexpr std::array<std::string_view, 2> kLightAccumulationNames{"single", "split"};
inline constexpr std::array<std::string_view, 4> kMsaaNames{"off", "2", "4", "8"};
inline constexpr std::array<std::string_view, 3> kMsaaLightingNames{"resolve-first", "per-sample", "edges"};
inline constexpr std::array<std::string_view, 2> kPrepassLightsNames{"quad", "volumes"};
inline constexpr std::array<std::string_view, 2> kShadingModelNames{"gbuffer-lab", "learnopengl"};
inline constexpr std::array<std::string_view, 19> kDebugViewNames{
    "final",        "lighting",  "position",      "normal",         "albedo",        "specular", "depth",
    "depth_linear", "heatmap",   "tile_lights",   "raw0",           "raw1",          "raw2",     "raw3",
    "emissive",     "occlusion", "diffuse_light", "specular_light", "cluster_slices"};

// Samples per pixel of a setting (1 for off).
constexpr int msaaSamples(Msaa m) {
    return m == Msaa::Off ? 1 : 1 << int(m);
}

// Whether a mode lights a pixel only inside the light's radius whatever the equation (its volume,
// tile or cluster lists are sized to it): there the learnopengl shading is cut at the radius too,
// as LearnOpenGL's own light-volume version is; quad and forward shade every light everywhere.
constexpr bool cutsAtRadius(LightingMode m) {
    return m == LightingMode::Volumes || m == LightingMode::Tiled || m == LightingMode::Clustered ||
           m == LightingMode::ForwardPlus;
}

// Whether the frame's lights are drawn as light volumes with the cull mode: volumes mode, and prepass
// with `prepass_lights: volumes` (its light pass then adds each volume into the light targets).
constexpr bool drawsLightVolumes(PipelineSettings const& s) {
    return s.mode == LightingMode::Volumes ||
           (s.mode == LightingMode::Prepass && s.prepassLights == PrepassLights::Volumes);
}

// Whether the frame of `s` cuts the learnopengl shading at each light's radius: its mode does, or it
// draws light volumes (prepass with volumes), which end there.
constexpr bool cutsAtRadius(PipelineSettings const& s) {
    return cutsAtRadius(s.mode) || drawsLightVolumes(s);
}

// Whether a mode shades while drawing the meshes, keeping no G-buffer (forward and forward+).
constexpr bool shadesForward(LightingMode m) {
    return m == LightingMode::Forward || m == LightingMode::ForwardPlus;
}

// Whether a mode's lighting draws the scene's meshes, which an imported G-buffer lacks (the forward
// modes, and prepass's second geometry pass).
constexpr bool lightsByDrawingMeshes(LightingMode m) {
    return shadesForward(m) || m == LightingMode::Prepass;
}

// The G-buffer views that prepass's thin G-buffer (normal and exponent, depth) has nothing for: it
// stores no albedo, emission or occlusion (shaders/view.frag, thinView, shows them as zero).
constexpr bool thinGBufferLacks(DebugView v) {
    return v == DebugView::Albedo || v == DebugView::Emissive || v == DebugView::Occlusion;
}

template <class Enum, std::size_t N>
std::optional<Enum> enumFromName(std::array<std::string_view, N> const& names, std::string_view name) {
    for (std::size_t i = 0; i < N; ++i)
        if (names[i] == name) return static_cast<Enum>(i);
    return std::nullopt;
}

template <class Enum, std::size_t N>
std::string_view enumName(std::array<std::string_view, N> const& names, Enum value) {
    auto const i = static_cast<std::size_t>(value);
    return i < N ? names[i] : std::string_view("?");
}

}  // namespace gbl
