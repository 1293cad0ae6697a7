// Per-light breakdown of a pixel.
#include "model/pixel_breakdown.h"

#include "core/shading_cpu.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gbl::ui {

std::optional<PixelBreakdown> breakDownPixel(PixelSample const& sample, std::span<PointLight const> lights,
                                             Camera const& camera, PipelineSettings const& settings,
                                             std::optional<PixelInFrame> const& where) {
    if (!sample.covered || sample.thinGBuffer) return std::nullopt;  // prepass's thin G-buffer: no albedo
    ShadingInputs in;
    // The stored values, exactly as the lighting pass reads them from the G-buffer.
    in.position = glm::vec3(sample.position);
    in.normal = glm::vec3(sample.normal);
    in.albedo = glm::vec3(sample.albedoSpec);
    in.specular = sample.albedoSpec.a;
    in.emissive = glm::vec3(sample.emissiveAo);
    in.occlusion = sample.emissiveAo.a;
    in.viewPosition = camera.position;
    shadingOf(settings, in);
    PixelBreakdown b;
    b.lightsTested = int(lights.size());
    b.ambient = surfaceTermsCpu(in, settings.ambient);  // ambient * albedo * occlusion + emissive
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

namespace {

float largestError(glm::vec3 a, glm::vec3 b, float* allowed) {
    float worst = -1.0f;
    for (int c = 0; c < 3; ++c) {
        float const e = std::abs(a[c] - b[c]), bound = storedValueBound(b[c]);
        if (e - bound > worst) {
            worst = e - bound;
            *allowed = bound;
        }
    }
    return worst + *allowed;
}

float brightness(glm::vec3 v) {
    return v.r + v.g + v.b;
}

// The brightest light the mode did not evaluate although it reaches the pixel (or evaluated more
// than once), with the sentence that names why.
std::string missedLightCause(PixelBreakdown const& b, PipelineSettings const& settings) {
    LightVerdict const* worst = nullptr;
    float worstAmount = 0.0f;
    for (LightVerdict const& v : b.verdicts) {
        if (!v.withinRadius || v.evaluations == 1) continue;
        float amount = 0.0f;
        for (LightContribution const& c : b.lights)
            if (c.lightIndex == v.lightIndex) amount = brightness(c.total());
        if (!worst || amount > worstAmount) {
            worst = &v;
            worstAmount = amount;
        }
    }
    if (!worst) return "";
    char buf[320];
    int const i = worst->lightIndex;
    if (worst->evaluations > 1)
        std::snprintf(buf, sizeof buf, "light %d is added %d times: cull `none` shades both faces of its volume", i,
                      worst->evaluations);
    else if (worst->why.find("camera inside the volume") != std::string::npos)
        std::snprintf(buf, sizeof buf,
                      "camera inside light %d's volume with cull `back`: its front faces are behind the camera, so "
                      "the light is lost (front, flip or stencil keep it)",
                      i);
    else if (settings.mode == LightingMode::Tiled)
        std::snprintf(buf, sizeof buf, "light %d is missing from this tile's light list", i);
    else
        std::snprintf(buf, sizeof buf, "light %d's volume was culled here (%s)", i, worst->why.c_str());
    return buf;
}

}  // namespace

ValueCheck checkStoredValue(glm::vec3 stored, PixelBreakdown const& b, PipelineSettings const& settings) {
    ValueCheck check;
    check.error = largestError(stored, b.total, &check.allowed);
    check.agrees = check.error <= check.allowed;
    if (check.agrees) return check;
    if (shadesForward(settings.mode)) {
        check.cause = "forward mode has no G-buffer: the surface the CPU shades is not the one forward shaded";
        return check;
    }
    if (settings.mode == LightingMode::Prepass) {
        check.cause =
            "prepass draws none of this layout's G-buffer: the surface the CPU shades is not the one "
            "prepass shaded";
        return check;
    }
    if (b.verdicts.empty()) {
        check.cause = "stored and summed values differ; hover the viewport for the per-light verdicts";
        return check;
    }
    // What the mode should have stored: ambient plus what each light it evaluated added.
    glm::vec3 byMode = b.ambient;
    for (LightVerdict const& v : b.verdicts) byMode += v.added;
    float allowedByMode = 0.0f;
    bool const modeExplains = largestError(stored, byMode, &allowedByMode) <= allowedByMode;
    std::string const missed = missedLightCause(b, settings);
    if (modeExplains && !missed.empty()) {
        check.cause = missed;
    } else if (brightness(stored) < brightness(byMode)) {
        // The CPU takes the enclosing sphere; a mesh that does not enclose the radius cuts light off.
        check.cause =
            "stored is below what the mode should give: a light volume too small for its radius (the sphere's "
            "enclosing scale) cuts the light off at its edge";
    } else {
        check.cause =
            "stored is above the sum of the lights: something else is drawn into the lit image here "
            "(a blended object; the light cubes and wireframes are drawn on the display image, not into it)";
    }
    return check;
}

std::string noBreakdownNote(PixelSample const& sample, PipelineSettings const& settings) {
    if (shadesForward(settings.mode) && !sample.covered) {
        char buf[200];
        std::snprintf(buf, sizeof buf,
                      "forward mode has no G-buffer, so there is no surface to break down (lit value stored: %.4f "
                      "%.4f %.4f)",
                      sample.lighting.r, sample.lighting.g, sample.lighting.b);
        return buf;
    }
    if (sample.thinGBuffer && sample.covered) {
        char buf[240];
        std::snprintf(buf, sizeof buf,
                      "prepass keeps a thin G-buffer of its own (normal, exponent, depth) and no albedo, so the "
                      "lights cannot be broken down from it (lit value stored: %.4f %.4f %.4f)",
                      sample.lighting.r, sample.lighting.g, sample.lighting.b);
        return buf;
    }
    if (settings.mode == LightingMode::Prepass && !sample.covered && !sample.thinGBuffer) {
        char buf[220];
        std::snprintf(buf, sizeof buf,
                      "prepass keeps a thin G-buffer of its own, not this layout's, so there is no surface to break "
                      "down (lit value stored: %.4f %.4f %.4f)",
                      sample.lighting.r, sample.lighting.g, sample.lighting.b);
        return buf;
    }
    return "background: no surface, no lights";
}

}  // namespace gbl::ui
