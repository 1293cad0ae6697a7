// Import pass.
#include "passes/import.h"

#include "core/frame_types.h"
#include "gl/shader_bindings.h"
#include "passes/shading_inputs.h"

namespace gbl {

namespace {

gl::Texture upload(std::vector<glm::vec4> const& pixels, int width, int height, char const* label) {
    gl::Texture t = gl::Texture::create2D(GL_RGBA32F, width, height, label);
    glBindTexture(GL_TEXTURE_2D, t.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, GL_RGBA, GL_FLOAT, pixels.data());
    glBindTexture(GL_TEXTURE_2D, 0);
    return t;
}

}  // namespace

std::optional<std::string> uploadImportedFrame(ImportedFrame const& frame, ImportedTextures& out) {
    std::size_t const n = frame.pixelCount();
    if (frame.width <= 0 || frame.height <= 0) return "the imported G-buffer is empty";
    if (frame.positionDepth.size() != n || frame.normal.size() != n || frame.albedoSpec.size() != n ||
        (!frame.emissiveAo.empty() && frame.emissiveAo.size() != n))
        return "the imported G-buffer's pixel arrays do not match its size " + std::to_string(frame.width) + "x" +
               std::to_string(frame.height);
    out.positionDepth = upload(frame.positionDepth, frame.width, frame.height, "imported.position_depth");
    out.normal = upload(frame.normal, frame.width, frame.height, "imported.normal");
    out.albedoSpec = upload(frame.albedoSpec, frame.width, frame.height, "imported.albedo_spec");
    // Without emission and occlusion every pixel is (0, 0, 0, 1): the frame the import pass wrote
    // before manifests carried them.
    out.emissiveAo = upload(frame.emissiveAo.empty() ? std::vector<glm::vec4>(n, kNoEmissiveAo) : frame.emissiveAo,
                            frame.width, frame.height, "imported.emissive_ao");
    out.camera = ImportedFrame{frame.width,     frame.height,  {}, {}, {}, {}, frame.view, frame.projection, frame.eye,
                               frame.nearPlane, frame.farPlane};
    return std::nullopt;
}

// Blending must be off (the alpha channels carry data); the depth test passes every fragment, which
// writes its own depth.
ImportOutput importPass(ImportInput const& in, ImportConfig const& config) {
    glBindFramebuffer(GL_FRAMEBUFFER, in.target.id());
    glViewport(0, 0, config.width, config.height);
    applyGroup(config.states, 0);  // cleared by the executor (PassDecl::clears)
    in.program.use();
    bindTextureUnit(slot::BIND_IMPORT_POSITION_DEPTH, GL_TEXTURE_2D, in.imported.positionDepth.id());
    bindTextureUnit(slot::BIND_IMPORT_NORMAL, GL_TEXTURE_2D, in.imported.normal.id());
    bindTextureUnit(slot::BIND_IMPORT_ALBEDO_SPEC, GL_TEXTURE_2D, in.imported.albedoSpec.id());
    bindTextureUnit(slot::BIND_IMPORT_EMISSIVE_AO, GL_TEXTURE_2D, in.imported.emissiveAo.id());
    in.triangle.draw();
    return {in.target};
}

}  // namespace gbl
