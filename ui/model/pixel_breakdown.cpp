// Per-light breakdown of a pixel.
#include "model/pixel_breakdown.h"

#include "core/shading_cpu.h"

#include <algorithm>

namespace gbl::ui {

std::optional<PixelBreakdown> breakDownPixel(PixelSample const& sample, std::span<PointLight const> lights,
                                             Camera const& camera, PipelineSettings const& settings,
                                             std::optional<PixelInFrame> const& where) {
    if (!sample.covered) return std::nullopt;
    ShadingInputs in;
    // The stored values, exactly as the lighting pass reads them from the G-buffer.
    in.position = glm::vec3(sample.position);
    in.normal = glm::vec3(sample.normal);
    in.albedo = glm::vec3(sample.albedoSpec);
    in.specular = sample.albedoSpec.a;
    in.viewPosition = camera.position;
    in.shininess = settings.shininess;
    PixelBreakdown b;
    b.lightsTested = int(lights.size());
    b.ambient = settings.ambient * in.albedo;
    b.total = shadePointCpu(lights, in, settings.ambient, &b.lights);
    std::sort(b.lights.begin(), b.lights.end(), [](auto const& x, auto const& y) {
        auto lum = [](glm::vec3 v) { return v.r + v.g + v.b; };
        return lum(x.total()) > lum(y.total());
    });
    if (where)
        b.verdicts =
            explainPixel({sample, where->pixel, where->frameSize, camera, settings, where->tileBounds}, lights);
    return b;
}

}  // namespace gbl::ui
