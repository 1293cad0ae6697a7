// Light-volume wireframes: each light's enclosing sphere (the very mesh the volumes pass draws)
// as lines in the light's colour, depth-tested against the scene and drawn into the HDR image.
#pragma once

#include "gpu/light_volume_gpu.h"
#include "passes/shading_inputs.h"

namespace gbl {

struct WireframesInput {
    LightBuffer const& lights;
    LightVolumeGpu const& volumes;  // instances prepared for this frame
    gl::Program const& program;     // ProgramId::LightVolumeWire
    // Holds the scene's depth: volumeFbo (G-buffer depth), or litFbo in forward mode.
    LitTarget target;
};
struct WireframesConfig {
    glm::mat4 viewProj{1.0f};
    float intensity = 2.0f;  // HDR brightness, so the lines survive tonemapping
};

void wireframesPass(WireframesInput const& in, WireframesConfig const& config);

}  // namespace gbl
