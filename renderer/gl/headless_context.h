// An OpenGL context without a window (EGL), for tests and the render/bench commands.
#pragma once

#include <memory>
#include <string>

namespace gbl {

class HeadlessContext {
public:
    // Creates and makes current a core-profile context, trying 4.6 down to 3.3. Returns null
    // and sets *error to one sentence when no EGL display or context can be had.
    static std::unique_ptr<HeadlessContext> create(std::string* error, bool debug = true);
    ~HeadlessContext();
    HeadlessContext(HeadlessContext const&) = delete;
    HeadlessContext& operator=(HeadlessContext const&) = delete;

    void makeCurrent();

private:
    HeadlessContext() = default;
    void* display_ = nullptr;
    void* context_ = nullptr;
    void* surface_ = nullptr;  // a 1x1 pbuffer when surfaceless contexts are unsupported
};

}  // namespace gbl
