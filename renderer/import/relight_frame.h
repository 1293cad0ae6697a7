// An imported G-buffer as the renderer re-lights it (core/imported_frame.h): world position with the
// window depth through the manifest's camera, normal, albedo and specular, emission and occlusion,
// rows turned bottom-up for GL. No GL here: Renderer::setImportedGBuffer uploads the result.
#pragma once

#include "core/camera.h"
#include "core/imported_frame.h"
#include "import/imported_gbuffer.h"

#include <optional>
#include <string>

namespace gbl {

struct RelightFrame {
    std::optional<ImportedFrame> frame;
    std::string error;  // "<manifest>: <field> ..." in one sentence when frame is empty
};

// Refused, naming the field: no camera (the lighting needs the eye and the matrices), no albedo.
// A manifest without specular re-lights with specular 0; without emissive, with emission 0; without
// occlusion, with occlusion 1 (emissiveAo stays empty when it has neither). Background and NaN/Inf
// pixels get depth 1, which the import pass leaves at the clear values.
RelightFrame relightFrame(ImportedGBuffer const& g);

// The editor's (fixed) camera for the frame: view() and projection() are the frame's matrices as
// given (Camera::fixedView), so a rolled camera or an off-centre projection is kept; the angle
// fields hold the nearest yaw/pitch camera (exact for a view built with up (0, 1, 0), as gbuffer-lab's
// own are), for camera.json's angles and the frame log.
Camera cameraOfFrame(ImportedFrame const& frame);

}  // namespace gbl
