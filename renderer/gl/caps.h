// What the current GL context can do, detected once at start-up.
#pragma once

#include <string>

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

    bool atLeast(int maj, int min) const { return major > maj || (major == maj && minor >= min); }

    // Why tiled lighting is unavailable, or empty when it is available.
    std::string tiledUnavailableReason() const {
        return computeShaders ? std::string()
                              : "compute shaders need OpenGL 4.3; this context is " + std::to_string(major) + "." +
                                    std::to_string(minor) + ", so tiled mode is unavailable";
    }
    std::string pipelineStatisticsUnavailableReason() const {
        return pipelineStatistics ? std::string()
                                  : "fragment invocation counts need ARB_pipeline_statistics_query, which this "
                                    "context lacks";
    }
};

// Reads the current context. limitMajor/limitMinor > 0 pretend the context is at most that
// version (to try the OpenGL 3.3 floor on a newer driver): features above it read as absent.
GlCaps detectGlCaps(int limitMajor = 0, int limitMinor = 0);

}  // namespace gbl
