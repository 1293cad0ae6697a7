// The viewport's MSAA views (model/msaa_views.h, issue 47): their toggles with the complex share,
// and the overlay or heat map drawn over the image.
#pragma once

#include "model/msaa_views.h"

#include <imgui.h>

namespace gbl::ui {

// "Complex" and "Samples" toggles and the complex pixels' share, each followed by SameLine; nothing
// while the frame shown ran without msaa.
void msaaViewsRow(MsaaViewState& m);
// Call after the frame's image is drawn at origin..end: the heat map in its place (with a legend),
// then the complex pixels over it.
void drawMsaaViews(MsaaViewState const& m, ImVec2 origin, ImVec2 end);

}  // namespace gbl::ui
