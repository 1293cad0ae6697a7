// The optional lighting modes: their programs are built when the mode is first asked for, and a
// mode that cannot run on this context says why in one sentence (the quad pass runs instead).
#include "renderer_impl.h"

#include <algorithm>
#include <string>

namespace gbl {

namespace {

// The line of a compiler log that says what went wrong (the first one naming an error), so a
// mode's reason stays one sentence; the whole log stays in ShaderLibrary::failureLog().
std::string firstErrorLine(std::string const& log) {
    std::string first;
    std::size_t pos = 0;
    while (pos < log.size()) {
        std::size_t const end = std::min(log.find('\n', pos), log.size());
        std::string line = log.substr(pos, end - pos);
        pos = end + 1;
        if (line.empty() || line.rfind("failed to ", 0) == 0) continue;  // our own stage headers
        if (first.empty()) first = line;
        if (line.find("error") != std::string::npos || line.find("ERROR") != std::string::npos) return line;
    }
    return first.empty() ? "no compiler log" : first;
}

std::string programFailure(std::string const& mode, ShaderLibrary const& shaders, ProgramId id) {
    return mode + " mode is unavailable: its shader program " + programInfo(id).desc.name +
           " failed to build on this context (" + firstErrorLine(shaders.failureLog(id)) + ")";
}

}  // namespace

// --- optional modes ------------------------------------------------------------------------------

bool RendererImpl::volumesReady() {
    OptionalFeature& f = volumesFeature;
    if (f.tried) return !f.unavailable;
    f.tried = true;
    for (ProgramInfo const& p : programTable()) {
        if (p.group != ProgramGroup::Volumes || shaders.add(p.id, nullptr)) continue;
        f.unavailable = programFailure("volumes", shaders, p.id);
        return false;
    }
    // Creating the mesh allocates GL objects; a failure there must not escape the frame loop.
    try {
        volumes = createLightVolumeGpu();
    } catch (std::exception const& e) {
        f.unavailable =
            std::string("volumes mode is unavailable: the light-volume mesh could not be created (") + e.what() + ")";
        return false;
    }
    return true;
}

bool RendererImpl::tiledReady() {
    OptionalFeature& f = tiledFeature;
    if (f.tried) return !f.unavailable;
    f.tried = true;
    if (!caps.computeShaders)
        f.unavailable = caps.tiledUnavailableReason();
    else
        for (ProgramId id : {ProgramId::LightingTiled, ProgramId::TileBin, ProgramId::TileDepth})
            if (!f.unavailable && !shaders.add(id, nullptr)) f.unavailable = programFailure("tiled", shaders, id);
    return !f.unavailable;
}

bool RendererImpl::clusteredReady() {
    OptionalFeature& f = clusteredFeature;
    if (f.tried) return !f.unavailable;
    f.tried = true;
    if (!caps.computeShaders) {
        f.unavailable = caps.computeUnavailableReason("clustered");
        return false;
    }
    for (ProgramId id : {ProgramId::ClusterBuild, ProgramId::ClusterBin, ProgramId::TileDepth, ProgramId::ClusterShade})
        if (!shaders.add(id, nullptr)) {
            f.unavailable = programFailure("clustered", shaders, id);
            return false;
        }
    return true;
}

bool RendererImpl::forwardPlusReady() {
    OptionalFeature& f = forwardPlusFeature;
    if (f.tried) return !f.unavailable;
    f.tried = true;
    if (!caps.computeShaders) {
        f.unavailable = caps.computeUnavailableReason("forward+");
        return false;
    }
    for (ProgramId id : {ProgramId::TileDepth, ProgramId::TileBin, ProgramId::ForwardPlus})
        if (!shaders.add(id, nullptr)) {
            f.unavailable = programFailure("forward+", shaders, id);
            return false;
        }
    return true;
}

bool RendererImpl::prepassReady() {
    OptionalFeature& f = prepassFeature;
    if (f.tried) return !f.unavailable;
    f.tried = true;
    for (ProgramInfo const& p : programTable()) {
        if (p.group != ProgramGroup::Prepass || shaders.add(p.id, nullptr)) continue;
        f.unavailable = programFailure("prepass", shaders, p.id);
        return false;
    }
    return true;
}

std::optional<std::string> RendererImpl::modeUnavailable(LightingMode mode) {
    switch (mode) {
        case LightingMode::Volumes:
            return volumesReady() ? std::nullopt : volumesFeature.unavailable;
        case LightingMode::Tiled:
            return tiledReady() ? std::nullopt : tiledFeature.unavailable;
        case LightingMode::Clustered:
            return clusteredReady() ? std::nullopt : clusteredFeature.unavailable;
        case LightingMode::ForwardPlus:
            return forwardPlusReady() ? std::nullopt : forwardPlusFeature.unavailable;
        case LightingMode::Prepass:
            return prepassReady() ? std::nullopt : prepassFeature.unavailable;
        case LightingMode::Quad:
        case LightingMode::Forward:
            break;  // core programs only
    }
    return std::nullopt;
}

}  // namespace gbl
