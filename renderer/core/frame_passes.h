// The frame as data: each pass's name, what it samples, what it renders into, what it clears and
// its fixed-function state, and the ordered passes a frame runs for its settings. Plain values, no
// GL: the renderer's executor runs exactly these (renderer_passes.cpp), the pass timer takes its
// names from them, and a CPU test checks every combination of settings for feedback loops.
#pragma once

#include "core/pipeline_settings.h"

#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace gbl {

// Every pass a frame can run. kPassNames holds the one name of each, used by the pass timer,
// FrameStats::passes, stats.json and bench.
enum class PassId {
    ForwardShading,  // forward mode: every opaque surface lit by every light
    Geometry,        // the G-buffer
    LightLists,      // tiled and clustered: each tile's or cluster's candidate lights
    VolumeDepth,     // the G-buffer's depth-stencil copied for the volume passes
    Lighting,        // the lighting mode's pass
    LightCombine,    // accumulation split: the two light targets into the lit image
    DepthCopy,       // the blit step: the G-buffer depth into the lit target
    Forward,         // blended surfaces, forward-lit over the lit image
    LightCubes,      // overlay: a small unlit cube at each light, on the display image
    Wireframes,      // overlay: light-volume outlines, on the display image
    Coverage,        // the counts behind the heat map and lights-per-tile views
    Display,         // tonemap or debug view into the display image (the overlays follow it)
    Import,          // re-lighting: an imported G-buffer written into the layout's targets, instead of geometry
    GlassOutline,    // overlay: hatches where blended surfaces are, on the display or a view (any view)
    DepthPrepass,    // forward+: the opaque surfaces' depth alone, before the light lists and the shading
    MsaaEdges,       // msaa: complex pixels (samples that differ) marked in the stencil and the complex mask
    MsaaComplex,     // msaa edges: the complex pixels lit per sample (the lighting pass lit the others once)
    MsaaResolve,     // msaa: the multisampled G-buffer resolved into the layout's targets, for what follows
    ThinGBuffer,     // prepass: the thin G-buffer (normal and specular exponent, depth), "prepass_geometry"
    PrepassShading,  // prepass: the scene drawn again, its materials applied to the summed light
};
inline constexpr std::array<std::string_view, 20> kPassNames{
    "forward_shading", "geometry", "light_lists", "volume_depth", "lighting", "light_combine", "depth_copy", "forward",
    "light_cubes", "wireframes", "coverage", "display", "import", "glass_outline", "depth_prepass",
    // msaa (docs/msaa.md)
    "msaa_edges", "lighting_complex", "msaa_resolve",
    // prepass (docs/deferred_lighting.md)
    "prepass_geometry", "prepass_shading"};

inline std::string_view passName(PassId id) {
    return enumName(kPassNames, id);
}
inline std::optional<PassId> passFromName(std::string_view name) {
    return enumFromName<PassId>(kPassNames, name);
}

// The lighting work of a frame (bench's lighting figure): shading the lights, and the passes that
// exist only to shade them (light lists, the volumes' depth copy, the split combine, forward+'s
// depth pre-pass: forward's figure includes its rasterising too; prepass's second geometry pass,
// which finishes the shading as the split combine does).
constexpr bool countsAsLighting(PassId id) {
    return id == PassId::ForwardShading || id == PassId::LightLists || id == PassId::VolumeDepth ||
           id == PassId::Lighting || id == PassId::LightCombine || id == PassId::DepthPrepass ||
           id == PassId::MsaaEdges || id == PassId::MsaaComplex || id == PassId::PrepassShading;
}

// The passes whose fragments FrameStats::fragmentInvocations counts: the shading of the lights.
constexpr bool countsFragments(PassId id) {
    return id == PassId::ForwardShading || id == PassId::Lighting;
}

// Everything a pass reads or writes (gpu/render_targets.h, gpu/light_buffer.h, ...).
enum class Resource {
    GBufferPosition,
    GBufferNormal,
    GBufferAlbedoSpec,
    GBufferEmissive,
    GBufferDepth,  // the G-buffer's depth-stencil texture
    VolumeDepth,   // its copy for the volume passes (RenderTargets::volumeDepth)
    Lighting,      // the HDR lit image
    LitDepth,      // the lit target's own depth-stencil
    DiffuseLight,
    SpecularLight,
    Coverage,
    Display,
    Lights,           // the light buffer texture
    VolumeInstances,  // the light-volume instance list
    Materials,        // the scene's material textures
    TileBins,         // storage buffers: tile depth bounds and candidate lists
    ClusterLists,     // storage buffers and list texture of the clustered mode
    Imported,         // the textures of an imported G-buffer (Renderer::setImportedGBuffer)
    View,             // a view's own image (Renderer::drawView's ViewTarget), in place of the display
    Readback,         // the browser's read-back target: depth or stencil as colour (renderer_readback.cpp)
    // msaa (RenderTargets::msaa): the multisampled G-buffer, and the complex pixels' mask.
    MsaaPosition,
    MsaaNormal,
    MsaaAlbedoSpec,
    MsaaEmissive,
    MsaaDepth,
    ComplexMask,
    PrepassNormal,  // prepass's thin G-buffer: world normal xyz, specular exponent w (RGBA16F)
};
inline constexpr std::array<std::string_view, 27> kResourceNames{"gbuffer.position",
                                                                 "gbuffer.normal",
                                                                 "gbuffer.albedo_spec",
                                                                 "gbuffer.emissive",
                                                                 "gbuffer.depth",
                                                                 "volumes.depth",
                                                                 "lighting",
                                                                 "lighting.depth",
                                                                 "diffuse_light",
                                                                 "specular_light",
                                                                 "coverage",
                                                                 "display",
                                                                 "lights",
                                                                 "volume_instances",
                                                                 "materials",
                                                                 "tile_bins",
                                                                 "cluster_lists",
                                                                 "imported",
                                                                 "view",
                                                                 "readback",
                                                                 "msaa.position",
                                                                 "msaa.normal",
                                                                 "msaa.albedo_spec",
                                                                 "msaa.emissive",
                                                                 "msaa.depth",
                                                                 "complex_mask",
                                                                 "prepass.normal_exp"};

inline std::string_view resourceName(Resource r) {
    return enumName(kResourceNames, r);
}

enum class PassKind {
    Raster,   // draws into a framebuffer
    Compute,  // dispatches; writes images and buffers, no framebuffer involved
    Blit,     // glBlitFramebuffer from `samples` into the attachments
};
enum class DepthTest { Off, Less, LessEqual, GreaterEqual, Always };
enum class Blend {
    Off,
    Add,    // ONE, ONE: lights summed
    Alpha,  // SRC_ALPHA, ONE_MINUS_SRC_ALPHA
};
enum class FaceCull {
    Off,
    Back,
    Front,
};
enum class StencilUse {
    Off,
    Mark,         // both faces, depth failures: back +1, front -1
    ShadeMarked,  // passes where the mark is 1, and zeroes every mark it visits
    EqualBits,    // passes where the bits of DrawState::stencilRef are set (ref and mask), writes none
    MarkComplex,  // msaa edges: every drawn fragment sets the complex bit (simple pixels discard)
    MarkCovered,  // light cubes: every drawn fragment sets the mark to 1 (the lit depth's stencil, cleared)
    Covered,      // the blended surfaces over the cubes: passes where the mark is 1, keeps it
};

// msaa edges (docs/msaa.md): which pixels a draw group keeps to, by the stencil's complex bit, on top
// of its own stencil use. The complex bit is the stencil's top bit; the volumes' stencil marks (Mark,
// ShadeMarked) count in the seven bits below it, so the two share one stencil.
enum class MsaaPixels {
    All,      // the complex bit is neither tested nor kept apart
    Simple,   // passes where the complex bit is 0
    Complex,  // passes where the complex bit is 1
};
inline constexpr int kComplexStencilBit = 0x80;

// The fixed-function state of one group of draws of a pass (most passes have one).
struct DrawState {
    std::string_view what;  // which draws, e.g. "ambient" or "stencil mark"
    DepthTest depthTest = DepthTest::Off;
    bool depthWrite = false;
    Blend blend = Blend::Off;
    FaceCull cull = FaceCull::Off;
    StencilUse stencil = StencilUse::Off;
    bool colorWrite = true;
    int stencilRef = 0;  // StencilUse::EqualBits: the bits tested
    MsaaPixels pixels = MsaaPixels::All;

    bool operator==(DrawState const&) const = default;
};

// One pass: what it reads, where it draws, and how.
struct PassDecl {
    PassId id = PassId::Display;
    PassKind kind = PassKind::Raster;
    std::vector<Resource> samples;  // read by its shaders, or the source of its blit
    // The framebuffer it draws into (raster and blit): colour attachments, then the depth-stencil.
    std::vector<Resource> color;
    std::optional<Resource> depthStencil;
    bool depthRead = false;  // depth-tested against
    bool depthWrite = false;
    bool stencilRead = false;
    bool stencilWrite = false;
    std::vector<Resource> writes;   // images and buffers a compute pass writes
    std::vector<DrawState> states;  // applied (gpu/draw_state_gl.h) before each group of draws, in order
    // Cleared by the executor before the pass runs: colour to zero, depth to 1, stencil to 0.
    std::vector<Resource> clears;
    // A pass that is not one of PassId's (a test's own, a read-back): its name in place of passName(id).
    std::string_view customName;

    std::string_view name() const { return customName.empty() ? passName(id) : customName; }
    bool operator==(PassDecl const&) const = default;
};

// The read-backs' draws, which are no pass of a frame (renderer_readback.cpp): the G-buffer decoded
// into positions and normals, full screen.
inline constexpr DrawState kDecodeState{"decode", DepthTest::Off, false, Blend::Off, FaceCull::Off};

// The browser's read-backs of the G-buffer's depth and stencil (renderer_readback.cpp; WebGL2 reads
// neither), which are no passes of a frame: "readback_depth" copies the depth texture's texels into
// the read-back target; "readback_stencil" tests the G-buffer's stencil and adds one constant per bit
// plane, one draw group per bit (group b passes where bit b is set: EqualBits with ref 1 << b).
PassDecl readbackPass(bool stencil);

// Whether the heat map or lights-per-tile view is shown: only then the frame runs the coverage pass.
constexpr bool viewNeedsCoverage(DebugView v) {
    return v == DebugView::Heatmap || v == DebugView::TileLights;
}

// Whether the display shows the overlays (light cubes, volume wireframes): only on the views of the
// lit image, the final picture and the HDR lighting view, where they appeared when they were drawn
// into the lit image. The G-buffer and count views show data the overlays would hide, so they get
// none; the lit image itself never holds them (it is the light sum, what lighting.exr exports).
constexpr bool viewShowsOverlays(DebugView v) {
    return v == DebugView::Final || v == DebugView::Lighting;
}

// The passes RendererImpl::render runs (it runs this list), in order, for a frame with `settings` as it ran (the mode
// after any fallback; split accumulation is ignored in forward mode, as the renderer does).
// `wireframes`: whether the volume outlines are asked for (the setting, or an accumulation outline);
// they, and the light cubes, run after the display pass, and only when viewShowsOverlays(view).
// `imported`: the frame re-lights an imported G-buffer (importedSettings applied): the import pass
// takes the geometry pass's place, and no scene is drawn (no blended surfaces).
std::vector<PassDecl> framePasses(PipelineSettings const& settings, bool wireframes, bool imported = false);
inline std::vector<PassDecl> framePasses(PipelineSettings const& settings) {
    return framePasses(settings, settings.volumeWireframes);
}

// Deferred lighting (prepass mode, docs/deferred_lighting.md), the passes framePasses puts first: the
// thin G-buffer (normal and specular exponent, the lit target's depth), every light summed into the
// diffuse and specular light targets, then the scene drawn again where it equals that depth, its
// materials applied to the light at its pixel (core/frame_passes_prepass.cpp). With `prepass_lights:
// volumes` the light pass draws the light volumes with `cull`, after a copy of the thin depth-stencil
// for them to test against (the volume_depth pass).
std::vector<PassDecl> prepassPasses(PipelineSettings const& s);

// What Renderer::drawView runs for a view of the frame `settings` ran (settings.view the view shown):
// the coverage counts again for a count view (after the volumes' depth copy, which only a volumes
// frame refreshed), then the view pass into the view's own image.
std::vector<PassDecl> viewPasses(PipelineSettings const& settings);

// What a frame that re-lights an imported G-buffer runs with: what needs the scene's meshes
// (forward shading) becomes the quad pass, and the light cubes, sized to a scene, are off. `why`
// gets one sentence per change.
PipelineSettings importedSettings(PipelineSettings settings, std::string* why = nullptr);

// Stopping after a pass (FrameInput::stopAfter): the passes up to and including `stop`, then the
// display pass if `stop` came before it, which shows the frame as it stands (an overlay after it
// keeps the display and the overlays before it). `passes` unchanged when `stop` is not among them.
// When passes are skipped, the first pass also clears what they would have overwritten (the lit
// image, the light targets, the counts), so the viewers show what this frame drew so far.
std::vector<PassDecl> passesUntil(std::vector<PassDecl> passes, PassId stop);
// Why the frame of `passes` cannot stop after the pass called `name` (no pass has that name, or this
// frame does not run it), in one sentence naming the passes it runs; nullopt when it can.
std::optional<std::string> stopAfterError(std::string_view name, std::span<PassDecl const> passes);

// A pass that samples a resource attached to the framebuffer it draws into: a feedback loop,
// undefined in GL.
struct FeedbackLoop {
    PassId pass = PassId::Display;
    Resource resource = Resource::GBufferDepth;
    bool operator==(FeedbackLoop const&) const = default;
};
std::vector<FeedbackLoop> feedbackLoops(std::span<PassDecl const> passes);

}  // namespace gbl
