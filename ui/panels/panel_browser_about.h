// Help > About this browser (the browser build's): everything the page cannot do that the desktop
// editor does, in one window, so no status line or dialog has to say it on the way.
#pragma once

#include <span>
#include <string>
#include <vector>

namespace gbl::ui {

struct BrowserAboutState {
    bool open = false;
    // What this browser's context cannot run, in the renderer's words (the lighting modes without
    // compute shaders); filled once at start-up by the editor.
    std::vector<std::string> contextLimits;
};

// The window's lines: the context's limits, whether the passes are timed on the GPU
// (`timingSource` as the Stats window's: "gpu_elapsed" or "cpu_finish"), then what every page
// lacks (keys, quitting, files). The frame log lists them too.
std::vector<std::string> browserLimits(BrowserAboutState const& state, std::string const& timingSource);

// Draws the window while `state.open`; its close button clears it.
void drawBrowserAboutWindow(BrowserAboutState& state, std::span<std::string const> lines);

}  // namespace gbl::ui
