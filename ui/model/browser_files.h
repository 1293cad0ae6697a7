// Files in the browser build (issue 29): the page's file pickers and downloads. The page's files
// chosen in its picker reach the editor as a drop onto the canvas (app/web/index.html), so they
// open as dropped files do; a folder (dropped, or chosen with File > Open folder...) is written
// into the page's file system keeping its subfolders and handed to the editor whole
// (app/web/pre.js, gbl_open_folder). Natively these functions do nothing and return false: the
// editor's own file browser opens files, and written files stay where they were written.
#pragma once

#include <string>

namespace gbl::ui {

#ifdef __EMSCRIPTEN__
inline constexpr bool kInBrowser = true;
#else
inline constexpr bool kInBrowser = false;
#endif

// Opens the page's file picker (several files: a glTF with its buffers and textures). True in the
// browser build.
bool pickFilesInBrowser();

// Opens the page's folder picker (a glTF with its buffers and textures in subfolders). True in
// the browser build.
bool pickFolderInBrowser();

// Offers the file at `path` (the build's in-memory file system) as a download named after it.
// True in the browser build when the file could be read.
bool offerDownload(std::string const& path);

}  // namespace gbl::ui
