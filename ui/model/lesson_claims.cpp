// The lesson claim kinds, each checked once over read-back images (see lesson_claims.h).
#include "model/lesson_claims.h"
#include "model/lesson_text.h"

#include "core/depth.h"
#include "core/light_math.h"
#include "core/tile_math.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace gbl::ui {

namespace {

std::string vecText(glm::vec3 v) {
    return "(" + lessonNumber(v.x) + ", " + lessonNumber(v.y) + ", " + lessonNumber(v.z) + ")";
}

glm::vec4 texel(FloatImage const& img, glm::ivec2 p) {
    glm::vec4 v(0.0f);
    for (int c = 0; c < std::min(img.channels, 4); ++c) v[c] = img.at(p.x, p.y, c);
    return v;
}

bool inside(FloatImage const& img, glm::ivec2 p) {
    return p.x >= 0 && p.y >= 0 && p.x < img.width && p.y < img.height;
}

// Per channel: |a - b| <= tolerance * |b| + absolute. The lit target is RGBA16F: 11 bits of
// mantissa give a relative rounding of 2^-11 (~5e-4) per stored value, which `tolerance` covers.
bool close(glm::vec3 a, glm::vec3 b, float tolerance, float absolute) {
    for (int c = 0; c < 3; ++c)
        if (std::abs(a[c] - b[c]) > tolerance * std::abs(b[c]) + absolute) return false;
    return true;
}

// The absolute slack of every lit-value comparison: a few fp16 steps at the values the lessons
// measure (0.01..2, where one step is at most 2^-10).
constexpr float kLitAbsolute = 2e-3f;

ClaimResult matchesCpu(LessonClaim const& c, ClaimFrame const& f, ClaimImages const& im) {
    auto const s = surfaceAt(im, f, f.pixel);
    if (!s) return {false, "no geometry at the lesson pixel"};
    glm::vec3 const cpu = shadePointCpu(f.lights, *s, f.pipeline.ambient);
    glm::vec3 const lit = glm::vec3(texel(im.lighting, f.pixel));
    bool ok = close(lit, cpu, c.tolerance, kLitAbsolute);
    std::string detail = "lit " + vecText(lit) + " vs CPU " + vecText(cpu);
    if (c.reached >= 0) {
        // A step whose text says the pixel is lit by its lights checks how many do, on the CPU: a
        // light "reaches" the pixel when it adds what loses_light calls visible.
        int reached = 0;
        for (PointLight const& l : f.lights) {
            glm::vec3 const own = shadeLightCpu(l, *s).total();
            if (std::max({own.r, own.g, own.b}) > 10.0f * kLitAbsolute) ++reached;
        }
        ok = ok && reached == c.reached;
        detail += "; " + std::to_string(reached) + " of " + std::to_string(f.lights.size()) +
                  " lights reach the pixel (the step says " + std::to_string(c.reached) + ")";
    }
    return {ok, detail};
}

ClaimResult losesLight(LessonClaim const& c, ClaimFrame const& f, ClaimImages const& im) {
    if (!im.referenceLighting) return {false, "no reference frame"};
    if (c.light < 0 || c.light >= int(f.lights.size()))
        return {false, "light " + std::to_string(c.light) + " does not exist"};
    auto const s = surfaceAt(im, f, f.pixel);
    if (!s) return {false, "no geometry at the lesson pixel"};
    glm::vec3 const own = shadeLightCpu(f.lights[std::size_t(c.light)], *s).total();
    glm::vec3 const drop = glm::vec3(texel(*im.referenceLighting, f.pixel) - texel(im.lighting, f.pixel));
    // The light must matter here, or "the drop equals it" says nothing.
    bool const visible = std::max({own.r, own.g, own.b}) > 10.0f * kLitAbsolute;
    bool const ok = visible && close(drop, own, c.tolerance, kLitAbsolute);
    return {ok, "lit drops by " + vecText(drop) + "; light " + std::to_string(c.light) + " adds " + vecText(own) +
                    " on the CPU" + (visible ? "" : " (too faint to show)")};
}

// The step's and the reference's image a comparing claim reads (LessonClaim::image), or nullopt
// without a reference frame.
std::optional<std::pair<FloatImage const*, FloatImage const*>> comparedImages(LessonClaim const& c,
                                                                              ClaimImages const& im) {
    bool const final = c.image == Attachment::Final;
    std::optional<FloatImage> const& reference = final ? im.referenceDisplay : im.referenceLighting;
    if (!reference) return std::nullopt;
    return std::pair{final ? &im.display : &im.lighting, &*reference};
}

ClaimResult sameImage(LessonClaim const& c, ClaimFrame const&, ClaimImages const& im) {
    auto const images = comparedImages(c, im);
    if (!images) return {false, "no reference frame"};
    FloatImage const& a = *images->first;
    FloatImage const& b = *images->second;
    if (a.width != b.width || a.height != b.height) return {false, "the frames differ in size"};
    float maxAbs = 0.0f;
    glm::ivec2 where{0};
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            for (int ch = 0; ch < 3; ++ch) {
                float const d = std::abs(a.at(x, y, ch) - b.at(x, y, ch));
                if (!(d <= maxAbs)) {  // NaN counts as a difference
                    maxAbs = std::isnan(d) ? INFINITY : d;
                    where = {x, y};
                }
            }
    return {maxAbs <= c.bound, "largest difference " + lessonNumber(maxAbs) + " at (" + std::to_string(where.x) + ", " +
                                   std::to_string(where.y) + "), bound " + lessonNumber(c.bound)};
}

ClaimResult differsFrom(LessonClaim const& c, ClaimFrame const&, ClaimImages const& im) {
    auto const images = comparedImages(c, im);
    if (!images) return {false, "no reference frame"};
    FloatImage const& a = *images->first;
    FloatImage const& b = *images->second;
    if (a.width != b.width || a.height != b.height) return {false, "the frames differ in size"};
    int covered = 0, differing = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            if (im.position.at(x, y, 3) == 0.0f) continue;
            ++covered;
            bool d = false;
            for (int ch = 0; ch < 3; ++ch) d = d || !(std::abs(a.at(x, y, ch) - b.at(x, y, ch)) <= c.bound);
            differing += d ? 1 : 0;
        }
    float const share = covered > 0 ? float(differing) / float(covered) : 0.0f;
    return {covered > 0 && share >= c.minFraction && share < c.maxFraction,
            std::to_string(differing) + " of " + std::to_string(covered) + " pixels differ by more than " +
                lessonNumber(c.bound) + " (" + lessonNumber(100.0f * share) + " %" +
                (c.maxFraction < 1.0f ? ", range " + lessonNumber(100.0f * c.minFraction) + " .. " +
                                            lessonNumber(100.0f * c.maxFraction) + " %"
                                      : std::string()) +
                ")"};
}

ClaimResult complexShare(LessonClaim const& c, ClaimFrame const&, ClaimImages const& im) {
    if (!im.complexShare) return {false, "the frame counted no complex pixels (msaa off, or it fell back to off)"};
    double const share = *im.complexShare;
    return {share >= c.minFraction && share < c.maxFraction,
            "complex pixels (lit per sample by edges): " + lessonNumber(float(100.0 * share)) +
                " % of the frame (range " + lessonNumber(100.0f * c.minFraction) + " .. " +
                lessonNumber(100.0f * c.maxFraction) + " %)"};
}

ClaimResult fewerEvaluations(LessonClaim const& c, ClaimFrame const&, ClaimImages const& im) {
    if (!im.referenceCoverage || im.coverage.channels < 1) return {false, "no coverage images (show heatmap)"};
    double const step = evaluationCount(im.coverage), ref = evaluationCount(*im.referenceCoverage);
    double const saved = ref > 0.0 ? (ref - step) / ref : 0.0;
    return {ref > 0.0 && saved >= double(c.minFraction) && saved < double(c.maxFraction),
            evaluationsLine(step, ref) + " than the reference (range " + lessonNumber(100.0f * c.minFraction) + " .. " +
                lessonNumber(100.0f * c.maxFraction) + " %)"};
}

ClaimResult fewerLitPixels(LessonClaim const& c, ClaimFrame const& f, ClaimImages const& im) {
    if (!im.referenceLighting) return {false, "no reference frame"};
    // An epsilon of a few fp16 steps: a pixel that a light reaches gets at least that much.
    constexpr float kEpsilon = 4e-3f;
    int const step = litPixelCount(im.lighting, im, f.pipeline.ambient, kEpsilon);
    int const ref =
        litPixelCount(*im.referenceLighting, im, c.reference ? c.reference->ambient : f.pipeline.ambient, kEpsilon);
    float const lost = ref > 0 ? float(ref - step) / float(ref) : 0.0f;
    return {ref > 0 && lost >= c.minFraction, std::to_string(step) + " lit pixels against " + std::to_string(ref) +
                                                  " in the reference: " + lessonNumber(100.0f * lost) + " % lost"};
}

ClaimResult positionError(LessonClaim const& c, ClaimFrame const& f, ClaimImages const& im) {
    int const w = im.depth.width, h = im.depth.height;
    glm::mat4 const inv = glm::inverse(f.camera.projection(float(w) / float(h)) * f.camera.view());
    float worst = 0.0f;
    glm::ivec2 at{0};
    int covered = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (im.position.at(x, y, 3) == 0.0f) continue;
            ++covered;
            float const gy = float(h - 1 - y);  // window y has its origin at the bottom
            glm::vec4 const ndc(2.0f * (float(x) + 0.5f) / float(w) - 1.0f, 2.0f * (gy + 0.5f) / float(h) - 1.0f,
                                2.0f * im.depth.at(x, y, 0) - 1.0f, 1.0f);
            glm::vec4 const world = inv * ndc;
            glm::vec3 const stored = glm::vec3(texel(im.position, {x, y}));
            float const error = glm::length(glm::vec3(world) / world.w - stored);
            if (error > worst) {
                worst = error;
                at = {x, y};
            }
        }
    ClaimResult out{covered > 0 && worst < c.bound && worst >= c.atLeast,
                    "largest |stored - rebuilt| " + lessonNumber(worst) + " at pixel (" + std::to_string(at.x) + ", " +
                        std::to_string(at.y) + ") over " + std::to_string(covered) + " pixels, bound " +
                        (c.atLeast > 0.0f ? lessonNumber(c.atLeast) + " .. " : std::string()) + lessonNumber(c.bound)};
    if (covered > 0) out.worst = at;
    out.worstValue = worst;
    return out;
}

ClaimResult tileCount(LessonClaim const& c, ClaimFrame const& f, ClaimImages const& im) {
    if (im.coverage.channels < 1 || !inside(im.coverage, f.pixel))
        return {false, "no coverage image (show tile_lights)"};
    int const gpu = int(im.coverage.at(f.pixel.x, f.pixel.y, 0));
    int const cpu = cpuTileLightCount(im, f, f.pixel);
    std::string detail = "the tile lists " + std::to_string(gpu) + " lights; the CPU tile test " + std::to_string(cpu);
    if (!c.most) return {gpu == cpu && cpu > 0, detail};
    // most: no tile of the frame lists more (every pixel of a tile holds its tile's count).
    int most = 0;
    glm::ivec2 at{0};
    for (int y = 0; y < im.coverage.height; ++y)
        for (int x = 0; x < im.coverage.width; ++x)
            if (int const n = int(im.coverage.at(x, y, 0)); n > most) {
                most = n;
                at = {x, y};
            }
    detail += "; the most of any tile " + std::to_string(most) + " (at pixel (" + std::to_string(at.x) + ", " +
              std::to_string(at.y) + "))";
    return {gpu == cpu && cpu > 0 && gpu >= most, detail};
}

ClaimResult executedExceedsLit(LessonClaim const& c, ClaimFrame const& f, ClaimImages const& im) {
    if (im.coverage.channels < 2 || !inside(im.coverage, f.pixel)) return {false, "no coverage image (show heatmap)"};
    float const executed = im.coverage.at(f.pixel.x, f.pixel.y, 0), lit = im.coverage.at(f.pixel.x, f.pixel.y, 1);
    std::string detail = lessonNumber(executed) + " lights evaluated, " + lessonNumber(lit) + " lit the pixel";
    if (c.minFraction <= 0.0f && c.maxFraction >= 1.0f) return {executed > lit, detail};
    // The frame-wide share of evaluations that added no light (a step's text states it in words).
    double evaluated = 0.0, useful = 0.0;
    for (int y = 0; y < im.coverage.height; ++y)
        for (int x = 0; x < im.coverage.width; ++x) {
            evaluated += double(im.coverage.at(x, y, 0));
            useful += double(im.coverage.at(x, y, 1));
        }
    double const wasted = evaluated > 0.0 ? (evaluated - useful) / evaluated : 0.0;
    detail += "; over the frame " + lessonNumber(float(100.0 * wasted)) + " % of " +
              lessonNumber(float(evaluated * 1e-6)) + " M evaluations added nothing (range " +
              lessonNumber(100.0f * c.minFraction) + " .. " + lessonNumber(100.0f * c.maxFraction) + " %)";
    return {executed > lit && wasted >= double(c.minFraction) && wasted < double(c.maxFraction), detail};
}

ClaimResult attachmentEquals(LessonClaim const& c, ClaimFrame const& f, ClaimImages const& im) {
    FloatImage const* img = c.attachment == Attachment::Position     ? &im.position
                            : c.attachment == Attachment::Normal     ? &im.normal
                            : c.attachment == Attachment::AlbedoSpec ? &im.albedoSpec
                            : c.attachment == Attachment::Depth      ? &im.depth
                                                                     : &im.lighting;
    if (!inside(*img, f.pixel)) return {false, "the pixel is outside the frame"};
    glm::vec4 const v = texel(*img, f.pixel);
    bool ok = true;
    std::string got;
    for (int i = 0; i < 4; ++i) {
        if (!(c.compare & (1u << i))) continue;
        ok = ok && std::abs(v[i] - c.value[i]) <= c.tolerance;
        got += std::string(got.empty() ? "" : ", ") + "xyzw"[i] + " " + lessonNumber(v[i]) + " (want " +
               lessonNumber(c.value[i]) + ")";
    }
    return {ok, "stored (" + got + "), expected within " + lessonNumber(c.tolerance)};
}

}  // namespace

std::optional<ShadingInputs> surfaceAt(ClaimImages const& im, ClaimFrame const& f, glm::ivec2 p) {
    if (!inside(im.position, p) || im.position.at(p.x, p.y, 3) == 0.0f) return std::nullopt;
    ShadingInputs s;
    s.position = glm::vec3(texel(im.position, p));
    s.normal = glm::normalize(glm::vec3(texel(im.normal, p)));
    glm::vec4 const as = texel(im.albedoSpec, p);
    s.albedo = glm::vec3(as);
    s.specular = as.a;
    s.viewPosition = f.camera.position;
    shadingOf(f.pipeline, s);
    return s;
}

int litPixelCount(FloatImage const& lighting, ClaimImages const& im, glm::vec3 ambient, float epsilon) {
    int n = 0;
    for (int y = 0; y < lighting.height; ++y)
        for (int x = 0; x < lighting.width; ++x) {
            if (im.position.at(x, y, 3) == 0.0f) continue;
            glm::vec3 const base = ambient * glm::vec3(texel(im.albedoSpec, {x, y}));
            glm::vec3 const lit = glm::vec3(texel(lighting, {x, y}));
            n += (lit.r - base.r > epsilon || lit.g - base.g > epsilon || lit.b - base.b > epsilon) ? 1 : 0;
        }
    return n;
}

double evaluationCount(FloatImage const& coverage) {
    double n = 0.0;
    if (coverage.channels < 1) return n;
    for (int y = 0; y < coverage.height; ++y)
        for (int x = 0; x < coverage.width; ++x) n += double(coverage.at(x, y, 0));
    return n;
}

std::string evaluationsLine(double a, double b) {
    char buf[160];
    double const saved = b > 0.0 ? 100.0 * (b - a) / b : 0.0;
    std::snprintf(buf, sizeof buf, "light evaluations (the heat map summed): A %.4g M, B %.4g M: A runs %.3g %% %s",
                  a * 1e-6, b * 1e-6, std::abs(saved), saved >= 0.0 ? "fewer" : "more");
    return buf;
}

int cpuTileLightCount(ClaimImages const& im, ClaimFrame const& f, glm::ivec2 pixel) {
    int const w = im.depth.width, h = im.depth.height;
    TileGrid const grid = tileGrid(w, h);
    int const gy = h - 1 - pixel.y;  // tiles count from the bottom
    gbl::PixelRect const rect = tilePixelRect(grid, w, h, pixel.x / grid.tileSize, gy / grid.tileSize);
    float minD = 1e30f, maxD = 0.0f;
    for (int y = rect.y0; y < rect.y1; ++y)
        for (int x = rect.x0; x < rect.x1; ++x) {
            int const row = h - 1 - y;
            if (im.position.at(x, row, 3) == 0.0f) continue;
            float const d = linearDepth(im.depth.at(x, row, 0), f.camera.nearPlane, f.camera.farPlane);
            minD = std::min(minD, d);
            maxD = std::max(maxD, d);
        }
    if (maxD <= 0.0f) return 0;
    glm::mat4 const proj = f.camera.projection(float(w) / float(h)), view = f.camera.view();
    TileFrustum const fr = tileFrustum(glm::inverse(proj), w, h, rect);
    int n = 0;
    for (PointLight const& l : f.lights) {
        float const r = lightRadius(l).radius;
        if (r > 0.0f && sphereTouchesTile(fr, minD, maxD, glm::vec3(view * glm::vec4(l.position, 1.0f)), r)) ++n;
    }
    return n;
}

namespace {

constexpr std::array<std::string_view, 2> kMatchesCpuOptional{"tolerance", "reached"};
constexpr std::array<std::string_view, 2> kLosesLightFields{"light", "reference"};
constexpr std::array<std::string_view, 1> kToleranceOptional{"tolerance"};
constexpr std::array<std::string_view, 2> kSameImageFields{"reference", "bound"};
constexpr std::array<std::string_view, 1> kImageOptional{"image"};
constexpr std::array<std::string_view, 3> kDiffersFromFields{"reference", "bound", "min_fraction"};
constexpr std::array<std::string_view, 2> kDiffersFromOptional{"image", "max_fraction"};
constexpr std::array<std::string_view, 2> kFewerEvaluationsFields{"reference", "min_fraction"};
constexpr std::array<std::string_view, 1> kMaxFractionOptional{"max_fraction"};
constexpr std::array<std::string_view, 2> kFewerLitFields{"reference", "min_fraction"};
constexpr std::array<std::string_view, 1> kBoundFields{"bound"};
constexpr std::array<std::string_view, 2> kAtLeastOptional{"at_least", "mark"};
constexpr std::array<std::string_view, 1> kMostOptional{"most"};
constexpr std::array<std::string_view, 2> kWastedShareOptional{"min_fraction", "max_fraction"};
constexpr std::array<std::string_view, 2> kAttachmentFields{"attachment", "value"};
constexpr std::array<std::string_view, 2> kComplexShareFields{"min_fraction", "max_fraction"};

// kind, name, fields, optional fields, about the step's pixel, needs a reference frame, check, doc.
std::array<ClaimKindInfo, 11> const kClaimKinds{{
    {ClaimKind::MatchesCpu,
     "matches_cpu",
     {},
     kMatchesCpuOptional,
     true,
     false,
     matchesCpu,
     "the lit value at `pixel` equals ambient * albedo + every light on the CPU; with `reached`, exactly that "
     "many lights add a visible amount there"},
    {ClaimKind::LosesLight, "loses_light", kLosesLightFields, kToleranceOptional, true, true, losesLight,
     "reference lit - step lit at `pixel` equals that light's CPU contribution, and it is visible"},
    {ClaimKind::SameImage, "same_image", kSameImageFields, kImageOptional, false, true, sameImage,
     "every lit pixel of step and reference differs by at most `bound`"},
    {ClaimKind::FewerLitPixels,
     "fewer_lit_pixels",
     kFewerLitFields,
     {},
     false,
     true,
     fewerLitPixels,
     "at least `min_fraction` of the reference's lit pixels are dark in the step"},
    {ClaimKind::PositionError, "position_error_below", kBoundFields, kAtLeastOptional, false, false, positionError,
     "on every covered pixel the stored position and the one rebuilt from depth differ by less than `bound`; with "
     "`at_least`, the largest error is at least that (so a step's text can say how large it is); with `mark`, the "
     "editor rings the pixel of the largest error in the viewport, with its value"},
    {ClaimKind::TileCountMatchesCpu,
     "tile_count_matches_cpu",
     {},
     kMostOptional,
     true,
     false,
     tileCount,
     "the lights the tile of `pixel` lists equal the CPU tile test, and are more than 0; with `most`, no tile of "
     "the frame lists more"},
    {ClaimKind::ExecutedExceedsLit,
     "executed_exceeds_lit",
     {},
     kWastedShareOptional,
     true,
     false,
     executedExceedsLit,
     "at `pixel` more lights were evaluated than lit it; with `min_fraction` (and `max_fraction`), that share "
     "of the frame's light evaluations added no light"},
    {ClaimKind::AttachmentEquals, "attachment_equals", kAttachmentFields, kToleranceOptional, true, false,
     attachmentEquals, "the attachment at `pixel` equals `value`; null entries are not compared"},
    {ClaimKind::DiffersFrom, "differs_from", kDiffersFromFields, kDiffersFromOptional, false, true, differsFrom,
     "at least `min_fraction` of the covered pixels differ from the reference by more than `bound`; with "
     "`max_fraction`, fewer than that share (so a step's text can say how many pixels change)"},
    {ClaimKind::FewerEvaluations, "fewer_evaluations", kFewerEvaluationsFields, kMaxFractionOptional, false, true,
     fewerEvaluations,
     "the heat map's light evaluations summed over the frame are at least `min_fraction` fewer than the "
     "reference's (and, with `max_fraction`, less than that); needs the heatmap view"},
    {ClaimKind::ComplexShare,
     "complex_share",
     kComplexShareFields,
     {},
     false,
     false,
     complexShare,
     "the share of the frame's pixels the msaa detection pass marks complex (lit per sample by `edges`) is at "
     "least `min_fraction` and below `max_fraction`; needs msaa 2, 4 or 8"},
}};

// The claims' numbers; `at_least` must also not exceed `bound`, `max_fraction` must exceed
// `min_fraction` (the reader checks both after the ranges).
constexpr std::array<ClaimNumberField, 5> kClaimNumberFields{{
    {"tolerance", &LessonClaim::tolerance, 0.0f, 10.0f, "relative and absolute tolerance of a comparison with the CPU"},
    {"bound", &LessonClaim::bound, 0.0f, 1e6f, "largest absolute difference (or error) that still counts as equal"},
    {"at_least", &LessonClaim::atLeast, 0.0f, 1e6f, "the largest error is at least this (at most `bound`)"},
    {"min_fraction", &LessonClaim::minFraction, 0.0f, 1.0f, "the least share of pixels or evaluations"},
    {"max_fraction", &LessonClaim::maxFraction, 0.0f, 1.0f, "the share is below this (above `min_fraction`)"},
}};

}  // namespace

std::span<ClaimNumberField const> claimNumberFields() {
    return kClaimNumberFields;
}

ClaimNumberField const* findClaimNumberField(std::string_view name) {
    for (ClaimNumberField const& f : kClaimNumberFields)
        if (f.name == name) return &f;
    return nullptr;
}

std::span<ClaimKindInfo const> claimKinds() {
    return kClaimKinds;
}

ClaimKindInfo const* findClaimKind(std::string_view name) {
    for (ClaimKindInfo const& k : kClaimKinds)
        if (k.name == name) return &k;
    return nullptr;
}

ClaimKindInfo const& claimKindInfo(ClaimKind kind) {
    for (ClaimKindInfo const& k : kClaimKinds)
        if (k.kind == kind) return k;
    return kClaimKinds[0];
}

bool claimNeedsReference(LessonClaim const& claim) {
    return claimKindInfo(claim.kind).needsReference;
}

ClaimResult checkClaim(LessonClaim const& c, ClaimFrame const& f, ClaimImages const& im) {
    return claimKindInfo(c.kind).check(c, f, im);
}

std::optional<ClaimMark> claimMark(LessonClaim const& c, ClaimResult const& r) {
    if (!c.mark || !r.worst || c.kind != ClaimKind::PositionError) return std::nullopt;
    return ClaimMark{*r.worst, r.worstValue, "largest |P_stored − P| of the frame: " + lessonNumber(r.worstValue)};
}

}  // namespace gbl::ui
