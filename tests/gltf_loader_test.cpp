// glTF loader on the CPU: the shared sample models, handcrafted bad files, mappings, progress.
#include "core/light_math.h"
#include "gltf/geometry.h"
#include "gltf/loader.h"
#include "gltf/mapping.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <thread>

using namespace gbl;
namespace fs = std::filesystem;

namespace {

fs::path localFile(std::string const& name) {
    return fs::path(test::dataDir()) / "gltf" / name;
}

fs::path sharedModel(std::string const& relative) {
    return fs::path(test::sharedGltfDir()) / relative;
}

#define SKIP_WITHOUT_SHARED_MODELS()                                                    \
    do {                                                                                \
        if (!fs::is_directory(test::sharedGltfDir()))                                   \
            GTEST_SKIP() << "shared glTF models not found at " << test::sharedGltfDir() \
                         << " (see ../shared/gltf/README.md)";                          \
    } while (0)

SceneData loadOk(fs::path const& file, GltfLoadOptions const& options = {}) {
    GltfLoadResult r = loadGltf(file, options);
    EXPECT_TRUE(r.scene.has_value()) << r.error;
    EXPECT_TRUE(r.error.empty()) << r.error;
    return r.scene ? std::move(*r.scene) : SceneData{};
}

// A failed load: no scene, one sentence naming the file and containing `cause`.
void expectRefused(GltfLoadResult const& r, std::string const& fileName, std::string const& cause) {
    EXPECT_FALSE(r.scene.has_value());
    EXPECT_FALSE(r.cancelled);
    EXPECT_NE(r.error.find(fileName), std::string::npos) << r.error;
    EXPECT_NE(r.error.find(cause), std::string::npos) << r.error;
    EXPECT_EQ(r.error.find('\n'), std::string::npos) << r.error;
    ASSERT_FALSE(r.error.empty());
    EXPECT_EQ(r.error.back(), '.') << r.error;
}

void expectRefused(fs::path const& file, std::string const& cause, GltfLoadOptions const& options = {}) {
    expectRefused(loadGltf(file, options), file.filename().string(), cause);
}

std::vector<std::uint8_t> bytesOf(std::string const& s) {
    return {s.begin(), s.end()};
}

std::vector<std::uint8_t> readFile(fs::path const& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

bool hasWarning(SceneData const& s, std::string const& text) {
    return std::any_of(s.warnings.begin(), s.warnings.end(),
                       [&](std::string const& w) { return w.find(text) != std::string::npos; });
}

// Checks every invariant the renderer relies on when it uploads a scene.
void expectWellFormed(SceneData const& s) {
    EXPECT_FALSE(s.meshes.empty());
    EXPECT_FALSE(s.instances.empty());
    EXPECT_GT(s.triangleCount(), 0u);
    for (auto const& m : s.meshes) {
        EXPECT_EQ(m.indices.size() % 3, 0u) << m.name;
        for (auto i : m.indices) ASSERT_LT(i, m.vertices.size()) << m.name;
        EXPECT_TRUE(m.material == -1 || (m.material >= 0 && std::size_t(m.material) < s.materials.size()));
        for (auto const& v : m.vertices) {
            ASSERT_NEAR(glm::length(v.normal), 1.0f, 1e-3f) << m.name;
            ASSERT_TRUE(std::isfinite(v.position.x) && std::isfinite(v.position.y) && std::isfinite(v.position.z));
        }
    }
    for (auto const& inst : s.instances) EXPECT_LT(std::size_t(inst.mesh), s.meshes.size());
    for (auto const& img : s.images) {
        EXPECT_GT(img.width, 0);
        EXPECT_GT(img.height, 0);
        EXPECT_EQ(img.pixels.size(), std::size_t(img.width) * img.height * img.channels) << img.name;
    }
    for (auto const& mat : s.materials)
        for (int t : {mat.baseColorTexture, mat.normalTexture, mat.specularTexture})
            EXPECT_TRUE(t == -1 || (t >= 0 && std::size_t(t) < s.images.size())) << mat.name;
    EXPECT_FALSE(s.lights.empty());
    for (auto const& l : s.lights) EXPECT_FALSE(validateLight(l).has_value()) << l.name;
    EXPECT_TRUE(s.camera.has_value());
}

// Every corner of the bounds projects inside the camera's view (aspect 1).
void expectFramed(SceneData const& s) {
    ASSERT_TRUE(s.camera.has_value());
    Bounds const b = s.bounds();
    glm::mat4 const vp = s.camera->projection(1.0f) * s.camera->view();
    for (int i = 0; i < 8; ++i) {
        glm::vec3 const p((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z);
        glm::vec4 const c = vp * glm::vec4(p, 1.0f);
        ASSERT_GT(c.w, 0.0f);
        glm::vec3 const ndc = glm::vec3(c) / c.w;
        EXPECT_LE(std::abs(ndc.x), 1.0f);
        EXPECT_LE(std::abs(ndc.y), 1.0f);
        EXPECT_LE(std::abs(ndc.z), 1.0f);
    }
}

}  // namespace

// --- the shared sample models -------------------------------------------------------------------

TEST(GltfSharedModels, EveryModelLoads) {
    SKIP_WITHOUT_SHARED_MODELS();
    std::vector<fs::path> files;
    for (auto const& dir : fs::directory_iterator(test::sharedGltfDir())) {
        if (!dir.is_directory()) continue;
        for (auto const& f : fs::directory_iterator(dir.path()))
            if (f.path().extension() == ".gltf" || f.path().extension() == ".glb") files.push_back(f.path());
    }
    ASSERT_GE(files.size(), 8u) << "expected the eight models of the README and their .glb variants";
    for (auto const& f : files) {
        SCOPED_TRACE(f.string());
        SceneData const s = loadOk(f);
        expectWellFormed(s);
        expectFramed(s);
        for (auto const& w : s.warnings) EXPECT_EQ(w.find("placeholder"), std::string::npos) << w;
    }
}

TEST(GltfSharedModels, BoxFaceNormalsAreAxisAlignedUnitVectors) {
    SKIP_WITHOUT_SHARED_MODELS();
    SceneData const s = loadOk(sharedModel("Box/Box.gltf"));
    ASSERT_EQ(s.instances.size(), 1u);
    EXPECT_EQ(s.triangleCount(), 12u);
    // Box's node matrix rotates by -90 degrees about X; world normals stay axis-aligned.
    glm::mat3 const normalMatrix = glm::transpose(glm::inverse(glm::mat3(s.instances[0].model)));
    std::set<std::tuple<int, int, int>> directions;
    for (auto const& v : s.meshes[std::size_t(s.instances[0].mesh)].vertices) {
        for (glm::vec3 n : {v.normal, glm::normalize(normalMatrix * v.normal)}) {
            EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
            int axes = 0;
            for (int i = 0; i < 3; ++i) axes += std::abs(std::abs(n[i]) - 1.0f) < 1e-5f;
            EXPECT_EQ(axes, 1) << n.x << " " << n.y << " " << n.z;
        }
        glm::vec3 const n = v.normal;
        directions.insert({int(std::lround(n.x)), int(std::lround(n.y)), int(std::lround(n.z))});
    }
    EXPECT_EQ(directions.size(), 6u) << "a box has six face directions";
}

TEST(GltfSharedModels, BoxTexturedHasItsBaseColourTexture) {
    SKIP_WITHOUT_SHARED_MODELS();
    SceneData const s = loadOk(sharedModel("BoxTextured/BoxTextured.gltf"));
    ASSERT_EQ(s.materials.size(), 1u);
    int const tex = s.materials[0].baseColorTexture;
    ASSERT_GE(tex, 0);
    ImageData const& img = s.images[std::size_t(tex)];
    EXPECT_TRUE(img.srgb);
    EXPECT_GT(img.width, 8) << "a real texture, not the 8x8 placeholder";
    EXPECT_GT(img.height, 8);
    // The Cesium logo has both light and dark texels: check the value range, not a snapshot.
    auto const [lo, hi] = std::minmax_element(img.pixels.begin(), img.pixels.end());
    EXPECT_LT(*lo, 64);
    EXPECT_GT(*hi, 192);
    EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
}

TEST(GltfSharedModels, NormalTangentTestHasNormalMapsAndTangents) {
    SKIP_WITHOUT_SHARED_MODELS();
    SceneData const s = loadOk(sharedModel("NormalTangentTest/NormalTangentTest.gltf"));
    int normalMapped = 0;
    for (auto const& m : s.meshes) {
        if (m.material < 0 || s.materials[std::size_t(m.material)].normalTexture < 0) continue;
        ++normalMapped;
        EXPECT_FALSE(s.images[std::size_t(s.materials[std::size_t(m.material)].normalTexture)].srgb);
        for (auto const& v : m.vertices) {
            glm::vec3 const t(v.tangent);
            ASSERT_NEAR(glm::length(t), 1.0f, 1e-3f);
            ASSERT_NEAR(glm::dot(t, v.normal), 0.0f, 0.05f);
            ASSERT_EQ(std::abs(v.tangent.w), 1.0f);
        }
    }
    EXPECT_GT(normalMapped, 0);
}

// Generated tangents must have the handedness of the TANGENT data artists' tools write, since
// the shader treats both alike: regenerate them for normal-mapped models that carry their own
// and compare. A flipped w would turn every bump of NormalTangentTest into a mirrored one.
TEST(GltfSharedModels, GeneratedTangentsMatchTheFilesOwn) {
    SKIP_WITHOUT_SHARED_MODELS();
    for (char const* model : {"WaterBottle/WaterBottle.gltf", "Avocado/Avocado.gltf"}) {
        SCOPED_TRACE(model);
        SceneData const s = loadOk(sharedModel(model));
        std::size_t compared = 0, sameHand = 0, sameDirection = 0;
        for (auto const& m : s.meshes) {
            if (m.material < 0 || s.materials[std::size_t(m.material)].normalTexture < 0) continue;
            MeshData generated = m;
            generateTangents(generated);
            for (std::size_t i = 0; i < m.vertices.size(); ++i) {
                glm::vec4 const a = m.vertices[i].tangent, b = generated.vertices[i].tangent;
                ++compared;
                sameHand += a.w == b.w;
                sameDirection += glm::dot(glm::vec3(a), glm::vec3(b)) > 0.7f;  // within about 45 degrees
            }
        }
        ASSERT_GT(compared, 100u);
        // Mirrored UV islands and seams make a few vertices ambiguous; a wrong convention makes
        // nearly all disagree, so 90% separates the two cases with room to spare.
        EXPECT_GT(double(sameHand), 0.9 * double(compared));
        EXPECT_GT(double(sameDirection), 0.9 * double(compared));
    }
}

TEST(GltfSharedModels, AvocadoTinyScaleIsFramedAndLitAtItsScale) {
    SKIP_WITHOUT_SHARED_MODELS();
    SceneData const s = loadOk(sharedModel("Avocado/Avocado.gltf"));
    float const r = s.bounds().radius();
    EXPECT_GT(r, 0.01f);
    EXPECT_LT(r, 0.1f);  // about 6 cm across
    ASSERT_TRUE(s.camera);
    EXPECT_LT(glm::distance(s.camera->position, s.bounds().center()), 10.0f * r);
    EXPECT_LT(s.camera->nearPlane, 0.1f * r);
    expectFramed(s);
    for (auto const& l : s.lights) EXPECT_LT(lightRadius(l).radius, 10.0f * r) << l.name;
    // Its metallic-roughness texture is baked into a single-channel specular image.
    ASSERT_FALSE(s.materials.empty());
    int const spec = s.materials[0].specularTexture;
    ASSERT_GE(spec, 0);
    EXPECT_EQ(s.images[std::size_t(spec)].channels, 1);
    EXPECT_FALSE(s.images[std::size_t(spec)].srgb);
}

TEST(GltfSharedModels, GlbVariantsMatchTheirGltf) {
    SKIP_WITHOUT_SHARED_MODELS();
    for (char const* name : {"Box", "BoxTextured", "Duck"}) {
        SCOPED_TRACE(name);
        fs::path const glb = sharedModel(std::string("glb/") + name + ".glb");
        if (!fs::exists(glb)) GTEST_SKIP() << "missing " << glb;
        SceneData const a = loadOk(glb);
        SceneData const b = loadOk(sharedModel(std::string(name) + "/" + name + ".gltf"));
        EXPECT_EQ(a.triangleCount(), b.triangleCount());
        EXPECT_EQ(a.images.size(), b.images.size());
        EXPECT_NEAR(glm::distance(a.bounds().min, b.bounds().min), 0.0f, 1e-4f);
    }
}

// --- handcrafted files that load ----------------------------------------------------------------

TEST(GltfLoader, TriangleWithoutNormalsGetsFlatNormalsAndGeneratedLights) {
    SceneData const s = loadOk(localFile("triangle.gltf"));
    expectWellFormed(s);
    ASSERT_EQ(s.meshes.size(), 1u);
    for (auto const& v : s.meshes[0].vertices) EXPECT_EQ(v.normal, glm::vec3(0, 0, 1));
    // Deterministic: the same file gives the same lights.
    SceneData const again = loadOk(localFile("triangle.gltf"));
    ASSERT_EQ(s.lights.size(), again.lights.size());
    for (std::size_t i = 0; i < s.lights.size(); ++i) EXPECT_EQ(s.lights[i].position, again.lights[i].position);
    // The key lights reach across the whole scene.
    EXPECT_GT(lightRadius(s.lights[0]).radius, 2.0f * s.bounds().radius());
}

TEST(GltfLoader, BinaryAndExternalBuffersGiveTheSameTriangle) {
    SceneData const a = loadOk(localFile("triangle.glb"));
    SceneData const b = loadOk(localFile("triangle_external.gltf"));
    ASSERT_EQ(a.meshes.size(), 1u);
    ASSERT_EQ(b.meshes.size(), 1u);
    ASSERT_EQ(a.meshes[0].vertices.size(), b.meshes[0].vertices.size());
    for (std::size_t i = 0; i < a.meshes[0].vertices.size(); ++i)
        EXPECT_EQ(a.meshes[0].vertices[i].position, b.meshes[0].vertices[i].position);
}

TEST(GltfLoader, IndexTypesNonIndexedAndTransformsHierarchy) {
    SceneData const s = loadOk(localFile("variety.gltf"));
    // u16, u8, u32 and non-indexed triangles load; the points primitive is skipped with a warning.
    EXPECT_EQ(s.meshes.size(), 4u);
    EXPECT_EQ(s.instances.size(), 4u);
    EXPECT_TRUE(hasWarning(s, "points")) << (s.warnings.empty() ? "" : s.warnings.front());
    // Parent: T(10,0,0) R(90 deg about Z) S(2); child: matrix translating (0,0,5).
    // Vertex (1,0,0) -> (1,0,5) -> scaled (2,0,10) -> rotated (0,2,10) -> translated (10,2,10).
    glm::vec3 const p = glm::vec3(s.instances[0].model * glm::vec4(1, 0, 0, 1));
    EXPECT_NEAR(p.x, 10.0f, 1e-5f);
    EXPECT_NEAR(p.y, 2.0f, 1e-5f);
    EXPECT_NEAR(p.z, 10.0f, 1e-5f);
}

TEST(GltfLoader, EmbeddedTexturesDecodeExactlyAndNormalMapsGetTangents) {
    SceneData const s = loadOk(localFile("embedded_texture.gltf"));
    ASSERT_EQ(s.materials.size(), 1u);
    Material const& m = s.materials[0];
    ASSERT_GE(m.baseColorTexture, 0);
    ImageData const& base = s.images[std::size_t(m.baseColorTexture)];
    EXPECT_TRUE(base.srgb);
    ASSERT_EQ(base.width, 2);
    ASSERT_EQ(base.channels, 4);
    // Straight alpha, exactly as written: red, green / blue, white at alpha 128 (not premultiplied).
    std::vector<std::uint8_t> const expected = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 128};
    EXPECT_EQ(base.pixels, expected);
    ASSERT_GE(m.normalTexture, 0);
    EXPECT_FALSE(s.images[std::size_t(m.normalTexture)].srgb);
    EXPECT_FLOAT_EQ(m.normalScale, 0.5f);
    // metallic 0, roughness 0.5: (1 - 0.5)^2 * 0.5
    EXPECT_FLOAT_EQ(m.specularFactor, 0.125f);
    // UVs (0,1) (1,1) (0,0) on (0,0,0) (1,0,0) (0,1,0): u grows along +X, v along -Y.
    // tangent = dP/du = +X; the bitangent must point up the image (+Y, against dP/dv, where
    // the normal map's green points) and cross(N, T) = +Y already does, so w = +1.
    for (auto const& v : s.meshes[0].vertices) {
        EXPECT_NEAR(glm::distance(glm::vec3(v.tangent), glm::vec3(1, 0, 0)), 0.0f, 1e-5f);
        EXPECT_EQ(v.tangent.w, 1.0f);
    }
}

TEST(GltfLoader, PunctualLightsMapRangeAndIntensity) {
    SceneData const s = loadOk(localFile("lights.gltf"));
    ASSERT_EQ(s.lights.size(), 3u) << "two point lights and a directional one";
    PointLight const& ranged = s.lights[0];
    EXPECT_EQ(ranged.name, "ranged");
    EXPECT_EQ(ranged.position, glm::vec3(1, 2, 3));
    EXPECT_EQ(ranged.color, glm::vec3(1.0f, 0.5f, 0.25f));
    EXPECT_NEAR(ranged.intensity, 10.0f, 1e-4f);  // 31.4159 cd / pi
    EXPECT_NEAR(lightRadius(ranged).radius, 5.0f, 1e-3f);
    PointLight const& unranged = s.lights[1];
    EXPECT_NEAR(unranged.intensity, 1.0f, 1e-5f);
    EXPECT_EQ(unranged.kc, 1.0f);
    EXPECT_EQ(unranged.kl, 0.0f);
    EXPECT_EQ(unranged.kq, 1.0f);
    // Inverse square: Imax / (1 + d^2) = 5/256 at d = sqrt(51.2 - 1).
    EXPECT_NEAR(lightRadius(unranged).radius, std::sqrt(51.2f - 1.0f), 1e-3f);
    EXPECT_EQ(unranged.kind, LightKind::Point);
    // Directional: 2 lux / pi, along its (identity) node's -Z; no radius of its own.
    PointLight const& sun = s.lights[2];
    EXPECT_EQ(sun.kind, LightKind::Directional);
    EXPECT_NEAR(sun.intensity, 2.0f / 3.14159265f, 1e-5f);
    EXPECT_NEAR(glm::distance(sun.direction, glm::vec3(0, 0, -1)), 0.0f, 1e-6f);
    // KHR_materials_specular 0.5 on a smooth dielectric halves our default 0.5.
    ASSERT_EQ(s.materials.size(), 1u);
    EXPECT_FLOAT_EQ(s.materials[0].specularFactor, 0.25f);
}

TEST(GltfMapping, SpecularFromMetallicRoughness) {
    EXPECT_FLOAT_EQ(specularFromMetallicRoughness(0.0f, 0.0f), 0.5f);  // smooth dielectric: our default
    EXPECT_FLOAT_EQ(specularFromMetallicRoughness(1.0f, 0.0f), 1.0f);  // smooth metal
    EXPECT_FLOAT_EQ(specularFromMetallicRoughness(0.0f, 1.0f), 0.0f);  // fully rough
    EXPECT_FLOAT_EQ(specularFromMetallicRoughness(0.5f, 0.5f), 0.25f * 0.75f);
    EXPECT_FLOAT_EQ(specularFromMetallicRoughness(0.0f, 0.0f, 0.0f), 0.0f);
    EXPECT_FLOAT_EQ(specularFromMetallicRoughness(0.0f, 0.0f, 4.0f), 1.0f);  // clamped
}

TEST(GltfMapping, RadiusOfALightMadeForARadius) {
    for (float radius : {0.05f, 1.0f, 5.0f, 300.0f}) {
        PointLight const l = pointLightWithRadius({}, glm::vec3(1.0f, 0.2f, 0.2f), 2.0f, radius, "r");
        EXPECT_NEAR(lightRadius(l).radius, radius, radius * 1e-4f);
    }
}

// --- bad input: one test per class ---------------------------------------------------------------

TEST(GltfBadInput, MissingFile) {
    expectRefused(localFile("no_such_scene.gltf"), "does not exist");
}

TEST(GltfBadInput, NotGltf) {
    expectRefused(localFile("not_gltf.gltf"), "not a glTF file");
}

TEST(GltfBadInput, MalformedJson) {
    expectRefused(localFile("malformed.gltf"), "malformed (at line 3");
}

// A number beyond double's range: malformed JSON, said as such (was "unexpected failure").
TEST(GltfBadInput, NumberTooLargeForADouble) {
    std::string const text = R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": []}], "x": 1e400})";
    expectRefused(loadGltfFromMemory(bytesOf(text), "/nonexistent/huge.gltf"), "huge.gltf", "malformed");
}

TEST(GltfBadInput, WrongJsonTypes) {
    expectRefused(localFile("wrong_types.gltf"), "nodes[0].mesh must be a non-negative integer but is string");
}

TEST(GltfBadInput, MissingBuffer) {
    expectRefused(localFile("missing_buffer.gltf"), "'does_not_exist.bin', which does not exist");
}

TEST(GltfBadInput, ShortBuffer) {
    expectRefused(localFile("short_buffer.gltf"), "holds 8 bytes but its byteLength is 44 (short buffer)");
    // The same in an embedded buffer: 44 bytes of data declared as 100.
    std::vector<std::uint8_t> const original = readFile(localFile("triangle.gltf"));
    std::string json(original.begin(), original.end());
    auto const at = json.find("\"byteLength\": 44");
    ASSERT_NE(at, std::string::npos);
    json.replace(at, 16, "\"byteLength\": 100");
    expectRefused(loadGltfFromMemory(bytesOf(json), localFile("short_embedded.gltf")), "short_embedded.gltf",
                  "short buffer");
}

TEST(GltfBadInput, AccessorOutOfRange) {
    expectRefused(localFile("accessor_out_of_range.gltf"),
                  "accessor 1 reads bytes up to 360 but buffer view 1 holds only 36");
}

TEST(GltfBadInput, IndexOutOfRange) {
    expectRefused(localFile("index_out_of_range.gltf"), "has index 7 at position 2, but only 3 vertices");
}

TEST(GltfBadInput, RecursiveNodeGraph) {
    expectRefused(localFile("cycle.gltf"), "the node graph is recursive");
}

TEST(GltfBadInput, NanAndInfinitePositions) {
    expectRefused(localFile("nan_position.gltf"), "NaN or infinite position at vertex 1");
    expectRefused(localFile("inf_position.gltf"), "NaN or infinite position at vertex 1");
}

TEST(GltfBadInput, MissingTextureLoadsWithPlaceholderAndWarning) {
    SceneData const s = loadOk(localFile("missing_texture.gltf"));
    EXPECT_TRUE(hasWarning(s, "no_such_texture.png")) << (s.warnings.empty() ? "no warnings" : s.warnings.front());
    ASSERT_EQ(s.materials.size(), 1u);
    ImageData const& img = s.images[std::size_t(s.materials[0].baseColorTexture)];
    EXPECT_EQ(img.width, 8);
    EXPECT_EQ(img.pixels[0], 255);  // magenta corner
    EXPECT_EQ(img.pixels[1], 0);
    EXPECT_EQ(img.pixels[2], 255);
    // A texture whose bytes are not an image is handled the same way.
    SceneData const c = loadOk(localFile("corrupt_texture.gltf"));
    EXPECT_TRUE(hasWarning(c, "placeholder"));
}

TEST(GltfBadInput, UriOutsideTheScenesFolderIsRefusedUnlessAllowed) {
    fs::path const file = localFile("outside/outside_uri.gltf");
    expectRefused(file, "'../triangle.bin' leaves the scene's folder, which is refused");
    GltfLoadOptions allow;
    allow.allowOutsideUris = true;
    SceneData const s = loadOk(file, allow);
    EXPECT_EQ(s.triangleCount(), 1u);
    // Absolute paths and schemes are refused the same way; nothing is read from them.
    std::vector<std::uint8_t> const original = readFile(localFile("triangle_external.gltf"));
    std::string json(original.begin(), original.end());
    json.replace(json.find("triangle.bin"), 12, "/etc/passwd");
    expectRefused(loadGltfFromMemory(bytesOf(json), localFile("absolute.gltf")), "absolute.gltf",
                  "leaves the scene's folder");
}

TEST(GltfBadInput, AbsurdCountsAndSizes) {
    expectRefused(localFile("absurd_count.gltf"), "4000000000 elements, more than the limit of");
    GltfLoadOptions tiny;
    tiny.maxNodes = 3;
    expectRefused(localFile("lights.gltf"), "4 nodes, more than the limit of 3", tiny);
    tiny = {};
    tiny.maxTriangles = 0;
    expectRefused(localFile("triangle.gltf"), "more than the limit of 0 triangles", tiny);
    tiny = {};
    tiny.maxImagePixels = 3;
    expectRefused(localFile("embedded_texture.gltf"), "2 x 2 pixels, more than the limit of 3 pixels", tiny);
    tiny = {};
    tiny.maxFileBytes = 100;
    expectRefused(localFile("triangle.gltf"), "more than the limit of 100 bytes", tiny);
    std::string deep = "{\"asset\":{\"version\":\"2.0\"},\"extras\":";
    for (int i = 0; i < 1000; ++i) deep += '[';
    for (int i = 0; i < 1000; ++i) deep += ']';
    deep += '}';
    expectRefused(loadGltfFromMemory(bytesOf(deep), localFile("deep.gltf")), "deep.gltf",
                  "deeper than the limit of 64");
}

TEST(GltfBadInput, TruncatedBinaryAndUnsupportedVersions) {
    std::vector<std::uint8_t> glb = readFile(localFile("triangle.glb"));
    ASSERT_GT(glb.size(), 100u);
    glb.resize(100);
    expectRefused(loadGltfFromMemory(glb, localFile("cut.glb")), "cut.glb", "truncated");
    expectRefused(loadGltfFromMemory(bytesOf(R"({"asset":{"version":"1.0"}})"), localFile("old.gltf")), "old.gltf",
                  "only glTF 2.0 is supported");
    // Required Draco is refused only by builds without the decoder (gltf_features_test covers both).
    if (!gltfDecodesDraco())
        expectRefused(loadGltfFromMemory(
                          bytesOf(R"({"asset":{"version":"2.0"},"extensionsRequired":["KHR_draco_mesh_compression"]})"),
                          localFile("draco.gltf")),
                      "draco.gltf", "libdraco-dev");
    expectRefused(
        loadGltfFromMemory(bytesOf(R"({"asset":{"version":"2.0"},"extensionsRequired":["EXT_meshopt_compression"]})"),
                           localFile("meshopt.gltf")),
        "meshopt.gltf", "EXT_meshopt_compression");
    expectRefused(loadGltfFromMemory({}, localFile("empty.gltf")), "empty.gltf", "empty");
}

// --- progress, cancellation, threads -------------------------------------------------------------

TEST(GltfProgress, ReportsMonotonicProgressEndingAtOne) {
    std::vector<std::pair<float, std::string>> calls;
    GltfLoadOptions options;
    options.progress = [&](float f, std::string_view stage) {
        calls.emplace_back(f, std::string(stage));
        return true;
    };
    loadOk(localFile("embedded_texture.gltf"), options);
    ASSERT_GE(calls.size(), 4u);
    for (std::size_t i = 1; i < calls.size(); ++i) EXPECT_GE(calls[i].first, calls[i - 1].first);
    EXPECT_EQ(calls.front().first, 0.0f);
    EXPECT_EQ(calls.back().first, 1.0f);
    EXPECT_TRUE(std::any_of(calls.begin(), calls.end(), [](auto const& c) { return c.second == "decoding images"; }));
}

TEST(GltfProgress, CancellingStopsTheLoadWithNoScene) {
    for (int stopAt = 1; stopAt <= 4; ++stopAt) {
        int calls = 0;
        GltfLoadOptions options;
        options.progress = [&](float, std::string_view) { return ++calls < stopAt; };
        GltfLoadResult const r = loadGltf(localFile("embedded_texture.gltf"), options);
        EXPECT_TRUE(r.cancelled) << stopAt;
        EXPECT_FALSE(r.scene.has_value());
        EXPECT_EQ(calls, stopAt) << "no progress after cancelling";
        EXPECT_NE(r.error.find("cancelled"), std::string::npos);
    }
}

TEST(GltfProgress, LoadsOnWorkerThreadsAtTheSameTime) {
    GltfLoadResult a, b;
    std::thread ta([&] { a = loadGltf(localFile("embedded_texture.gltf")); });
    std::thread tb([&] { b = loadGltf(localFile("variety.gltf")); });
    ta.join();
    tb.join();
    EXPECT_TRUE(a.scene.has_value()) << a.error;
    EXPECT_TRUE(b.scene.has_value()) << b.error;
}
