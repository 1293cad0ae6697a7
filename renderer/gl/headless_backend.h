// The two ways gbl_gl makes a headless context; private to renderer/gl (headless_context.cpp chooses).
#pragma once

#include <memory>
#include <string>

namespace gbl::detail {

// One backend's context and whatever it needs to stay alive (display, surface, hidden window).
class HeadlessBackend {
public:
    virtual ~HeadlessBackend() = default;
    virtual void makeCurrent() = 0;
};

// Core-profile versions both backends ask for, newest first: 3.3 is the renderer's floor.
inline constexpr int kContextVersions[][2] = {{4, 6}, {4, 5}, {4, 3}, {4, 1}, {3, 3}};

// Each returns a current context, or null with *reason set to a lower-case fragment saying what failed
// (headless_context.cpp makes the sentence).
#ifndef GBL_HEADLESS_GLFW
std::unique_ptr<HeadlessBackend> createEglContext(bool debug, std::string* reason);
#endif
std::unique_ptr<HeadlessBackend> createGlfwContext(bool debug, std::string* reason);

}  // namespace gbl::detail
