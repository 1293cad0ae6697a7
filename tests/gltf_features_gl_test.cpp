// glTF texture transforms and TEXCOORD_1 in real frames: `gbuffer-lab render --camera 0` of a handcrafted quad
// with a 2x2 checker, the albedo read back where the transform says each texel lands.
#include "handmade_gltf.h"
#include "image/image_io.h"
#include "run_command.h"
#include "scene/texture_transform.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>

using namespace gbl;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

constexpr int kSize = 64;

// The checker's texels, row 0 at the top (glTF's v = 0): red, green / blue, white. Pure
// primaries read the same as sRGB and as linear albedo.
constexpr std::array<std::array<float, 3>, 4> kTexels = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}}};

// A 2x2 quad at z = 0 filling the view of camera 0 (at z = 1, 90 degree field of view) at aspect 1.
// TEXCOORD_0 maps the quad's top-left to (0, 0); with `uv1`, TEXCOORD_0 is one constant point of
// the red texel and TEXCOORD_1 carries the mapping instead.
json quadDocument(test::HandmadeGltf& g, json const& textureInfo, bool uv1) {
    std::vector<float> const mapped = {0, 1, 1, 1, 1, 0, 0, 0};  // corners (-1,-1) (1,-1) (1,1) (-1,1)
    std::vector<float> const constant = {0.25f, 0.25f, 0.25f, 0.25f, 0.25f, 0.25f, 0.25f, 0.25f};
    json attrs = {{"POSITION", g.floats({-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0}, "VEC3")},
                  {"NORMAL", g.floats({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3")},
                  {"TEXCOORD_0", g.floats(uv1 ? constant : mapped, "VEC2")}};
    if (uv1) attrs["TEXCOORD_1"] = g.floats(mapped, "VEC2");
    g.doc["images"] = {{{"uri", "checker.png"}}};
    g.doc["textures"] = {{{"source", 0}}};
    g.doc["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", textureInfo}, {"metallicFactor", 0.0}}}}};
    g.meshNode(json::array({{{"attributes", attrs}, {"indices", g.indices({0, 1, 2, 0, 2, 3})}, {"material", 0}}}));
    g.doc["cameras"] = {{{"type", "perspective"},
                         {"perspective", {{"yfov", 1.5707963}, {"aspectRatio", 1.0}, {"znear", 0.1}, {"zfar", 10.0}}}}};
    g.node({{"camera", 0}, {"translation", {0.0, 0.0, 1.0}}});
    return g.doc;
}

// Writes the scene and its checker into a fresh folder, renders it from camera 0 and returns albedo.png.
std::optional<FloatImage> renderAlbedo(std::string const& name, json const& textureInfo, bool uv1) {
    fs::path const dir = test::freshTempDir("gltf_features_" + name);
    FloatImage checker{2, 2, 3, {}};
    for (auto const& t : kTexels) checker.pixels.insert(checker.pixels.end(), t.begin(), t.end());
    if (auto err = writePng((dir / "checker.png").string(), checker)) {
        ADD_FAILURE() << *err;
        return std::nullopt;
    }
    test::HandmadeGltf g;
    quadDocument(g, textureInfo, uv1);
    auto const bytes = g.bytes();
    std::ofstream((dir / "quad.gltf").string(), std::ios::binary)
        .write(reinterpret_cast<char const*>(bytes.data()), std::streamsize(bytes.size()));
    std::string const out = (dir / "out").string();
    auto const r = test::runGbufferLab({"render", "--scene", (dir / "quad.gltf").string(), "--camera", "0", "--out",
                                        out, "--size", std::to_string(kSize) + "x" + std::to_string(kSize)});
    if (r.exitCode != 0) {
        ADD_FAILURE() << name << ": exit " << r.exitCode << "\n" << r.output;
        return std::nullopt;
    }
    EXPECT_EQ(r.output.find("warning"), std::string::npos) << r.output;
    return readImage(out + "/albedo.png");
}

// Compares every pixel whose transformed coordinates land near a texel's centre with that texel.
// Returns how many pixels were compared.
int expectTexels(FloatImage const& albedo, TextureTransform const& t) {
    int compared = 0, wrong = 0;
    for (int y = 0; y < albedo.height; ++y)
        for (int x = 0; x < albedo.width; ++x) {
            glm::vec2 const uv((float(x) + 0.5f) / float(albedo.width), (float(y) + 0.5f) / float(albedo.height));
            glm::vec2 const st = applyTextureTransform(t, uv);
            glm::vec2 const texel = (st - glm::floor(st)) * 2.0f;  // repeat wrapping, in texels
            glm::vec2 const fromCentre = texel - glm::floor(texel) - 0.5f;
            // Within 0.05 texels of a centre on both axes the bilinear filter keeps at least
            // 0.95 x 0.95 = 90% of the texel (measured: 0.855 red at 0.08 texels off on both axes).
            if (std::abs(fromCentre.x) > 0.05f || std::abs(fromCentre.y) > 0.05f) continue;
            int const index = int(texel.y) * 2 + int(texel.x);
            ++compared;
            for (int c = 0; c < 3; ++c)
                // 0.12: the 10% neighbour mix plus 8-bit storage of the albedo; other texels differ by 1.
                if (std::abs(albedo.at(x, y, c) - kTexels[std::size_t(index)][std::size_t(c)]) > 0.12f) {
                    if (++wrong <= 5)
                        ADD_FAILURE() << "pixel (" << x << ", " << y << ") channel " << c << " is "
                                      << albedo.at(x, y, c) << ", texel " << index << " expected";
                    break;
                }
        }
    EXPECT_EQ(wrong, 0) << "of " << compared << " pixels";
    return compared;
}

}  // namespace

TEST(GltfFeaturesRender, WithoutATransformTheCheckerLiesAsTheFileMapsIt) {
    auto const albedo = renderAlbedo("plain", {{"index", 0}}, false);
    ASSERT_TRUE(albedo);
    ASSERT_EQ(albedo->width, kSize);
    // The top-left quadrant's centre is the red texel, the bottom-right one the white texel.
    EXPECT_NEAR(albedo->at(16, 16, 0), 1.0f, 0.1f);
    EXPECT_NEAR(albedo->at(16, 16, 1), 0.0f, 0.1f);
    EXPECT_NEAR(albedo->at(48, 48, 2), 1.0f, 0.1f);
    EXPECT_GE(expectTexels(*albedo, {}), 36);  // 3 x 3 pixels or more around each texel centre
}

TEST(GltfFeaturesRender, AnOffsetMovesEachTexelWhereTheTransformSays) {
    TextureTransform const t{{0.5f, 0.0f}, 0.0f, {1.0f, 1.0f}, 0};
    auto const albedo = renderAlbedo(
        "offset", {{"index", 0}, {"extensions", {{"KHR_texture_transform", {{"offset", {0.5, 0.0}}}}}}}, false);
    ASSERT_TRUE(albedo);
    // u + 0.5: the top-left quadrant now shows the green texel, the top-right one the red texel.
    EXPECT_NEAR(albedo->at(16, 16, 1), 1.0f, 0.1f);
    EXPECT_NEAR(albedo->at(16, 16, 0), 0.0f, 0.1f);
    EXPECT_NEAR(albedo->at(48, 16, 0), 1.0f, 0.1f);
    EXPECT_NEAR(albedo->at(48, 16, 1), 0.0f, 0.1f);
    EXPECT_GE(expectTexels(*albedo, t), 36);
}

TEST(GltfFeaturesRender, RotationAndScaleTurnTheCheckerAsTheCpuMatrix) {
    TextureTransform const t{{0.1f, 0.2f}, 0.5f, {1.5f, 0.75f}, 0};
    json const ext = {{"offset", {0.1, 0.2}}, {"rotation", 0.5}, {"scale", {1.5, 0.75}}};
    auto const albedo =
        renderAlbedo("rotation", {{"index", 0}, {"extensions", {{"KHR_texture_transform", ext}}}}, false);
    ASSERT_TRUE(albedo);
    EXPECT_GE(expectTexels(*albedo, t), 20);
}

TEST(GltfFeaturesRender, TexCoord1IsUsedWhenTheTextureAsksForIt) {
    // TEXCOORD_0 is one point of the red texel: only TEXCOORD_1 can show the checker.
    auto const first = renderAlbedo("uv0", {{"index", 0}}, true);
    ASSERT_TRUE(first);
    EXPECT_NEAR(first->at(48, 48, 1), 0.0f, 0.1f) << "TEXCOORD_0 reads red everywhere";
    auto const second = renderAlbedo("uv1", {{"index", 0}, {"texCoord", 1}}, true);
    ASSERT_TRUE(second);
    EXPECT_GE(expectTexels(*second, {}), 36);
    // The transform's texCoord overrides the textureInfo's.
    auto const overridden =
        renderAlbedo("uv1_ext", {{"index", 0}, {"extensions", {{"KHR_texture_transform", {{"texCoord", 1}}}}}}, true);
    ASSERT_TRUE(overridden);
    EXPECT_GE(expectTexels(*overridden, {}), 36);
}

TEST(GltfFeaturesRender, CameraOutOfRangeIsRefused) {
    fs::path const box = fs::path(test::dataDir()) / "gltf" / "triangle.gltf";
    test::expectRefused({"render", "--scene", box.string(), "--camera", "0", "--out",
                         test::freshTempDir("gltf_features_camera"), "--size", "32x32"},
                        "--camera 0 does not exist: the scene has 0 cameras");
}
