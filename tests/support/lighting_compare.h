// Holding one lighting mode's lit image to another's, for the GL tests that compare modes
// (light_modes_gl_test, prepass_gl_test, forward_plus_gl_test; a new mode's test starts here):
//   compareRgb(image, reference, bound) and describe(diff): the RGB differences against a per-value
//     bound, and a failure message that says them;
//   the bounds the modes are held to (volumeBound, sameSumBound, forwardBound), each saying why;
//   lightingSettings(mode): settings that show the lighting alone;
//   LightingGlTest: the courtyard fixture (gl_fixture.h) with lighting() (render, check the mode ran
//     without GL errors, read the lit image back) and insideCamera() (the eye inside a light's volume);
//   passCalls(stats, name): one declared pass's draws and dispatches.
#pragma once

#include "gl_fixture.h"

#include <functional>
#include <span>
#include <string>
#include <string_view>

namespace gbl::test {

// fp16 rounding: the lit target is RGBA16F, so every stored value carries a relative error of up
// to 2^-11; additive blending rounds once per light.
inline constexpr double kHalfUlp = 1.0 / 2048.0;

// Additive blending (volumes against quad) rounds once per light to fp16: up to 16 overlapping
// volumes over a pixel of the default scene, plus 1e-4 absolute (the fp16 spacing of the darkest
// lit values).
inline double volumeBound(double v) {
    return 16 * kHalfUlp * v + 1e-4;
}
// The same lights added in fp32 in another order and stored once (tiled or clustered against quad,
// forward+ against forward): one fp16 rounding each side (2 half-ulps) plus slack for the compiler
// fusing the sums differently.
inline double sameSumBound(double v) {
    return 4 * kHalfUlp * v + 1e-5;
}
// Forward shading (and prepass, which reads its material from the scene) against the G-buffer
// modes: position in fp16 (1/64 unit at 16..32 units from the origin), albedo and specular in 8
// bits (1/510), normal in fp16 move the result by a few percent at worst (dark albedo, grazing
// specular): 3 % of the value + 2e-3, met at 99.5 % of the pixels.
inline double forwardBound(double v) {
    return 0.03 * v + 2e-3;
}

struct ImageDiff {
    double maxAbs = 0.0;
    double meanAbs = 0.0;
    double maxRel = 0.0;     // |a - b| / max(|a|, |b|) over channels with max(|a|, |b|) > relFloor
    double meanValue = 0.0;  // mean of |reference| over every channel, for scale
    int pixelsOver = 0;      // pixels where some channel exceeds the bound given
};

// Compares the RGB channels of two lighting images of one size. bound(|reference value|) is the
// error allowed in a channel; pixelsOver counts the pixels that exceed it in any channel.
ImageDiff compareRgb(FloatImage const& image, FloatImage const& reference, std::function<double(double)> const& bound,
                     double relFloor = 1e-2);
std::string describe(ImageDiff const& d);

// `mode` with volume culling `cull` and the light cubes off: the lighting alone.
PipelineSettings lightingSettings(LightingMode mode, CullMode cull = CullMode::Front);

// The named declared pass's counts in a frame's stats (all zero when it did not run).
PassCalls passCalls(FrameStats const& stats, std::string_view name);

class LightingGlTest : public CourtyardGlTest {
protected:
    using CourtyardGlTest::CourtyardGlTest;

    // Renders `s` and reads the lit image; the frame must have run `s.mode` without GL errors.
    FloatImage lighting(PipelineSettings const& s, Camera const& cam, std::span<PointLight const> lights,
                        FrameStats* stats = nullptr);
    FloatImage lighting(PipelineSettings const& s, Camera const& cam) { return lighting(s, cam, lights_); }
    FloatImage lighting(PipelineSettings const& s) { return lighting(s, camera_, lights_); }

    // The eye inside light 0's sphere, looking at the floor under it: the case the inside-safe
    // volume cull modes exist for.
    Camera insideCamera() const;
};

}  // namespace gbl::test
