// The shader-checks build (renderer/gl/shader_checks.h, shaders/shader_checks.glsl): an
// out-of-range access in a compute shader is clamped, counted and reported with the program's and
// the access's names; the report's parts on the CPU.
#include "gl_fixture.h"
#include "test_scenes.h"

#include "gl/program_id.h"
#include "gl/shader_checks.h"

#include <unistd.h>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace gbl::test {
namespace {

TEST(ShaderCheckReport, SiteNamesComeFromTheDefinesOfTheShaderFile) {
    std::vector<std::string> const names =
        shaderCheckSiteNames("#define CHECK_SITE_TILE_BIN_LIGHT 3  // x\n#define OTHER 4\n#define CHECK_SITE_KEPT 1\n");
    ASSERT_EQ(names.size(), 4u);
    EXPECT_EQ(names[1], "kept");
    EXPECT_EQ(names[2], "");
    EXPECT_EQ(names[3], "tile bin light");
}

TEST(ShaderCheckReport, TheSentenceNamesProgramSiteIndexAndSize) {
    ShaderCheckRecord r;
    r.failures = 3;
    r.program = std::uint32_t(ProgramId::LightingTiled);
    r.site = 1;
    r.index = 1030;
    r.size = 1024;
    std::string const s = describeShaderChecks(r, {"", "kept"});
    EXPECT_EQ(s,
              "shader check: 3 out-of-range accesses this frame; the first in program lighting_tiled, kept (site 1): "
              "index 1030 outside [0, 1024)");
}

class ShaderChecksGlTest : public GlTest {};

// A copy of lighting_tiled.comp whose candidate read is pushed past the bins, hot-reloaded into a
// renderer with the checks on: the frame reports the program and the access by name, and the
// clamped read keeps the process alive.
TEST_F(ShaderChecksGlTest, AnInjectedOutOfRangeReadIsReportedByName) {
    if (!caps().computeShaders) GTEST_SKIP() << caps().tiledUnavailableReason();
    ASSERT_TRUE(shaderChecksRequested()) << "run with GBL_SHADER_CHECKS=1 (tests/CMakeLists.txt sets it)";
    namespace fs = std::filesystem;
    fs::path const dir = fs::temp_directory_path() / ("gbl_shader_checks_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    fs::path const file = dir / "lighting_tiled.comp";
    fs::copy_file(fs::path(GBL_SOURCE_DIR) / "shaders" / "lighting_tiled.comp", file,
                  fs::copy_options::overwrite_existing);
    setenv("GBL_SHADER_DIR", dir.c_str(), 1);
    auto r = makeRenderer(64, 48);
    unsetenv("GBL_SHADER_DIR");
    ASSERT_FALSE(r->setScene(floorScene()));
    Camera cam;
    cam.position = {0.0f, 5.0f, 5.0f};
    cam.lookAt({0.0f, 0.0f, 0.0f});
    PointLight light;
    light.position = {0.0f, 1.0f, 0.0f};
    std::vector<PointLight> const lights{light};
    PipelineSettings tiled;
    tiled.mode = LightingMode::Tiled;
    FrameStats const clean = r->render({cam, lights, tiled});
    ASSERT_EQ(clean.modeUsed, LightingMode::Tiled) << clean.fallbackReason;
    EXPECT_EQ(clean.shaderCheckReport, "");

    std::stringstream text;
    text << std::ifstream(file).rdbuf();
    std::string source = text.str();
    std::string const read = "int index = binnedLight(tile, k);";
    auto const at = source.find(read);
    ASSERT_NE(at, std::string::npos) << "the injection point moved; update the test";
    source.replace(at, read.size(), "int index = binnedLight(tile, k + uBinCap * 4096);");
    auto const before = fs::last_write_time(file);
    std::ofstream(file) << source;
    fs::last_write_time(file, before + std::chrono::seconds(1));
    auto const messages = r->reloadChangedShaders();
    ASSERT_FALSE(messages.empty());

    std::uint64_t const failuresBefore = shaderCheckFailureCount();
    FrameStats const broken = r->render({cam, lights, tiled});
    EXPECT_NE(broken.shaderCheckReport.find("program lighting_tiled"), std::string::npos) << broken.shaderCheckReport;
    EXPECT_NE(broken.shaderCheckReport.find("tile bin light"), std::string::npos) << broken.shaderCheckReport;
    EXPECT_GT(shaderCheckFailureCount(), failuresBefore);
    EXPECT_EQ(lastShaderCheckReport(), broken.shaderCheckReport);
    acceptGlErrors();  // the report was the point; TearDown checks from here on
    fs::remove_all(dir);
}

}  // namespace
}  // namespace gbl::test
