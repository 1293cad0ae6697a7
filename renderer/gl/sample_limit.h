// GBL_MAX_SAMPLES=n: the context's sample limits read as at most n (detectGlCaps), so a test can see
// the editor grey out the counts a smaller driver refuses; llvmpipe offers every count. Like
// GBL_SHADER_BRANCHES, an override for tests and for trying the editor as another driver would run it.
#pragma once

#include "gl/caps.h"

#include <string>

namespace gbl {

// Lowers caps' three sample limits (GL_MAX_SAMPLES, GL_MAX_COLOR_TEXTURE_SAMPLES,
// GL_MAX_DEPTH_TEXTURE_SAMPLES) to `value`, a whole number from 1 to 64; null leaves them. A bad
// value leaves them too and returns the one-sentence message to show; empty otherwise.
std::string applySampleLimit(GlCaps& caps, char const* value);

}  // namespace gbl
