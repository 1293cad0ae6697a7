// The viewport's A/B comparison: side A is the editor's pipeline, side B the same with the fields
// chosen in the table below changed; split at a divider or diffed through the lit-pin machinery.
#pragma once

#include "core/frame_types.h"
#include "core/pipeline_fields.h"
#include "core/pipeline_settings.h"
#include "model/viewer_tools.h"

#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace gbl::ui {

// The A/B table's rows: the fields of core/pipeline_fields.h that side B can change, in its order.
using AbField = PipelineField;
using AbFieldKind = SettingKind;

std::span<AbField const> abFields();

enum class AbView { Split, Diff };
// What the diff view compares: the lit HDR frame, or (issue 12) the angle in degrees between A's
// and B's decoded normals, for comparing G-buffer layouts (B's layout ticked, e.g. classic).
enum class AbMetric { Lit, NormalAngle };

struct AbState {
    bool enabled = false;
    AbView view = AbView::Split;
    float divider = 0.5f;        // where A ends, as a share of the image width (A left, B right)
    glm::vec4 toggleRect{0.0f};  // where the viewport drew the A/B checkbox (window coordinates; --log-frames)
    PipelineSettings b;          // B's values of the fields it overrides
    std::vector<bool> overrides = std::vector<bool>(abFields().size(), false);
    DiffMode diffMode = DiffMode::Absolute;  // relative: |A - B| / |B|
    // A pixel differs when its largest RGB difference exceeds this: the fp16 bound of the GL tests.
    float threshold = 2e-3f;
    bool heatToThreshold = false;  // heat map from 0 to the threshold (else to the largest difference)
    LitPin pin;                    // B's lit frame pinned, A's diffed against it (the lit pin's code)
    AbMetric metric = AbMetric::Lit;
    float angleThreshold = 1.0f;               // normal angle: pixels turned by more than this many degrees are counted
    DiffStats normalDiff;                      // normal angle: per pixel, degrees between A's and B's decoded normals
    std::vector<PassTiming> passesA, passesB;  // GPU ms per pass of each side's last frame
    double gpuMsA = 0.0, gpuMsB = 0.0;
    bool passesTimed = true;  // false in a browser without timer queries (gl/gpu_timer.h passesTimed)
    // In the heat view: each side's light evaluations, the heat map's counts summed over the frame
    // (model/lesson_claims.h, evaluationCount); nullopt in other views.
    std::optional<std::pair<double, double>> evaluations;
};

// What the teaching views add to a frame's inputs (RenderInputs): a change renders again.
struct TeachingInputs {
    std::optional<int> accumulate;
    bool contribution = false;
    int wireframeLight = -1;
    std::optional<PipelineSettings> sideB;  // while A/B is on
    bool normalAngle = false;               // the diff shows the normal angle: the frame must read both sides' normals
    float angleThreshold = 0.0f;            // ... counted over this many degrees
    bool operator==(TeachingInputs const&) const = default;
};

// Turning A/B on: B starts as A with only the mode ticked, set to another mode (volumes, or quad
// when A already is volumes), so the first split already compares something.
void startAb(AbState& state, PipelineSettings const& a);

// Sets side B's `field` (a table name) from text as the UI script writes it ("volumes", "1",
// "64") and ticks it; false for an unknown field or value.
bool setAbField(AbState& state, std::string_view field, std::string const& value);

// Side B: A with the overridden fields taken from state.b.
PipelineSettings sideB(AbState const& state, PipelineSettings const& a);
// Whether side B overrides the G-buffer layout (the "normal angle" metric compares layouts).
bool abComparesLayout(AbState const& state);
// The names of the fields where two settings differ, in table order.
std::vector<std::string_view> differingFields(PipelineSettings const& a, PipelineSettings const& b);
// "mode quad | volumes, cull front | back": what the split compares, for its label.
std::string describeAb(PipelineSettings const& a, PipelineSettings const& b);
// A field's value as the table shows it ("volumes", "on", "32").
std::string fieldText(AbField const& field, PipelineSettings const& s);

}  // namespace gbl::ui
