// The deferred core on a headless context: resizing, shader hot reload and a volume program that
// fails to build, the timed passes, stopping after a pass, the sampler units. The pixels against
// analytic values and the CPU equation: renderer_shading_gl_test.
#include "core/frame_passes.h"
#include "gl/shader_bindings.h"
#include "gl/shader_library.h"
#include "gl_fixture.h"
#include "gpu/light_buffer.h"
#include "test_scenes.h"

#include <glm/gtc/matrix_transform.hpp>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <thread>

using namespace gbl;
using gbl::test::GlTest;

namespace {

using test::lookingAt;
using test::plainSettings;

}  // namespace

class RendererGlTest : public GlTest {};

TEST_F(RendererGlTest, ResizeToZeroAndBackKeepsWorking) {
    auto r = makeRenderer(40, 30);
    ASSERT_FALSE(r->setScene(test::floorScene()));
    Camera const cam = lookingAt({0.0f, 5.0f, 5.0f}, {0.0f, 0.0f, 0.0f});
    r->render({cam, {}, plainSettings()});
    r->resizeTargets(0, 0);
    EXPECT_EQ(r->texture(Attachment::Final), 0u);
    FrameStats const empty = r->render({cam, {}, plainSettings()});
    EXPECT_EQ(empty.width, 0);
    EXPECT_TRUE(empty.passes.empty()) << "nothing is drawn into 0x0 targets";
    EXPECT_EQ(r->readAttachment(Attachment::Final).width, 0);
    r->resizeTargets(33, 17);  // odd sizes: no assumption of even or tile-aligned sizes
    FrameStats const back = r->render({cam, {}, plainSettings()});
    EXPECT_EQ(back.width, 33);
    EXPECT_FALSE(back.passes.empty());
    FloatImage const n = r->readAttachment(Attachment::Normal);
    EXPECT_EQ(n.width, 33);
    EXPECT_EQ(n.height, 17);
    EXPECT_EQ(n.at(16, 16, 1), 1.0f) << "the floor is drawn again after the resize";
    // Every target is checked for completeness when created; an incomplete one throws.
    EXPECT_NO_THROW(r->resizeTargets(1, 1));
}

TEST_F(RendererGlTest, FailedHotReloadKeepsLastGoodProgram) {
    namespace fs = std::filesystem;
    fs::path const dir = fs::temp_directory_path() / ("gbl_reload_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    fs::copy_file(fs::path(GBL_SOURCE_DIR) / "shaders" / "depth_copy.frag", dir / "depth_copy.frag",
                  fs::copy_options::overwrite_existing);
    ShaderLibrary lib(dir);
    std::string log;
    ASSERT_TRUE(lib.add(ProgramId::DepthCopy, &log)) << log;
    GLuint const good = lib.get(ProgramId::DepthCopy).id();
    EXPECT_TRUE(lib.reloadChanged().empty()) << "nothing changed yet";

    auto writeLater = [&](std::string const& text) {
        // File times can be coarse; make sure the new write is seen as a change.
        auto const before = fs::last_write_time(dir / "depth_copy.frag");
        std::ofstream(dir / "depth_copy.frag") << text;
        fs::last_write_time(dir / "depth_copy.frag", before + std::chrono::seconds(1));
    };
    writeLater("#version 330 core\nvoid main() { this is not glsl; }\n");
    auto messages = lib.reloadChanged();
    ASSERT_EQ(messages.size(), 1u);
    EXPECT_NE(messages[0].find("keeping the last good one"), std::string::npos) << messages[0];
    EXPECT_NE(messages[0].find("depth_copy.frag"), std::string::npos) << "the log names the file: " << messages[0];
    EXPECT_EQ(lib.get(ProgramId::DepthCopy).id(), good) << "the last good program stays in use";

    std::ifstream original(fs::path(GBL_SOURCE_DIR) / "shaders" / "depth_copy.frag");
    writeLater(std::string(std::istreambuf_iterator<char>(original), {}));
    messages = lib.reloadChanged();
    ASSERT_EQ(messages.size(), 1u);
    EXPECT_NE(messages[0].find("reloaded"), std::string::npos) << messages[0];
    EXPECT_NE(lib.get(ProgramId::DepthCopy).id(), good);
    fs::remove_all(dir);
}

TEST_F(RendererGlTest, GpuTimingsCoverEveryPass) {
    auto r = makeRenderer(32, 32);
    ASSERT_FALSE(r->setScene(test::floorScene()));
    FrameStats const s = r->render({lookingAt({0, 5, 5}, {0, 0, 0}), {}, plainSettings()});
    std::vector<std::string> names;
    for (auto const& p : s.passes) {
        names.push_back(p.name);
        EXPECT_GE(p.gpuMs, 0.0);
    }
    EXPECT_EQ(names, (std::vector<std::string>{"geometry", "lighting", "depth_copy", "forward", "display"}));
}

TEST_F(RendererGlTest, TheTimedPassesAreTheDeclaredOnes) {
    // core/frame_passes.h describes the frame render() runs: the timer's names, in order, are the
    // declared passes' for every mode and layout, with and without the optional passes.
    auto r = makeRenderer(32, 24);
    ASSERT_FALSE(r->setScene(test::floorScene()));
    PointLight light;
    light.position = {0, 1, 0};
    std::vector<PointLight> const lights{light};
    int frames = 0;
    for (std::size_t layout = 0; layout < kGBufferLayoutNames.size(); ++layout)
        for (std::size_t mode = 0; mode < kLightingModeNames.size(); ++mode)
            for (CullMode cull : {CullMode::Front, CullMode::Stencil})
                for (bool extras : {false, true}) {
                    PipelineSettings s = plainSettings();
                    s.layout = GBufferLayout(layout);
                    s.mode = LightingMode(mode);
                    s.cull = cull;
                    s.lightCubes = s.volumeWireframes = extras;
                    s.accumulation = extras ? LightAccumulation::Split : LightAccumulation::Single;
                    s.view = extras ? DebugView::Heatmap : DebugView::Final;
                    FrameStats const st = r->render({lookingAt({0, 5, 5}, {0, 0, 0}), lights, s});
                    s.mode = st.modeUsed;  // as it ran (a mode this context lacks falls back to quad)
                    std::vector<std::string> timed, declared;
                    for (auto const& p : st.passes) timed.push_back(p.name);
                    for (PassDecl const& p : framePasses(s)) declared.emplace_back(p.name());
                    EXPECT_EQ(timed, declared) << kGBufferLayoutNames[layout] << " " << kLightingModeNames[mode];
                    EXPECT_EQ(st.glErrors, 0u);
                    ++frames;
                }
    EXPECT_EQ(frames, 4 * 7 * 2 * 2);  // layouts, modes (forward+ the sixth, prepass the seventh), cull modes, extras
}

namespace {
float maxAbs(FloatImage const& image, int channels) {
    float m = 0.0f;
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        if (int(i % std::size_t(image.channels)) < channels) m = std::max(m, std::abs(image.pixels[i]));
    return m;
}
}  // namespace

TEST_F(RendererGlTest, StoppingAfterGeometryLeavesTheLitTargetCleared) {
    int const w = 48, h = 32;
    auto r = makeRenderer(w, h);
    ASSERT_FALSE(r->setScene(test::floorScene()));
    PointLight light;
    light.position = {0.0f, 1.0f, 0.0f};
    std::vector<PointLight> const lights{light};
    Camera const cam = lookingAt({0, 5, 5}, {0, 0, 0});
    for (LightingMode mode :
         {LightingMode::Quad, LightingMode::Volumes, LightingMode::Tiled, LightingMode::Clustered}) {
        PipelineSettings s = plainSettings();
        s.mode = mode;
        s.lightCubes = true;
        std::string const name(enumName(kLightingModeNames, mode));
        r->render({cam, lights, s});  // a whole frame first: its light must not survive the stopped one
        ASSERT_GT(maxAbs(r->readAttachment(Attachment::Lighting), 3), 0.0f) << name;
        FrameInput input{cam, lights, s};
        input.stopAfter = PassId::Geometry;
        FrameStats const st = r->render(input);
        EXPECT_EQ(st.stoppedAfter, PassId::Geometry) << name;
        EXPECT_EQ(st.fallbackReason, "") << name;
        std::vector<std::string> ran;
        for (auto const& p : st.passes) ran.push_back(p.name);
        EXPECT_EQ(ran, (std::vector<std::string>{"geometry", "display"})) << name;
        // Exactly zero: the stopped frame cleared the lit target and nothing drew into it since.
        EXPECT_EQ(maxAbs(r->readAttachment(Attachment::Lighting), 4), 0.0f) << name;
        EXPECT_EQ(maxAbs(r->readAttachment(Attachment::Final), 3), 0.0f) << name << ": the display shows it black";
        // The G-buffer is filled: the floor covers the lower part of the view with its albedo.
        FloatImage const pos = r->readAttachment(Attachment::Position);
        FloatImage const alb = r->readAttachment(Attachment::AlbedoSpec);
        EXPECT_EQ(pos.at(w / 2, h - 1, 3), 1.0f) << name;
        EXPECT_NEAR(alb.at(w / 2, h - 1, 0), test::kPlaneAlbedo.x, 1.0f / 255.0f) << name;  // RGBA8: one step
        EXPECT_EQ(st.glErrors, 0u) << name;
    }
}

TEST_F(RendererGlTest, StoppingAfterLightingGivesTheLightSumWithoutCubes) {
    int const w = 48, h = 32;
    auto r = makeRenderer(w, h);
    ASSERT_FALSE(r->setScene(test::floorScene()));  // no blended surfaces: the forward pass adds nothing
    PointLight light;
    light.position = {0.0f, 1.0f, 0.0f};
    std::vector<PointLight> const lights{light};
    Camera const cam = lookingAt({0, 5, 5}, {0, 0, 0});
    // The largest difference of the colour channels (alpha is not part of the light sum).
    auto maxDiff = [](FloatImage const& a, FloatImage const& b) {
        float m = 0.0f;
        for (std::size_t i = 0; i < a.pixels.size(); ++i)
            if (i % 4 != 3) m = std::max(m, std::abs(a.pixels[i] - b.pixels[i]));
        return m;
    };
    for (LightingMode mode :
         {LightingMode::Quad, LightingMode::Volumes, LightingMode::Tiled, LightingMode::Clustered}) {
        std::string const name(enumName(kLightingModeNames, mode));
        PipelineSettings s = plainSettings();
        s.mode = mode;
        s.lightCubes = false;
        r->render({cam, lights, s});
        FloatImage const withoutCubes = r->readAttachment(Attachment::Lighting);
        FloatImage const displayWithoutCubes = r->readAttachment(Attachment::Final);
        s.lightCubes = true;
        r->render({cam, lights, s});
        FloatImage const withCubes = r->readAttachment(Attachment::Lighting);
        FloatImage const displayWithCubes = r->readAttachment(Attachment::Final);
        FrameInput input{cam, lights, s};
        input.stopAfter = PassId::Lighting;
        FrameStats const st = r->render(input);
        EXPECT_EQ(st.stoppedAfter, PassId::Lighting) << name;
        FloatImage const stopped = r->readAttachment(Attachment::Lighting);
        ASSERT_EQ(stopped.pixels.size(), withoutCubes.pixels.size());
        EXPECT_GT(maxAbs(stopped, 3), 0.0f) << name << ": the light sum is there";
        // The same passes drew the same light into the same target: equal to the bit. The cubes are an
        // overlay on the display image, so the whole frame's lit image is the same with them.
        EXPECT_EQ(maxDiff(stopped, withoutCubes), 0.0f) << name << ": stopped after lighting = a frame without cubes";
        EXPECT_EQ(maxDiff(stopped, withCubes), 0.0f) << name << ": the lit image holds no cube";
        // On the display, the stopped frame shows no cube: the cube (kLightCubeEmissive x white,
        // tonemapped to 0.88) is far brighter than the floor there.
        FloatImage const stoppedDisplay = r->readAttachment(Attachment::Final);
        EXPECT_EQ(maxDiff(stoppedDisplay, displayWithoutCubes), 0.0f) << name;
        EXPECT_GT(maxDiff(stoppedDisplay, displayWithCubes), 0.3f) << name << ": the full frame shows the cube";
        EXPECT_EQ(st.glErrors, 0u) << name;
    }
}

TEST_F(RendererGlTest, AStopThisFrameDoesNotRunIsReportedAndTheWholeFrameRuns) {
    auto r = makeRenderer(32, 24);
    ASSERT_FALSE(r->setScene(test::floorScene()));
    FrameInput input{lookingAt({0, 5, 5}, {0, 0, 0}), {}, plainSettings()};
    input.stopAfter = PassId::LightLists;  // quad mode builds no light lists
    EXPECT_EQ(r->framePasses(input).size(), 5u);
    FrameStats const st = r->render(input);
    EXPECT_EQ(st.stoppedAfter, std::nullopt);
    EXPECT_NE(st.fallbackReason.find("cannot stop after 'light_lists'"), std::string::npos) << st.fallbackReason;
    EXPECT_EQ(st.passes.size(), 5u);
    EXPECT_EQ(st.glErrors, 0u);
}

TEST_F(RendererGlTest, EverySamplerReadsTheUnitOfBindingsGlsl) {
    // After linking, the library points each sampler at its slot of shaders/bindings.glsl; a
    // sampler missing from the table would silently read unit 0.
    ShaderLibrary lib("");
    std::map<std::string, int> slots;
    for (auto const& s : slot::kSamplerSlots) slots[s.uniform] = s.unit;
    int samplers = 0;
    for (ProgramInfo const& info : programTable()) {
        if ((info.group == ProgramGroup::Tiled || info.group == ProgramGroup::ForwardPlus) && !caps().computeShaders)
            continue;
        std::string log;
        ASSERT_TRUE(lib.add(info.id, &log)) << info.desc.name << ": " << log;
        GLuint const program = lib.get(info.id).id();
        GLint count = 0;
        glGetProgramiv(program, GL_ACTIVE_UNIFORMS, &count);
        std::map<int, std::string> unitUsers;
        for (GLint i = 0; i < count; ++i) {
            char name[128];
            GLint size = 0;
            GLenum type = 0;
            glGetActiveUniform(program, GLuint(i), sizeof name, nullptr, &size, &type, name);
            bool const sampler = type == GL_SAMPLER_2D || type == GL_SAMPLER_BUFFER || type == GL_INT_SAMPLER_BUFFER;
            if (!sampler) continue;
            ++samplers;
            auto const it = slots.find(name);
            ASSERT_NE(it, slots.end()) << info.desc.name << ": sampler " << name << " has no slot in bindings.glsl";
            GLint unit = -1;
            glGetUniformiv(program, glGetUniformLocation(program, name), &unit);
            EXPECT_EQ(unit, it->second) << info.desc.name << ": " << name;
            // Two samplers on one unit within a program would read the same texture.
            EXPECT_TRUE(unitUsers.emplace(unit, name).second)
                << info.desc.name << ": " << name << " and " << unitUsers[unit] << " share unit " << unit;
        }
    }
    EXPECT_GT(samplers, 20) << "the programs declare samplers; none found means the query is wrong";
}

TEST_F(RendererGlTest, VolumeProgramThatFailsToBuildFallsBackToQuadWithTheReason) {
    namespace fs = std::filesystem;
    // A shader directory whose light_volume.frag is broken, seen by hot reload before the
    // volumes mode is first used: building its programs then fails inside render().
    fs::path const dir = fs::temp_directory_path() / ("gbl_broken_volume_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    fs::copy_file(fs::path(GBL_SOURCE_DIR) / "shaders" / "light_volume.frag", dir / "light_volume.frag",
                  fs::copy_options::overwrite_existing);
    setenv("GBL_SHADER_DIR", dir.c_str(), 1);
    auto r = makeRenderer(48, 32);
    unsetenv("GBL_SHADER_DIR");
    auto const before = fs::last_write_time(dir / "light_volume.frag");
    std::ofstream(dir / "light_volume.frag") << "#version 330 core\nvoid main() { this is not glsl; }\n";
    fs::last_write_time(dir / "light_volume.frag", before + std::chrono::seconds(1));
    r->reloadChangedShaders();

    ASSERT_FALSE(r->setScene(test::floorScene()));
    Camera const cam = lookingAt({0.0f, 5.0f, 5.0f}, {0.0f, 0.0f, 0.0f});
    PointLight light;
    light.position = {0.0f, 1.0f, 0.0f};
    std::vector<PointLight> const lights{light};
    PipelineSettings volumes = plainSettings();
    volumes.mode = LightingMode::Volumes;
    FrameStats const st = r->render({cam, lights, volumes});
    EXPECT_EQ(st.modeUsed, LightingMode::Quad);
    EXPECT_NE(st.fallbackReason.find("light_volume"), std::string::npos) << st.fallbackReason;
    EXPECT_NE(st.fallbackReason.find("quad"), std::string::npos) << st.fallbackReason;
    auto const why = r->modeUnavailable(LightingMode::Volumes);
    ASSERT_TRUE(why.has_value());
    EXPECT_NE(why->find("volumes mode is unavailable"), std::string::npos) << *why;
    EXPECT_FALSE(r->modeUnavailable(LightingMode::Quad));
    // What ran is exactly the quad pass.
    FloatImage const fallback = r->readAttachment(Attachment::Lighting);
    r->render({cam, lights, plainSettings()});
    EXPECT_EQ(fallback.pixels, r->readAttachment(Attachment::Lighting).pixels);
    fs::remove_all(dir);
}
