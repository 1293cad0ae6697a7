// Quit, New and Open ask before unsaved edits are discarded: the request waits here until the
// user answers the confirmation window (ui/panels/panel_confirm.h).
#pragma once

#include <optional>
#include <string>

namespace gbl::ui {

enum class DiscardingAction { Quit, NewSession, OpenScene, OpenSession };

struct DiscardGuard {
    std::optional<DiscardingAction> asking;     // the confirmation window is up for this
    std::optional<DiscardingAction> confirmed;  // answered "Discard" this frame: carry it out
};

// True when `action` may go ahead now (nothing unsaved); otherwise it waits for an answer.
inline bool mayDiscard(DiscardGuard& guard, DiscardingAction action, bool unsavedEdits) {
    if (!unsavedEdits) return true;
    guard.asking = action;
    return false;
}

// The actions that waited and were confirmed, once.
inline std::optional<DiscardingAction> takeConfirmed(DiscardGuard& guard) {
    std::optional<DiscardingAction> out = guard.confirmed;
    guard.confirmed.reset();
    return out;
}

inline char const* discardingVerb(DiscardingAction action) {
    switch (action) {
        case DiscardingAction::Quit:
            return "Quit";
        case DiscardingAction::NewSession:
            return "Start a new session";
        case DiscardingAction::OpenScene:
            return "Open another scene";
        case DiscardingAction::OpenSession:
            return "Open another session";
    }
    return "";
}

}  // namespace gbl::ui
