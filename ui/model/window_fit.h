// The editor's first window size: the default (1600x900) is larger than a 1280x720 laptop or
// projector screen, where the right column and the bottom strip would open off-screen. Without
// --size the window is fitted to the monitor's work area; a --size is taken as given. No GLFW.
#pragma once

#include <algorithm>

namespace gbl::ui {

struct WindowFit {
    int width = 0;  // screen coordinates, as glfwCreateWindow takes them
    int height = 0;
    bool reduced = false;  // smaller than asked: the work area could not hold it
};

// `width` x `height` in screen coordinates, shrunk to fit a work area of `areaWidth` x `areaHeight`
// pixels on a monitor whose content scale is `scale` (the window grows by it with
// GLFW_SCALE_TO_MONITOR). An unknown area (0 or less) or scale leaves the size as asked.
inline WindowFit fitWindowToWorkArea(int width, int height, int areaWidth, int areaHeight, float scale) {
    WindowFit fit{width, height, false};
    if (areaWidth <= 0 || areaHeight <= 0) return fit;
    if (!(scale > 0.0f)) scale = 1.0f;
    int const maxWidth = std::max(1, int(float(areaWidth) / scale));
    int const maxHeight = std::max(1, int(float(areaHeight) / scale));
    if (width > maxWidth || height > maxHeight) {
        fit.width = std::min(width, maxWidth);
        fit.height = std::min(height, maxHeight);
        fit.reduced = true;
    }
    return fit;
}

}  // namespace gbl::ui
