// File > Capture a program… (desktop only) and its dialog over model/program_capture.h.
#pragma once

#include "model/program_capture.h"

#include <string>

namespace gbl::ui {

void openCaptureDialog(ProgramCaptureState& state);
// The menu item (call inside the File menu); draws nothing in the browser build.
void drawCaptureMenuItem(ProgramCaptureState& state);
// The dialog while it is open; `self` is the gbuffer-lab executable that runs `capture`.
void drawCaptureDialog(ProgramCaptureState& state, std::string const& self);

}  // namespace gbl::ui
