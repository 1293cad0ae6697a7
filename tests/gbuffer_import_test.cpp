// The G-buffer manifest and checks on handmade G-buffers written here: clean gives no finding,
// each planted bug gives its own, bad input names the field.
#include "import/gbuffer_checks.h"
#include "import/gbuffer_manifest.h"
#include "import/imported_gbuffer.h"
#include "run_command.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace gbl;
namespace fs = std::filesystem;

namespace {

constexpr int kW = 16, kH = 16;

void writeExr(std::string const& path, int channels, std::vector<float> const& v) {
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out);
    OIIO::ImageSpec spec(kW, kH, channels, OIIO::TypeDesc::FLOAT);
    ASSERT_TRUE(out->open(path, spec));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, v.data()));
    out->close();
}

// A plane z = 0 facing +z seen from (0, 0, 5); the top 4 rows are cleared background.
// `normalScale` plants the not-unit bug when it is not 1.
std::string writeGBuffer(std::string const& name, float normalScale = 1.0f) {
    std::string const dir = test::freshTempDir(name);
    char const* camera =
        R"({"position": [0, 0, 5], "target": [0, 0, 0], "fov_y_degrees": 60, "near": 0.1, "far": 100})";
    std::string manifest = R"({"format": "gbuffer-lab-gbuffer", "version": 1,
      "position": {"file": "position.exr", "coverage": "a"},
      "normal": {"file": "normal.exr", "encoding": "float"},
      "albedo": {"file": "albedo.exr"},
      "depth": {"file": "depth.exr", "convention": "window"},
      "camera": )";
    manifest.append(camera).append("}");
    std::ofstream(dir + "/manifest.json") << manifest;
    auto cam = parseManifest(manifest, "m.json", dir);
    EXPECT_TRUE(cam.manifest) << cam.error;
    CameraMatrices const c = cameraForSize(*cam.manifest->camera, kW, kH);
    glm::mat4 const iv = glm::inverse(c.view), ip = glm::inverse(c.projection);
    std::vector<float> pos, nrm, alb, dep;
    float const n = 0.1f, f = 100.0f, z = 5.0f;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            bool const bg = y < 4;
            glm::vec3 const p = worldFromDistance(c, iv, ip, kW, kH, float(x), float(y), z);
            pos.insert(pos.end(), {bg ? 0 : p.x, bg ? 0 : p.y, bg ? 0 : p.z, bg ? 0.0f : 1.0f});
            nrm.insert(nrm.end(), {0, 0, bg ? 0 : normalScale});
            alb.insert(alb.end(), {0.3f, 0.2f, 0.1f});
            dep.push_back(bg ? 1.0f : (f - n * f / z) / (f - n));
        }
    writeExr(dir + "/position.exr", 4, pos);
    writeExr(dir + "/normal.exr", 3, nrm);
    writeExr(dir + "/albedo.exr", 3, alb);
    writeExr(dir + "/depth.exr", 1, dep);
    return dir;
}

GBufferCheckReport check(std::string const& dir) {
    ManifestLoad m = loadManifest(dir);
    EXPECT_TRUE(m.manifest) << m.error;
    GBufferLoad g = loadGBuffer(*m.manifest);
    EXPECT_TRUE(g.gbuffer) << g.error;
    return checkGBuffer(*g.gbuffer);
}

}  // namespace

TEST(GBufferImport, CleanHandmadeGBufferHasNoFinding) {
    GBufferCheckReport const r = check(writeGBuffer("gbi_clean"));
    EXPECT_EQ(r.backgroundPixels, std::size_t(4 * kW));
    EXPECT_EQ(r.geometryPixels, std::size_t(12 * kW));
    for (auto const& f : r.findings) ADD_FAILURE() << f.check << ": " << f.cause;
}

TEST(GBufferImport, NormalsNotUnitLengthAreFound) {
    GBufferCheckReport const r = check(writeGBuffer("gbi_notunit", 0.5f));
    ASSERT_EQ(r.findings.size(), 1u);
    EXPECT_EQ(r.findings[0].check, "normal_not_unit");
    EXPECT_EQ(r.findings[0].pixels, std::size_t(12 * kW));  // every geometry pixel, no background one
}

TEST(GBufferImport, MissingFileNamesTheField) {
    std::string const dir = writeGBuffer("gbi_missing");
    fs::remove(dir + "/normal.exr");
    ManifestLoad m = loadManifest(dir);
    ASSERT_TRUE(m.manifest) << m.error;
    GBufferLoad const g = loadGBuffer(*m.manifest);
    ASSERT_FALSE(g.gbuffer);
    EXPECT_NE(g.error.find("normal.file"), std::string::npos) << g.error;
}

TEST(GBufferImport, BadFieldsAreNamed) {
    auto err = [](std::string const& body) {
        return parseManifest(R"({"format": "gbuffer-lab-gbuffer", "version": 1, )" + body + "}", "m.json", ".").error;
    };
    EXPECT_NE(
        err(R"("preset": "learnopengl", "normal": {"encoding": "spherical"})").find("normal.encoding must be one of"),
        std::string::npos);
    EXPECT_NE(
        err(R"("preset": "learnopengl", "camera": {"view": [1,0,0,0, 0,1,0,0, 0,0,0,0, 0,0,0,1], "projection": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1], "matrix_layout": "row-major"})")
            .find("camera.view is singular"),
        std::string::npos);
    EXPECT_NE(
        err(R"("preset": "learnopengl", "lights": {"positions": [[0,0,0]], "colors": [[1,1,1]], "linear": [null], "quadratic": 1})")
            .find("lights.linear[0] must be a finite number"),
        std::string::npos);
}

TEST(GBufferImport, PresetsParse) {
    for (char const* preset : {"learnopengl", "newcastle"}) {
        ManifestLoad const m = parseManifest(
            std::string(R"({"format": "gbuffer-lab-gbuffer", "version": 1, "preset": ")") + preset +
                R"(", "camera": {"position": [0, 0, 5], "target": [0, 0, 0], "fov_y_degrees": 45, "near": 0.1, "far": 100}})",
            "m.json", "/x");
        ASSERT_TRUE(m.manifest) << preset << ": " << m.error;
    }
    ManifestLoad const lo =
        parseManifest(R"({"format": "gbuffer-lab-gbuffer", "version": 1, "preset": "learnopengl"})", "m.json", "/x");
    ASSERT_TRUE(lo.manifest) << lo.error;
    EXPECT_EQ(lo.manifest->normal.image.path, "/x/gNormal.exr");
    EXPECT_EQ(lo.manifest->specular->channels, std::vector<int>{3});
    EXPECT_EQ(lo.manifest->shininess, 16.0f);
}
