// Value ranges of read-back attachments, for the viewers' "fit" button. Pure, no GL.
#pragma once

#include "core/frame_types.h"

namespace gbl::ui {

struct ValueRange {
    float min = 0.0f;
    float max = 1.0f;
    long samples = 0;  // values that took part; 0 means the image held no geometry
};

// Which pixels count: background pixels would pull the range to the clear value.
enum class RangeSkip {
    None,
    ZeroAlpha,  // channel 3 == 0: nothing was drawn there (position, normal attachments)
    FarDepth,   // value >= 1: the cleared depth (depth attachment)
};

// Min and max over the channels set in channelMask (bit 0 = R ... bit 3 = A), skipping
// background pixels. With linearize, values are window depths turned into
// distances in front of the camera first (linearDepth(), core/depth.h).
ValueRange fitRange(FloatImage const& image, unsigned channelMask, RangeSkip skip, bool linearize = false,
                    float nearPlane = 0.1f, float farPlane = 100.0f);

}  // namespace gbl::ui
