// Scene upload and the draw loop shared by the geometry and forward passes.
#include "gpu/gpu_scene.h"

#include "gl/draw_count.h"
#include "scene/draw_order.h"

#include "gl/shader_bindings.h"

#include <glm/gtc/matrix_inverse.hpp>

#include <algorithm>
#include <cstddef>
#include <numeric>

namespace gbl {

namespace {

std::optional<std::string> validate(SceneData const& scene) {
    for (std::size_t i = 0; i < scene.images.size(); ++i) {
        auto const& img = scene.images[i];
        std::size_t const expected = std::size_t(img.width) * std::size_t(img.height) * std::size_t(img.channels);
        if (img.width <= 0 || img.height <= 0 || img.channels < 1 || img.channels > 4 || img.pixels.size() != expected)
            return "image " + std::to_string(i) + " (" + img.name + ") has " + std::to_string(img.pixels.size()) +
                   " bytes for " + std::to_string(img.width) + "x" + std::to_string(img.height) + "x" +
                   std::to_string(img.channels);
    }
    auto badTexture = [&](int t) { return t < -1 || t >= int(scene.images.size()); };
    for (auto const& m : scene.materials)
        if (badTexture(m.baseColorTexture) || badTexture(m.normalTexture) || badTexture(m.specularTexture) ||
            badTexture(m.emissiveTexture) || badTexture(m.occlusionTexture))
            return "material " + m.name + " names a texture that does not exist";
    for (auto const& mesh : scene.meshes) {
        if (mesh.material < -1 || mesh.material >= int(scene.materials.size()))
            return "mesh " + mesh.name + " names a material that does not exist";
        for (auto idx : mesh.indices)
            if (idx >= mesh.vertices.size()) return "mesh " + mesh.name + " has an index out of range";
        if (mesh.indices.size() % 3 != 0)
            return "mesh " + mesh.name + " has an index count that is not a multiple of 3";
    }
    for (auto const& inst : scene.instances)
        if (inst.mesh < 0 || inst.mesh >= int(scene.meshes.size()))
            return "an instance names a mesh that does not exist";
    return std::nullopt;
}

// WebGL2 has no texture swizzle, and its RGB formats (SRGB8 among them) cannot have mipmaps
// generated: grey and RGB images become RGBA there (grey as (v, v, v, 1), what the swizzle gives
// natively), so every texture reads as on the desktop.
ImageData asWebGl2Texture(ImageData const& img) {
    if (img.channels != 1 && img.channels != 3) return img;
    ImageData out = img;
    out.channels = 4;
    std::size_t const texels = std::size_t(img.width) * std::size_t(img.height);
    out.pixels.assign(texels * 4, 255);
    for (std::size_t p = 0; p < texels; ++p)
        for (int c = 0; c < 3; ++c)
            out.pixels[p * 4 + std::size_t(c)] =
                img.pixels[p * std::size_t(img.channels) + (img.channels == 1 ? 0 : std::size_t(c))];
    return out;
}

gl::Texture uploadImage(ImageData const& given) {
    ImageData const expanded = gl::kWebGL2 ? asWebGl2Texture(given) : ImageData{};
    ImageData const& img = gl::kWebGL2 ? expanded : given;
    static constexpr GLenum kFormats[] = {GL_RED, GL_RG, GL_RGB, GL_RGBA};
    GLenum internal = GL_RGBA8;
    if (img.srgb)
        internal = img.channels == 4 ? GL_SRGB8_ALPHA8 : GL_SRGB8;
    else if (img.channels == 1)
        internal = GL_R8;
    else if (img.channels == 2)
        internal = GL_RG8;
    else if (img.channels == 3)
        internal = GL_RGB8;
    // sRGB textures need 3 or 4 channels; grey sRGB images are expanded by the sampler swizzle below.
    if (img.srgb && img.channels < 3) internal = img.channels == 1 ? GL_R8 : GL_RG8;
    int levels = 1;
    for (int s = std::max(img.width, img.height); s > 1; s /= 2) ++levels;
    gl::Texture t =
        gl::Texture::create2D(internal, img.width, img.height, img.name.empty() ? "scene image" : img.name, levels);
    glBindTexture(GL_TEXTURE_2D, t.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, img.width, img.height, kFormats[img.channels - 1], GL_UNSIGNED_BYTE,
                    img.pixels.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
#ifdef GL_TEXTURE_SWIZZLE_RGBA  // not in WebGL2, where grey images were expanded above
    if (img.channels == 1) {
        GLint const swizzle[] = {GL_RED, GL_RED, GL_RED, GL_ONE};
        glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_RGBA, swizzle);
    }
#endif
    glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glBindTexture(GL_TEXTURE_2D, 0);
    return t;
}

GpuMesh uploadMesh(MeshData const& mesh) {
    GpuMesh g;
    g.vao = gl::VertexArray::create(mesh.name.empty() ? "mesh" : mesh.name);
    g.vertices = gl::Buffer::create(GL_ARRAY_BUFFER, mesh.vertices.size() * sizeof(Vertex), mesh.vertices.data(),
                                    GL_STATIC_DRAW, mesh.name + ".vertices");
    g.indices = gl::Buffer::create(GL_ELEMENT_ARRAY_BUFFER, mesh.indices.size() * sizeof(std::uint32_t),
                                   mesh.indices.data(), GL_STATIC_DRAW, mesh.name + ".indices");
    g.indexCount = GLsizei(mesh.indices.size());
    g.material = mesh.material;
    if (!mesh.vertices.empty()) {
        glm::vec3 lo = mesh.vertices.front().position, hi = lo;
        for (Vertex const& v : mesh.vertices) {
            lo = glm::min(lo, v.position);
            hi = glm::max(hi, v.position);
        }
        g.center = (lo + hi) * 0.5f;
    }
    glBindVertexArray(g.vao.id());
    glBindBuffer(GL_ARRAY_BUFFER, g.vertices.id());
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g.indices.id());
    auto attrib = [](GLuint loc, GLint size, std::size_t offset) {
        glEnableVertexAttribArray(loc);
        glVertexAttribPointer(loc, size, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void const*>(offset));
    };
    attrib(0, 3, offsetof(Vertex, position));
    attrib(1, 3, offsetof(Vertex, normal));
    attrib(2, 2, offsetof(Vertex, uv));
    attrib(3, 4, offsetof(Vertex, tangent));
    attrib(4, 2, offsetof(Vertex, uv1));
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    return g;
}

}  // namespace

std::optional<std::string> uploadScene(SceneData const& scene, GpuScene& out) {
    if (auto err = validate(scene)) return "scene " + scene.source + ": " + *err;
    GpuScene g;
    for (auto const& img : scene.images) g.textures.push_back(uploadImage(img));
    g.materials = scene.materials;
    for (auto const& mesh : scene.meshes) g.meshes.push_back(uploadMesh(mesh));
    g.instances = scene.instances;
    g.triangleCount = scene.triangleCount();
    ImageData white{"white", 1, 1, 4, false, {255, 255, 255, 255}};
    g.white = uploadImage(white);
    out = std::move(g);
    return std::nullopt;
}

bool hasBlended(GpuScene const& scene) {
    return std::any_of(scene.instances.begin(), scene.instances.end(), [&](MeshInstance const& inst) {
        int const m = scene.meshes[std::size_t(inst.mesh)].material;
        return m >= 0 && scene.materials[std::size_t(m)].alphaMode == AlphaMode::Blend;
    });
}

void drawScene(GpuScene const& scene, gl::Program const& program, MaterialFilter filter, bool useNormalMaps,
               std::span<DrawState const> states, std::optional<glm::mat4> backToFrontFrom) {
    static Material const kDefaultMaterial{};
    program.set("uUseNormalMaps", useNormalMaps ? 1 : 0);
    // The flag, coordinate set and UV matrix uniforms of one texture (shaders/material.glsl).
    struct TextureUniforms {
        char const* has;
        char const* texCoord;
        char const* transform;
    };
    auto bindTexture = [&](int unit, int index, TextureTransform const& t, TextureUniforms const& u) {
        glActiveTexture(GLenum(GL_TEXTURE0 + unit));
        bool const has = index >= 0;
        glBindTexture(GL_TEXTURE_2D, has ? scene.textures[std::size_t(index)].id() : scene.white.id());
        program.set(u.has, has ? 1 : 0);
        program.set(u.texCoord, t.texCoord);
        program.set(u.transform, textureTransformMatrix(t));
    };
    std::vector<std::size_t> order(scene.instances.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    if (backToFrontFrom) {
        std::vector<glm::vec3> centers;
        for (MeshInstance const& inst : scene.instances)
            centers.push_back(glm::vec3(inst.model * glm::vec4(scene.meshes[std::size_t(inst.mesh)].center, 1.0f)));
        order = backToFrontOrder(centers, *backToFrontFrom);
    }
    std::size_t applied = states.size();  // none yet
    for (std::size_t index : order) {
        MeshInstance const& inst = scene.instances[index];
        GpuMesh const& mesh = scene.meshes[std::size_t(inst.mesh)];
        Material const& m = mesh.material >= 0 ? scene.materials[std::size_t(mesh.material)] : kDefaultMaterial;
        bool const blended = m.alphaMode == AlphaMode::Blend;
        if ((filter == MaterialFilter::Opaque && blended) || (filter == MaterialFilter::Blended && !blended)) continue;
        program.set("uModel", inst.model);
        program.set("uNormalMatrix", glm::mat3(glm::inverseTranspose(inst.model)));
        program.set("uBaseColorFactor", m.baseColorFactor);
        program.set("uNormalScale", m.normalScale);
        program.set("uSpecularFactor", m.specularFactor);
        program.set("uEmissiveFactor", m.emissiveFactor);
        program.set("uOcclusionStrength", m.occlusionStrength);
        program.set("uAlphaMask", m.alphaMode == AlphaMode::Mask ? 1 : 0);
        program.set("uAlphaCutoff", m.alphaCutoff);
        bindTexture(slot::BIND_MATERIAL_BASE_COLOR, m.baseColorTexture, m.baseColorTransform,
                    {"uHasBaseColorTex", "uBaseColorTexCoord", "uBaseColorUvTransform"});
        bindTexture(slot::BIND_MATERIAL_NORMAL, m.normalTexture, m.normalTransform,
                    {"uHasNormalTex", "uNormalTexCoord", "uNormalUvTransform"});
        bindTexture(slot::BIND_MATERIAL_SPECULAR, m.specularTexture, m.specularTransform,
                    {"uHasSpecularTex", "uSpecularTexCoord", "uSpecularUvTransform"});
        bindTexture(slot::BIND_MATERIAL_EMISSIVE, m.emissiveTexture, m.emissiveTransform,
                    {"uHasEmissiveTex", "uEmissiveTexCoord", "uEmissiveUvTransform"});
        bindTexture(slot::BIND_MATERIAL_OCCLUSION, m.occlusionTexture, m.occlusionTransform,
                    {"uHasOcclusionTex", "uOcclusionTexCoord", "uOcclusionUvTransform"});
        // glTF: double-sided faces are seen from both sides. A pass with one group (an overlay that culls
        // nothing) draws every material under it.
        std::size_t const group = m.doubleSided && states.size() > 1 ? 1 : 0;
        if (group != applied) applyGroup(states, applied = group);
        // A mirroring transform turns counter-clockwise triangles clockwise on screen (glTF 2.0
        // asks renderers to flip the winding for such nodes).
        glFrontFace(glm::determinant(glm::mat3(inst.model)) < 0.0f ? GL_CW : GL_CCW);
        glBindVertexArray(mesh.vao.id());
        glDrawElements(GL_TRIANGLES, mesh.indexCount, GL_UNSIGNED_INT, nullptr);
        gl::countDraw(std::uint64_t(mesh.indexCount / 3));
    }
    glBindVertexArray(0);
    glFrontFace(GL_CCW);
}

}  // namespace gbl
