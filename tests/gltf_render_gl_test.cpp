// Real glTF files through `gbuffer-lab render --scene`: every shared model renders, and the G-buffer holds what the
// files say.
#include "image/image_io.h"
#include "run_command.h"
#include "test_paths.h"

#include <gtest/gtest.h>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace gbl;
using gbl::test::runGbufferLab;
namespace fs = std::filesystem;

namespace {

// Small frames: llvmpipe on two cores renders these in about a second each.
constexpr int kWidth = 160;
constexpr int kHeight = 120;
constexpr char const* kSize = "160x120";

#define SKIP_WITHOUT_SHARED_MODELS()                                               \
    do {                                                                           \
        if (!fs::is_directory(test::sharedGltfDir()))                              \
            GTEST_SKIP() << "../shared/gltf not found: " << test::sharedGltfDir(); \
    } while (0)

fs::path sharedModel(std::string const& relative) {
    return fs::path(test::sharedGltfDir()) / relative;
}
fs::path localFile(std::string const& name) {
    return fs::path(test::dataDir()) / "gltf" / name;
}

struct Frame {
    bool ok = false;
    std::string output;  // what the command printed, for failure messages
    FloatImage final, albedo, normal, position;
    nlohmann::json stats;

    bool covered(int x, int y) const { return normal.at(x, y, 3) != 0.0f; }  // the G-buffer's w = 1 where drawn
    int coveredCount() const {
        int n = 0;
        for (int y = 0; y < normal.height; ++y)
            for (int x = 0; x < normal.width; ++x) n += covered(x, y);
        return n;
    }
};

// Renders the scene (at kSize unless `size` says otherwise) into a fresh folder and reads the images back. Reports a
// test failure (and returns ok = false) when the command fails or an image is missing.
Frame renderScene(fs::path const& scene, std::string const& name, std::vector<std::string> const& extra = {},
                  std::string const& size = kSize) {
    Frame f;
    if (!fs::exists(test::binaryPath())) {
        ADD_FAILURE() << "gbuffer-lab is not built: " << test::binaryPath();
        return f;
    }
    std::string const out = test::freshTempDir("gltf_render_" + name);
    std::vector<std::string> args = {"render", "--scene", scene.string(), "--out", out, "--size", size};
    args.insert(args.end(), extra.begin(), extra.end());
    auto const r = runGbufferLab(args);
    f.output = r.output;
    if (r.exitCode != 0) {
        ADD_FAILURE() << scene << ": exit " << r.exitCode << "\n" << r.output;
        return f;
    }
    auto finalImg = readImage(out + "/final.png"), albedo = readImage(out + "/albedo.png");
    auto normal = readImage(out + "/normal.exr"), position = readImage(out + "/position.exr");
    if (!finalImg || !albedo || !normal || !position) {
        ADD_FAILURE() << scene << ": an image is missing in " << out;
        return f;
    }
    f.final = std::move(*finalImg);
    f.albedo = std::move(*albedo);
    f.normal = std::move(*normal);
    f.position = std::move(*position);
    f.stats = test::readJsonFile(fs::path(out) / "stats.json");
    f.ok = f.normal.channels == 4 && f.normal.width * f.normal.height == f.final.width * f.final.height;
    if (!f.ok) ADD_FAILURE() << scene << ": normal.exr is " << f.normal.width << "x" << f.normal.height;
    return f;
}

float srgbToLinear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

// Bilinear sample of an image at glTF UV (origin at the top-left texel's corner), repeat wrapping.
std::array<float, 3> sampleBilinear(FloatImage const& img, float u, float v) {
    float const x = (u - std::floor(u)) * float(img.width) - 0.5f, y = (v - std::floor(v)) * float(img.height) - 0.5f;
    int const x0 = int(std::floor(x)), y0 = int(std::floor(y));
    float const fx = x - float(x0), fy = y - float(y0);
    auto wrap = [](int i, int n) { return ((i % n) + n) % n; };
    std::array<float, 3> out{};
    for (int c = 0; c < 3; ++c) {
        auto at = [&](int xi, int yi) { return img.at(wrap(xi, img.width), wrap(yi, img.height), c); };
        out[std::size_t(c)] = (at(x0, y0) * (1 - fx) + at(x0 + 1, y0) * fx) * (1 - fy) +
                              (at(x0, y0 + 1) * (1 - fx) + at(x0 + 1, y0 + 1) * fx) * fy;
    }
    return out;
}

// Every .gltf one folder below ../shared/gltf and every .glb in its glb/ folder.
std::vector<fs::path> sharedModels() {
    std::vector<fs::path> models;
    for (auto const& dir : fs::directory_iterator(test::sharedGltfDir())) {
        if (!dir.is_directory()) continue;
        for (auto const& f : fs::directory_iterator(dir.path()))
            if (f.path().extension() == ".gltf" || f.path().extension() == ".glb") models.push_back(f.path());
    }
    std::sort(models.begin(), models.end());
    return models;
}

}  // namespace

TEST(GltfRender, EveryModelRendersWithNonEmptyAttachments) {
    SKIP_WITHOUT_SHARED_MODELS();
    std::vector<fs::path> const models = sharedModels();
    // The README lists 8 folders with .gltf files and 4 .glb files.
    EXPECT_GE(models.size(), 12u);
    for (fs::path const& model : models) {
        SCOPED_TRACE(model.string());
        std::string const name = model.parent_path().filename().string() + "_" + model.stem().string();
        Frame const f = renderScene(model, name);
        if (!f.ok) continue;
        EXPECT_EQ(f.stats["gl_errors"], 0);
        EXPECT_GT(f.stats["triangles"].get<long long>(), 0) << f.stats.dump();

        int const covered = f.coveredCount();
        double albedoSum = 0.0, finalSum = 0.0;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                if (!f.covered(x, y)) continue;
                for (int c = 0; c < 3; ++c) albedoSum += f.albedo.at(x, y, c), finalSum += f.final.at(x, y, c);
                for (int c = 0; c < 3; ++c) ASSERT_TRUE(std::isfinite(f.position.at(x, y, c))) << x << "," << y;
            }
        // The camera fits the bounding sphere into the vertical field of view with a 10% margin,
        // so every model covers well over 5% of the frame (measured: Suzanne 10%, DamagedHelmet
        // 11%, Box 27%); a wrong framing or scale (Avocado is 6 cm) leaves a speck or nothing.
        EXPECT_GT(covered, kWidth * kHeight / 20) << "covered pixels";
        if (covered == 0) continue;
        double const meanAlbedo = albedoSum / (3.0 * covered), meanFinal = finalSum / (3.0 * covered);
        // Measured lowest: Suzanne's mean linear albedo 0.12, Box's lit mean 0.14. Black
        // attachments (textures lost, no light reaching the surface) give about 0.
        EXPECT_GT(meanAlbedo, 0.02) << "mean albedo of covered pixels";
        EXPECT_GT(meanFinal, 0.02) << "mean final colour of covered pixels: the frame must not be black";
    }
}

TEST(GltfRender, BoxFaceNormalsAreAxisAlignedUnitVectors) {
    SKIP_WITHOUT_SHARED_MODELS();
    Frame const f = renderScene(sharedModel("Box/Box.gltf"), "box");
    ASSERT_TRUE(f.ok);
    EXPECT_EQ(f.stats["gl_errors"], 0);
    // Counts per axis direction: +X -X +Y -Y +Z -Z.
    std::array<int, 6> faces{};
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            if (!f.covered(x, y)) continue;
            glm::vec3 const n(f.normal.at(x, y, 0), f.normal.at(x, y, 1), f.normal.at(x, y, 2));
            int axis = 0;
            for (int a = 1; a < 3; ++a)
                if (std::abs(n[a]) > std::abs(n[axis])) axis = a;
            // Flat faces carry one vertex normal, so interpolation changes nothing: the only
            // error is the RGBA16F store, exact for 0 and 1 (2^-11 covers any rounding).
            ASSERT_NEAR(std::abs(n[axis]), 1.0f, 1.0f / 2048.0f) << "pixel " << x << "," << y;
            for (int a = 0; a < 3; ++a) {
                if (a != axis) {
                    ASSERT_NEAR(n[a], 0.0f, 1.0f / 2048.0f) << "pixel " << x << "," << y;
                }
            }
            ++faces[std::size_t(axis * 2 + (n[axis] < 0.0f))];
        }
    // The framing camera sits on +Z, 20 degrees up and centred in x: it sees the front (+Z) and
    // top (+Y) faces only; the node matrix turns the mesh's faces onto these axes.
    EXPECT_GT(faces[4], kWidth * kHeight / 10) << "front face (+Z)";
    EXPECT_GT(faces[2], kWidth * kHeight / 100) << "top face (+Y)";
    EXPECT_EQ(faces[0] + faces[1] + faces[3] + faces[5], 0) << "faces the camera cannot see";
}

TEST(GltfRender, BoxTexturedAlbedoShowsTheCesiumLogo) {
    SKIP_WITHOUT_SHARED_MODELS();
    Frame const f = renderScene(sharedModel("BoxTextured/BoxTextured.gltf"), "box_textured");
    ASSERT_TRUE(f.ok);
    auto texture = readImage(sharedModel("BoxTextured/CesiumLogoFlat.png").string());
    ASSERT_TRUE(texture);
    FloatImage linear = *texture;  // the G-buffer holds linear albedo: sRGB decoded on sampling
    for (std::size_t i = 0; i < linear.pixels.size(); ++i)
        if (int(i % std::size_t(linear.channels)) < 3) linear.pixels[i] = srgbToLinear(linear.pixels[i]);

    // The front face (+Z, world normal after the node matrix) is the mesh's -Y face: its
    // vertices put u = 0.5 - x and v = 0.5 - y (fraction of the UVs in the file), so every
    // covered pixel's texel is known from its world position. The logo shows mirrored, upright.
    int front = 0, matching = 0;
    double sum[3] = {}, sumSq[3] = {};
    int all = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            if (!f.covered(x, y)) continue;
            ++all;
            for (int c = 0; c < 3; ++c)
                sum[c] += f.albedo.at(x, y, c), sumSq[c] += f.albedo.at(x, y, c) * f.albedo.at(x, y, c);
            if (f.normal.at(x, y, 2) < 0.999f) continue;
            ++front;
            auto const expected = sampleBilinear(linear, 0.5f - f.position.at(x, y, 0), 0.5f - f.position.at(x, y, 1));
            float err = 0.0f;
            for (int c = 0; c < 3; ++c) err = std::max(err, std::abs(f.albedo.at(x, y, c) - expected[std::size_t(c)]));
            // 0.1: 8-bit storage of linear values (1/255) plus mipmap blurring across the logo's
            // colour edges, which only pixels near an edge exceed.
            matching += err < 0.1f;
        }
    ASSERT_GT(front, kWidth * kHeight / 10) << "front face pixels";
    // Measured 92.5%. The same comparison with the texture upside down matches 40%, mirrored
    // 73% (the logo is nearly symmetric left to right); a missing texture far less.
    EXPECT_GT(double(matching), 0.85 * double(front)) << matching << " of " << front << " front-face pixels match";

    // Not a constant colour: grey border, blue sky, white wave and green hills.
    double variance = 0.0;
    for (int c = 0; c < 3; ++c) variance += sumSq[c] / all - (sum[c] / all) * (sum[c] / all);
    EXPECT_GT(variance, 0.02) << "summed channel variance of the albedo";
}

TEST(GltfRender, NormalTangentTestNormalMapChangesTheNormals) {
    SKIP_WITHOUT_SHARED_MODELS();
    fs::path const source = sharedModel("NormalTangentTest");
    // The same mesh, camera (framed from the same bounds) and lights, without the normal map.
    fs::path const copy = test::freshTempDir("gltf_render_ntt_copy");
    for (auto const& e : fs::directory_iterator(source)) fs::copy_file(e.path(), copy / e.path().filename());
    nlohmann::json doc = test::readJsonFile((copy / "NormalTangentTest.gltf").string());
    int removed = 0;
    for (auto& m : doc["materials"]) removed += int(m.erase("normalTexture"));
    ASSERT_GT(removed, 0);
    std::ofstream(copy / "NormalTangentTest.gltf") << doc.dump();

    // 320x240: each bump is then about 14 pixels wide, enough for per-pixel gradients.
    Frame const mapped = renderScene(source / "NormalTangentTest.gltf", "ntt_mapped", {}, "320x240");
    Frame const plain = renderScene(copy / "NormalTangentTest.gltf", "ntt_plain", {}, "320x240");
    ASSERT_TRUE(mapped.ok && plain.ok);
    EXPECT_EQ(mapped.stats["gl_errors"], 0);
    ASSERT_EQ(mapped.coveredCount(), plain.coveredCount()) << "the same mesh from the same camera";

    int covered = 0, differing = 0;
    int const w = mapped.normal.width, h = mapped.normal.height;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (!mapped.covered(x, y)) continue;
            ++covered;
            glm::vec3 const a(mapped.normal.at(x, y, 0), mapped.normal.at(x, y, 1), mapped.normal.at(x, y, 2));
            glm::vec3 const b(plain.normal.at(x, y, 0), plain.normal.at(x, y, 1), plain.normal.at(x, y, 2));
            differing += glm::dot(a, b) < std::cos(glm::radians(10.0f));
        }
    // Half the tiles are flat quads whose bumps exist only in the normal map; their domes cover
    // about a fifth of the panel (measured: 19% of covered pixels turn by more than 10 degrees).
    EXPECT_GT(double(differing), 0.1 * double(covered)) << differing << " of " << covered << " pixels differ";

    // The file's point: every tile shows the same outward dome, half as geometry and half as
    // normal map. The panel faces the camera (+Z), so in each dome n.x grows to the right of
    // its centre and n.y upwards. A normal map read with the wrong tangent handedness or
    // orientation mirrors its domes in x or y. Domes: connected pixels tilted off the panel's +Z.
    std::vector<char> seen(std::size_t(w * h), 0);
    auto tilted = [&](int x, int y) { return mapped.covered(x, y) && mapped.normal.at(x, y, 2) < 0.98f; };
    int domes = 0, outward = 0;
    for (int y0 = 0; y0 < h; ++y0)
        for (int x0 = 0; x0 < w; ++x0) {
            if (seen[std::size_t(y0 * w + x0)] || !tilted(x0, y0)) continue;
            std::vector<std::pair<int, int>> pixels, stack = {{x0, y0}};
            seen[std::size_t(y0 * w + x0)] = 1;
            while (!stack.empty()) {
                auto const [x, y] = stack.back();
                stack.pop_back();
                pixels.push_back({x, y});
                for (auto const& [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
                    int const nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= w || ny >= h || seen[std::size_t(ny * w + nx)] || !tilted(nx, ny))
                        continue;
                    seen[std::size_t(ny * w + nx)] = 1;
                    stack.push_back({nx, ny});
                }
            }
            if (pixels.size() < 40) continue;  // a dome is about 14 pixels across at this size
            double cx = 0.0, cy = 0.0;
            for (auto const& [x, y] : pixels) cx += x, cy += y;
            cx /= double(pixels.size()), cy /= double(pixels.size());
            double alongX = 0.0, alongY = 0.0;  // correlation of the normal with the offset from the centre
            for (auto const& [x, y] : pixels) {
                alongX += mapped.normal.at(x, y, 0) * (x - cx);
                alongY += mapped.normal.at(x, y, 1) * (cy - y);  // image rows grow downwards
            }
            ++domes;
            outward += alongX > 0.0 && alongY > 0.0;
        }
    EXPECT_EQ(domes, 30) << "15 pairs of tiles";
    EXPECT_EQ(outward, domes) << "domes that bulge outwards in both x and y";
}

// ---------------------------------------------------------------------------------------------
// Bad input through the command line

TEST(GltfRenderBadInput, BrokenFileExitsTwoWithOneSentenceNamingIt) {
    std::string const out = test::freshTempDir("gltf_render_broken");
    std::string const file = localFile("malformed.gltf").string();
    auto const r = runGbufferLab({"render", "--scene", file, "--out", out, "--size", kSize});
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find(file), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("malformed"), std::string::npos) << r.output;
    ASSERT_FALSE(r.output.empty());
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << "one line:\n" << r.output;
    EXPECT_EQ(r.output.substr(r.output.size() - 2), ".\n") << r.output;
    EXPECT_FALSE(fs::exists(fs::path(out) / "final.png")) << "nothing rendered from a refused file";
}

TEST(GltfRenderBadInput, MissingTextureRendersWithAWarning) {
    Frame const f = renderScene(localFile("missing_texture.gltf"), "missing_texture");
    ASSERT_TRUE(f.ok) << f.output;
    EXPECT_NE(f.output.find("warning: "), std::string::npos) << f.output;
    EXPECT_NE(f.output.find("no_such_texture.png"), std::string::npos) << f.output;
    EXPECT_NE(f.output.find("placeholder"), std::string::npos) << f.output;
    EXPECT_EQ(f.stats["gl_errors"], 0);
    EXPECT_GT(f.coveredCount(), 0) << "the triangle is still drawn";
}

TEST(GltfRenderBadInput, OutsideUrisNeedTheFlag) {
    std::string const file = localFile("outside/outside_uri.gltf").string();
    std::string const out = test::freshTempDir("gltf_render_outside_refused");
    auto const refused = runGbufferLab({"render", "--scene", file, "--out", out, "--size", kSize});
    EXPECT_EQ(refused.exitCode, 2) << refused.output;
    EXPECT_NE(refused.output.find(file), std::string::npos) << refused.output;
    EXPECT_NE(refused.output.find("--allow-outside-uris"), std::string::npos) << refused.output;
    EXPECT_EQ(std::count(refused.output.begin(), refused.output.end(), '\n'), 1) << refused.output;

    // With the flag the buffer one folder up is read and its triangle drawn.
    Frame const allowed = renderScene(file, "outside_allowed", {"--allow-outside-uris"});
    ASSERT_TRUE(allowed.ok) << allowed.output;
    EXPECT_EQ(allowed.stats["gl_errors"], 0);
    EXPECT_EQ(allowed.stats["triangles"], 1);
    EXPECT_GT(allowed.coveredCount(), kWidth * kHeight / 20) << "the framed triangle";
}
