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

}  // namespace gbl
