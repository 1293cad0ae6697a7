// glTF files as they come, on the CPU: strips and fans, Draco, texture transforms, TEXCOORD_1 and cameras.
#include "core/light_math.h"
#include "gltf/geometry.h"
#include "gltf/loader.h"
#include "gltf/mapping.h"
#include "handmade_gltf.h"
#include "scene/texture_transform.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#if GBL_TEST_DRACO
#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>

using namespace gbl;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

SceneData loadOk(std::vector<std::uint8_t> const& bytes, std::string const& name) {
    GltfLoadResult r = loadGltfFromMemory(bytes, fs::path(test::dataDir()) / "gltf" / name);
    EXPECT_TRUE(r.scene.has_value()) << r.error;
    return r.scene ? std::move(*r.scene) : SceneData{};
}

bool hasWarning(SceneData const& s, std::string const& text) {
    return std::any_of(s.warnings.begin(), s.warnings.end(),
                       [&](std::string const& w) { return w.find(text) != std::string::npos; });
}

// A triangle as its corners (position and normal), turned so that its smallest corner comes first:
// the same triangle with the same winding gives the same value whatever vertex it starts at.
using Corner = std::array<float, 6>;
using Triangle = std::array<Corner, 3>;

std::vector<Triangle> trianglesOf(SceneData const& s) {
    std::vector<Triangle> out;
    for (auto const& inst : s.instances) {
        MeshData const& m = s.meshes[std::size_t(inst.mesh)];
        for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3) {
            Triangle tri;
            for (int c = 0; c < 3; ++c) {
                Vertex const& v = m.vertices[m.indices[t + std::size_t(c)]];
                glm::vec3 const p = glm::vec3(inst.model * glm::vec4(v.position, 1.0f));
                tri[std::size_t(c)] = {p.x, p.y, p.z, v.normal.x, v.normal.y, v.normal.z};
            }
            std::rotate(tri.begin(), std::min_element(tri.begin(), tri.end()), tri.end());
            out.push_back(tri);
        }
    }
    std::sort(out.begin(), out.end());
    return out;
}

void expectSameTriangles(std::vector<Triangle> const& a, std::vector<Triangle> const& b, float tolerance = 0.0f) {
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t t = 0; t < a.size(); ++t)
        for (int c = 0; c < 3; ++c)
            for (int k = 0; k < 6; ++k)
                ASSERT_NEAR(a[t][std::size_t(c)][std::size_t(k)], b[t][std::size_t(c)][std::size_t(k)], tolerance)
                    << "triangle " << t << " corner " << c;
}

// z of the triangle's geometric normal (all the test shapes lie in the z = 0 plane).
float windingZ(Triangle const& t) {
    glm::vec3 const a(t[0][0], t[0][1], t[0][2]), b(t[1][0], t[1][1], t[1][2]), c(t[2][0], t[2][1], t[2][2]);
    return glm::cross(b - a, c - a).z;
}

// One primitive of `positions` (normals +Z) drawn in `mode`, with `indices` when not empty.
std::vector<std::uint8_t> primitiveFile(std::vector<glm::vec2> const& positions, int mode,
                                        std::vector<std::uint32_t> const& indices = {}) {
    test::HandmadeGltf g;
    std::vector<float> pos, nrm;
    for (glm::vec2 p : positions) pos.insert(pos.end(), {p.x, p.y, 0.0f}), nrm.insert(nrm.end(), {0.0f, 0.0f, 1.0f});
    json prim = {{"attributes", {{"POSITION", g.floats(pos, "VEC3")}, {"NORMAL", g.floats(nrm, "VEC3")}}},
                 {"mode", mode}};
    if (!indices.empty()) prim["indices"] = g.indices(indices);
    g.meshNode(json::array({prim}));
    return g.bytes();
}

}  // namespace

// --- triangle strips and fans --------------------------------------------------------------------

TEST(GltfTriangleModes, StripAndFanOrderFollowsTheSpecification) {
    // Strip triangle i = (v[i], v[i+1+i%2], v[i+2-i%2]); fan triangle i = (v[i+1], v[i+2], v[0]).
    EXPECT_EQ(triangleList(TriangleMode::Strip, {0, 1, 2, 3, 4}),
              (std::vector<std::uint32_t>{0, 1, 2, 1, 3, 2, 2, 3, 4}));
    EXPECT_EQ(triangleList(TriangleMode::Fan, {0, 1, 2, 3}), (std::vector<std::uint32_t>{1, 2, 0, 2, 3, 0}));
    // A repeated index stitches two strips: the zero-area triangles it makes are dropped.
    EXPECT_EQ(triangleList(TriangleMode::Strip, {0, 1, 2, 2, 3, 4}), (std::vector<std::uint32_t>{0, 1, 2, 2, 4, 3}));
    EXPECT_EQ(triangleList(TriangleMode::List, {0, 1, 2, 3}), (std::vector<std::uint32_t>{0, 1, 2}));
    EXPECT_TRUE(triangleList(TriangleMode::Strip, {0, 1}).empty());
    EXPECT_TRUE(triangleList(TriangleMode::Fan, {}).empty());
}

TEST(GltfTriangleModes, AStripGivesTheTrianglesOfTheEquivalentList) {
    // A zigzag of five vertices: three triangles, all counter-clockwise seen from -Z.
    std::vector<glm::vec2> const zigzag = {{0, 0}, {0, 1}, {1, 0}, {1, 1}, {2, 0}};
    SceneData const list = loadOk(primitiveFile(zigzag, 4, {0, 1, 2, 1, 3, 2, 2, 3, 4}), "list.gltf");
    SceneData const plain = loadOk(primitiveFile(zigzag, 5), "strip.gltf");
    // The same strip through indices into shuffled vertices.
    std::vector<glm::vec2> const shuffled = {zigzag[3], zigzag[0], zigzag[4], zigzag[2], zigzag[1]};
    SceneData const indexed = loadOk(primitiveFile(shuffled, 5, {1, 4, 3, 0, 2}), "strip_indexed.gltf");

    auto const expected = trianglesOf(list);
    ASSERT_EQ(expected.size(), 3u);
    expectSameTriangles(trianglesOf(plain), expected);
    expectSameTriangles(trianglesOf(indexed), expected);
    // Every triangle keeps the first one's winding (odd triangles swap two vertices).
    for (auto const& t : trianglesOf(plain)) EXPECT_LT(windingZ(t), 0.0f);
    EXPECT_FALSE(hasWarning(plain, "skipped"));
}

TEST(GltfTriangleModes, AFanGivesTheTrianglesOfTheEquivalentList) {
    // A fan around the origin, counter-clockwise seen from +Z.
    std::vector<glm::vec2> const fan = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {-1, 1}};
    SceneData const list = loadOk(primitiveFile(fan, 4, {0, 1, 2, 0, 2, 3, 0, 3, 4}), "list.gltf");
    SceneData const plain = loadOk(primitiveFile(fan, 6), "fan.gltf");
    std::vector<glm::vec2> const shuffled = {fan[2], fan[4], fan[0], fan[1], fan[3]};
    SceneData const indexed = loadOk(primitiveFile(shuffled, 6, {2, 3, 0, 4, 1}), "fan_indexed.gltf");

    auto const expected = trianglesOf(list);
    ASSERT_EQ(expected.size(), 3u);
    expectSameTriangles(trianglesOf(plain), expected);
    expectSameTriangles(trianglesOf(indexed), expected);
    for (auto const& t : trianglesOf(plain)) EXPECT_GT(windingZ(t), 0.0f);
}

TEST(GltfTriangleModes, PointsAndLinesStaySkippedWithAWarning) {
    test::HandmadeGltf g;
    int const pos = g.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
    g.meshNode(json::array({{{"attributes", {{"POSITION", pos}}}, {"mode", 0}},
                            {{"attributes", {{"POSITION", pos}}}, {"mode", 1}},
                            {{"attributes", {{"POSITION", pos}}}, {"mode", 4}}}));
    SceneData const s = loadOk(g.bytes(), "points.gltf");
    EXPECT_TRUE(hasWarning(s, "primitive 0 draws points"));
    EXPECT_TRUE(hasWarning(s, "primitive 1 draws lines"));
    EXPECT_EQ(s.meshes.size(), 1u) << "only the triangle list is loaded";
}

// --- Draco ---------------------------------------------------------------------------------------

namespace {

// A unit box of 24 vertices (own normals per face) and 12 triangles, as plain arrays.
struct BoxArrays {
    std::vector<float> positions, normals;
    std::vector<std::uint32_t> indices;
};

// The box with its data only in a KHR_draco_mesh_compression buffer view (extension required).
std::vector<std::uint8_t> dracoBoxFile(std::vector<std::uint8_t> const& draco, std::size_t vertices, int positionId,
                                       int normalId, bool binary = false) {
    test::HandmadeGltf g;
    int const view = g.view(draco);
    json prim = {
        {"attributes",
         {{"POSITION", g.placeholder(5126, vertices, "VEC3")}, {"NORMAL", g.placeholder(5126, vertices, "VEC3")}}},
        {"indices", g.placeholder(5125, 36, "SCALAR")},
        {"extensions",
         {{"KHR_draco_mesh_compression",
           {{"bufferView", view}, {"attributes", {{"POSITION", positionId}, {"NORMAL", normalId}}}}}}}};
    g.meshNode(json::array({prim}));
    g.doc["extensionsUsed"] = {"KHR_draco_mesh_compression"};
    g.doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    return binary ? g.glb() : g.bytes();
}

}  // namespace

#if GBL_TEST_DRACO

namespace {

BoxArrays boxArrays() {
    BoxArrays b;
    for (int axis = 0; axis < 3; ++axis)
        for (float sign : {1.0f, -1.0f}) {
            glm::vec3 n(0.0f);
            n[axis] = sign;
            glm::vec3 const u = glm::vec3(n.y, n.z, n.x), v = glm::cross(n, u);  // in the face, v = n x u
            auto const base = std::uint32_t(b.positions.size() / 3);
            for (glm::vec2 c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
                glm::vec3 const p = 0.5f * (n + c.x * u + c.y * v);
                b.positions.insert(b.positions.end(), {p.x, p.y, p.z});
                b.normals.insert(b.normals.end(), {n.x, n.y, n.z});
            }
            b.indices.insert(b.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
        }
    return b;
}

std::vector<std::uint8_t> plainBoxFile(BoxArrays const& b) {
    test::HandmadeGltf g;
    json prim = {{"attributes", {{"POSITION", g.floats(b.positions, "VEC3")}, {"NORMAL", g.floats(b.normals, "VEC3")}}},
                 {"indices", g.indices(b.indices)}};
    g.meshNode(json::array({prim}));
    return g.bytes();
}

}  // namespace

TEST(GltfDraco, ADracoBoxEqualsThePlainBox) {
    ASSERT_TRUE(gltfDecodesDraco()) << "the test found Draco's encoder, so the loader was built with its decoder";
    BoxArrays const box = boxArrays();
    draco::TriangleSoupMeshBuilder builder;
    builder.Start(12);
    int const pos = builder.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
    int const nrm = builder.AddAttribute(draco::GeometryAttribute::NORMAL, 3, draco::DT_FLOAT32);
    for (int f = 0; f < 12; ++f) {
        std::uint32_t const* i = &box.indices[std::size_t(f) * 3];
        builder.SetAttributeValuesForFace(pos, draco::FaceIndex(std::uint32_t(f)), &box.positions[i[0] * 3],
                                          &box.positions[i[1] * 3], &box.positions[i[2] * 3]);
        builder.SetAttributeValuesForFace(nrm, draco::FaceIndex(std::uint32_t(f)), &box.normals[i[0] * 3],
                                          &box.normals[i[1] * 3], &box.normals[i[2] * 3]);
    }
    std::unique_ptr<draco::Mesh> mesh = builder.Finalize();
    ASSERT_TRUE(mesh);
    draco::Encoder encoder;  // no quantisation: floats are stored exactly
    draco::EncoderBuffer encoded;
    ASSERT_TRUE(encoder.EncodeMeshToBuffer(*mesh, &encoded).ok());
    std::vector<std::uint8_t> const bytes(encoded.data(), encoded.data() + encoded.size());
    int const posId = int(mesh->attribute(pos)->unique_id()), nrmId = int(mesh->attribute(nrm)->unique_id());

    SceneData const plain = loadOk(plainBoxFile(box), "box.gltf");
    SceneData const compressed = loadOk(dracoBoxFile(bytes, mesh->num_points(), posId, nrmId), "box_draco.gltf");
    ASSERT_EQ(trianglesOf(plain).size(), 12u);
    // Draco reorders vertices and triangles, never their values or winding.
    expectSameTriangles(trianglesOf(compressed), trianglesOf(plain));
    EXPECT_TRUE(compressed.warnings.empty()) << compressed.warnings.front();
    // The same as .glb (the loader hands tinygltf a rebuilt binary without the Draco index accessor).
    SceneData const glb = loadOk(dracoBoxFile(bytes, mesh->num_points(), posId, nrmId, true), "box_draco.glb");
    expectSameTriangles(trianglesOf(glb), trianglesOf(plain));

    // Damaged Draco data is refused in one sentence.
    std::vector<std::uint8_t> broken = bytes;
    broken.resize(broken.size() / 2);
    GltfLoadResult const r = loadGltfFromMemory(dracoBoxFile(broken, mesh->num_points(), posId, nrmId),
                                                fs::path(test::dataDir()) / "gltf" / "broken_draco.gltf");
    EXPECT_FALSE(r.scene.has_value());
    EXPECT_NE(r.error.find("Draco data cannot be decoded"), std::string::npos) << r.error;
    EXPECT_NE(r.error.find("broken_draco.gltf"), std::string::npos) << r.error;
}

#endif

TEST(GltfDraco, WithoutTheDecoderDracoFilesAreRefusedNamingTheLibrary) {
    if (gltfDecodesDraco()) GTEST_SKIP() << "this build decodes Draco (GltfDraco.ADracoBoxEqualsThePlainBox covers it)";
    GltfLoadResult const r =
        loadGltfFromMemory(dracoBoxFile({1, 2, 3, 4}, 24, 0, 1), fs::path(test::dataDir()) / "gltf" / "draco.gltf");
    EXPECT_FALSE(r.scene.has_value());
    EXPECT_NE(r.error.find("KHR_draco_mesh_compression"), std::string::npos) << r.error;
    EXPECT_NE(r.error.find("libdraco-dev"), std::string::npos) << r.error;
    EXPECT_EQ(r.error.find('\n'), std::string::npos) << r.error;
}

// --- texture transforms and TEXCOORD_1 -----------------------------------------------------------

TEST(GltfTextureTransform, MatrixIsTranslationRotationScaleAsTheExtensionDefines) {
    // The extension's example: offset (0, 1), rotation pi/2, scale 0.5 shows the image's
    // lower-left quadrant (v grows downwards), turned.
    TextureTransform t{{0.0f, 1.0f}, 1.5707963f, {0.5f, 0.5f}, 0};
    auto near = [](glm::vec2 a, glm::vec2 b) { return glm::length(a - b) < 1e-6f; };
    EXPECT_TRUE(near(applyTextureTransform(t, {0, 0}), {0.0f, 1.0f}));
    EXPECT_TRUE(near(applyTextureTransform(t, {1, 0}), {0.0f, 0.5f}));
    EXPECT_TRUE(near(applyTextureTransform(t, {0, 1}), {0.5f, 1.0f}));
    EXPECT_TRUE(near(applyTextureTransform(t, {1, 1}), {0.5f, 0.5f}));
    // Scale happens first, then rotation, then the offset.
    TextureTransform const s{{0.25f, 0.0f}, 0.0f, {2.0f, 3.0f}, 0};
    EXPECT_TRUE(near(applyTextureTransform(s, {0.5f, 0.5f}), {1.25f, 1.5f}));
    EXPECT_TRUE(TextureTransform{}.isIdentity());
    EXPECT_EQ(textureTransformMatrix(TextureTransform{}), glm::mat3(1.0f));
}

namespace {

// A quad whose base colour and normal textures carry `baseColorInfo` / `normalInfo` (textureInfo objects).
// The image is a 2x2 PNG (the one of tests/data/gltf/embedded_texture.gltf).
std::vector<std::uint8_t> texturedQuad(json const& baseColorInfo, json const& normalInfo, bool withUv1) {
    test::HandmadeGltf g;
    json attrs = {{"POSITION", g.floats({0, 0, 0, 1, 0, 0, 1, 1, 0}, "VEC3")},
                  {"NORMAL", g.floats({0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3")},
                  {"TEXCOORD_0", g.floats({0, 0, 1, 0, 1, 1}, "VEC2")}};
    if (withUv1) attrs["TEXCOORD_1"] = g.floats({0.5f, 0.25f, 0.75f, 0.25f, 0.75f, 0.5f}, "VEC2");
    g.doc["images"] = {{{"uri",
                         "data:image/png;base64,iVBORw0KGgoAAAANSUhEUgAAAAIAAAACCAYAAABytg0kAAAAE0lEQVR4nGP4z8DwHwyB"
                         "NAg0AABJSQl4KKDbdwAAAABJRU5ErkJggg=="}}};
    g.doc["textures"] = {{{"source", 0}}};
    g.doc["materials"] = {
        {{"pbrMetallicRoughness", {{"baseColorTexture", baseColorInfo}}}, {"normalTexture", normalInfo}}};
    g.meshNode(json::array({{{"attributes", attrs}, {"material", 0}}}));
    g.doc["extensionsUsed"] = {"KHR_texture_transform"};
    return g.bytes();
}

}  // namespace

TEST(GltfTextureTransform, EachTextureKeepsItsTransformAndCoordinateSet) {
    json const base = {{"index", 0},
                       {"extensions",
                        {{"KHR_texture_transform",
                          {{"offset", {0.5, -0.25}}, {"rotation", 0.3}, {"scale", {2.0, 4.0}}, {"texCoord", 1}}}}}};
    json const normal = {{"index", 0}, {"texCoord", 1}};
    SceneData const s = loadOk(texturedQuad(base, normal, true), "transform.gltf");
    ASSERT_EQ(s.materials.size(), 1u);
    Material const& m = s.materials[0];
    EXPECT_EQ(m.baseColorTransform, (TextureTransform{{0.5f, -0.25f}, 0.3f, {2.0f, 4.0f}, 1}));
    // texCoord without the extension: the set changes, the transform stays the identity.
    EXPECT_EQ(m.normalTransform, (TextureTransform{{0.0f, 0.0f}, 0.0f, {1.0f, 1.0f}, 1}));
    ASSERT_EQ(s.meshes.size(), 1u);
    EXPECT_EQ(s.meshes[0].vertices[1].uv, glm::vec2(1.0f, 0.0f));
    EXPECT_EQ(s.meshes[0].vertices[1].uv1, glm::vec2(0.75f, 0.25f));
    EXPECT_FALSE(hasWarning(s, "TEXCOORD"));

    // Asking for TEXCOORD_1 on a primitive without one falls back to TEXCOORD_0, with a warning;
    // sets past 1 are not loaded.
    SceneData const missing =
        loadOk(texturedQuad({{"index", 0}, {"texCoord", 1}}, {{"index", 0}, {"texCoord", 2}}, false), "no_uv1.gltf");
    EXPECT_TRUE(hasWarning(missing, "reads TEXCOORD_1, which the primitive lacks")) << missing.warnings.size();
    EXPECT_TRUE(hasWarning(missing, "TEXCOORD_2"));
    ASSERT_EQ(missing.meshes.size(), 1u);
    EXPECT_EQ(missing.meshes[0].vertices[2].uv1, glm::vec2(1.0f, 1.0f));
    EXPECT_EQ(missing.materials[0].normalTransform.texCoord, 0);
}

// --- cameras -------------------------------------------------------------------------------------

TEST(GltfCameras, APerspectiveCameraIsLoadedWhereItsNodePlacesIt) {
    test::HandmadeGltf g;
    int const pos = g.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
    g.meshNode(json::array({{{"attributes", {{"POSITION", pos}}}}}));
    g.doc["cameras"] = {
        {{"type", "perspective"},
         {"name", "overview"},
         {"perspective", {{"yfov", 0.8}, {"aspectRatio", 1.5}, {"znear", 0.05}, {"zfar", 250.0}}}},
        {{"type", "orthographic"}, {"orthographic", {{"xmag", 1.0}, {"ymag", 1.0}, {"znear", 0.1}, {"zfar", 10.0}}}},
        {{"type", "perspective"}, {"perspective", {{"yfov", 1.0}, {"znear", 0.1}}}}};
    // Camera 0 at (1, 2, 10) turned 90 degrees about +Y: glTF cameras look down their -Z, so it looks down -X.
    g.node({{"camera", 0}, {"translation", {1.0, 2.0, 10.0}}, {"rotation", {0.0, 0.70710678, 0.0, 0.70710678}}});
    g.node({{"camera", 1}});
    g.node({{"camera", 2}, {"translation", {0.0, 0.0, 5.0}}});
    SceneData const s = loadOk(g.bytes(), "cameras.gltf");

    ASSERT_EQ(s.cameras.size(), 2u) << "the orthographic camera is not offered";
    EXPECT_TRUE(hasWarning(s, "orthographic"));
    SceneCamera const& c = s.cameras[0];
    EXPECT_EQ(c.name, "overview");
    EXPECT_NEAR(c.camera.position.x, 1.0f, 1e-5f);
    EXPECT_NEAR(c.camera.position.y, 2.0f, 1e-5f);
    EXPECT_NEAR(c.camera.position.z, 10.0f, 1e-5f);
    glm::vec3 const f = c.camera.forward();
    EXPECT_NEAR(f.x, -1.0f, 1e-5f);
    EXPECT_NEAR(f.y, 0.0f, 1e-5f);
    EXPECT_NEAR(f.z, 0.0f, 1e-5f);
    EXPECT_NEAR(c.camera.fovYDegrees, 0.8f * 180.0f / 3.14159265f, 1e-4f);
    EXPECT_FLOAT_EQ(c.aspectRatio, 1.5f);
    EXPECT_FLOAT_EQ(c.camera.nearPlane, 0.05f);
    EXPECT_FLOAT_EQ(c.camera.farPlane, 250.0f);

    // No zfar (glTF's infinite projection): a far plane that holds the scene from there.
    SceneCamera const& infinite = s.cameras[1];
    EXPECT_EQ(infinite.name, "camera 2");
    EXPECT_EQ(infinite.aspectRatio, 0.0f);
    EXPECT_NEAR(infinite.camera.forward().z, -1.0f, 1e-5f);
    EXPECT_GT(infinite.camera.farPlane, 5.0f + s.bounds().radius());
}

TEST(GltfCameras, TheDuckModelsCameraIsOffered) {
    fs::path const duck = fs::path(test::sharedGltfDir()) / "Duck/Duck.gltf";
    if (!fs::exists(duck)) GTEST_SKIP() << "shared glTF models not found at " << test::sharedGltfDir();
    GltfLoadResult const r = loadGltf(duck);
    ASSERT_TRUE(r.scene) << r.error;
    ASSERT_EQ(r.scene->cameras.size(), 1u);
    Camera const& cam = r.scene->cameras[0].camera;
    // Duck.gltf: camera node 1's matrix puts it at (400.113, 463.264, -431.078), under a root scaled by 0.01.
    EXPECT_NEAR(cam.position.x, 4.00113f, 1e-4f);
    EXPECT_NEAR(cam.position.y, 4.63264f, 1e-4f);
    EXPECT_NEAR(cam.position.z, -4.31078f, 1e-4f);
    EXPECT_NEAR(cam.fovYDegrees, 37.8492f, 1e-3f);
    EXPECT_FLOAT_EQ(r.scene->cameras[0].aspectRatio, 1.5f);
    // It looks at the duck: the direction to the scene's centre is within its half field of view.
    glm::vec3 const toCentre = glm::normalize(r.scene->bounds().center() - cam.position);
    EXPECT_GT(glm::dot(toCentre, cam.forward()), std::cos(glm::radians(cam.fovYDegrees * 0.5f)));
}

// --- KHR_lights_punctual spot and directional lights ---------------------------------------------

TEST(GltfLightKinds, SpotAndDirectionalLightsLoadAsSuchAlongTheirNodesMinusZ) {
    test::HandmadeGltf g;
    g.meshNode(json::array({{{"attributes", {{"POSITION", g.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3")}}}}}));
    g.doc["extensionsUsed"] = {"KHR_lights_punctual"};
    g.doc["extensions"]["KHR_lights_punctual"]["lights"] = {
        {{"type", "spot"},
         {"name", "down"},
         {"intensity", 3.14159265},
         {"range", 6},
         {"spot", {{"innerConeAngle", 0.2617993878}, {"outerConeAngle", 0.5235987756}}}},
        {{"type", "spot"}, {"spot", json::object()}},  // KHR defaults: inner 0, outer pi/4
        {{"type", "directional"}, {"intensity", 2.0}, {"color", {1.0, 0.5, 0.25}}},
        {{"type", "spot"}, {"spot", {{"innerConeAngle", 0.6}, {"outerConeAngle", 0.5}}}},  // inner > outer
    };
    // -90 degrees about X turns -Z to -Y (down); +90 about Y turns -Z to -X.
    float const h = std::sqrt(0.5f);
    auto lightNode = [&](int light, json rotation) {
        g.node({{"translation", {0, 4, 0}},
                {"rotation", rotation},
                {"extensions", {{"KHR_lights_punctual", {{"light", light}}}}}});
    };
    lightNode(0, {-h, 0, 0, h});
    lightNode(1, {0, 0, 0, 1});
    lightNode(2, {0, h, 0, h});
    lightNode(3, {0, 0, 0, 1});
    SceneData const s = loadOk(g.bytes(), "light_kinds.gltf");
    ASSERT_EQ(s.lights.size(), 3u);
    PointLight const& down = s.lights[0];
    EXPECT_EQ(down.kind, LightKind::Spot);
    EXPECT_EQ(down.name, "down");
    EXPECT_NEAR(glm::distance(down.direction, glm::vec3(0, -1, 0)), 0.0f, 1e-5f);
    EXPECT_NEAR(down.innerConeDeg, 15.0f, 1e-4f);
    EXPECT_NEAR(down.outerConeDeg, 30.0f, 1e-4f);
    EXPECT_NEAR(down.intensity, 1.0f, 1e-5f);            // candela / pi, as for points
    EXPECT_NEAR(lightRadius(down).radius, 6.0f, 1e-3f);  // the range, as for points
    PointLight const& plain = s.lights[1];
    EXPECT_EQ(plain.kind, LightKind::Spot);
    EXPECT_NEAR(glm::distance(plain.direction, glm::vec3(0, 0, -1)), 0.0f, 1e-6f);
    EXPECT_EQ(plain.innerConeDeg, 0.0f);
    EXPECT_NEAR(plain.outerConeDeg, 45.0f, 1e-4f);
    PointLight const& sun = s.lights[2];
    EXPECT_EQ(sun.kind, LightKind::Directional);
    EXPECT_NEAR(glm::distance(sun.direction, glm::vec3(-1, 0, 0)), 0.0f, 1e-5f);
    EXPECT_NEAR(sun.intensity, 2.0f / 3.14159265f, 1e-5f);  // lux / pi
    EXPECT_EQ(sun.color, glm::vec3(1.0f, 0.5f, 0.25f));
    EXPECT_TRUE(hasWarning(s, "light 3 is skipped because its spot cone is unusable"));
    EXPECT_TRUE(hasWarning(s, "inner_cone_deg must not exceed outer_cone_deg"));
}
