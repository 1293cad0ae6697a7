// Capability detection for the current context.
#include "gl/caps.h"

#include "gl/gl_api.h"
#include "gl/sample_limit.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace gbl {

namespace {
std::string glString(GLenum name) {
    auto const* s = reinterpret_cast<char const*>(glGetString(name));
    return s ? s : "";
}
}  // namespace

bool rendererMasksBranches(std::string_view renderer, char const* override) {
    std::string_view const choice = override ? override : "";
    if (choice == "masked") return true;
    if (choice == "skipping") return false;
    return renderer.find("llvmpipe") != std::string_view::npos || renderer.find("softpipe") != std::string_view::npos;
}

std::string applySampleLimit(GlCaps& caps, char const* value) {
    if (!value) return {};
    int n = 0;
    char const* const end = value + std::strlen(value);
    auto const [stop, ec] = std::from_chars(value, end, n);
    if (ec != std::errc() || stop != end || n < 1 || n > 64)
        return std::string("GBL_MAX_SAMPLES=") + value +
               " is not a sample count from 1 to 64, so the driver's sample limits are used";
    for (int* limit : {&caps.maxSamples, &caps.maxColorTextureSamples, &caps.maxDepthTextureSamples})
        *limit = std::min(*limit, n);
    return {};
}

GlCaps detectGlCaps(int limitMajor, int limitMinor) {
    GlCaps caps;
    glGetIntegerv(GL_MAJOR_VERSION, &caps.major);
    glGetIntegerv(GL_MINOR_VERSION, &caps.minor);
    caps.vendor = glString(GL_VENDOR);
    caps.renderer = glString(GL_RENDERER);
    caps.version = glString(GL_VERSION);
    caps.glslVersion = glString(GL_SHADING_LANGUAGE_VERSION);
    bool limited = false;
    if (limitMajor > 0 && !(caps.major < limitMajor || (caps.major == limitMajor && caps.minor <= limitMinor))) {
        caps.major = limitMajor;
        caps.minor = limitMinor;
        limited = true;
    }
    // Under a version limit, extensions that bring a newer version's feature are ignored too, so
    // the limit shows what a real context of that version would offer.
    auto has = [&](char const* ext) { return !limited && gl::hasExtension(ext); };
    caps.khrDebug = caps.atLeast(4, 3) || has("GL_KHR_debug");
    caps.computeShaders =
        caps.atLeast(4, 3) || (has("GL_ARB_compute_shader") && has("GL_ARB_shader_storage_buffer_object") &&
                               has("GL_ARB_shader_image_load_store"));
    caps.pipelineStatistics = caps.atLeast(4, 6) || has("GL_ARB_pipeline_statistics_query");
    caps.masksBranches = rendererMasksBranches(caps.renderer, std::getenv("GBL_SHADER_BRANCHES"));
    if (caps.computeShaders) {
        GLint64 maxBlock = 0;
        glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlock);
        caps.maxStorageBlockBytes = maxBlock;
    }
    if (gl::kBufferTextures) glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &caps.maxTextureBufferTexels);
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &caps.maxTextureSize);
    if (!gl::kWebGL2) {
        glGetIntegerv(GL_MAX_SAMPLES, &caps.maxSamples);
        glGetIntegerv(GL_MAX_COLOR_TEXTURE_SAMPLES, &caps.maxColorTextureSamples);
        glGetIntegerv(GL_MAX_DEPTH_TEXTURE_SAMPLES, &caps.maxDepthTextureSamples);
        if (std::string const why = applySampleLimit(caps, std::getenv("GBL_MAX_SAMPLES")); !why.empty())
            std::fprintf(stderr, "%s\n", why.c_str());
        // The vendors' memory queries (their enums, as their extension specifications give them).
        constexpr GLenum kNvxAvailableKiB = 0x9049;  // GPU_MEMORY_INFO_CURRENT_AVAILABLE_VIDMEM_NVX
        constexpr GLenum kAtiTextureFree = 0x87FC;   // TEXTURE_FREE_MEMORY_ATI: 4 values, [0] the free KiB
        GLint values[4] = {0, 0, 0, 0};
        if (has("GL_NVX_gpu_memory_info")) {
            glGetIntegerv(kNvxAvailableKiB, values);
            caps.freeVideoMemorySource = "GL_NVX_gpu_memory_info";
        } else if (has("GL_ATI_meminfo")) {
            glGetIntegerv(kAtiTextureFree, values);
            caps.freeVideoMemorySource = "GL_ATI_meminfo";
        }
        caps.freeVideoMemoryKiB = values[0];
        if (caps.freeVideoMemoryKiB <= 0) caps.freeVideoMemorySource.clear();
    }
    return caps;
}

}  // namespace gbl
