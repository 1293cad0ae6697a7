// The file browser window over model/file_browser.h, used by Open scene, Open session and Save.
#pragma once

#include "model/file_browser.h"

#include <optional>
#include <string>

namespace gbl::ui {

// Draws the browser as a modal while state.open. Returns the chosen absolute path in the frame
// the user confirms it (OK, Enter in the name field, or a double-click on a file); the browser
// then closes. Cancel or Escape closes it and returns nothing.
std::optional<std::string> drawFileBrowser(FileBrowserState& state);

}  // namespace gbl::ui
