// The glTF fuzzer's seed corpus (tests/fuzz/corpus), mutated with a fixed seed and carried past the
// loader into every lighting mode: whatever the loader accepts must render without a crash, a GL
// error, a shader-check report or a non-finite lit value. The libFuzzer target (tests/fuzz) stops at
// the loader, since it has no GL context; this is its seeded, rendering half. Numbers in the JSON are
// the mutation's target (digits, signs, exponents), so most mutants still parse and reach the renderer.
#include "gl_fixture.h"

#include "gltf/loader.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace gbl::test {
namespace {

namespace fs = std::filesystem;

// Rewrites a few numbers of a glTF file's text: a digit becomes another, a sign flips, an exponent
// grows a number past float range, a number becomes 0.
// Positions of the digits of the JSON's numbers (not those inside strings: URIs, base64 buffers).
std::vector<std::size_t> numberDigits(std::string const& text) {
    std::vector<std::size_t> digits;
    bool inString = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '"' && (i == 0 || text[i - 1] != '\\')) inString = !inString;
        if (!inString && text[i] >= '0' && text[i] <= '9') digits.push_back(i);
    }
    return digits;
}

std::string mutateNumbers(std::string text, std::mt19937& rng) {
    std::vector<std::size_t> digits = numberDigits(text);
    if (digits.empty()) return text;
    int const edits = 1 + int(rng() % 2);
    for (int e = 0; e < edits; ++e) {
        std::size_t const at = digits[rng() % digits.size()];
        switch (rng() % 4) {
            case 0:
                text[at] = char('0' + rng() % 10);
                break;
            case 1:
                text.insert(at, "-");
                break;
            case 2:
                text.insert(at + 1, "e3");
                break;
            default:
                text[at] = '0';
                break;
        }
        digits = numberDigits(text);  // later positions moved by the insertions
    }
    return text;
}

constexpr int kMutants = 48;  // per corpus file, the unmutated one first

class GltfRenderRandomGlTest : public GlTest {};

TEST_F(GltfRenderRandomGlTest, MutatedCorpusFilesThatLoadRenderInEveryMode) {
    fs::path const corpus = fs::path(GBL_SOURCE_DIR) / "tests" / "fuzz" / "corpus";
    std::vector<fs::path> files;
    for (auto const& e : fs::directory_iterator(corpus))
        if (e.path().extension() == ".gltf") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    ASSERT_FALSE(files.empty());
    auto renderer = makeRenderer(48, 32);
    std::mt19937 rng(25);  // fixed: the same mutants every run
    int loaded = 0, frames = 0;
    for (fs::path const& file : files) {
        std::ifstream in(file, std::ios::binary);
        std::string const original((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        for (int m = 0; m < kMutants; ++m) {
            std::string const text = m == 0 ? original : mutateNumbers(original, rng);
            std::vector<std::uint8_t> const bytes(text.begin(), text.end());
            GltfLoadResult const r = loadGltfFromMemory(bytes, file);
            if (!r.scene) continue;
            if (renderer->setScene(*r.scene)) continue;  // refused with a reason: fine
            ++loaded;
            Camera const camera = r.scene->camera.value_or(Camera{});
            for (LightingMode mode : {LightingMode::Quad, LightingMode::Volumes, LightingMode::Tiled,
                                      LightingMode::Forward, LightingMode::Clustered}) {
                if (renderer->modeUnavailable(mode)) continue;
                FrameInput input;
                input.camera = camera;
                input.lights = r.scene->lights;
                input.settings.mode = mode;
                std::uint64_t const errors = glErrorsSinceSetUp();
                FrameStats const stats = renderer->render(input);
                ++frames;
                std::string const what =
                    file.filename().string() + " mutant " + std::to_string(m) + " mode " + std::to_string(int(mode));
                ASSERT_EQ(glErrorsSinceSetUp(), errors) << what;
                ASSERT_EQ(stats.shaderCheckReport, "") << what;
                FloatImage const lit = renderer->readAttachment(Attachment::Lighting);
                for (float v : lit.pixels) ASSERT_TRUE(std::isfinite(v)) << what << ": a non-finite lit value";
            }
        }
    }
    // The mutation keeps most files loadable: a run that renders almost nothing tests nothing.
    EXPECT_GT(loaded, int(files.size()) * kMutants / 8) << "of " << files.size() * kMutants << " mutants";
    RecordProperty("mutants_rendered", loaded);
    RecordProperty("frames", frames);
}

}  // namespace
}  // namespace gbl::test
