// Every program's stages under every define set it can be built with, through the Khronos
// reference compiler (glslangValidator, Debian's glslang-tools): the strictest check of the
// shaders without a GPU, since llvmpipe's compiler accepts some things others refuse. The define
// sets: each G-buffer layout's, with and without GBL_MASKED_BRANCHES (software rasterisers) and
// GBL_SHADER_CHECKS (the test build's range checks); the coverage variants are programs of their own.
#include "core/gbuffer_layout.h"
#include "gl/shader_sources.h"

#include <gtest/gtest.h>

#include <unistd.h>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace gbl {
namespace {

namespace fs = std::filesystem;

char const* stageExtension(GLenum stage) {
    switch (stage) {
        case GL_VERTEX_SHADER:
            return "vert";
        case GL_FRAGMENT_SHADER:
            return "frag";
        case GL_COMPUTE_SHADER:
            return "comp";
        default:
            return "glsl";
    }
}

// Runs the validator on one file; returns its output when it fails, "" when it passes.
std::string validate(fs::path const& file) {
    fs::path const log = file.string() + ".log";
    std::string const command = "glslangValidator \"" + file.string() + "\" > \"" + log.string() + "\" 2>&1";
    int const status = std::system(command.c_str());
    if (status == 0) return "";
    std::ifstream in(log);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return text.empty() ? "exit status " + std::to_string(status) : text;
}

TEST(ShaderCompile, EveryProgramUnderEveryDefineSetPassesTheReferenceCompiler) {
    if (std::system("glslangValidator --version > /dev/null 2>&1") != 0)
        GTEST_FAIL() << "glslangValidator not found: install Debian's glslang-tools (scripts/install-deps.sh does)";
    fs::path const dir = fs::temp_directory_path() / ("gbl_glslang_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    ShaderSources shaders{fs::path()};
    int variants = 0;
    std::vector<std::string> failures;
    for (GBufferLayout layout :
         {GBufferLayout::Classic, GBufferLayout::Packed, GBufferLayout::Naive8, GBufferLayout::Rgb10a2})
        for (bool masked : {false, true})
            for (bool checks : {false, true}) {
                std::vector<std::string> defines = layoutShaderDefines(layoutDesc(layout));
                if (masked) defines.push_back("GBL_MASKED_BRANCHES");
                if (checks) defines.push_back("GBL_SHADER_CHECKS");
                shaders.setGlobalDefines(defines);
                std::string defineNames;
                for (auto const& d : defines) defineNames += " " + d;
                for (ProgramInfo const& p : programTable())
                    for (auto const& [stage, file] : p.desc.stages) {
                        std::string error;
                        auto const text = shaders.stageSource(p.id, file, &error);
                        ASSERT_TRUE(text.has_value()) << file << ": " << error;
                        fs::path const out =
                            dir / (p.desc.name + "_" + std::to_string(variants) + "." + stageExtension(stage));
                        std::ofstream(out) << *text;
                        ++variants;
                        if (std::string const log = validate(out); !log.empty())
                            failures.push_back(p.desc.name + " (" + file + ", defines" + defineNames + "):\n" + log);
                    }
            }
    EXPECT_TRUE(failures.empty()) << failures.size() << " of " << variants << " stage variants failed; the first:\n"
                                  << failures.front();
    EXPECT_GT(variants, 100);
    fs::remove_all(dir);
}

// The browser build's text (issue 29): every vertex and fragment stage as the shader library emits it
// for WebGL2 (GLSL ES 3.00, precision statements, the light buffer as a 2D texture), per G-buffer
// layout. Compute stages are left out: WebGL2 has none and the library never builds them there. So are,
// for now, the stages that still read a list other than the lights through a buffer texture (the
// light volumes' instance list, isamplerBuffer): volumes mode is unavailable in the browser until that
// list is a 2D texture too; the test prints which stages it left out.
TEST(ShaderCompile, EveryWebGL2StagePassesTheReferenceCompilerAsGlslEs300) {
    if (std::system("glslangValidator --version > /dev/null 2>&1") != 0)
        GTEST_FAIL() << "glslangValidator not found: install Debian's glslang-tools (scripts/install-deps.sh does)";
    fs::path const dir = fs::temp_directory_path() / ("gbl_glslang_es_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    ShaderSources shaders{fs::path()};
    shaders.setEsProfile(true);
    int variants = 0;
    std::vector<std::string> failures;
    for (GBufferLayout layout :
         {GBufferLayout::Classic, GBufferLayout::Packed, GBufferLayout::Naive8, GBufferLayout::Rgb10a2}) {
        shaders.setGlobalDefines(layoutShaderDefines(layoutDesc(layout)));
        for (ProgramInfo const& p : programTable())
            for (auto const& [stage, file] : p.desc.stages) {
                if (stage == GL_COMPUTE_SHADER) continue;
                // forward+ reads storage buffers, which WebGL2 lacks: the browser never builds it
                // (GlCaps::computeUnavailableReason refuses the mode there).
                if (p.group == ProgramGroup::ForwardPlus) continue;
                std::string error;
                auto const text = shaders.stageSource(p.id, file, &error);
                ASSERT_TRUE(text.has_value()) << file << ": " << error;
                ASSERT_NE(text->find("#version 300 es"), std::string::npos) << file;
                if (text->find("isamplerBuffer") != std::string::npos ||
                    text->find("usamplerBuffer") != std::string::npos) {
                    if (layout == GBufferLayout::Classic)
                        std::printf("left out (reads a buffer texture): %s (%s)\n", p.desc.name.c_str(), file.c_str());
                    continue;
                }
                fs::path const out = dir / (p.desc.name + "_" + std::to_string(variants) + "." + stageExtension(stage));
                std::ofstream(out) << *text;
                ++variants;
                if (std::string const log = validate(out); !log.empty())
                    failures.push_back(p.desc.name + " (" + file + ", " + std::string(layoutDesc(layout).name) +
                                       "):\n" + log);
            }
    }
    EXPECT_TRUE(failures.empty()) << failures.size() << " of " << variants << " stage variants failed; the first:\n"
                                  << (failures.empty() ? std::string() : failures.front());
    EXPECT_GT(variants, 20);
    fs::remove_all(dir);
}

// Each view's own program (view.frag with VIEW_ONLY, built by ShaderLibrary::variant on first
// use), desktop and WebGL2 text, with and without position from depth (packed).
TEST(ShaderCompile, EveryViewsOwnProgramPassesTheReferenceCompiler) {
    if (std::system("glslangValidator --version > /dev/null 2>&1") != 0)
        GTEST_FAIL() << "glslangValidator not found: install Debian's glslang-tools (scripts/install-deps.sh does)";
    fs::path const dir = fs::temp_directory_path() / ("gbl_glslang_views_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::vector<std::string> failures;
    int variants = 0;
    for (bool es : {false, true})
        for (GBufferLayout layout : {GBufferLayout::Classic, GBufferLayout::Packed}) {
            ShaderSources shaders{fs::path()};
            shaders.setEsProfile(es);
            shaders.setGlobalDefines(layoutShaderDefines(layoutDesc(layout)));
            for (std::size_t v = 0; v < kDebugViewNames.size(); ++v) {
                std::string error;
                auto const text =
                    shaders.stageSource(ProgramId::View, "view.frag", &error, "VIEW_ONLY " + std::to_string(v));
                ASSERT_TRUE(text.has_value()) << error;
                fs::path const out = dir / ("view_" + std::to_string(variants++) + ".frag");
                std::ofstream(out) << *text;
                if (std::string const log = validate(out); !log.empty())
                    failures.push_back(std::string(kDebugViewNames[v]) + (es ? " (GLSL ES)" : "") + ":\n" + log);
            }
        }
    EXPECT_TRUE(failures.empty()) << failures.size() << " of " << variants << " failed; the first:\n"
                                  << (failures.empty() ? std::string() : failures.front());
    EXPECT_EQ(variants, 4 * int(kDebugViewNames.size()));
    fs::remove_all(dir);
}

}  // namespace
}  // namespace gbl
