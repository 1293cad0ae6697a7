// The PipelineSettings field table.
#include "core/pipeline_fields.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <type_traits>

namespace gbl {

namespace {

// A field's get and set for its kind; the columns that only describe it come from `f`.
template <auto Member, std::size_t N>
constexpr PipelineField choice(std::array<std::string_view, N> const& names, PipelineField f) {
    f.kind = SettingKind::Choice;
    f.choices = std::span<std::string_view const>(names.data(), names.size());
    f.min = 0.0f;
    f.max = float(N - 1);
    f.get = [](PipelineSettings const& s) { return double(int(s.*Member)); };
    f.set = [](PipelineSettings& s, double v) {
        using Enum = std::remove_reference_t<decltype(s.*Member)>;
        s.*Member = Enum(int(v));
    };
    return f;
}

template <auto Member>
constexpr PipelineField toggle(PipelineField f) {
    f.kind = SettingKind::Toggle;
    f.min = 0.0f;
    f.max = 1.0f;
    f.widget = PipelineWidget::Checkbox;
    f.get = [](PipelineSettings const& s) { return (s.*Member) ? 1.0 : 0.0; };
    f.set = [](PipelineSettings& s, double v) { s.*Member = v != 0.0; };
    return f;
}

template <auto Member>
constexpr PipelineField number(PipelineField f) {
    f.kind = SettingKind::Number;
    f.get = [](PipelineSettings const& s) { return double(s.*Member); };
    f.set = [](PipelineSettings& s, double v) { s.*Member = float(v); };
    return f;
}

bool volumesOnly(PipelineSettings const& s) {
    return drawsLightVolumes(s);
}
bool prepassOnly(PipelineSettings const& s) {
    return s.mode == LightingMode::Prepass;
}
bool withWireframes(PipelineSettings const& s) {
    return s.volumeWireframes;
}
bool withMsaa(PipelineSettings const& s) {
    return s.msaa != Msaa::Off;
}

// One line per choice, shown on hover over its radio button: the editor is a teaching tool.
constexpr std::array<std::string_view, 7> kModeHelp{
    "quad: one full-screen pass evaluates every light at every pixel (cost = pixels x lights)",
    "volumes: one sphere per light, scaled to its radius; only covered pixels are shaded",
    "tiled: a compute pass builds a light list per 16x16 tile, then shades each pixel with its tile's lights",
    "forward: no G-buffer; every object is shaded with every light while it is drawn",
    "clustered: the GPU lists the lights of each 16x16 tile's exponential depth slices; each pixel shades with its "
    "slice's list",
    "forward+: a depth pre-pass, tiled's light list per 16x16 tile, then a forward pass whose fragments shade with "
    "their tile's lights only (no G-buffer)",
    "prepass: deferred lighting; a thin G-buffer (normal, exponent, depth), every light summed into diffuse and "
    "specular light, then the scene drawn again applying its materials",
};
constexpr std::array<std::string_view, 5> kCullHelp{
    "back: cull back faces; the volume vanishes when the camera is inside it",
    "front: cull front faces and draw the far side; works with the camera inside",
    "none: draw both sides, so each light is applied twice (the classic bug)",
    "flip: back faces normally, front faces for lights whose volume holds the camera",
    "stencil: two passes, mark then shade, so each pixel is shaded once and only if inside",
};
constexpr std::array<std::string_view, 3> kDepthCopyHelp{
    "blit: glBlitFramebuffer copies the G-buffer depth so light cubes are hidden by walls",
    "shader: a full-screen pass writes gl_FragDepth from the depth texture (works where blits between formats fail)",
    "off: no depth before the forward pass; light cubes show through walls",
};
static_assert(kModeHelp.size() == kLightingModeNames.size() && kCullHelp.size() == kCullModeNames.size() &&
              kDepthCopyHelp.size() == kDepthCopyNames.size());

constexpr bool kOptional = true;

using S = PipelineSettings;
using W = PipelineWidget;
using P = PipelineSection;

// The A/B table shows the sideB rows in this order; its first row is the mode (startAb ticks it).
// The Pipeline panel draws each section's fields in this order too.
std::array<PipelineField, 20> const kFields{
    choice<&S::mode>(kLightingModeNames, {.name = "mode",
                                          .help = "How the lights are added: the lighting mode",
                                          .sideB = true,
                                          .label = "Lighting mode",
                                          .section = P::LightingMode,
                                          .widget = W::Radio,
                                          .choiceHelp = kModeHelp,
                                          .option = "--mode"}),
    choice<&S::cull>(kCullModeNames, {.name = "cull",
                                      .help = "Which faces of a light volume are drawn (volumes mode, and prepass "
                                              "with --prepass-lights volumes)",
                                      .sideB = true,
                                      .label = "Volume cull mode",
                                      .section = P::VolumeCull,
                                      .widget = W::Radio,
                                      .choiceHelp = kCullHelp,
                                      .applies = volumesOnly,
                                      .option = "--cull"}),
    choice<&S::depthCopy>(kDepthCopyNames,
                          {.name = "depth_copy",
                           .help = "How the G-buffer depth reaches the lit target before the forward pass",
                           .sideB = true,
                           .label = "Depth copy",
                           .section = P::DepthCopy,
                           .widget = W::Radio,
                           .choiceHelp = kDepthCopyHelp,
                           .option = "--depth-copy",
                           .oldName = "blit",
                           .oldOption = "--blit"}),
    choice<&S::tonemap>(kTonemapNames, {.name = "tonemap",
                                        .help = "HDR to display: exposure, Reinhard or clamp",
                                        .sideB = true,
                                        .label = "Tonemap",
                                        .option = "--tonemap"}),
    choice<&S::layout>(kGBufferLayoutNames,
                       {.name = "layout",
                        .help = "What the G-buffer stores, and how",
                        .optionalInFiles = kOptional,
                        .sideB = true,
                        .label = "G-buffer",
                        .tooltip = "how the G-buffer stores its quantities; the Pipeline's A/B compare can set side B "
                                   "to classic",
                        .option = "--layout"}),
    toggle<&S::normalMaps>({.name = "normal_maps",
                            .help = "Use the materials' normal maps",
                            .sideB = true,
                            .label = "Normal maps",
                            .section = P::Overlays,
                            .option = "--normal-maps"}),
    toggle<&S::lightCubes>({.name = "light_cubes",
                            .help = "A small unlit cube at each light, after the depth copy",
                            .sideB = true,
                            .label = "Light cubes",
                            .section = P::Overlays,
                            .option = "--light-cubes"}),
    toggle<&S::volumeWireframes>({.name = "volume_wireframes",
                                  .help = "Outline each light's volume",
                                  .sideB = true,
                                  .label = "Volume wireframes",
                                  .section = P::Overlays,
                                  .option = "--volume-wireframes"}),
    toggle<&S::glassOutline>({.name = "glass_outline",
                              .help = "Hatch where the blended surfaces (glass) are, over every view",
                              .optionalInFiles = kOptional,
                              .label = "Glass outline",
                              .section = P::Overlays,
                              .tooltip = "blended surfaces are drawn forward after lighting, so the G-buffer views "
                                         "cannot show them: the hatching marks where they are",
                              .option = "--glass-outline"}),
    number<&S::shininess>({.name = "shininess",
                           .min = 1.0f,
                           .max = 512.0f,
                           .help = "Blinn-Phong specular exponent",
                           .sideB = true,
                           .label = "Shininess",
                           .widget = W::Drag,
                           .format = "%.1f",
                           .option = "--shininess"}),
    number<&S::exposure>({.name = "exposure",
                          .min = 0.05f,
                          .max = 16.0f,
                          .help = "Multiplies the HDR frame before tonemapping",
                          .sideB = true,
                          .label = "Exposure",
                          .widget = W::LogSlider,
                          .option = "--exposure"}),
    PipelineField{.name = "ambient",
                  .kind = SettingKind::Number,
                  .min = 0.0f,
                  .max = 1.0f,
                  .help = "Ambient light: albedo times this colour (a grey on the command line and in the A/B table)",
                  .sideB = true,
                  .get = [](S const& s) { return double(s.ambient.x); },
                  .set = [](S& s, double v) { s.ambient = glm::vec3(float(v)); },
                  .rgb = &S::ambient,
                  .label = "Ambient",
                  .widget = W::Colour,
                  .option = "--ambient"},
    // render's --view writes extra views beside the final image: no option sets this one.
    choice<&S::view>(kDebugViewNames,
                     {.name = "view",
                      .help = "What the viewport shows",
                      .label = "Coverage heatmap",
                      .section = P::Overlays,
                      .widget = W::ChoiceCheckbox,
                      .tooltip = "per pixel: how many lights the mode evaluated (volumes, tile or cluster list) and "
                                 "how many\nlit it; colours in bins 0, 1, 2, 4, 8, 16, 32, 64+, dim where the lights "
                                 "evaluated did not light it",
                      .checkedChoice = int(DebugView::Heatmap)}),
    choice<&S::accumulation>(kLightAccumulationNames,
                             {.name = "accumulation",
                              .help = "Lights into one lit target (single) or diffuse and specular targets plus a "
                                      "combine pass (split)",
                              .optionalInFiles = kOptional,
                              .sideB = true,
                              .label = "Targets",
                              .tooltip = "single: one lit target\nsplit: diffuse and specular light targets, then a "
                                         "combine pass (forward mode keeps one target)",
                              .option = "--accumulation"}),
    choice<&S::shading>(
        kShadingModelNames,
        {.name = "shading",
         .help = "The lighting equation: gbuffer-lab (docs/lighting.md) or learnopengl (LearnOpenGL's deferred "
                 "shader: no attenuation window; with --gbuffer it overrides the manifest's)",
         .optionalInFiles = kOptional,
         .sideB = true,
         .label = "Equation",
         .tooltip = "gbuffer-lab: windowed attenuation, zero from each light's radius on (docs/lighting.md)\n"
                    "learnopengl: LearnOpenGL's deferred lighting shader: 1/(Kc + Kl d + Kq d^2) with no window,\n"
                    "specular not gated by N.L; quad and forward light every pixel with every light, volumes,\n"
                    "tiled and clustered stop at the radius. A manifest with \"shading\": \"learnopengl\" also\n"
                    "sets ambient 0.1 and shininess 16, as that shader does.",
         .option = "--shading"}),
    toggle<&S::wireframesSelectedOnly>(
        {.name = "wireframes_selected_only",
         .help = "The wireframes outline the selected light's volume only",
         .optionalInFiles = kOptional,
         .label = "Selected light's volume only",
         .section = P::Overlays,
         .tooltip = "32 volumes at once are a tangle: outline only the light selected in the Lights window",
         .applies = withWireframes,
         .option = "--wireframes-selected-only"}),
    number<&S::volumeScale>(
        {.name = "volume_scale",
         .min = 0.1f,
         .max = 4.0f,
         .help = "Scales every light volume (1 just encloses the light's radius)",
         .optionalInFiles = kOptional,
         .sideB = true,
         .label = "Volume scale",
         .section = P::VolumeCull,
         .widget = W::Slider,
         .tooltip = "1: each volume just encloses its light's radius; below 1 its faces cut the light off (dark "
                    "rims), above 1 it shades pixels the light cannot reach",
         .applies = volumesOnly,
         .option = "--volume-scale"}),
    choice<&S::msaa>(kMsaaNames,
                     {.name = "msaa",
                      .help = "Samples per pixel of the G-buffer: off, 2, 4 or 8 (quad and volumes modes, every "
                              "layout; docs/msaa.md)",
                      .optionalInFiles = kOptional,
                      .sideB = true,
                      .label = "MSAA",
                      .tooltip = "a multisampled G-buffer: the geometry pass stores 2, 4 or 8 samples per pixel;\n"
                                 "counts the driver refuses are greyed out; the modes that cannot light it (tiled,\n"
                                 "clustered, forward, forward+) and a G-buffer too large for the memory fall back\n"
                                 "to off with the reason (docs/msaa.md)",
                      .option = "--msaa"}),
    choice<&S::msaaLighting>(kMsaaLightingNames,
                             {.name = "msaa_lighting",
                              .help = "How a multisampled G-buffer is lit: resolve-first (wrong on purpose), "
                                      "per-sample or edges",
                              .optionalInFiles = kOptional,
                              .sideB = true,
                              .label = "MSAA lighting",
                              .tooltip = "resolve-first: attributes averaged before lighting, so silhouettes halo\n"
                                         "per-sample: every sample lit, the results averaged (correct, costly)\n"
                                         "edges: complex pixels found and marked in stencil, lit per sample; the "
                                         "others once",
                              .applies = withMsaa,
                              .option = "--msaa-lighting"}),
    choice<&S::prepassLights>(kPrepassLightsNames,
                              {.name = "prepass_lights",
                               .help = "prepass's light pass: one full-screen draw (quad) or the light volumes with "
                                       "the cull mode (volumes)",
                               .optionalInFiles = kOptional,
                               .sideB = true,
                               .label = "Prepass lights",
                               .section = P::LightingMode,
                               .tooltip = "quad: one full-screen draw sums every light at every pixel of the thin "
                                          "G-buffer\nvolumes: each light's volume drawn with the volume cull mode, "
                                          "its diffuse and\nspecular light added into the two light targets "
                                          "(docs/deferred_lighting.md)",
                               .applies = prepassOnly,
                               .option = "--prepass-lights"}),
};

}  // namespace

std::span<PipelineField const> pipelineFields() {
    return kFields;
}

PipelineField const* findPipelineField(std::string_view name) {
    for (PipelineField const& f : kFields)
        if (f.name == name || (!f.oldName.empty() && f.oldName == name)) return &f;
    return nullptr;
}

std::string fieldScriptText(PipelineField const& f, PipelineSettings const& s) {
    double const v = f.get(s);
    switch (f.kind) {
        case SettingKind::Choice: {
            std::size_t const i = std::size_t(v);
            return i < f.choices.size() ? std::string(f.choices[i]) : std::string("?");
        }
        case SettingKind::Toggle:
            return v != 0.0 ? "1" : "0";
        case SettingKind::Number:
            break;
    }
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

bool fieldAccepts(PipelineField const& f, double v) {
    return std::isfinite(v) && v >= f.min && v <= f.max;
}

std::optional<double> parseFieldValue(PipelineField const& f, std::string const& text) {
    switch (f.kind) {
        case SettingKind::Choice:
            for (std::size_t i = 0; i < f.choices.size(); ++i)
                if (f.choices[i] == text) return double(i);
            return std::nullopt;
        case SettingKind::Toggle:
            if (text == "1" || text == "on") return 1.0;
            if (text == "0" || text == "off") return 0.0;
            return std::nullopt;
        case SettingKind::Number:
            break;
    }
    char* end = nullptr;
    double const v = std::strtod(text.c_str(), &end);
    if (end == text.c_str() || *end != '\0' || !fieldAccepts(f, v)) return std::nullopt;
    return v;
}

std::string fieldValuesText(PipelineField const& f) {
    switch (f.kind) {
        case SettingKind::Choice: {
            std::string s = "one of ";
            for (std::size_t i = 0; i < f.choices.size(); ++i) {
                if (i) s += i + 1 == f.choices.size() ? " or " : ", ";
                s += f.choices[i];
            }
            return s;
        }
        case SettingKind::Toggle:
            return "0 or 1 (or off or on)";
        case SettingKind::Number:
            break;
    }
    char buf[64];
    std::snprintf(buf, sizeof buf, "a number from %g to %g", double(f.min), double(f.max));
    return buf;
}

}  // namespace gbl
