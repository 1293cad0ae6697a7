// The glTF scene builder's images and materials: decoding on first use, sRGB/linear copies, baked specular.
#include "gltf/scene_builder_parts.h"

#include "gltf/images.h"
#include "gltf/mapping.h"

#include <algorithm>
#include <climits>
#include <cmath>

namespace gbl::gltf {

int SceneBuilder::textureSource(int texture, std::string const& who) {
    if (texture < 0) return -1;
    if (std::size_t(texture) >= model_.textures.size())
        fail(who + " refers to texture " + std::to_string(texture) + ", but the file has " +
             num(model_.textures.size()));
    int const source = model_.textures[std::size_t(texture)].source;
    if (source < 0) {
        scene_.warnings.push_back(who + " uses texture " + std::to_string(texture) +
                                  ", which has no image this loader can read; ignored");
        return -1;
    }
    if (std::size_t(source) >= model_.images.size())
        fail("texture " + std::to_string(texture) + " refers to image " + std::to_string(source) +
             ", but the file has " + num(model_.images.size()));
    return source;
}

std::size_t SceneBuilder::countImages(std::set<int> const& materials) {
    std::set<int> images;
    for (int m : materials) {
        auto const& mat = model_.materials[std::size_t(m)];
        std::string const who = "material " + std::to_string(m);
        for (int t : {mat.pbrMetallicRoughness.baseColorTexture.index, mat.normalTexture.index,
                      mat.pbrMetallicRoughness.metallicRoughnessTexture.index, mat.emissiveTexture.index,
                      mat.occlusionTexture.index})
            if (int s = textureSource(t, who); s >= 0) images.insert(s);
    }
    return std::max<std::size_t>(images.size(), 1);
}

// The decoded image, or null (with a warning) when it is missing or unreadable.
ImageData const* SceneBuilder::decoded(int image) {
    auto found = decoded_.find(image);
    if (found != decoded_.end()) return found->second ? &*found->second : nullptr;
    auto const& src = model_.images[std::size_t(image)];
    std::string const label =
        "image " + std::to_string(image) +
        (src.uri.empty() || src.uri.rfind("data:", 0) == 0 ? std::string() : " ('" + printable(src.uri, 80) + "')");
    std::span<std::uint8_t const> bytes;
    if (src.bufferView >= 0) {
        bytes = reader_.bufferView(src.bufferView, "image " + std::to_string(image));
    } else if (auto it = stash_.encoded.find(image); it != stash_.encoded.end()) {
        bytes = it->second;
    }
    std::optional<ImageData> result;
    if (bytes.empty()) {
        scene_.warnings.push_back(label + " is missing; a placeholder texture is shown instead");
    } else {
        DecodedImage d = decodeImage(bytes, src.name.empty() ? label : src.name,
                                     src.mimeType.empty() ? std::string_view(src.uri) : std::string_view(src.mimeType),
                                     options_.maxImagePixels);
        if (d.overLimit) fail(label + ": " + d.error);
        if (!d.image)
            scene_.warnings.push_back(label + " cannot be used (" + d.error +
                                      "); a placeholder texture is shown instead");
        result = std::move(d.image);
    }
    ++imagesDecoded_;
    progress_.report(0.1f + 0.5f * float(imagesDecoded_) / float(imagesToDecode_), "decoding images");
    auto const& stored = decoded_.emplace(image, std::move(result)).first->second;
    return stored ? &*stored : nullptr;
}

// Index into scene_.images for a glTF image used as colour (sRGB) or as data (linear).
int SceneBuilder::sceneImage(int image, bool srgb) {
    auto const key = std::make_pair(image, srgb);
    if (auto it = sceneImages_.find(key); it != sceneImages_.end()) return it->second;
    ImageData const* img = decoded(image);
    ImageData copy = img ? *img : placeholderImage("placeholder for image " + std::to_string(image));
    copy.srgb = srgb;
    scene_.images.push_back(std::move(copy));
    int const index = int(scene_.images.size() - 1);
    sceneImages_.emplace(key, index);
    return index;
}

TextureTransform SceneBuilder::textureTransform(int index, char const* parent, char const* slot, int texCoord,
                                                std::string const& who) {
    Json const* info = nullptr;
    if (Json const* mats = member(doc_, "materials"); mats && std::size_t(index) < mats->size()) {
        Json const* holder = &(*mats)[std::size_t(index)];
        if (parent) holder = member(*holder, parent);
        info = holder ? member(*holder, slot) : nullptr;
    }
    return readTransform(info, texCoord, who + "'s " + slot);
}

// KHR_texture_transform's texCoord overrides the textureInfo's; sets past TEXCOORD_1 fall back to 0.
TextureTransform SceneBuilder::readTransform(Json const* info, int texCoord, std::string const& who) {
    TextureTransform t;
    Json const* exts = info ? member(*info, "extensions") : nullptr;
    Json const* ext = exts ? member(*exts, "KHR_texture_transform") : nullptr;
    if (ext) {
        requireKind(*ext, Kind::Object, who + "'s KHR_texture_transform");
        auto vec2 = [&](char const* key, glm::vec2& out) {
            Json const* v = member(*ext, key);
            if (!v) return;
            requireKind(*v, Kind::NumberArray, who + "'s KHR_texture_transform." + key);
            if (v->size() != 2)
                fail(who + "'s KHR_texture_transform." + key + " has " + num(v->size()) + " numbers; expected 2");
            out = glm::vec2((*v)[0].get<float>(), (*v)[1].get<float>());
        };
        vec2("offset", t.offset);
        vec2("scale", t.scale);
        if (Json const* r = member(*ext, "rotation")) {
            requireKind(*r, Kind::Number, who + "'s KHR_texture_transform.rotation");
            t.rotation = r->get<float>();
        }
        if (Json const* c = member(*ext, "texCoord")) {
            requireKind(*c, Kind::Index, who + "'s KHR_texture_transform.texCoord");
            texCoord = int(std::min<std::uint64_t>(c->get<std::uint64_t>(), INT_MAX));
        }
        if (!std::isfinite(t.offset.x) || !std::isfinite(t.offset.y) || !std::isfinite(t.scale.x) ||
            !std::isfinite(t.scale.y) || !std::isfinite(t.rotation)) {
            scene_.warnings.push_back(who + " has a non-finite KHR_texture_transform; it is ignored");
            t = TextureTransform{};
        }
    }
    if (texCoord == 0 || texCoord == 1) {
        t.texCoord = texCoord;
    } else {
        scene_.warnings.push_back(who + " uses TEXCOORD_" + std::to_string(texCoord) +
                                  "; only TEXCOORD_0 and TEXCOORD_1 are loaded, so TEXCOORD_0 is used");
    }
    return t;
}

// Emission and ambient occlusion: docs/gltf.md, "glTF materials and lights".
void SceneBuilder::emissiveAndOcclusion(int index, Material& mat) {
    auto const& src = model_.materials[std::size_t(index)];
    std::string const who = "material " + std::to_string(index);
    if (src.emissiveFactor.size() == 3) {
        glm::vec3 const e(float(src.emissiveFactor[0]), float(src.emissiveFactor[1]), float(src.emissiveFactor[2]));
        if (std::isfinite(e.x) && std::isfinite(e.y) && std::isfinite(e.z))
            mat.emissiveFactor = glm::clamp(e, 0.0f, 1.0f);  // glTF 2.0 limits each to [0, 1]
        else
            scene_.warnings.push_back(who + "'s emissiveFactor is not finite; no emission is used");
    } else if (!src.emissiveFactor.empty()) {
        scene_.warnings.push_back(who + "'s emissiveFactor does not have 3 numbers; no emission is used");
    }
    if (int s = textureSource(src.emissiveTexture.index, who); s >= 0) {
        mat.emissiveTexture = sceneImage(s, true);
        mat.emissiveTransform = textureTransform(index, nullptr, "emissiveTexture", src.emissiveTexture.texCoord, who);
    }
    if (int s = textureSource(src.occlusionTexture.index, who); s >= 0) {
        mat.occlusionTexture = sceneImage(s, false);
        double const strength = src.occlusionTexture.strength;
        if (std::isfinite(strength)) {
            mat.occlusionStrength = float(std::clamp(strength, 0.0, 1.0));  // glTF 2.0: [0, 1]
        } else {
            scene_.warnings.push_back(who + "'s occlusionTexture.strength is not finite; 1 is used");
        }
        mat.occlusionTransform =
            textureTransform(index, nullptr, "occlusionTexture", src.occlusionTexture.texCoord, who);
    }
}

int SceneBuilder::material(int index) {
    if (auto it = materials_.find(index); it != materials_.end()) return it->second;
    auto const& src = model_.materials[std::size_t(index)];
    std::string const who = "material " + std::to_string(index);
    Material mat;
    mat.name = src.name.empty() ? who : src.name;
    auto const& pbr = src.pbrMetallicRoughness;
    if (pbr.baseColorFactor.size() == 4)
        mat.baseColorFactor = glm::clamp(glm::vec4(float(pbr.baseColorFactor[0]), float(pbr.baseColorFactor[1]),
                                                   float(pbr.baseColorFactor[2]), float(pbr.baseColorFactor[3])),
                                         0.0f, 1.0f);
    else if (!pbr.baseColorFactor.empty())
        scene_.warnings.push_back(who + "'s baseColorFactor does not have 4 numbers; white is used");
    if (int s = textureSource(pbr.baseColorTexture.index, who); s >= 0) {
        mat.baseColorTexture = sceneImage(s, true);
        mat.baseColorTransform =
            textureTransform(index, "pbrMetallicRoughness", "baseColorTexture", pbr.baseColorTexture.texCoord, who);
    }
    if (int s = textureSource(src.normalTexture.index, who); s >= 0) {
        mat.normalTexture = sceneImage(s, false);
        mat.normalScale = std::isfinite(src.normalTexture.scale) ? float(src.normalTexture.scale) : 1.0f;
        mat.normalTransform = textureTransform(index, nullptr, "normalTexture", src.normalTexture.texCoord, who);
    }
    emissiveAndOcclusion(index, mat);

    // Specular intensity: docs/gltf.md, "glTF materials and lights".
    float weight = 1.0f;
    int specularImage = -1;
    TextureTransform specularTransform;
    Json const* specExt = nullptr;
    if (Json const* mats = member(doc_, "materials"); mats && std::size_t(index) < mats->size())
        if (Json const* ext = member((*mats)[std::size_t(index)], "extensions"))
            specExt = member(*ext, "KHR_materials_specular");
    if (specExt) {
        requireKind(*specExt, Kind::Object, who + "'s KHR_materials_specular");
        if (Json const* f = member(*specExt, "specularFactor")) {
            requireKind(*f, Kind::Number, who + "'s specularFactor");
            weight = f->get<float>();
        }
        if (Json const* f = member(*specExt, "specularColorFactor")) {
            requireKind(*f, Kind::NumberArray, who + "'s specularColorFactor");
            float strongest = 0.0f;
            for (auto const& c : *f) strongest = std::max(strongest, c.get<float>());
            if (!f->empty()) weight *= strongest;
        }
        if (Json const* t = member(*specExt, "specularTexture")) {
            requireKind(*t, Kind::Object, who + "'s specularTexture");
            if (Json const* i = member(*t, "index")) {
                requireKind(*i, Kind::Index, who + "'s specularTexture.index");
                specularImage = textureSource(int(std::min<std::uint64_t>(i->get<std::uint64_t>(), INT_MAX)), who);
            }
            int texCoord = 0;
            if (Json const* c = member(*t, "texCoord")) {
                requireKind(*c, Kind::Index, who + "'s specularTexture.texCoord");
                texCoord = int(std::min<std::uint64_t>(c->get<std::uint64_t>(), INT_MAX));
            }
            specularTransform = readTransform(t, texCoord, who + "'s specularTexture");
        }
    }
    float const metallic = float(pbr.metallicFactor), roughness = float(pbr.roughnessFactor);
    int const mrImage = textureSource(pbr.metallicRoughnessTexture.index, who);
    ImageData const* mr = mrImage >= 0 ? decoded(mrImage) : nullptr;
    ImageData const* sp = specularImage >= 0 ? decoded(specularImage) : nullptr;
    if (mr || sp) {
        // Bake once per distinct input: many materials share one texture set.
        std::string const key = std::to_string(mr ? mrImage : -1) + "/" + std::to_string(sp ? specularImage : -1) +
                                "/" + std::to_string(metallic) + "/" + std::to_string(roughness) + "/" +
                                std::to_string(weight);
        auto it = bakes_.find(key);
        if (it == bakes_.end()) {
            scene_.images.push_back(
                bakeSpecularImage(mr, sp, metallic, roughness, weight, mat.name + " specular (baked)"));
            it = bakes_.emplace(key, int(scene_.images.size() - 1)).first;
        }
        mat.specularTexture = it->second;
        mat.specularFactor = 1.0f;
        // The bake reads both inputs texel by texel, so they share one mapping: the
        // metallic-roughness texture's when there is one.
        TextureTransform const mrTransform = textureTransform(index, "pbrMetallicRoughness", "metallicRoughnessTexture",
                                                              pbr.metallicRoughnessTexture.texCoord, who);
        mat.specularTransform = mr ? mrTransform : specularTransform;
        if (mr && sp && !(mrTransform == specularTransform))
            scene_.warnings.push_back(who +
                                      "'s specular and metallic-roughness textures use different texture "
                                      "coordinates or transforms; the metallic-roughness one is used for both");
    } else {
        mat.specularFactor = specularFromMetallicRoughness(metallic, roughness, weight);
    }

    if (src.alphaMode == "MASK")
        mat.alphaMode = AlphaMode::Mask;
    else if (src.alphaMode == "BLEND")
        mat.alphaMode = AlphaMode::Blend;
    else if (src.alphaMode != "OPAQUE" && !src.alphaMode.empty())
        scene_.warnings.push_back(who + " has an unknown alphaMode '" + printable(src.alphaMode, 20) +
                                  "'; drawn opaque");
    mat.alphaCutoff = std::isfinite(src.alphaCutoff) ? float(src.alphaCutoff) : 0.5f;
    mat.doubleSided = src.doubleSided;

    scene_.materials.push_back(std::move(mat));
    int const ours = int(scene_.materials.size() - 1);
    materials_.emplace(index, ours);
    return ours;
}

}  // namespace gbl::gltf
