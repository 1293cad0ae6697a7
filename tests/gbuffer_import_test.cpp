// The G-buffer manifest and checks on handmade G-buffers written here: clean gives no finding,
// each planted bug gives its own, bad input names the field.
#include "import/gbuffer_checks.h"
#include "import/gbuffer_manifest.h"
#include "import/imported_gbuffer.h"
#include "import/relight_frame.h"
#include "run_command.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>

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
// `normalScale` plants the not-unit bug when it is not 1; `bug` plants one of the others.
enum class Bug {
    None,
    FacingAway,
    NoBackground,
    AlbedoOver1,
    DepthFlipped,
    NaN,                // one position NaN
    NormalUnbiased,     // (0, 0, 1) in a 16-bit PNG without the 0.5 n + 0.5 bias, declared biased
    Transposed,         // camera matrices listed row by row, declared column-major
    WrongNearFar,       // depth written with near 0.1, declared 0.5
    ViewLabelledWorld,  // view-space positions, declared world
    SrgbAlbedo,         // bright albedo, as sRGB bytes read as linear look
    EightBitNormals,    // correctly biased normals in an 8-bit PNG, at shininess 64
};

// An 8- or 16-bit unsigned PNG of the floats (OpenImageIO clamps negative values to 0, as a UNORM
// target does).
void writePng(std::string const& path, int channels, std::vector<float> const& v, OIIO::TypeDesc type) {
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out);
    OIIO::ImageSpec spec(kW, kH, channels, type);
    ASSERT_TRUE(out->open(path, spec));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, v.data()));
    out->close();
}

std::string writeGBuffer(std::string const& name, float normalScale = 1.0f, Bug bug = Bug::None) {
    std::string const dir = test::freshTempDir(name);
    std::string const fovCamera =
        R"({"position": [0, 0, 5], "target": [0, 0, 0], "fov_y_degrees": 60, "near": 0.1, "far": 100})";
    auto manifestWith = [](std::string const& normal, std::string const& depth, std::string const& camera) {
        return R"({"format": "gbuffer-lab-gbuffer", "version": 1,
          "position": {"file": "position.exr", "coverage": "a"},
          "normal": )" +
               normal + R"(, "albedo": {"file": "albedo.exr"}, "depth": )" + depth + R"(, "camera": )" + camera + "}";
    };
    std::string const exrNormal = R"({"file": "normal.exr", "encoding": "float"})";
    std::string const depth = R"({"file": "depth.exr", "convention": "window"})";
    auto cam = parseManifest(manifestWith(exrNormal, depth, fovCamera), "m.json", dir);
    EXPECT_TRUE(cam.manifest) << cam.error;
    CameraMatrices const c = cameraForSize(*cam.manifest->camera, kW, kH);

    std::string manifest = manifestWith(exrNormal, depth, fovCamera);
    if (bug == Bug::NormalUnbiased)
        manifest = manifestWith(R"({"file": "normal.png", "encoding": "biased"})", depth, fovCamera);
    if (bug == Bug::EightBitNormals)  // (N.H)^64 is off by about 2.7 % of its peak at 8 bits' 0.32 degrees
        manifest = manifestWith(R"({"file": "normal.png", "encoding": "biased"}, "shininess": 64)", depth, fovCamera);
    if (bug == Bug::WrongNearFar)
        manifest = manifestWith(exrNormal, R"({"file": "depth.exr", "convention": "window", "near": 0.5, "far": 100})",
                                fovCamera);
    if (bug == Bug::Transposed) {
        // Each matrix row by row (glm indexes [column][row]), labelled column-major. The transposed
        // projection gives no near/far, so depth states them.
        auto rows = [](glm::mat4 const& m) {
            std::string t;
            for (int r = 0; r < 4; ++r)
                for (int k = 0; k < 4; ++k) {
                    char number[32];
                    std::snprintf(number, sizeof number, "%.9g", double(m[k][r]));
                    t += (t.empty() ? "" : ", ") + std::string(number);
                }
            return "[" + t + "]";
        };
        manifest = manifestWith(exrNormal, R"({"file": "depth.exr", "convention": "window", "near": 0.1, "far": 100})",
                                R"({"matrix_layout": "column-major", "view": )" + rows(c.view) + R"(, "projection": )" +
                                    rows(c.projection) + "}");
    }
    std::ofstream(dir + "/manifest.json") << manifest;
    glm::mat4 const iv = glm::inverse(c.view), ip = glm::inverse(c.projection);
    std::vector<float> pos, nrm, alb, dep;
    float const n = 0.1f, f = 100.0f;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            bool const bg = y < 4 && bug != Bug::NoBackground;
            // A surface whose distance changes down the frame. With transposed matrices the eye the
            // manifest implies is the origin; 6 units and more keep the surface beyond it (z < 0), so
            // that eye still sees its front and only the position/depth check speaks.
            float const z = (bug == Bug::Transposed ? 6.0f : 4.0f) + 0.1f * float(y);
            glm::vec3 p = worldFromDistance(c, iv, ip, kW, kH, float(x), float(y), z);
            if (bug == Bug::ViewLabelledWorld) p = glm::vec3(c.view * glm::vec4(p, 1.0f));
            if (bug == Bug::NaN && x == 3 && y == 8) p.y = std::nanf("");
            pos.insert(pos.end(), {bg ? 0 : p.x, bg ? 0 : p.y, bg ? 0 : p.z, bg ? 0.0f : 1.0f});
            nrm.insert(nrm.end(), {0, 0, bg ? 0 : normalScale * (bug == Bug::FacingAway ? -1.0f : 1.0f)});
            if (bug == Bug::EightBitNormals && !bg)  // stored as 0.5 n + 0.5
                for (auto it = nrm.end() - 3; it != nrm.end(); ++it) *it = 0.5f * *it + 0.5f;
            glm::vec3 const a = bug == Bug::AlbedoOver1  ? glm::vec3(1.5f, 0.2f, 0.1f)
                                : bug == Bug::SrgbAlbedo ? glm::vec3(0.8f, 0.7f, 0.6f)
                                                         : glm::vec3(0.3f, 0.2f, 0.1f);
            alb.insert(alb.end(), {a.r, a.g, a.b});
            dep.push_back(bg ? 1.0f : (f - n * f / z) / (f - n));
        }
    writeExr(dir + "/position.exr", 4, pos);
    if (bug == Bug::NormalUnbiased)
        writePng(dir + "/normal.png", 3, nrm, OIIO::TypeDesc::UINT16);
    else if (bug == Bug::EightBitNormals)
        writePng(dir + "/normal.png", 3, nrm, OIIO::TypeDesc::UINT8);
    else
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

// A number beyond double's range is refused like any other bad JSON (the manifest fuzzer found it
// ending the process: nlohmann throws out_of_range for it, not parse_error).
TEST(GBufferImport, ANumberTooLargeForADoubleIsRefusedNotACrash) {
    ManifestLoad const m = parseManifest(R"({"format": "gbuffer-lab-gbuffer", "version": 1e400})", "m.json", ".");
    EXPECT_FALSE(m.manifest);
    EXPECT_EQ(m.error.rfind("m.json: not valid JSON", 0), 0u) << m.error;
    EXPECT_NE(m.error.find("1e400"), std::string::npos) << m.error;
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
    EXPECT_EQ(lo.manifest->shading, ShadingModel::LearnOpenGl);
}

// "shading": "learnopengl" alone brings that shader's exponent (16) unless "shininess" is given;
// applied to the re-light's settings it also brings the shader's ambient 0.1.
TEST(GBufferImport, TheLearnOpenGlShadingSetsItsConstants) {
    std::string const head = R"({"format": "gbuffer-lab-gbuffer", "version": 1, "preset": "newcastle",
        "camera": {"position": [0, 0, 5], "target": [0, 0, 0], "fov_y_degrees": 45, "near": 0.1, "far": 100}, )";
    ManifestLoad const plain = parseManifest(head + R"("shading": "learnopengl"})", "m.json", "/x");
    ASSERT_TRUE(plain.manifest) << plain.error;
    EXPECT_EQ(plain.manifest->shininess, kLearnOpenGlShininess);
    ManifestLoad const given = parseManifest(head + R"("shading": "learnopengl", "shininess": 40})", "m.json", "/x");
    ASSERT_TRUE(given.manifest) << given.error;
    EXPECT_EQ(given.manifest->shininess, 40.0f);
    ManifestLoad const ours = parseManifest(head + R"("shininess": 40})", "m.json", "/x");
    ASSERT_TRUE(ours.manifest) << ours.error;
    EXPECT_EQ(ours.manifest->shading, ShadingModel::GbufferLab);

    PipelineSettings s;
    s.ambient = glm::vec3(0.03f);
    applyManifestShading(given.manifest->shininess, given.manifest->shading, s);
    EXPECT_EQ(s.shading, ShadingModel::LearnOpenGl);
    EXPECT_EQ(s.shininess, 40.0f);
    EXPECT_EQ(s.ambient, glm::vec3(kLearnOpenGlAmbient));
    PipelineSettings kept;
    kept.ambient = glm::vec3(0.05f);
    applyManifestShading(32.0f, ShadingModel::GbufferLab, kept);
    EXPECT_EQ(kept.ambient, glm::vec3(0.05f)) << "gbuffer-lab's shading keeps the editor's ambient";

    ManifestLoad const bad = parseManifest(head + R"("shading": "phong"})", "m.json", "/x");
    EXPECT_FALSE(bad.manifest);
    EXPECT_NE(bad.error.find("shading"), std::string::npos) << bad.error;
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
          Case{Bug::DepthFlipped, "position_depth_mismatch", "upside down"}, Case{Bug::NaN, "nan_inf", "position"},
          Case{Bug::NormalUnbiased, "normal_unbiased", "0.5·n + 0.5 bias"},
          Case{Bug::Transposed, "position_depth_mismatch", "transposed camera matrices"},
          Case{Bug::WrongNearFar, "position_depth_mismatch", "wrong near/far"},
          Case{Bug::ViewLabelledWorld, "position_depth_mismatch", "view-space positions labelled world"},
          Case{Bug::SrgbAlbedo, "albedo_srgb", "sRGB-encoded"},
          Case{Bug::EightBitNormals, "normal_precision", "store normals in 16 bits"}}) {
        GBufferCheckReport const r = check(writeGBuffer("gbi_bug" + std::to_string(int(c.bug)), 1.0f, c.bug));
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

// Another program's camera may roll, or project off-centre (a jittered or tiled projection): the
// editor's camera for the frame returns its matrices as given, which no yaw/pitch camera can, so
// picking, the pixel inspector and why-this-value project through the frame's own transform.
TEST(GBufferImport, TheFramesCameraKeepsItsExactMatrices) {
    ImportedFrame f;
    f.eye = {1.0f, 4.0f, 9.0f};
    float const roll = glm::radians(30.0f);
    f.view = glm::lookAt(f.eye, glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(std::sin(roll), std::cos(roll), 0.0f));
    f.projection = glm::frustum(-0.05f, 0.09f, -0.04f, 0.05f, 0.1f, 100.0f);
    f.nearPlane = 0.1f;
    f.farPlane = 100.0f;
    Camera const c = cameraOfFrame(f);
    EXPECT_EQ(c.view(), f.view);
    EXPECT_EQ(c.projection(16.0f / 9.0f), f.projection);
    glm::vec4 const p(0.5f, 1.5f, -0.5f, 1.0f);
    EXPECT_EQ(c.projection(1.0f) * c.view() * p, f.projection * f.view * p);
    // Its angles are the nearest yaw/pitch camera's: the same eye and forward, but not the same view.
    EXPECT_EQ(c.position, f.eye);
    Camera nearest = c;
    nearest.fixedView.reset();
    nearest.fixedProjection.reset();
    glm::vec3 const forward = -glm::vec3(f.view[0][2], f.view[1][2], f.view[2][2]);
    EXPECT_NEAR(glm::dot(nearest.forward(), glm::normalize(forward)), 1.0f, 1e-5f);
    float largest = 0.0f;
    for (int col = 0; col < 4; ++col)
        for (int row = 0; row < 4; ++row)
            largest = std::max(largest, std::abs(nearest.view()[col][row] - f.view[col][row]));
    EXPECT_GT(largest, 0.3f) << "a 30 degree roll should be far from any yaw/pitch view";
}

// Every attachment gets a precision note; the normal's names the manifest's shininess and the
// highlight error, which is what fires normal_precision on 8-bit normals at shininess 64.
TEST(GBufferImport, PrecisionNotesNameStorageStepAndHighlightError) {
    GBufferCheckReport const r = check(writeGBuffer("gbi_precision", 1.0f, Bug::EightBitNormals));
    PrecisionNote const* normal = nullptr;
    for (PrecisionNote const& p : r.precision)
        if (p.attachment == "normal") normal = &p;
    ASSERT_NE(normal, nullptr);
    EXPECT_EQ(normal->shininess, 64.0);
    EXPECT_NEAR(normal->step, 1.0 / 255.0, 1e-9);
    EXPECT_GT(normal->highlightError, 2.0 / 255.0);
    std::string const line = precisionLine(*normal);
    EXPECT_EQ(
        line.rfind("normal: " + normal->storage + ", step 0.00392; a highlight of shininess 64 moves by up to ", 0), 0u)
        << line;
    char percent[32];
    std::snprintf(percent, sizeof percent, "%.2g %% of its peak", normal->highlightError * 100.0);
    EXPECT_NE(line.find(percent), std::string::npos) << line;

    PrecisionNote other;
    other.attachment = "albedo";
    other.storage = "16-bit float";
    other.step = 0.0009765625;
    EXPECT_EQ(precisionLine(other), "albedo: 16-bit float, step 0.000977");
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

// --- emission and occlusion (issue 28) ----------------------------------------------------------

namespace {

// The clean handmade G-buffer's manifest with `extra` fields added (", \"emissive\": {...}").
std::string withFields(std::string const& dir, std::string const& extra) {
    std::ifstream in(dir + "/manifest.json");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    text.insert(text.rfind('}'), extra);
    return text;
}

}  // namespace

TEST(GBufferImport, EmissiveAndOcclusionParseAndDefaultToNone) {
    std::string const head = R"({"format": "gbuffer-lab-gbuffer", "version": 1, "preset": "learnopengl")";
    ManifestLoad const none = parseManifest(head + "}", "m.json", "/x");
    ASSERT_TRUE(none.manifest) << none.error;
    EXPECT_FALSE(none.manifest->emissive);
    EXPECT_FALSE(none.manifest->occlusion);
    ManifestLoad const both =
        parseManifest(head + R"(, "emissive": {"file": "e.png", "channels": "bgr", "encoding": "srgb", "scale": 4},
                   "occlusion": {"file": "ao.exr", "channel": "a"}})",
                      "m.json", "/x");
    ASSERT_TRUE(both.manifest) << both.error;
    ASSERT_TRUE(both.manifest->emissive);
    EXPECT_EQ(both.manifest->emissive->image.path, "/x/e.png");
    EXPECT_EQ(both.manifest->emissive->image.channels, (std::vector<int>{2, 1, 0}));
    EXPECT_EQ(both.manifest->emissive->encoding, ColorEncoding::Srgb);
    EXPECT_EQ(both.manifest->emissive->scale, 4.0f);
    ASSERT_TRUE(both.manifest->occlusion);
    EXPECT_EQ(both.manifest->occlusion->channels, std::vector<int>{3});
    // Defaults: rgb, linear, scale 1; channel r.
    ManifestLoad const plain =
        parseManifest(head + R"(, "emissive": {"file": "e.exr"}, "occlusion": {"file": "ao.png"}})", "m.json", "/x");
    ASSERT_TRUE(plain.manifest) << plain.error;
    EXPECT_EQ(plain.manifest->emissive->image.channels, (std::vector<int>{0, 1, 2}));
    EXPECT_EQ(plain.manifest->emissive->encoding, ColorEncoding::Linear);
    EXPECT_EQ(plain.manifest->emissive->scale, 1.0f);
    EXPECT_EQ(plain.manifest->occlusion->channels, std::vector<int>{0});
    // gbuffer-lab's export folder names emissive.exr for both; null takes a preset's field away.
    ManifestLoad const ours = parseManifest(R"({"format": "gbuffer-lab-gbuffer", "version": 1, "preset": "gbuffer-lab",
        "occlusion": null, "camera": {"position": [0, 0, 5], "target": [0, 0, 0], "fov_y_degrees": 45, "near": 0.1,
        "far": 100}})",
                                            "m.json", "/x");
    ASSERT_TRUE(ours.manifest) << ours.error;
    ASSERT_TRUE(ours.manifest->emissive);
    EXPECT_EQ(ours.manifest->emissive->image.path, "/x/emissive.exr");
    EXPECT_FALSE(ours.manifest->occlusion);
}

TEST(GBufferImport, EmissiveAndOcclusionBadFieldsAreNamed) {
    auto err = [](std::string const& body) {
        return parseManifest(
                   R"({"format": "gbuffer-lab-gbuffer", "version": 1, "preset": "learnopengl", )" + body + "}",
                   "m.json", ".")
            .error;
    };
    struct Case {
        char const* body;
        char const* message;
    };
    for (Case const& c : {
             Case{R"("emissive": "e.png")", "m.json: emissive must be an object"},
             Case{R"("emissive": {"channels": "rgb"})", "m.json: emissive.file is missing"},
             Case{R"("emissive": {"file": ""})", "m.json: emissive.file must name a file"},
             Case{R"("emissive": {"file": "e.png", "channels": "rg"})", "m.json: emissive.channels must be 3 of"},
             Case{R"("emissive": {"file": "e.png", "channels": "rgq"})", "m.json: emissive.channels must be 3 of"},
             Case{R"("emissive": {"file": "e.png", "encoding": "gamma"})", "m.json: emissive.encoding must be one of"},
             Case{R"("emissive": {"file": "e.png", "scale": -1})",
                  "m.json: emissive.scale must be a finite number >= 0"},
             Case{R"("emissive": {"file": "e.png", "scale": "2"})", "m.json: emissive.scale must be a finite number"},
             Case{R"("emissive": {"file": "e.png", "strength": 2})", "m.json: emissive.strength is not a known field"},
             Case{R"("emissive": {"file": "e.raw", "raw": {"type": "float", "width": 4, "height": 4}})",
                  "m.json: emissive.raw.channels is missing"},
             Case{R"("occlusion": 1)", "m.json: occlusion must be an object"},
             Case{R"("occlusion": {"channel": "r"})", "m.json: occlusion.file is missing"},
             Case{R"("occlusion": {"file": "ao.png", "channel": "rg"})", "m.json: occlusion.channel must be 1 of"},
             Case{R"("occlusion": {"file": "ao.png", "channels": "r"})", "m.json: occlusion.channels is not a known"},
             Case{R"("occlusion": {"file": "ao.png", "encoding": "srgb"})",
                  "m.json: occlusion.encoding is not a known"},
         }) {
        std::string const e = err(c.body);
        EXPECT_EQ(e.rfind(c.message, 0), 0u) << c.body << "\n  gave: " << e;
    }
}

// The images are read, decoded (sRGB, scale) and checked: missing files, sizes and values a field
// cannot hold are refused naming it; the re-light frame carries them bottom-up, and a manifest
// without them re-lights as before (no emissive/AO pixels: emission 0, occlusion 1).
TEST(GBufferImport, EmissiveAndOcclusionLoadDecodeAndRefuseBadValues) {
    std::string const dir = writeGBuffer("gbi_emissive");
    std::vector<float> em, ao;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            bool const patch = x >= 4 && x < 8 && y >= 6 && y < 10;
            em.insert(em.end(), {patch ? 1.0f : 0.0f, patch ? 0.6f : 0.0f, 0.0f});  // 0.6: 153/255 exactly
            ao.push_back(y >= 12 ? 0.25f : 1.0f);
        }
    writePng(dir + "/emissive.png", 3, em, OIIO::TypeDesc::UINT8);
    writeExr(dir + "/ao.exr", 1, ao);
    std::string const fields = R"(, "emissive": {"file": "emissive.png", "encoding": "srgb", "scale": 2},
        "occlusion": {"file": "ao.exr"})";
    ManifestLoad const m = parseManifest(withFields(dir, fields), "m.json", dir);
    ASSERT_TRUE(m.manifest) << m.error;
    GBufferLoad const g = loadGBuffer(*m.manifest);
    ASSERT_TRUE(g.gbuffer) << g.error;
    ASSERT_EQ(g.gbuffer->emissive.size(), g.gbuffer->pixelCount());
    ASSERT_EQ(g.gbuffer->occlusion.size(), g.gbuffer->pixelCount());
    std::size_t const inPatch = std::size_t(7 * kW + 5), outside = std::size_t(7 * kW + 9);
    // sRGB 0.6 is ((0.6 + 0.055) / 1.055)^2.4 = 0.3185 linear; times the scale 2.
    EXPECT_NEAR(g.gbuffer->emissive[inPatch].r, 2.0f, 1e-6f);
    EXPECT_NEAR(g.gbuffer->emissive[inPatch].g, 2.0f * std::pow(0.655f / 1.055f, 2.4f), 1e-5f);
    EXPECT_EQ(g.gbuffer->emissive[outside], glm::vec3(0.0f));
    EXPECT_EQ(g.gbuffer->occlusion[std::size_t(13 * kW)], 0.25f);
    EXPECT_EQ(g.gbuffer->occlusion[std::size_t(5 * kW)], 1.0f);
    RelightFrame const f = relightFrame(*g.gbuffer);
    ASSERT_TRUE(f.frame) << f.error;
    ASSERT_EQ(f.frame->emissiveAo.size(), g.gbuffer->pixelCount());
    // Row 7 from the top is row kH - 1 - 7 from the bottom.
    glm::vec4 const e = f.frame->emissiveAo[std::size_t((kH - 1 - 7) * kW + 5)];
    EXPECT_EQ(glm::vec3(e), g.gbuffer->emissive[inPatch]);
    EXPECT_EQ(e.a, 1.0f);
    EXPECT_EQ(f.frame->emissiveAo[std::size_t((kH - 1 - 13) * kW)], glm::vec4(0.0f, 0.0f, 0.0f, 0.25f));

    // Without the fields: nothing decoded, and no emissive/AO pixels in the frame (the pass then
    // writes emission 0 and occlusion 1, the frame of before).
    GBufferLoad const plain = loadGBuffer(*loadManifest(dir).manifest);
    ASSERT_TRUE(plain.gbuffer) << plain.error;
    EXPECT_TRUE(plain.gbuffer->emissive.empty());
    EXPECT_TRUE(plain.gbuffer->occlusion.empty());
    EXPECT_TRUE(relightFrame(*plain.gbuffer).frame->emissiveAo.empty());

    auto refused = [&](std::string const& extra) {
        ManifestLoad const bad = parseManifest(withFields(dir, extra), "m.json", dir);
        EXPECT_TRUE(bad.manifest) << bad.error;
        GBufferLoad const r = loadGBuffer(*bad.manifest);
        EXPECT_FALSE(r.gbuffer);
        return r.error;
    };
    std::string e1 = refused(R"(, "occlusion": {"file": "none.png"})");
    EXPECT_EQ(e1.rfind("m.json: occlusion.file " + dir + "/none.png cannot be read", 0), 0u) << e1;
    std::string e2 = refused(R"(, "occlusion": {"file": "emissive.png", "channel": "a"})");
    EXPECT_EQ(e2.rfind("m.json: occlusion asks for channel a but", 0), 0u) << e2;
    // The lit-frame sized 16x16 files against an 8x8 one.
    {
        auto out = OIIO::ImageOutput::create(dir + "/small.exr");
        OIIO::ImageSpec spec(8, 8, 3, OIIO::TypeDesc::FLOAT);
        std::vector<float> zeros(8 * 8 * 3, 0.0f);
        ASSERT_TRUE(out->open(dir + "/small.exr", spec));
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, zeros.data()));
        out->close();
    }
    std::string e3 = refused(R"(, "emissive": {"file": "small.exr"})");
    EXPECT_EQ(e3.rfind("m.json: emissive.file " + dir + "/small.exr is 8x8 but position is 16x16", 0), 0u) << e3;
    // Occlusion 4 (a distance or a count, not a visibility) and negative emission are no such values.
    for (float& v : ao) v *= 4.0f;
    writeExr(dir + "/ao4.exr", 1, ao);
    std::string e4 = refused(R"(, "occlusion": {"file": "ao4.exr"})");
    EXPECT_EQ(e4.rfind("m.json: occlusion holds values outside [0, 1] in " + dir + "/ao4.exr at " +
                           std::to_string(12 * kW) + " pixels (e.g. 4)",
                       0),
              0u)
        << e4;
    for (float& v : em) v = -v;
    writeExr(dir + "/negative.exr", 3, em);
    std::string e5 = refused(R"(, "emissive": {"file": "negative.exr"})");
    EXPECT_EQ(e5.rfind("m.json: emissive holds negative values in " + dir + "/negative.exr at 16 pixels", 0), 0u) << e5;
}

// Shares are of the geometry pixels: a fault on every drawn pixel is 100 %, not the 75 % of the frame
// the geometry covers here (12 of 16 rows).
TEST(GBufferImport, FindingSharesAreOfTheGeometryPixels) {
    GBufferCheckReport const r = check(writeGBuffer("gbi_share", 0.5f));
    ASSERT_EQ(r.findings.size(), 1u);
    EXPECT_DOUBLE_EQ(r.findings[0].share, 1.0);
}

// Bad files are refused before anything is decoded: a device file, a missing file named after a large
// one, and a G-buffer over the memory budget (a sparse raw file: its size is there, its bytes are not).
TEST(GBufferImport, FilesAreProbedBeforeAnyIsDecoded) {
    std::string const dir = writeGBuffer("gbi_probe");
    auto loadWith = [&](std::string const& extra) {
        std::string text;
        {
            std::ifstream in(dir + "/manifest.json");
            text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
        }
        text.insert(text.rfind('}'), extra);
        ManifestLoad m = parseManifest(text, "m.json", dir);
        EXPECT_TRUE(m.manifest) << m.error;
        if (!m.manifest) return std::string();
        auto const start = std::chrono::steady_clock::now();
        GBufferLoad const g = loadGBuffer(*m.manifest);
        // Refused from headers and directory entries: well under a second even on a loaded 2-core machine.
        EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
        EXPECT_FALSE(g.gbuffer);
        return g.error;
    };
    std::string const device = loadWith(
        R"(, "lit": {"file": "/dev/zero", "raw": {"type": "float", "width": 20000, "height": 20000, "channels": 4}})");
    EXPECT_NE(device.find("lit.file /dev/zero is not a regular file"), std::string::npos) << device;

    std::string const missing = loadWith(R"(, "specular": {"file": "nowhere.png", "channel": "r"})");
    EXPECT_NE(missing.find("specular.file"), std::string::npos) << missing;

    std::string const big = dir + "/big.raw";
    { std::ofstream(big, std::ios::binary).put('\0'); }
    fs::resize_file(big, std::uintmax_t(20000) * 20000 * 4 * 4);  // sparse: no disk is written
    std::string const budget = loadWith(
        R"(, "lit": {"file": "big.raw", "raw": {"type": "float", "width": 20000, "height": 20000, "channels": 4}})");
    // It is the size that is refused here, not the budget: the frame is 16x16.
    EXPECT_NE(budget.find("is 20000x20000 but position is 16x16"), std::string::npos) << budget;
    fs::remove(big);
}

TEST(GBufferImport, AGBufferOverTheMemoryBudgetIsRefusedInOneSentence) {
    std::string const dir = test::freshTempDir("gbi_budget");
    for (char const* name : {"p.raw", "n.raw"}) {
        { std::ofstream(dir + "/" + name, std::ios::binary).put('\0'); }
        fs::resize_file(dir + "/" + name, std::uintmax_t(20000) * 20000 * 3 * 4);  // sparse
    }
    ManifestLoad m = parseManifest(R"({"format": "gbuffer-lab-gbuffer", "version": 1,
        "position": {"file": "p.raw", "raw": {"type": "float", "width": 20000, "height": 20000, "channels": 3}},
        "normal": {"file": "n.raw", "encoding": "float",
                   "raw": {"type": "float", "width": 20000, "height": 20000, "channels": 3}}})",
                                   "m.json", dir);
    ASSERT_TRUE(m.manifest) << m.error;
    GBufferLoad const g = loadGBuffer(*m.manifest);
    ASSERT_FALSE(g.gbuffer);
    EXPECT_NE(g.error.find("the G-buffer would take 18 GiB decoded (20000x20000, 2 attachments), over the 4.0 GiB"),
              std::string::npos)
        << g.error;
    fs::remove_all(dir);
}
