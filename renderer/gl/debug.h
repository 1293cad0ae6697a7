// GL error accounting: the KHR_debug callback where present, glGetError polling otherwise.
#pragma once

#include "gl/caps.h"

#include <cstdint>
#include <functional>
#include <string>

namespace gbl {

// Installs the debug callback on the current context when caps.khrDebug. Messages of type
// error are counted and logged to stderr; other high-severity messages are logged only.
void installGlDebug(GlCaps const& caps);

// Drains glGetError and returns the number of errors the GL reported since the last call,
// from either the callback or the error flag (each error counted once).
std::uint64_t collectGlErrors();

// Total errors counted in this process.
std::uint64_t totalGlErrors();

}  // namespace gbl
