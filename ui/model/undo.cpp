// Snapshot undo history with merging of continuous edits.
#include "model/undo.h"

namespace gbl::ui {

namespace {

std::size_t snapshotBytes(UndoSnapshot const& s) {
    std::size_t n = sizeof(UndoSnapshot) + s.lights.capacity() * sizeof(PointLight);
    for (auto const& l : s.lights) n += l.name.capacity();
    return n;
}

}  // namespace

std::string editTarget(UndoSnapshot const& before, UndoSnapshot const& after) {
    return editTarget(before, after.lights, after.pipeline);
}

std::string editTarget(UndoSnapshot const& before, std::vector<PointLight> const& lights,
                       PipelineSettings const& pipeline) {
    bool const pipelineChanged = before.pipeline != pipeline;
    if (before.lights.size() != lights.size()) return "lights";
    int changed = -1, count = 0;
    for (std::size_t i = 0; i < before.lights.size(); ++i)
        if (before.lights[i] != lights[i]) {
            changed = int(i);
            ++count;
        }
    if (count == 0) return pipelineChanged ? "pipeline" : "";
    if (count > 1 || pipelineChanged) return "lights";
    return "light " + std::to_string(changed);
}

UndoStack::UndoStack(UndoLimits limits) : limits_(limits) {}

void UndoStack::reset(UndoSnapshot const& state) {
    recorded_ = state;
    undo_.clear();
    redo_.clear();
    lastTarget_.clear();
    lastTime_ = -1e300;
    bytes_ = 0;
}

bool UndoStack::observe(UndoSnapshot const& current, bool editing, double now) {
    return observe(current.lights, current.pipeline, editing, now);
}

bool UndoStack::observe(std::vector<PointLight> const& lights, PipelineSettings const& pipeline, bool editing,
                        double now) {
    if (editing) return false;
    std::string const target = editTarget(recorded_, lights, pipeline);
    if (target.empty()) return false;
    // Two edits of the same light (or of the pipeline) in quick succession are one gesture:
    // keep the state before the first as the undo point and move only the end state. "lights"
    // edits (add, delete) never merge: each is a deliberate action.
    bool const merge =
        !undo_.empty() && target == lastTarget_ && target != "lights" && now - lastTime_ < limits_.mergeSeconds;
    if (!merge) {
        bytes_ += snapshotBytes(recorded_);
        undo_.push_back(std::move(recorded_));
    }
    recorded_.lights = lights;
    recorded_.pipeline = pipeline;
    for (auto const& r : redo_) bytes_ -= snapshotBytes(r);
    redo_.clear();
    lastTarget_ = target;
    lastTime_ = now;
    trim();
    return true;
}

bool UndoStack::commit(UndoSnapshot const& current, double now) {
    lastTarget_.clear();  // nothing before merges into this step
    bool const recorded = observe(current, false, now);
    lastTarget_ = "lights";  // "lights" never merges: nothing after merges into it either
    return recorded;
}

std::optional<UndoSnapshot> UndoStack::undo(UndoSnapshot const& current, double now) {
    observe(current, false, now);
    if (undo_.empty()) return std::nullopt;
    bytes_ += snapshotBytes(recorded_);
    redo_.push_back(std::move(recorded_));
    recorded_ = std::move(undo_.back());
    undo_.pop_back();
    bytes_ -= snapshotBytes(recorded_);
    // The next edit starts a new step even if it touches what the undone step touched.
    lastTarget_.clear();
    return recorded_;
}

std::optional<UndoSnapshot> UndoStack::redo(UndoSnapshot const& current, double now) {
    // An edit made after an undo clears the redo history (observe does that) before we look.
    observe(current, false, now);
    if (redo_.empty()) return std::nullopt;
    bytes_ += snapshotBytes(recorded_);
    undo_.push_back(std::move(recorded_));
    recorded_ = std::move(redo_.back());
    redo_.pop_back();
    bytes_ -= snapshotBytes(recorded_);
    lastTarget_.clear();
    trim();
    return recorded_;
}

void UndoStack::trim() {
    // Oldest steps go first; the newest step is always kept so one undo works even for a
    // snapshot larger than the whole budget.
    while (undo_.size() > 1 && (undo_.size() > limits_.maxSteps || bytes_ > limits_.maxBytes)) {
        bytes_ -= snapshotBytes(undo_.front());
        undo_.pop_front();
    }
    if (limits_.maxSteps == 0 && !undo_.empty()) {
        bytes_ -= snapshotBytes(undo_.front());
        undo_.pop_front();
    }
}

}  // namespace gbl::ui
