// Lighting image comparisons and the lighting-mode fixture shared by the GL tests (lighting_compare.h).
#include "lighting_compare.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gbl::test {

ImageDiff compareRgb(FloatImage const& image, FloatImage const& reference, std::function<double(double)> const& bound,
                     double relFloor) {
    ImageDiff d;
    EXPECT_EQ(image.width, reference.width);
    EXPECT_EQ(image.height, reference.height);
    double sum = 0.0, sumRef = 0.0;
    for (int y = 0; y < reference.height; ++y) {
        for (int x = 0; x < reference.width; ++x) {
            bool over = false;
            for (int c = 0; c < 3; ++c) {
                double const va = image.at(x, y, c), vr = reference.at(x, y, c);
                double const e = std::abs(va - vr);
                sum += e;
                sumRef += std::abs(vr);
                d.maxAbs = std::max(d.maxAbs, e);
                double const m = std::max(std::abs(va), std::abs(vr));
                if (m > relFloor) d.maxRel = std::max(d.maxRel, e / m);
                if (e > bound(std::abs(vr))) over = true;
            }
            d.pixelsOver += over;
        }
    }
    double const n = double(reference.width) * reference.height * 3;
    d.meanAbs = sum / n;
    d.meanValue = sumRef / n;
    return d;
}

std::string describe(ImageDiff const& d) {
    char buf[200];
    std::snprintf(buf, sizeof buf, "max abs %.3g, mean abs %.3g (mean value %.3g), max rel %.3g, pixels over bound %d",
                  d.maxAbs, d.meanAbs, d.meanValue, d.maxRel, d.pixelsOver);
    return buf;
}

PipelineSettings lightingSettings(LightingMode mode, CullMode cull) {
    PipelineSettings s;
    s.mode = mode;
    s.cull = cull;
    s.lightCubes = false;
    return s;
}

PassCalls passCalls(FrameStats const& stats, std::string_view name) {
    auto const it =
        std::find_if(stats.calls.begin(), stats.calls.end(), [&](PassCalls const& c) { return c.name == name; });
    return it == stats.calls.end() ? PassCalls{} : *it;
}

FloatImage LightingGlTest::lighting(PipelineSettings const& s, Camera const& cam, std::span<PointLight const> lights,
                                    FrameStats* stats) {
    FrameStats const st = renderer_->render({cam, lights, s, true});
    EXPECT_EQ(st.modeUsed, s.mode) << st.fallbackReason;
    EXPECT_EQ(st.glErrors, 0u);
    if (stats) *stats = st;
    return renderer_->readAttachment(Attachment::Lighting);
}

Camera LightingGlTest::insideCamera() const {
    PointLight const& l = lights_[0];
    Camera c = camera_;
    c.position = l.position + glm::vec3(0.3f, 0.4f, 0.3f);
    c.lookAt(glm::vec3(l.position.x, 0.0f, l.position.z) + glm::vec3(0.0f, 0.0f, -2.0f));
    return c;
}

}  // namespace gbl::test
