// Viewer export through the renderer's view pass and image/image_io.h.
#include "viewer_export.h"

#include "image/image_io.h"

namespace gbl::ui {

Camera viewerCamera(ViewerState const& viewer, Camera const& sceneCamera) {
    Camera c = sceneCamera;
    if (viewer.kind == ViewerKind::Depth && viewer.linearDepth && !viewer.cameraClipPlanes) {
        c.nearPlane = viewer.nearPlane;
        c.farPlane = viewer.farPlane;
    }
    return c;
}

std::optional<std::string> exportViewerPng(Renderer& renderer, ViewerState const& viewer, Camera const& sceneCamera,
                                           std::string const& path) {
    if (renderer.width() <= 0 || renderer.height() <= 0)
        return "cannot write " + path + ": there is no frame (the viewport is 0x0)";
    ViewTarget target;
    // Viewers show G-buffer data: of the frame they need only the clip planes (depth views).
    renderer.drawView(viewerParams(viewer), FrameInput{viewerCamera(viewer, sceneCamera), {}, {}}, target);
    return writePng(path, renderer.readViewTarget(target), 3);
}

std::optional<std::string> exportViewerExr(Renderer& renderer, ViewerKind kind, std::string const& path) {
    if (renderer.width() <= 0 || renderer.height() <= 0)
        return "cannot write " + path + ": there is no frame (the viewport is 0x0)";
    switch (kind) {
        case ViewerKind::Position:
            return writeExr(path, renderer.readAttachment(Attachment::Position));
        case ViewerKind::Normal:
            return writeExr(path, renderer.readAttachment(Attachment::Normal));
        case ViewerKind::Albedo:
            return writeExr(path, renderer.readAttachment(Attachment::AlbedoSpec), 0, 3);
        case ViewerKind::Specular:
            return writeExr(path, renderer.readAttachment(Attachment::AlbedoSpec), 3, 1);
        case ViewerKind::Depth:
            return writeExr(path, renderer.readAttachment(Attachment::Depth));
        case ViewerKind::Lighting:
            return writeExr(path, renderer.readAttachment(Attachment::Lighting));
    }
    return "cannot write " + path + ": unknown viewer";
}

std::string viewerPngName(ViewerKind kind) {
    return std::string(viewerKindName(kind)) + "_view.png";
}
std::string viewerExrName(ViewerKind kind) {
    return std::string(viewerKindName(kind)) + ".exr";
}

}  // namespace gbl::ui
