// Re-lighting an imported G-buffer (docs/import.md): the public calls that set it up. The frame
// itself (renderer.cpp) runs the import pass in the geometry pass's place.
#include "renderer_impl.h"

namespace gbl {

std::optional<std::string> Renderer::setImportedGBuffer(ImportedFrame const& frame) {
    ImportedTextures textures;
    if (auto err = uploadImportedFrame(frame, textures)) return err;
    if (frame.width != impl_->targets.width || frame.height != impl_->targets.height)
        impl_->resizeTargets(frame.width, frame.height);
    impl_->imported = std::move(textures);
    return std::nullopt;
}

void Renderer::clearImportedGBuffer() {
    impl_->imported.reset();
}

bool Renderer::hasImportedGBuffer() const {
    return bool(impl_->imported);
}

}  // namespace gbl
