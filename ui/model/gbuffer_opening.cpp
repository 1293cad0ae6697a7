// Opening, showing and closing another program's G-buffer in the editor.
#include "model/gbuffer_opening.h"

#include "import/gbuffer_manifest.h"
#include "import/imported_gbuffer.h"
#include "import/relight_frame.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <utility>

namespace gbl::ui {

namespace {

std::string lowerExtension(std::string const& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

// Takes away a pin that an open G-buffer's lit image made (a pin of our own frames stays).
void dropTheirLitPin(LitPin& pin) {
    if (pin.pinnedName.empty()) return;
    pin.pinned.reset();
    pin.pinnedName.clear();
    pin.pinnedFrame = -1;
    pin.showDiff = false;
    pin.diff = {};
    pin.diffFor.reset();
}

void syncViewport(GBufferOpenState const& state, EditorState& editor) {
    editor.viewport.importedFrame = state.path;
    editor.viewport.importedSize = state.size;
    editor.viewport.findings.clear();
    for (GBufferFinding const& f : state.checks.findings)
        editor.viewport.findings.push_back({.check = f.check,
                                            .attachment = f.attachment,
                                            .pixels = f.pixels,
                                            .share = f.share,
                                            .cause = f.cause,
                                            .heuristic = f.heuristic,
                                            .mask = {}});
    editor.viewport.precision.clear();
    for (PrecisionNote const& p : state.checks.precision) editor.viewport.precision.push_back(precisionLine(p));
    editor.viewport.markedFinding = -1;
}

// "; checks: 2 findings (normal_not_unit 12.5 %, nan_inf 0.1 %)" or "; checks: no finding".
std::string findingsSummary(GBufferCheckReport const& report) {
    if (report.findings.empty()) return "; checks: no finding";
    std::string s = "; checks: " + std::to_string(report.findings.size()) +
                    (report.findings.size() == 1 ? " finding (" : " findings (");
    for (std::size_t i = 0; i < report.findings.size(); ++i) {
        char share[32];
        std::snprintf(share, sizeof share, " %.3g %%", 100.0 * report.findings[i].share);
        s += (i ? ", " : "") + report.findings[i].check + share;
    }
    return s + "): Checks in the viewport marks their pixels";
}

}  // namespace

GBufferRead readGBuffer(std::string const& path) {
    GBufferRead out;
    ManifestLoad const manifest = loadManifest(path);
    if (!manifest.manifest) {
        out.error = manifest.error;
        return out;
    }
    GBufferLoad const loaded = loadGBuffer(*manifest.manifest);
    if (!loaded.gbuffer) {
        out.error = loaded.error;
        return out;
    }
    RelightFrame relight = relightFrame(*loaded.gbuffer);
    if (!relight.frame) {
        out.error = relight.error;
        return out;
    }
    out.camera = cameraOfFrame(*relight.frame);
    out.frame = std::move(relight.frame);
    out.lights = loaded.gbuffer->manifest.lights;
    out.shininess = loaded.gbuffer->manifest.shininess;
    out.shading = loaded.gbuffer->manifest.shading;
    ImportedGBuffer const& g = *loaded.gbuffer;
    out.checks = checkGBuffer(g);
    if (!g.lit.empty() && g.manifest.lit) {
        FloatImage lit{g.width, g.height, 4, {}};
        lit.pixels.reserve(g.lit.size() * 4);
        for (glm::vec3 const& c : g.lit) lit.pixels.insert(lit.pixels.end(), {c.r, c.g, c.b, 1.0f});
        out.lit = std::move(lit);
        out.litFile = std::filesystem::path(g.manifest.lit->path).filename().string();
    }
    return out;
}

bool isGBufferPath(std::string const& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) return true;
    return lowerExtension(path) == ".json";
}

void takeGBufferDrops(std::vector<std::string>& dropped, GBufferOpenState& state) {
    auto const scenes =
        std::stable_partition(dropped.begin(), dropped.end(), [](std::string const& p) { return !isGBufferPath(p); });
    if (scenes == dropped.end()) return;
    state.requests.push_back(dropped.back());  // one G-buffer at a time: the last dropped
    dropped.erase(scenes, dropped.end());
}

std::optional<std::string> installGBuffer(GBufferOpenState& state, std::string const& path, GBufferRead const& read,
                                          EditorState& editor, GBufferUploader const& upload) {
    if (!read.frame) return read.error;
    if (auto error = upload(*read.frame)) return path + ": the G-buffer could not be uploaded: " + *error;
    if (!state.scene)
        state.scene = SceneViewSnapshot{editor.camera,
                                        editor.rig,
                                        editor.lights,
                                        editor.lightsPanel.selected,
                                        editor.pipeline.shininess,
                                        editor.pipeline.shading,
                                        editor.pipeline.ambient};
    state.path = path;
    state.size = glm::ivec2(read.frame->width, read.frame->height);
    state.lastError.clear();
    state.checks = read.checks;
    editor.camera = read.camera;
    editor.lights = read.lights;
    applyManifestShading(read.shininess, read.shading, editor.pipeline);
    editor.lightsPanel.selected = editor.lights.empty() ? -1 : 0;
    editor.animation.time = 0.0f;
    syncViewport(state, editor);
    dropTheirLitPin(editor.litPin);  // a previous G-buffer's
    if (read.lit) {
        LitPin& pin = editor.litPin;
        pin.pinned = *read.lit;
        pin.pinnedFrame = -1;
        pin.pinnedName = "their lit image (" + read.litFile + ")";
        pin.values = {};  // the next read-back is at the G-buffer's size: Diff compares at once
        pin.frame = -1;
    }
    logMessage(editor.log, "G-buffer " + path + ": " + std::to_string(state.size.x) + "x" +
                               std::to_string(state.size.y) + ", " + std::to_string(editor.lights.size()) +
                               " lights, re-lit from its own camera" + findingsSummary(read.checks) +
                               (read.lit ? "; its lit image " + read.litFile +
                                               " is pinned: Diff in the viewport compares our re-light with it"
                                         : std::string()));
    return std::nullopt;
}

void closeGBuffer(GBufferOpenState& state, EditorState& editor) {
    if (state.scene) {
        editor.camera = state.scene->camera;
        editor.rig = state.scene->rig;
        editor.lights = state.scene->lights;
        editor.lightsPanel.selected = std::min(state.scene->selectedLight, int(editor.lights.size()) - 1);
        editor.pipeline.shininess = state.scene->shininess;
        editor.pipeline.shading = state.scene->shading;
        editor.pipeline.ambient = state.scene->ambient;
    }
    logMessage(editor.log, "closed G-buffer " + state.path + "; showing " + editor.sceneSource + " again");
    forgetGBuffer(state, editor);
}

void forgetGBuffer(GBufferOpenState& state, EditorState& editor) {
    dropTheirLitPin(editor.litPin);
    state.checks = {};
    state.path.clear();
    state.size = glm::ivec2(0);
    state.scene.reset();
    syncViewport(state, editor);
}

bool gbufferOpen(GBufferOpenState const& state) {
    return !state.path.empty();
}

EditorState sceneBehind(EditorState state, GBufferOpenState const& gbuffer) {
    if (gbuffer.scene) {
        state.camera = gbuffer.scene->camera;
        state.rig = gbuffer.scene->rig;
        state.lights = gbuffer.scene->lights;
        state.lightsPanel.selected = gbuffer.scene->selectedLight;
        state.pipeline.shininess = gbuffer.scene->shininess;
        state.pipeline.shading = gbuffer.scene->shading;
        state.pipeline.ambient = gbuffer.scene->ambient;
    }
    return state;
}

GBufferChange updateGBufferOpening(GBufferOpenState& state, EditorState& editor, GBufferUploader const& upload,
                                   std::function<void()> const& clear) {
    GBufferChange change = GBufferChange::None;
    if (std::exchange(state.closeRequested, false) && gbufferOpen(state)) {
        clear();
        closeGBuffer(state, editor);
        change = GBufferChange::Closed;
    }
    for (std::string const& path : std::exchange(state.requests, {})) {
        GBufferRead const read = readGBuffer(path);
        if (auto error = installGBuffer(state, path, read, editor, upload)) {
            state.lastError = *error;
            std::string const keeps = gbufferOpen(state) ? "The G-buffer " + state.path : "The scene";
            logMessage(editor.log, *error + ". " + keeps + " stays shown.", true);
            change = GBufferChange::Failed;
            continue;
        }
        change = GBufferChange::Opened;
    }
    return change;
}

}  // namespace gbl::ui
