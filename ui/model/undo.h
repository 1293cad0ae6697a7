// Undo and redo of light and pipeline edits: snapshots of both, with continuous edits (a slider
// drag, quick wheel notches on one field) merged into one step, and a bounded history.
#pragma once

#include "core/pipeline_settings.h"
#include "core/point_light.h"

#include <cstddef>
#include <deque>
#include <optional>
#include <string>
#include <vector>

namespace gbl::ui {

// Snapshots compare with the members' defaulted operator==: every field, floats exactly, which
// is what "did this edit change anything" means.
struct UndoSnapshot {
    std::vector<PointLight> lights;
    PipelineSettings pipeline;

    bool operator==(UndoSnapshot const&) const = default;
};

// What an edit touched, so that repeated edits of the same thing can merge: "light 3",
// "pipeline", "lights" (added, deleted or more than one changed), "" for no change.
std::string editTarget(UndoSnapshot const& before, UndoSnapshot const& after);
std::string editTarget(UndoSnapshot const& before, std::vector<PointLight> const& lights,
                       PipelineSettings const& pipeline);

struct UndoLimits {
    std::size_t maxSteps = 200;
    // Snapshots copy every light; with thousands of lights the byte budget bounds memory first.
    std::size_t maxBytes = std::size_t(64) << 20;
    // Edits of the same target closer together than this merge (wheel notches, arrow keys).
    double mergeSeconds = 0.75;
};

// Usage, once per frame after the panels ran:
//     undo.observe({lights, pipeline}, ImGui::IsAnyItemActive(), now);
// While `editing` is true (a widget is held) nothing is recorded; the whole drag becomes one
// step when it ends. undo()/redo() return the state to apply.
class UndoStack {
public:
    explicit UndoStack(UndoLimits limits = {});

    // Starts a fresh history at `state` (a session was opened, the scene changed).
    void reset(UndoSnapshot const& state);

    // Records `current` as a step when it differs from the last recorded state and no edit is
    // in progress. Returns true when a step was recorded or merged into the previous one.
    bool observe(UndoSnapshot const& current, bool editing, double now);
    // The same without building a snapshot: the lights are only copied when they changed.
    bool observe(std::vector<PointLight> const& lights, PipelineSettings const& pipeline, bool editing, double now);

    // Lessons (ui/model/lesson_state.h): records `current` as a step of its own at once, never
    // merged with the step before or after it, so each lesson step is one undo entry. False
    // when nothing changed.
    bool commit(UndoSnapshot const& current, double now);

    // Steps back/forward. `current` is the live state: an edit not recorded yet is recorded
    // first, so undo always undoes what the user sees last. nullopt when there is nothing.
    std::optional<UndoSnapshot> undo(UndoSnapshot const& current, double now);
    std::optional<UndoSnapshot> redo(UndoSnapshot const& current, double now);

    bool canUndo() const { return !undo_.empty(); }
    bool canRedo() const { return !redo_.empty(); }
    std::size_t undoSteps() const { return undo_.size(); }
    std::size_t redoSteps() const { return redo_.size(); }
    std::size_t bytes() const { return bytes_; }
    UndoSnapshot const& recorded() const { return recorded_; }

private:
    void trim();

    UndoLimits limits_;
    UndoSnapshot recorded_;           // the state the top of the history leads to
    std::deque<UndoSnapshot> undo_;   // states before each step, oldest first
    std::vector<UndoSnapshot> redo_;  // states undone, most recent last
    std::string lastTarget_;          // what the last step changed, for merging
    double lastTime_ = -1e300;
    std::size_t bytes_ = 0;  // approximate memory held by undo_ and redo_
};

}  // namespace gbl::ui
