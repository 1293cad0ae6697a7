// The Glossary window: every term of assets/glossary.json with its definition, a filter, and
// opening at one term (from a term under a lesson step, or Help > Glossary).
#pragma once

#include "session/glossary_file.h"

#include <string>

namespace gbl::ui {

struct GlossaryWindowState {
    bool open = false;
    std::string focus;      // the term to open and scroll to on the next frame ("" = none)
    std::string filter;     // typed text: only terms whose name or definition contain it
    std::string shownTerm;  // the term it last opened at (for the frame log)
};

void drawGlossaryWindow(GlossaryWindowState& state, Glossary const& glossary);

// A term's definition as a tooltip, when the last item is hovered.
void glossaryTooltip(GlossaryTerm const& term);

}  // namespace gbl::ui
