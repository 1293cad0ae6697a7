// `gbuffer-lab render --gbuffer MANIFEST --out DIR`: another program's G-buffer re-lit on the GPU
// (docs/import.md, "Re-lighting"), written out as `render --out` writes a frame.
#include "render_command.h"

#include "frame_export.h"
#include "import/gbuffer_manifest.h"
#include "import/imported_gbuffer.h"
#include "import/relight_frame.h"

#include <cstdio>

namespace gbl {

namespace {

int refuse(std::string const& message) {
    std::fprintf(stderr, "gbuffer-lab render: %s\n", message.c_str());
    return 2;
}

}  // namespace

int runRenderImported(RenderOptions const& o) {
    // What a G-buffer replaces: the scene, its camera and lights, and the frame size.
    for (char const* name : {"--scene", "--lights", "--session", "--camera", "--size"})
        if (o.given.count(name))
            return refuse(std::string(name) + " cannot be combined with --gbuffer (the G-buffer brings its own " +
                          (std::string(name) == "--size" ? "size" : "surfaces, camera and lights") + ")");
    if (o.lesson) return refuse("--lesson cannot be combined with --gbuffer (a lesson renders its own scene)");
    if (o.accumulate || o.contribution || o.saveSessionPath)
        return refuse("--accumulate, --contribution and --save-session need a scene, which --gbuffer replaces");
    std::string error;
    auto const parsed = renderSettings(o, &error);
    if (!parsed) return refuse(error);
    PipelineSettings settings = *parsed;
    if (lightsByDrawingMeshes(settings.mode))
        return refuse("--mode " + std::string(enumName(kLightingModeNames, settings.mode)) +
                      " draws the scene's meshes, and a G-buffer has none: use quad, volumes, tiled or clustered");
    std::vector<DebugView> views;
    for (auto const& name : o.views) {
        auto v = enumFromName<DebugView>(kDebugViewNames, name);
        if (!v) return refuse("--view '" + name + "' is not a debug view (see render --help)");
        views.push_back(*v);
    }

    ManifestLoad const manifest = loadManifest(*o.gbuffer);
    if (!manifest.manifest) return refuse(manifest.error);
    GBufferLoad loaded = loadGBuffer(*manifest.manifest);
    if (!loaded.gbuffer) return refuse(loaded.error);
    RelightFrame const relight = relightFrame(*loaded.gbuffer);
    if (!relight.frame) return refuse(relight.error);
    ImportedFrame const& frame = *relight.frame;
    std::vector<PointLight> const lights = loaded.gbuffer->manifest.lights;
    // The manifest's shading, unless --shading names one.
    bool const shadingGiven = o.given.count(std::string(findPipelineField("shading")->option)) > 0;
    ShadingModel const shading = shadingGiven ? settings.shading : loaded.gbuffer->manifest.shading;
    applyManifestShading(loaded.gbuffer->manifest.shininess, shading, settings);
    settings.lightCubes = false;  // sized to a scene (importedSettings)
    if (auto err = prepareOutDir(o.outDir)) return refuse(*err);

    auto headless = createHeadlessRenderer(frame.width, frame.height, o.glLimit, &error);
    if (!headless) {
        std::fprintf(stderr, "gbuffer-lab render: %s\n", error.c_str());
        return 1;
    }
    Renderer& renderer = *headless->renderer;
    if (auto const why = renderer.modeUnavailable(settings.mode)) return refuse(*why);
    if (auto err = renderer.setImportedGBuffer(frame)) return refuse(*err);
    Camera const camera = cameraOfFrame(frame);
    FrameInput input{camera, lights, settings, true};
    if (o.until) {
        if (auto why = stopAfterError(*o.until, renderer.framePasses(input))) return refuse("--until " + *why);
        input.stopAfter = passFromName(*o.until);
    }
    FrameStats const stats = renderer.render(input);
    FrameExport exported{camera, lights, settings, stats, 0, views};
    if (auto err = exportFrame(renderer, exported, o.outDir)) return refuse(*err);
    std::printf("wrote %s (%dx%d re-lit from %s, %d lights, %.2f GPU ms, %llu GL errors)\n", o.outDir.c_str(),
                frame.width, frame.height, o.gbuffer->c_str(), stats.lightsSubmitted, stats.gpuFrameMs,
                (unsigned long long)renderer.glErrorCount());
    return 0;
}

}  // namespace gbl
