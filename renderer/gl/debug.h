// GL error accounting: the KHR_debug callback where present, glGetError polling otherwise.
#pragma once

#include "gl/caps.h"

#include <cstdint>

namespace gbl {

// Installs the debug callback on the current context when caps.khrDebug. Messages of type
// error are counted and logged to stderr; other high-severity messages are logged only.
void installGlDebug(GlCaps const& caps);

// Errors the GL reported in this process so far, from the callback or the error flag (each
// counted once; the flag is drained into the count). Only ever grows: a check compares the
// count before and after the code it watches, so no caller can hide an error from another.
std::uint64_t glErrorCount();

}  // namespace gbl
