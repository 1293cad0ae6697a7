// Light cubes: one small emissive cube per light, drawn unlit into the HDR image.
#pragma once

#include "gl/vertex_array.h"
#include "passes/shading_inputs.h"

namespace gbl {

struct LightCubesInput {
    LightBuffer const& lights;
    gl::Program const& program;   // ProgramId::LightCube
    gl::VertexArray const& cube;  // 36 vertices of a unit cube
    LitTarget target;             // depth-tested against its depth (the blit step's copy)
};
struct LightCubesConfig {
    glm::mat4 viewProj{1.0f};
    float halfSize = 0.05f;
};

void lightCubesPass(LightCubesInput const& in, LightCubesConfig const& config);

}  // namespace gbl
