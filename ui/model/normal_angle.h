// Issue 12: how far a G-buffer layout's decoded normals turn from the classic layout's: the angle
// between two normals per pixel, in degrees, as a DiffStats the A/B heat map shows.
#pragma once

#include "model/image_stats.h"

#include <glm/glm.hpp>

namespace gbl::ui {

// The angle between two directions in degrees, 0..180, from atan2(|a x b|, a . b): exact for
// the small angles a normal encoding loses (acos of a dot product near 1 is not). NaN when
// either is zero-length or not finite.
float angleDegrees(glm::vec3 a, glm::vec3 b);

// Per pixel, the angle between the normals of two Attachment::Normal read-backs (xyz decoded,
// alpha 1 where geometry was drawn, 0 on the background). Background in both: 0 and not counted
// in `pixels`; drawn on one side only or a normal without a direction: NaN (counted in
// nanPixels, magenta in the heat map). Pixels whose angle is > thresholdDegrees are counted in
// overThreshold. Not comparable when the sizes differ or an image has fewer than 4 channels.
DiffStats normalAngleDiff(FloatImage const& a, FloatImage const& b, float thresholdDegrees);

}  // namespace gbl::ui
