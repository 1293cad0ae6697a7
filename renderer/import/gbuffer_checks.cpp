// The checks of an imported G-buffer, each over every pixel, with the likely cause worked out
// where a finding has more than one (position against depth tries each hypothesis in turn).
#include "import/gbuffer_checks.h"

#include "import/gbuffer_causes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace gbl {

namespace {

std::string format(char const* fmt, double a, double b = 0.0, double c = 0.0) {
    char buf[256];
    std::snprintf(buf, sizeof buf, fmt, a, b, c);
    return buf;
}

GBufferFinding finding(ImportedGBuffer const& g, std::string check, std::string attachment,
                       std::vector<std::uint8_t> mask, std::string cause, bool heuristic = false) {
    GBufferFinding f;
    f.check = std::move(check);
    f.attachment = std::move(attachment);
    f.pixels = std::size_t(std::count(mask.begin(), mask.end(), std::uint8_t(1)));
    f.share = g.pixelCount() ? double(f.pixels) / double(g.pixelCount()) : 0.0;
    f.cause = std::move(cause);
    f.heuristic = heuristic;
    f.mask = std::move(mask);
    return f;
}

// Error of one decoded normal component: half a storage step, doubled by a 0.5 n + 0.5 bias.
double normalComponentError(NormalEncoding encoding, SampleStorage storage) {
    double const half = storageStep(storage) / 2.0;
    return encoding == NormalEncoding::Float ? half : 2.0 * half;
}

bool isUnsigned(SampleStorage s) {
    return s == SampleStorage::Uint8 || s == SampleStorage::Uint16;
}

// Share of the sampled pixels (at most ~2000 of `pixels`) for which `matches` holds.
template <class F>
double matchShare(std::vector<std::size_t> const& pixels, F&& matches) {
    if (pixels.empty()) return 0.0;
    std::size_t const stride = std::max<std::size_t>(1, pixels.size() / 2000);
    std::size_t tried = 0, hit = 0;
    for (std::size_t i = 0; i < pixels.size(); i += stride) {
        ++tried;
        if (matches(pixels[i])) ++hit;
    }
    return double(hit) / double(tried);
}

}  // namespace

double highlightError(double angle, double shininess) {
    double worst = 0.0;
    constexpr int kSteps = 4096;
    for (int i = 0; i <= kSteps; ++i) {
        double const theta = std::numbers::pi / 2.0 * i / kSteps;
        double const off = std::min(theta + angle, std::numbers::pi / 2.0);
        worst = std::max(worst, std::abs(std::pow(std::cos(theta), shininess) - std::pow(std::cos(off), shininess)));
    }
    return worst;
}

double normalAngleError(NormalEncoding encoding, double step) {
    // Two components across the normal each off by their error: sqrt(2) of it, in radians.
    double const component = encoding == NormalEncoding::Float ? step / 2.0 : step;
    return std::sqrt(2.0) * component;
}

GBufferCheckReport checkGBuffer(ImportedGBuffer const& g) {
    GBufferCheckReport r;
    r.width = g.width;
    r.height = g.height;
    std::size_t const n = g.pixelCount();
    GBufferManifest const& m = g.manifest;
    std::vector<std::uint8_t> geometry(n, 0);
    for (std::size_t p = 0; p < n; ++p) {
        geometry[p] = !g.nonFinite[p] && !g.background[p];
        r.geometryPixels += geometry[p];
        r.backgroundPixels += g.background[p] && !g.nonFinite[p];
    }

    // --- NaN / Inf -------------------------------------------------------------------------
    if (std::find(g.nonFinite.begin(), g.nonFinite.end(), 1) != g.nonFinite.end()) {
        std::string which;
        for (ImportedImage const& im : g.images)
            if (std::any_of(im.values.begin(), im.values.end(), [](float v) { return !std::isfinite(v); }))
                which += (which.empty() ? "" : ", ") + im.field;
        r.findings.push_back(finding(g, "nan_inf", which, g.nonFinite,
                                     "NaN or Inf in " + which +
                                         ": a normalize() of a zero vector, a division by a zero w or length, or a "
                                         "target read back before anything was written; lighting turns them into black "
                                         "or white pixels."));
    }

    // --- normals ---------------------------------------------------------------------------
    ImportedImage const& ni = *g.image("normal");
    double const componentError = normalComponentError(m.normal.encoding, ni.storage);
    // Three components each off by their error, with room for the writer's own rounding.
    float const unitTolerance = float(std::max(1e-3, 2.0 * std::sqrt(3.0) * componentError));
    std::vector<std::uint8_t> unbiased(n, 0);
    if (isUnsigned(ni.storage) && m.normal.encoding != NormalEncoding::Octahedral) {
        for (std::size_t p = 0; p < n; ++p) {
            if (!geometry[p]) continue;
            bool const zero = ni.at(p, 0) == 0.0f || ni.at(p, 1) == 0.0f || ni.at(p, 2) == 0.0f;
            if (zero && std::abs(glm::length(g.normal[p]) - 1.0f) > unitTolerance) unbiased[p] = 1;
        }
        if (std::find(unbiased.begin(), unbiased.end(), 1) != unbiased.end())
            r.findings.push_back(finding(
                g, "normal_unbiased", "normal", unbiased,
                "Normal components stuck at 0 in an unsigned (" + std::string(storageName(ni.storage)) +
                    ") target: the normals were stored without the 0.5·n + 0.5 bias, so surfaces facing -x, -y or -z "
                    "lost their negative components; store 0.5·n + 0.5 and declare encoding biased."));
    }
    if (m.normal.encoding != NormalEncoding::Octahedral) {
        std::vector<std::uint8_t> mask(n, 0);
        for (std::size_t p = 0; p < n; ++p)
            if (geometry[p] && !unbiased[p] && std::abs(glm::length(g.normal[p]) - 1.0f) > unitTolerance) mask[p] = 1;
        if (std::find(mask.begin(), mask.end(), 1) != mask.end())
            r.findings.push_back(finding(
                g, "normal_not_unit", "normal", std::move(mask),
                "Normals are not unit length beyond what " + std::string(storageName(ni.storage)) +
                    format(" storage explains (tolerance %.4f): normalise after interpolation and after applying the "
                           "normal map, before writing the G-buffer.",
                           unitTolerance)));
    }
    if (g.camera && !g.position.empty()) {
        glm::vec3 const eye = g.camera->position;
        glm::mat3 const toWorld(glm::inverse(g.camera->view)), toView(g.camera->view);
        // Interpolated normals at silhouettes may lean a little past 90°; clearly away is beyond this.
        constexpr float kAwayCos = -0.2f;
        std::vector<std::uint8_t> mask(n, 0);
        std::size_t other = 0;
        for (std::size_t p = 0; p < n; ++p) {
            if (!geometry[p]) continue;
            glm::vec3 const v = eye - g.position[p];
            float const len = glm::length(v) * glm::length(g.normal[p]);
            if (len <= 0.0f) continue;
            if (glm::dot(g.normal[p], v) < kAwayCos * len) mask[p] = 1;
            // The same normal read in the other space, for the cause.
            glm::vec3 const alt = m.normal.space == Space::World ? toWorld * g.normal[p] : toView * g.normal[p];
            if (glm::dot(alt, v) < kAwayCos * len) ++other;
        }
        std::size_t const count = std::size_t(std::count(mask.begin(), mask.end(), std::uint8_t(1)));
        // A few silhouette pixels of a bent normal map are not a bug; a surface facing away is.
        if (count > r.geometryPixels / 200) {
            bool const otherSpace = other * 4 < count;
            std::string const declared(kSpaceNames[std::size_t(m.normal.space)]);
            std::string const actual(kSpaceNames[1 - std::size_t(m.normal.space)]);
            r.findings.push_back(
                finding(g, "normal_facing_away", "normal", std::move(mask),
                        otherSpace ? "Normals face away from the camera on visible surfaces but face it when read as " +
                                         actual + " space: " + actual + "-space normals labelled " + declared +
                                         " (set normal.space to " + actual + ", or transform them before writing)."
                                   : "Normals face away from the camera on visible surfaces: the normal matrix "
                                     "(transpose(inverse(mat3(model)))) was not applied, or the normals are flipped."));
        }
    }

    // --- position against depth ------------------------------------------------------------
    if (m.position && m.depth && g.camera) {
        CameraMatrices const& cam = *g.camera;
        glm::mat4 const invView = glm::inverse(cam.view), invProj = glm::inverse(cam.projection);
        double const posStep = storageStep(g.image("position")->storage);
        auto tolerance = [&](glm::vec3 stored, float distance) {
            return 0.01f * distance + float(4.0 * posStep) * glm::length(stored) + 1e-4f;
        };
        auto at = [&](std::size_t p, int& x, int& y) {
            x = int(p % std::size_t(g.width));
            y = int(p / std::size_t(g.width));
        };
        std::vector<std::uint8_t> mask(n, 0);
        std::vector<std::size_t> bad;
        for (std::size_t p = 0; p < n; ++p) {
            if (!geometry[p]) continue;
            int x, y;
            at(p, x, y);
            glm::vec3 const fromDepth =
                worldFromDistance(cam, invView, invProj, g.width, g.height, float(x), float(y), g.viewDistance[p]);
            if (glm::length(fromDepth - g.position[p]) > tolerance(g.position[p], g.viewDistance[p])) {
                mask[p] = 1;
                bad.push_back(p);
            }
        }
        if (bad.size() > r.geometryPixels / 1000) {
            auto near = [&](glm::vec3 a, glm::vec3 b, float d) { return glm::length(a - b) <= tolerance(b, d); };
            int const h = g.height;
            double const flipAll = matchShare(bad, [&](std::size_t p) {
                int x, y;
                at(p, x, y);
                return near(
                    worldFromDistance(cam, invView, invProj, g.width, h, float(x), float(h - 1 - y), g.viewDistance[p]),
                    g.position[p], g.viewDistance[p]);
            });
            double const flipOne = matchShare(bad, [&](std::size_t p) {
                int x, y;
                at(p, x, y);
                std::size_t const q = std::size_t(h - 1 - y) * std::size_t(g.width) + std::size_t(x);
                return near(worldFromDistance(cam, invView, invProj, g.width, h, float(x), float(y), g.viewDistance[q]),
                            g.position[p], g.viewDistance[q]);
            });
            double const otherSpace = matchShare(bad, [&](std::size_t p) {
                int x, y;
                at(p, x, y);
                glm::vec3 const alt = m.position->space == Space::World
                                          ? glm::vec3(invView * glm::vec4(g.position[p], 1))
                                          : glm::vec3(cam.view * glm::vec4(g.position[p], 1));
                return near(worldFromDistance(cam, invView, invProj, g.width, h, float(x), float(y), g.viewDistance[p]),
                            alt, g.viewDistance[p]);
            });
            CameraMatrices transposed = cam;
            transposed.view = glm::transpose(cam.view);
            transposed.projection = glm::transpose(cam.projection);
            glm::mat4 const tInvView = glm::inverse(transposed.view), tInvProj = glm::inverse(transposed.projection);
            double const swapped = matchShare(bad, [&](std::size_t p) {
                int x, y;
                at(p, x, y);
                return near(worldFromDistance(transposed, tInvView, tInvProj, g.width, h, float(x), float(y),
                                              g.viewDistance[p]),
                            g.position[p], g.viewDistance[p]);
            });
            glm::mat4 const viewProj = cam.projection * cam.view;
            double const onPixel = matchShare(bad, [&](std::size_t p) {
                int x, y;
                at(p, x, y);
                glm::vec4 const c = viewProj * glm::vec4(g.position[p], 1.0f);
                if (c.w <= 0.0f) return false;
                float const px = (c.x / c.w * 0.5f + 0.5f) * float(g.width) - 0.5f;
                float const py = (0.5f - c.y / c.w * 0.5f) * float(h) - 0.5f;
                return std::abs(px - float(x)) <= 1.5f && std::abs(py - float(y)) <= 1.5f;
            });
            constexpr double kConvincing = 0.8;  // of the disagreeing pixels, explained by one hypothesis
            std::string cause;
            if (flipAll >= kConvincing || flipOne >= kConvincing)
                cause = flipAll >= flipOne
                            ? "Position and depth agree once the rows are turned over: the images are upside down "
                              "for this camera (glReadPixels rows run bottom-up: set flip_y)."
                            : "Position and depth agree once one of them is turned upside down: a flipped image "
                              "(one attachment was saved bottom-up, the other top-down).";
            else if (otherSpace >= kConvincing)
                cause = m.position->space == Space::World
                            ? "Position agrees with depth when read as view space: view-space positions labelled "
                              "world (set position.space to view)."
                            : "Position agrees with depth when read as world space: world-space positions labelled "
                              "view (set position.space to world).";
            else if (swapped >= kConvincing)
                cause =
                    "Position agrees with depth under the transposed camera matrices: the view and projection "
                    "were given in the other layout (swap camera.matrix_layout).";
            else if (onPixel >= kConvincing)
                cause =
                    "Positions land on the right pixels but at other distances than depth says: wrong near/far "
                    "for the depth (depth.near, depth.far), or the wrong depth convention.";
            else
                cause =
                    "Position and depth disagree under the given camera: they come from different frames or "
                    "cameras, or the manifest's camera is not the one that rendered them.";
            r.findings.push_back(finding(g, "position_depth_mismatch", "position", std::move(mask), cause));
        }
    }

    // --- background ------------------------------------------------------------------------
    if (r.backgroundPixels == 0)
        r.findings.push_back(finding(
            g, "no_background", m.depth ? "depth" : "position", std::vector<std::uint8_t>(n, 1),
            "No pixel reads as background (no depth at its clear value, no zero coverage, normal or position): clear "
            "the G-buffer before the geometry pass, or lighting shades stale values where nothing was drawn (ignore "
            "this if geometry really covers the whole frame)."));

    // --- albedo ----------------------------------------------------------------------------
    if (m.albedo) {
        float const slack = float(storageStep(g.image("albedo")->storage));
        std::vector<std::uint8_t> mask(n, 0);
        std::vector<float> luminance;
        std::vector<std::uint8_t> bright(n, 0);
        for (std::size_t p = 0; p < n; ++p) {
            if (!geometry[p]) continue;
            glm::vec3 const a = g.albedo[p];
            if (glm::any(glm::lessThan(a, glm::vec3(-slack))) || glm::any(glm::greaterThan(a, glm::vec3(1.0f + slack))))
                mask[p] = 1;
            float const l = glm::dot(a, glm::vec3(0.2126f, 0.7152f, 0.0722f));
            luminance.push_back(l);
            bright[p] = l > 0.5f;
        }
        if (std::find(mask.begin(), mask.end(), 1) != mask.end())
            r.findings.push_back(finding(g, "albedo_range", "albedo", std::move(mask),
                                         "Albedo outside [0, 1]: albedo is a reflectance; a lit or HDR colour, or an "
                                         "unclamped tint, was written to the albedo target."));
        // Heuristic: linear reflectances of ordinary materials sit mostly below 0.5 (the median
        // of the frame), while the sRGB-encoded bytes of the same textures sit above it.
        if (m.albedo->encoding == ColorEncoding::Linear && !luminance.empty()) {
            auto mid = luminance.begin() + std::ptrdiff_t(luminance.size() / 2);
            std::nth_element(luminance.begin(), mid, luminance.end());
            if (*mid > 0.5f)
                r.findings.push_back(finding(
                    g, "albedo_srgb", "albedo", std::move(bright),
                    format("Albedo looks sRGB-encoded though declared linear (a heuristic: its median luminance is "
                           "%.2f, above the 0.5 few linear reflectances reach): a colour texture loaded without an "
                           "sRGB format, or set albedo.encoding to srgb.",
                           double(*mid)),
                    true));
        }
    }

    // --- precision -------------------------------------------------------------------------
    for (ImportedImage const& im : g.images) {
        PrecisionNote note;
        note.attachment = im.field;
        note.storage = storageName(im.storage);
        note.step = storageStep(im.storage);
        if (im.field == "normal") {
            note.highlightError = highlightError(normalAngleError(m.normal.encoding, note.step), m.shininess);
            note.shininess = m.shininess;
        }
        r.precision.push_back(note);
        // Two levels of an 8-bit display at the highlight's peak: banding a viewer sees.
        constexpr double kVisible = 2.0 / 255.0;
        if (im.field == "normal" && note.highlightError > kVisible)
            r.findings.push_back(finding(
                g, "normal_precision", "normal", geometry,
                std::string(storageName(im.storage)) +
                    format(" normals may be off by %.2f degrees, which moves a highlight of shininess %.0f by up to "
                           "%.1f%% of its peak (banding in smooth highlights): store normals in 16 bits (RGB16F, or "
                           "RG16 octahedral) at this shininess.",
                           normalAngleError(m.normal.encoding, note.step) * 180.0 / std::numbers::pi,
                           double(m.shininess), note.highlightError * 100.0)));
    }
    addProvenCauses(g, geometry, r);
    // A fault on every drawn pixel reads 100 %, however much of the frame is background: the shares are
    // of the geometry, but for the two checks that look at every pixel (non-finite values, no background).
    for (auto& f : r.findings)
        if (f.check != "nan_inf" && f.check != "no_background" && r.geometryPixels > 0)
            f.share = double(f.pixels) / double(r.geometryPixels);
    return r;
}

std::string precisionLine(PrecisionNote const& note) {
    std::string line = note.attachment + ": " + note.storage + format(", step %.3g", note.step);
    if (note.attachment == "normal")
        line += format("; a highlight of shininess %.0f moves by up to %.2g %% of its peak", note.shininess,
                       note.highlightError * 100.0);
    return line;
}

}  // namespace gbl
