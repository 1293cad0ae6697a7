// The browser's lesson check (issue 29): `?check-lessons=all` (or ID:STEP,...) renders each shipped
// step with a claim in WebGL2 and prints one console line per step, as `render --lesson` checks a
// step natively, then a summary line the browser test reads. It runs in the page's own context
// instead of the editor.
#pragma once

#include <string>

namespace gbl {

// Prints "lesson-check ID:STEP holds|FAILS|skipped: ..." per step and "lesson-check: H hold, F fail,
// S skipped"; returns 0 when no claim fails, 1 when one does, 2 for a bad spec or lesson folder.
int checkLessonsInBrowser(std::string const& spec);

// `?bench-renderer=MODE`: the renderer alone at 1280x720 on the default scene (32 lights), no
// editor: 3 frames to warm up, then 10, each ended by a one-pixel read of the final image (which
// waits until the browser's GPU process has drawn it). Prints the mean and the fastest frame.
int benchRendererInBrowser(std::string const& mode);

}  // namespace gbl
