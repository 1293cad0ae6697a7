// Import pass: an imported G-buffer (core/imported_frame.h) written into the G-buffer in the current
// layout's encoding, in the geometry pass's place when the frame re-lights another program's output.
#pragma once

#include "core/imported_frame.h"
#include "gl/fullscreen_triangle.h"
#include "gl/program.h"
#include "gl/texture.h"
#include "gpu/draw_state_gl.h"
#include "gpu/render_targets.h"

#include <optional>
#include <string>

#include <span>

namespace gbl {

// The imported frame's pixels as float textures, and its camera.
struct ImportedTextures {
    gl::Texture positionDepth;  // RGBA32F: world position, window depth (1: background)
    gl::Texture normal;         // RGBA32F: world normal
    gl::Texture albedoSpec;     // RGBA32F: linear albedo, specular intensity
    gl::Texture emissiveAo;     // RGBA32F: linear emitted radiance, ambient occlusion
    ImportedFrame camera;       // the frame's camera fields (its pixel vectors left empty)
};

// Uploads `frame`; an error (one sentence) when its pixel arrays do not match its size.
std::optional<std::string> uploadImportedFrame(ImportedFrame const& frame, ImportedTextures& out);

struct ImportInput {
    ImportedTextures const& imported;
    gl::Program const& program;  // ProgramId::Import
    gl::FullscreenTriangle const& triangle;
    gl::Framebuffer const& target;  // the G-buffer's: cleared by the executor, then written
};
struct ImportConfig {
    int width = 0;
    int height = 0;
    std::span<DrawState const> states;  // its declared draw groups (PassDecl::states), applied in order
};
struct ImportOutput {
    gl::Framebuffer const& gbuffer;  // position (or depth), normal, albedo/specular, emissive/AO of the imported frame
};

ImportOutput importPass(ImportInput const& in, ImportConfig const& config);

}  // namespace gbl
