// Files in the browser build (issue 29): the page's file picker and downloads. The page's files
// chosen in its picker reach the editor as a drop onto the canvas (app/web/index.html), so they
// open as dropped files do. Natively both functions do nothing and return false: the editor's
// own file browser opens files, and written files stay where they were written.
#pragma once

#include <string>

namespace gbl::ui {

// Opens the page's file picker (several files: a glTF with its buffers and textures). True in the
// browser build.
bool pickFilesInBrowser();

// Offers the file at `path` (the build's in-memory file system) as a download named after it.
// True in the browser build when the file could be read.
bool offerDownload(std::string const& path);

}  // namespace gbl::ui
