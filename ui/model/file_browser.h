// The file browser behind Open scene, Open session and Save session: a current folder as an
// absolute path, its entries (folders first, files filtered by extension), recent places and
// parent/child navigation. Plain values and std::filesystem; the ImGui window is
// ui/panels/panel_file_browser.h.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace gbl::ui {

// OpenGBuffer takes a manifest or a folder (an empty name opens the folder shown).
enum class FileBrowserPurpose { OpenScene, OpenSession, SaveSession, OpenLesson, OpenGBuffer };

struct FileEntry {
    std::string name;
    bool folder = false;
    std::uintmax_t bytes = 0;  // files only
};

inline constexpr std::size_t kMaxRecentPlaces = 8;

struct FileBrowserState {
    bool open = false;
    bool justOpened = false;  // the window focuses its name field on the first frame
    FileBrowserPurpose purpose = FileBrowserPurpose::OpenScene;
    std::string folder;                     // absolute, without a trailing separator (except "/")
    std::vector<std::string> extensions;    // lower case with the dot (".gltf"); empty = every file
    std::vector<FileEntry> entries;         // folders first, then files, each sorted by name
    std::string fileName;                   // the name field: a file in `folder`, or an absolute path
    int selected = -1;                      // index into entries
    std::vector<std::string> recentPlaces;  // absolute folders, most recent first
    std::string error;                      // one sentence; empty when the last step worked
};

// Extensions each purpose lists.
std::vector<std::string> extensionsFor(FileBrowserPurpose purpose);
char const* browserTitle(FileBrowserPurpose purpose);

// The absolute folder to start in: `hint`'s folder when it names one, else the working folder.
std::string defaultFolder(std::string const& hint = {});

// Opens the browser for `purpose` in the folder of `hint` (a file or folder; empty: the working
// folder), with hint's file name prefilled for saving.
void openFileBrowser(FileBrowserState& state, FileBrowserPurpose purpose, std::string const& hint);

// Lists `path` (made absolute and normal) into state.entries. On failure the state keeps its
// folder and entries, and state.error says why in one sentence; returns false.
bool changeFolder(FileBrowserState& state, std::string const& path);
bool goToParent(FileBrowserState& state);
bool enterFolder(FileBrowserState& state, std::string const& name);
// Re-reads the current folder.
bool refreshFolder(FileBrowserState& state);

// Whether `name` ends in one of `extensions` (case-insensitive); true for an empty list.
bool matchesExtension(std::string const& name, std::vector<std::string> const& extensions);

// The absolute path the name field and folder describe, or nullopt with state.error set (empty
// name, a folder where a file is wanted, a missing file when opening). Confirming records the
// folder in the recent places.
std::optional<std::string> confirmFileBrowser(FileBrowserState& state);

// Moves `folder` to the front of the recent places, at most kMaxRecentPlaces.
void rememberPlace(std::vector<std::string>& places, std::string const& folder);

}  // namespace gbl::ui
