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

// A surface in front of the camera at (0, 0, 5), facing it; the top 4 rows are cleared background.
// `normalScale` plants the not-unit bug when it is not 1.
enum class Bug { None, FacingAway, NoBackground, AlbedoOver1, DepthFlipped };

std::string writeGBuffer(std::string const& name, float normalScale = 1.0f, Bug bug = Bug::None) {
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
    float const n = 0.1f, f = 100.0f;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            bool const bg = y < 4 && bug != Bug::NoBackground;
            float const z = 4.0f + 0.1f * float(y);  // a surface whose distance changes down the frame
            glm::vec3 const p = worldFromDistance(c, iv, ip, kW, kH, float(x), float(y), z);
            pos.insert(pos.end(), {bg ? 0 : p.x, bg ? 0 : p.y, bg ? 0 : p.z, bg ? 0.0f : 1.0f});
            nrm.insert(nrm.end(), {0, 0, bg ? 0 : normalScale * (bug == Bug::FacingAway ? -1.0f : 1.0f)});
            alb.insert(alb.end(), {bug == Bug::AlbedoOver1 ? 1.5f : 0.3f, 0.2f, 0.1f});
            dep.push_back(bg ? 1.0f : (f - n * f / z) / (f - n));
        }
    writeExr(dir + "/position.exr", 4, pos);
    writeExr(dir + "/normal.exr", 3, nrm);
    writeExr(dir + "/albedo.exr", 3, alb);
    if (bug == Bug::DepthFlipped)  // the depth rows bottom-up, the other attachments top-down
        for (int y = 0; y < kH / 2; ++y)
            std::swap_ranges(dep.begin() + y * kW, dep.begin() + (y + 1) * kW, dep.begin() + (kH - 1 - y) * kW);
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

// Each planted bug gives its own finding and only it (the flipped depth also moves the background).
TEST(GBufferImport, EachPlantedBugIsFound) {
    struct Case {
        Bug bug;
        char const* check;
        char const* causeWord;
    };
    for (Case const& c :
         {Case{Bug::FacingAway, "normal_facing_away", "normal matrix"},
          Case{Bug::NoBackground, "no_background", "clear"}, Case{Bug::AlbedoOver1, "albedo_range", "reflectance"},
          Case{Bug::DepthFlipped, "position_depth_mismatch", "upside down"}}) {
        GBufferCheckReport const r = check(writeGBuffer(std::string("gbi_") + c.check, 1.0f, c.bug));
        bool found = false;
        for (auto const& f : r.findings)
            if (f.check == c.check) {
                found = true;
                EXPECT_GT(f.pixels, 0u) << c.check;
                EXPECT_NE(f.cause.find(c.causeWord), std::string::npos) << f.cause;
            } else if (c.bug != Bug::DepthFlipped) {
                ADD_FAILURE() << c.check << " also gave " << f.check << ": " << f.cause;
            }
        EXPECT_TRUE(found) << c.check;
    }
}

// As session files (session_test's EveryTruncationAndByteFlipFailsCleanly): whatever is cut off or
// overwritten, reading ends with a manifest or one message, never a crash (the sanitizer build
// runs this too).
TEST(GBufferImport, EveryTruncationAndByteFlipFailsCleanly) {
    std::string const text = R"({"format": "gbuffer-lab-gbuffer", "version": 1, "flip_y": true,
      "position": {"file": "p.exr", "channels": "rgb", "space": "world", "coverage": "a"},
      "normal": {"file": "n.png", "channels": "rgb", "encoding": "biased", "space": "view"},
      "albedo": {"file": "a.png", "encoding": "srgb"}, "specular": {"file": "a.png", "channel": "a"},
      "depth": {"file": "d.exr", "convention": "window", "near": 0.1, "far": 100},
      "camera": {"position": [0, 1, 5], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y_degrees": 60,
                 "near": 0.1, "far": 100},
      "lights": {"positions": [[0, 1, 2], [3, 1, 0]], "colors": [[1, 1, 1], [1, 0.5, 0]],
                 "linear": 0.7, "quadratic": [1.8, 0.44]}})";
    ManifestLoad const whole = parseManifest(text, "m.json", "/x");
    ASSERT_TRUE(whole.manifest) << whole.error;
    for (std::size_t n = 0; n + 1 < text.size(); n += 5) {
        ManifestLoad const r = parseManifest(std::string_view(text).substr(0, n), "m.json", "/x");
        EXPECT_FALSE(r.manifest) << n;
        EXPECT_FALSE(r.error.empty()) << n;
    }
    int accepted = 0, refused = 0;
    for (std::size_t i = 0; i < text.size(); i += 3)
        for (char c : {'\0', '-', '9', '"', '}', 'e', 'x'}) {
            std::string t = text;
            t[i] = c;
            ManifestLoad const r = parseManifest(t, "m.json", "/x");
            EXPECT_NE(bool(r.manifest), !r.error.empty()) << i << " " << int(c);
            accepted += bool(r.manifest);
            refused += !r.manifest;
        }
    // Some flips stay valid (a digit for a digit); most must not.
    EXPECT_GT(accepted, 0);
    EXPECT_GT(refused, accepted);
}
