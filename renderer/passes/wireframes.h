// Light-volume wireframes: each light's enclosing sphere or cone (the very mesh the volumes pass draws)
// as lines in the light's colour, depth-tested against the scene: an overlay drawn onto the display
// image after the view pass (tonemapped as the lit image is), so the lit image stays the light sum.
#pragma once

#include "core/camera.h"
#include "core/point_light.h"
#include "gpu/draw_state_gl.h"
#include "gpu/light_volume_gpu.h"
#include "passes/shading_inputs.h"

#include <optional>
#include <span>

namespace gbl {

struct WireframesInput {
    LightBuffer const& lights;
    LightVolumeGpu const& volumes;  // instances prepared for this frame
    gl::Program const& program;     // ProgramId::LightVolumeWire
    // The display image with the scene's depth: overlayGBufferDepthFbo (the G-buffer's depth, so
    // the lines need no depth-copy step), or overlayFbo in forward mode (forward's own depth).
    gl::Framebuffer const& target;
};
struct WireframesConfig {
    glm::mat4 viewProj{1.0f};
    float intensity = 2.0f;    // HDR brightness, so the lines survive tonemapping
    DisplayTonemap tonemap{};  // the display pass's
    int firstInstance = 0;     // a range of the prepared instances; count -1 = all of them
    int count = -1;
    // With every instance drawn (count -1), each directional light also gets an arrow this long
    // from its position along its direction.
    float arrowLength = 1.5f;
    std::span<DrawState const> states;  // its declared draw groups (PassDecl::states), applied in order
};

// Where light `light` sits in the instance list prepareVolumeInstances builds from the same
// camera, lights and scales (sphere lights, outside-the-camera volumes first, then cone lights
// likewise), or nullopt when it has no volume.
std::optional<int> volumeInstanceSlot(std::span<PointLight const> lights, int light, Camera const& camera, float aspect,
                                      float enclosingScale, float coneRadialScale = 1.0f, float volumeScale = 1.0f);

void wireframesPass(WireframesInput const& in, WireframesConfig const& config);

}  // namespace gbl
