// What the current GL context can do, detected once at start-up.
#pragma once

#include "gl/gl_api.h"

#include <string>
#include <string_view>

namespace gbl {

struct GlCaps {
    int major = 0;
    int minor = 0;
    std::string vendor;
    std::string renderer;
    std::string version;
    std::string glslVersion;
    bool khrDebug = false;            // GL 4.3 or GL_KHR_debug: debug callback and object labels
    bool computeShaders = false;      // GL 4.3 or ARB_compute_shader + SSBOs: tiled lighting
    bool pipelineStatistics = false;  // ARB_pipeline_statistics_query: fragment invocations
    // The rasteriser runs shaders on the CPU and executes both sides of every branch under a mask
    // (Mesa's llvmpipe and softpipe), so a test that only skips work saves nothing and costs its
    // mask: the light loops are then built without such tests (GBL_MASKED_BRANCHES,
    // shaders/light_accumulation.glsl). GBL_SHADER_BRANCHES=masked or =skipping overrides it.
    bool masksBranches = false;
    // Limits, read once here so no pass queries GL at draw time.
    long long maxStorageBlockBytes = 0;  // GL_MAX_SHADER_STORAGE_BLOCK_SIZE (0 without compute shaders)
    int maxTextureBufferTexels = 0;      // GL_MAX_TEXTURE_BUFFER_SIZE (desktop)
    int maxTextureSize = 0;              // GL_MAX_TEXTURE_SIZE
    // Multisampling (the MSAA G-buffer): GL_MAX_SAMPLES, GL_MAX_COLOR_TEXTURE_SAMPLES and
    // GL_MAX_DEPTH_TEXTURE_SAMPLES; 0 in WebGL2, which has no multisample textures.
    int maxSamples = 0;
    int maxColorTextureSamples = 0;
    int maxDepthTextureSamples = 0;
    // Free video memory in KiB at start-up, where the driver reports it (GL_NVX_gpu_memory_info's
    // available memory, or GL_ATI_meminfo's free texture memory), and which extension said so; 0 and
    // empty elsewhere. The msaa targets' budget is half of it (docs/msaa.md).
    long long freeVideoMemoryKiB = 0;
    std::string freeVideoMemorySource;

    bool atLeast(int maj, int min) const { return major > maj || (major == maj && minor >= min); }

    // Why a compute mode ("tiled", "clustered") is unavailable for want of compute shaders, or
    // empty when they exist. WebGL2 has none at any version, and its 3.0 is ES's, not desktop GL's.
    std::string computeUnavailableReason(std::string const& mode) const {
        if (computeShaders) return {};
        if (gl::kWebGL2)
            return "compute shaders need OpenGL 4.3 and WebGL2 has none, so " + mode +
                   " mode is unavailable in the browser";
        return "compute shaders need OpenGL 4.3; this context is " + std::to_string(major) + "." +
               std::to_string(minor) + ", so " + mode + " mode is unavailable";
    }
    // Why tiled lighting is unavailable, or empty when it is available.
    std::string tiledUnavailableReason() const { return computeUnavailableReason("tiled"); }
    // How the light loops were built for this context, one line for bench and the editor's info.
    std::string lightLoopsNote() const {
        return masksBranches ? "built for masked branches: this rasteriser runs both sides of every branch,\nso "
                               "lights out of reach are shaded with a zero factor instead of tested\n"
                               "(GBL_SHADER_BRANCHES=skipping builds the tests)"
                             : "lights out of reach are skipped after a distance test";
    }
    // The most samples a multisampled G-buffer can have here (colour and depth textures both).
    int maxMsaaSamples() const {
        int const m = maxSamples < maxColorTextureSamples ? maxSamples : maxColorTextureSamples;
        return m < maxDepthTextureSamples ? m : maxDepthTextureSamples;
    }
    // Why a G-buffer of `samples` samples cannot be made here, in one sentence, or empty when it can.
    std::string msaaUnavailableReason(int samples) const {
        if (gl::kWebGL2)
            return "WebGL2 has multisampled renderbuffers but no multisample textures to light from, so MSAA is "
                   "unavailable in the browser";
        if (samples <= maxMsaaSamples()) return {};
        return std::to_string(samples) + " samples exceed this driver's limit (GL_MAX_SAMPLES " +
               std::to_string(maxSamples) + ", GL_MAX_COLOR_TEXTURE_SAMPLES " + std::to_string(maxColorTextureSamples) +
               ", GL_MAX_DEPTH_TEXTURE_SAMPLES " + std::to_string(maxDepthTextureSamples) + ")";
    }
    std::string pipelineStatisticsUnavailableReason() const {
        return pipelineStatistics ? std::string()
                                  : "fragment invocation counts need ARB_pipeline_statistics_query, which this "
                                    "context lacks";
    }
};

// Whether a context with this GL_RENDERER string masks branches (GlCaps::masksBranches);
// `override` is GBL_SHADER_BRANCHES ("masked", "skipping"; null or anything else: detect).
bool rendererMasksBranches(std::string_view renderer, char const* override);

// Reads the current context. limitMajor/limitMinor > 0 pretend the context is at most that
// version (to try the OpenGL 3.3 floor on a newer driver): features above it read as absent.
GlCaps detectGlCaps(int limitMajor = 0, int limitMinor = 0);

}  // namespace gbl
