// Checking a lesson step's claim on real read-back images: one function per claim kind, shared by
// the GL test of every shipped lesson and `gbuffer-lab render --lesson` (claim.json).
#pragma once

#include "core/camera.h"
#include "core/frame_types.h"
#include "core/pipeline_settings.h"
#include "core/point_light.h"
#include "core/shading_cpu.h"
#include "model/lesson_state.h"

#include <glm/glm.hpp>

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>

namespace gbl::ui {

// The images of the step's frame (rows top to bottom, as Renderer::readAttachment returns
// them) and, for claims with a reference, the reference frame's lit and display images.
struct ClaimImages {
    FloatImage lighting;
    FloatImage display;  // the final image, with the overlays (same_image / differs_from on "final")
    FloatImage position;
    FloatImage normal;
    FloatImage albedoSpec;
    FloatImage depth;
    FloatImage coverage;  // filled only when the step shows the heat map or the tile view
    std::optional<FloatImage> referenceLighting;
    std::optional<FloatImage> referenceDisplay;
    std::optional<FloatImage> referenceCoverage;  // when the step shows the heat map
    std::optional<double> complexShare;           // msaa frames: the share of complex pixels (FrameStats)
};

struct ClaimFrame {
    Camera camera;
    std::span<PointLight const> lights;
    PipelineSettings pipeline;
    glm::ivec2 pixel{0};  // top-left origin
};

struct ClaimResult {
    ClaimResult() = default;
    ClaimResult(bool holds_, std::string detail_) : holds(holds_), detail(std::move(detail_)) {}
    bool holds = false;
    std::string detail;  // what was measured, in one sentence ("lit 0.0170 vs CPU 0.0532 ...")
    // position_error_below: the pixel with the largest error (top-left origin), which a step's
    // pixel task may ask the student to find.
    std::optional<glm::ivec2> worst;
    float worstValue = 0.0f;  // the largest error itself
};

// What the viewport marks for a claim with `mark` (the editor measures it on its own frame): the
// pixel its check named and one line saying what was measured there. nullopt: nothing to mark.
struct ClaimMark {
    glm::ivec2 pixel{0};  // top-left origin
    float value = 0.0f;
    std::string label;
};
std::optional<ClaimMark> claimMark(LessonClaim const& claim, ClaimResult const& result);

// One row per claim kind (issue 24), the one place a kind is described: the name lesson files
// use, its fields (required, then optional, which take their default when left out),
// whether it is about the step's pixel (the step must then have one) and needs a reference frame,
// its check, and one line of documentation (docs/lessons.md's table says the same, in full). The
// numbers' ranges and defaults are claimNumberFields()'.
struct ClaimKindInfo {
    ClaimKind kind;
    std::string_view name;
    std::span<std::string_view const> fields;
    std::span<std::string_view const> optionalFields;
    bool atPixel;
    bool needsReference;
    ClaimResult (*check)(LessonClaim const&, ClaimFrame const&, ClaimImages const&);
    std::string_view doc;
};
std::span<ClaimKindInfo const> claimKinds();
ClaimKindInfo const* findClaimKind(std::string_view name);
ClaimKindInfo const& claimKindInfo(ClaimKind kind);

// One number a claim may carry (claimKinds() says which kinds take it, and whether they must): its
// key in lesson files, its LessonClaim member, the values a file may give, and its default, which is
// LessonClaim{}'s: what an optional one is when the file leaves it out. The lesson reader reads every
// claim number through this table (session/lesson_file_fields.cpp), so a range is written once.
struct ClaimNumberField {
    std::string_view name;
    float LessonClaim::*member = nullptr;
    float min = 0.0f, max = 0.0f;
    std::string_view help;
    float defaultValue() const { return LessonClaim{}.*member; }
};
std::span<ClaimNumberField const> claimNumberFields();
ClaimNumberField const* findClaimNumberField(std::string_view name);

// Whether the claim compares with a reference frame (claimKindInfo's needsReference).
bool claimNeedsReference(LessonClaim const& claim);

ClaimResult checkClaim(LessonClaim const& claim, ClaimFrame const& frame, ClaimImages const& images);

// Pieces the claims use, exposed for their tests.
// The surface at a pixel as the shading sees it (position, normal, albedo, specular, camera).
std::optional<ShadingInputs> surfaceAt(ClaimImages const& images, ClaimFrame const& frame, glm::ivec2 pixel);
// Pixels whose lit value exceeds ambient * albedo by more than `epsilon` in any channel.
int litPixelCount(FloatImage const& lighting, ClaimImages const& images, glm::vec3 ambient, float epsilon);
// The heat map's light evaluations summed over the frame (coverage x: the lighting shader's runs
// per pixel); what fewer_evaluations compares and the A/B split shows in the heat view.
double evaluationCount(FloatImage const& coverage);
// "A 1.234 M, B 2.345 M light evaluations: A runs 47.3 % fewer" (or "more").
std::string evaluationsLine(double a, double b);
// Lights the CPU tile test lists for the tile holding `pixel` (depth bounds from the depth image).
int cpuTileLightCount(ClaimImages const& images, ClaimFrame const& frame, glm::ivec2 pixel);

}  // namespace gbl::ui
