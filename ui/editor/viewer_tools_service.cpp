// Read-backs, requests and heat-map uploads of the viewer tools.
#include "viewer_tools_service.h"

#include "model/image_range.h"
#include "model/viewer_tools.h"

#include "gl/gl_api.h"

namespace gbl::ui {

namespace {
// Uploads the RGBA8 rows (top to bottom) that make() returns into tex, (re)making it at that
// size; a new texture is always filled, an unchanged one is left as it is.
template <class Make>
void uploadRgba(gl::Texture& tex, int w, int h, bool changed, char const* label, Make make) {
    if (!tex || tex.width() != w || tex.height() != h) {
        tex = gl::Texture::create2D(GL_RGBA8, w, h, label);
        tex.setFilter(GL_NEAREST, GL_NEAREST);
        changed = true;
    }
    if (!changed) return;
    std::vector<std::uint8_t> const rgba = make();
    // Rows top to bottom in memory; the views draw textures with v flipped (GL's bottom-up rows).
    glBindTexture(GL_TEXTURE_2D, tex.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    for (int y = 0; y < h; ++y)
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, h - 1 - y, w, 1, GL_RGBA, GL_UNSIGNED_BYTE,
                        rgba.data() + std::size_t(y) * std::size_t(w) * 4);
    glBindTexture(GL_TEXTURE_2D, 0);
}
}  // namespace

// Scale: the threshold when one is set (so "over" reads as the top of the ramp), else the max.
void uploadDiff(gl::Texture& tex, DiffStats const& diff, float threshold, bool changed) {
    float const scale = threshold > 0.0f ? threshold : diff.max;
    uploadRgba(tex, diff.diff.width, diff.diff.height, changed, "viewer diff",
               [&] { return diffHeatmap(diff, scale); });
}

void uploadPicture(gl::Texture& tex, int w, int h, std::vector<std::uint8_t> const& rgba, char const* label) {
    if (rgba.size() != std::size_t(w) * std::size_t(h) * 4) return;
    uploadRgba(tex, w, h, true, label, [&] { return rgba; });
}

namespace {
// The attachment a viewer shows, or its selected msaa sample while one is (msaa_views.h), decoded
// as the lighting reads it in every layout; the resolved attachment when the sample cannot be read
// (msaa went off since it was picked).
FloatImage viewerAttachmentImage(ViewerState const& v, Renderer& renderer) {
    if (auto slot = viewerSampleSlot(v.kind); slot && v.sample >= 0) {
        FloatImage sample = renderer.readMsaaDecodedSample(*slot, v.sample);
        if (!sample.pixels.empty()) return sample;
    }
    return renderer.readAttachment(viewerAttachment(v));
}

// Reads back what one viewer's tools need and services its requests. Returns whether the diff
// changed (re-upload its heat map).
bool serviceViewerData(ViewerState& v, ViewerData& d, Renderer& renderer, Camera const& camera, long frame,
                       bool forceRead) {
    if (!forceRead && !viewerDataDue(v, d, frame)) return updateViewerStats(v, d);
    bool const ownPlanes = v.kind == ViewerKind::Depth && !v.cameraClipPlanes;
    float const nearPlane = ownPlanes ? v.nearPlane : camera.nearPlane;
    float const farPlane = ownPlanes ? v.farPlane : camera.farPlane;
    setViewerValues(v, d, viewerValues(v, viewerAttachmentImage(v, renderer), nearPlane, farPlane), frame);
    return v.showDiff && d.pinned;
}
}  // namespace

void serviceViewerTools(EditorState& state, Renderer& renderer, long frame, std::array<unsigned, 5>& textures,
                        ViewerToolsGpu& gpu) {
    GBufferPanelState& panel = state.gbuffer;
    if (renderer.width() <= 0 || renderer.height() <= 0) return;
    for (std::size_t i = 0; i < panel.viewers.size(); ++i) {
        ViewerState& v = panel.viewers[i];
        ViewerData& d = panel.data[i];
        if (!viewerNeedsData(panel, i)) continue;
        bool const diffChanged = serviceViewerData(v, d, renderer, state.camera, frame, false);
        if (v.showDiff && d.diff.comparable) {
            uploadDiff(gpu.diff[i], d.diff, v.diffThreshold, diffChanged);
            textures[i] = gpu.diff[i].id();
        } else if (((v.kind == ViewerKind::Depth && v.showStencil) || v.sample >= 0) && d.values.width > 0) {
            // No view pass reads the stencil or one msaa sample: their picture is coloured on the
            // CPU from the read-back.
            ViewParams const params = viewerParams(v);
            bool const changed =
                gpu.pictureParams[i] != params || gpu.pictureFrame[i] != d.frame || gpu.pictureKey[i] != d.key;
            uploadRgba(gpu.picture[i], d.values.width, d.values.height, changed, "viewer picture",
                       [&] { return viewerPicture(v, d.values); });
            gpu.pictureParams[i] = params;
            gpu.pictureFrame[i] = d.frame;
            gpu.pictureKey[i] = d.key;
            textures[i] = gpu.picture[i].id();
        }
    }
}

unsigned findingMaskTexture(ViewerToolsGpu& gpu, GBufferCheckReport const& report, std::string const& path,
                            int marked) {
    if (marked < 0 || std::size_t(marked) >= report.findings.size() || report.width <= 0 || report.height <= 0)
        return 0;
    std::vector<std::uint8_t> const& mask = report.findings[std::size_t(marked)].mask;
    if (mask.size() != std::size_t(report.width) * std::size_t(report.height)) return 0;
    bool const changed = gpu.findingMaskFor != std::pair(path, marked);
    gpu.findingMaskFor = {path, marked};
    uploadRgba(gpu.findingMask, report.width, report.height, changed, "G-buffer finding mask", [&] {
        std::vector<std::uint8_t> rgba(mask.size() * 4, 0);
        for (std::size_t i = 0; i < mask.size(); ++i)
            if (mask[i]) {
                rgba[i * 4 + 0] = 255;
                rgba[i * 4 + 1] = 0;
                rgba[i * 4 + 2] = 220;
                rgba[i * 4 + 3] = 190;
            }
        return rgba;
    });
    return gpu.findingMask.id();
}

unsigned serviceLitPin(LitPin& pin, Renderer& renderer, long frame, ViewerToolsGpu& gpu) {
    if (renderer.width() <= 0 || renderer.height() <= 0) return 0;
    bool const due = litPinDue(pin, frame);
    if (due) setLitValues(pin, renderer.readAttachment(Attachment::Lighting), frame);
    // A new threshold or mode applies at once, from the values already read back.
    bool const changed = due || updateLitDiff(pin);
    if (!pin.showDiff || !pin.diff.comparable) return 0;
    uploadDiff(gpu.litDiff, pin.diff, pin.diffThreshold, changed);
    return gpu.litDiff.id();
}

namespace {

// The clip planes a viewer's linear depth uses: its own or the camera's.
glm::vec2 viewerClipPlanes(ViewerState const& v, Camera const& camera) {
    bool const own = v.kind == ViewerKind::Depth && !v.cameraClipPlanes;
    return own ? glm::vec2(v.nearPlane, v.farPlane) : glm::vec2(camera.nearPlane, camera.farPlane);
}

// Auto-fit and the Fit button of a viewer outside the G-buffer window (the viewport's, the
// overview's cells), from its own read-back: auto-fit takes the readable range (readableRange),
// Fit the whole min..max. Reads back when a fit, an open tool or `extraRead` needs the values.
// Returns whether the diff changed (re-upload its heat map).
bool fitOwnViewer(ViewerState& v, ViewerData& d, Renderer& renderer, Camera const& camera, long frame, bool rendered,
                  bool extraRead) {
    glm::vec2 const planes = viewerClipPlanes(v, camera);
    bool const asked = v.fitRequested;
    bool const fit = (asked || autoFitDue(v, d, planes, frame, rendered)) && viewerRemaps(v.kind);
    v.fitRequested = false;
    bool diffChanged = false;
    if (fit || viewerToolsNeedData(v) || extraRead) diffChanged = serviceViewerData(v, d, renderer, camera, frame, fit);
    if (!fit) return diffChanged;
    ValueRange const r =
        asked ? fitRange(d.values, viewerStatsMask(v), viewerSkip(v.kind)) : readableRange(v, d.values);
    if (r.samples > 0) {
        v.rangeMin = r.min;
        v.rangeMax = r.max > r.min ? r.max : r.min + 1e-6f;
        v.lastFitFrame = frame;
        if (!asked) d.autoFitFor = std::make_pair(viewerValuesKey(v), planes);
        updateViewerStats(v, d);
    }
    return diffChanged;
}

// Draws `params` into `target` when a new frame was rendered or the target is stale.
void drawOwnView(Renderer& renderer, ViewParams const& params, ViewerState const* v, FrameInput const& frameInput,
                 bool rendered, ViewTarget& target, std::optional<ViewParams>& drawn) {
    bool const stale = !target.texture || target.texture.width() != renderer.width() ||
                       target.texture.height() != renderer.height() || drawn != params;
    if (!rendered && !stale) return;
    FrameInput input = frameInput;
    if (v && v->kind == ViewerKind::Depth && !v->cameraClipPlanes) {
        input.camera.nearPlane = v->nearPlane;
        input.camera.farPlane = v->farPlane;
    }
    renderer.drawView(params, input, target);
    target.texture.setFilter(GL_NEAREST, GL_NEAREST);
    drawn = params;
}

}  // namespace

unsigned serviceViewportTools(EditorState& state, Renderer& renderer, FrameInput const& frameInput, long frame,
                              bool rendered, ViewerToolsGpu& gpu) {
    ViewportTools& tools = state.viewportTools;
    if (!tools.open || renderer.width() <= 0 || renderer.height() <= 0) return 0;
    if (!followViewportView(tools, state.pipeline.view)) return 0;
    ViewerState& v = tools.viewer;
    ViewerData& d = tools.data;
    v.imageSize = glm::ivec2(renderer.width(), renderer.height());
    bool const magnifier = state.gbuffer.showMagnifier && state.gbuffer.activeViewer == kViewportViewer;
    bool const diffChanged = fitOwnViewer(v, d, renderer, state.camera, frame, rendered, magnifier);
    if (v.showDiff && d.diff.comparable) {
        uploadDiff(gpu.viewportDiff, d.diff, v.diffThreshold, diffChanged);
        return gpu.viewportDiff.id();
    }
    if (v.sample >= 0 && d.values.width > 0) {
        ViewParams const params = viewerParams(v);
        if (gpu.viewportPictureFrame != d.frame || gpu.viewportPictureKey != d.key ||
            gpu.viewportPictureParams != params) {
            uploadPicture(gpu.viewportPicture, d.values.width, d.values.height, viewerPicture(v, d.values),
                          "viewport sample picture");
            gpu.viewportPictureFrame = d.frame;
            gpu.viewportPictureKey = d.key;
            gpu.viewportPictureParams = params;
        }
        return gpu.viewportPicture.id();
    }
    drawOwnView(renderer, viewerParams(v), &v, frameInput, rendered, gpu.viewport, gpu.viewportParams);
    return gpu.viewport.texture.id();
}

std::vector<unsigned> serviceOverview(EditorState& state, Renderer& renderer, FrameInput const& frameInput, long frame,
                                      bool rendered, ViewerToolsGpu& gpu) {
    OverviewState& overview = state.viewport.overview;
    std::vector<unsigned> textures;
    if (!overview.on || renderer.width() <= 0 || renderer.height() <= 0) return textures;
    std::vector<DebugView> const views = overviewViews();
    overview.viewers.resize(views.size());
    gpu.overview.resize(views.size());
    gpu.overviewParams.resize(views.size());
    for (std::size_t i = 0; i < views.size(); ++i) {
        ViewportTools& cell = overview.viewers[i];
        ViewParams params;
        params.view = views[i];
        ViewerState const* viewer = nullptr;
        // The attachments a viewer kind covers get its readable range; the lit frame is tonemapped
        // as in the viewport, emission and occlusion are colours and fractions already.
        if (followViewportView(cell, views[i])) {
            cell.viewer.imageSize = glm::ivec2(renderer.width(), renderer.height());
            fitOwnViewer(cell.viewer, cell.data, renderer, state.camera, frame, rendered, false);
            params = viewerParams(cell.viewer);
            viewer = &cell.viewer;
        }
        drawOwnView(renderer, params, viewer, frameInput, rendered, gpu.overview[i], gpu.overviewParams[i]);
        textures.push_back(gpu.overview[i].texture.id());
    }
    return textures;
}

}  // namespace gbl::ui
