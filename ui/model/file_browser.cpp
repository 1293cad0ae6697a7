// File browser navigation and listing over std::filesystem.
#include "model/file_browser.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <system_error>

namespace gbl::ui {

namespace fs = std::filesystem;

namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

// Absolute, with . and .. resolved and no trailing separator (the root stays "/").
fs::path normalFolder(fs::path const& p) {
    std::error_code ec;
    fs::path abs = fs::absolute(p, ec);
    if (ec) abs = p;
    abs = abs.lexically_normal();
    if (abs.has_relative_path() && !abs.has_filename()) abs = abs.parent_path();
    return abs;
}

}  // namespace

std::vector<std::string> extensionsFor(FileBrowserPurpose purpose) {
    switch (purpose) {
        case FileBrowserPurpose::OpenScene:
            return {".gltf", ".glb"};
        case FileBrowserPurpose::OpenSession:
        case FileBrowserPurpose::SaveSession:
        case FileBrowserPurpose::OpenLesson:
        case FileBrowserPurpose::OpenGBuffer:
            return {".json"};
    }
    return {};
}

char const* browserTitle(FileBrowserPurpose purpose) {
    switch (purpose) {
        case FileBrowserPurpose::OpenScene:
            return "Open scene";
        case FileBrowserPurpose::OpenSession:
            return "Open session";
        case FileBrowserPurpose::SaveSession:
            return "Save session as";
        case FileBrowserPurpose::OpenLesson:
            return "Open lesson";
        case FileBrowserPurpose::OpenGBuffer:
            return "Open G-buffer";
    }
    return "";
}

std::string defaultFolder(std::string const& hint) {
    std::error_code ec;
    if (!hint.empty()) {
        fs::path const p = normalFolder(hint);
        if (fs::is_directory(p, ec)) return p.string();
        if (fs::is_directory(p.parent_path(), ec)) return p.parent_path().string();
    }
    fs::path const cwd = fs::current_path(ec);
    return ec ? std::string("/") : normalFolder(cwd).string();
}

bool matchesExtension(std::string const& name, std::vector<std::string> const& extensions) {
    if (extensions.empty()) return true;
    std::string const l = lower(name);
    for (std::string const& ext : extensions)
        if (l.size() > ext.size() && l.compare(l.size() - ext.size(), ext.size(), ext) == 0) return true;
    return false;
}

bool changeFolder(FileBrowserState& state, std::string const& path) {
    fs::path const folder = normalFolder(path);
    std::error_code ec;
    if (!fs::is_directory(folder, ec)) {
        state.error =
            folder.string() + " is not a folder that can be opened" + (ec ? ": " + ec.message() : std::string()) + ".";
        return false;
    }
    fs::directory_iterator it(folder, fs::directory_options::skip_permission_denied, ec);
    if (ec) {
        state.error = "Cannot list " + folder.string() + ": " + ec.message() + ".";
        return false;
    }
    std::vector<FileEntry> folders, files;
    for (; it != fs::directory_iterator(); it.increment(ec)) {
        if (ec) break;
        std::string const name = it->path().filename().string();
        if (name.empty() || name[0] == '.') continue;  // hidden entries, as file managers do by default
        std::error_code entryError;
        if (it->is_directory(entryError)) {
            folders.push_back({name, true, 0});
        } else if (matchesExtension(name, state.extensions)) {
            std::uintmax_t const bytes = it->file_size(entryError);
            files.push_back({name, false, entryError ? 0 : bytes});
        }
    }
    auto const byName = [](FileEntry const& a, FileEntry const& b) { return lower(a.name) < lower(b.name); };
    std::sort(folders.begin(), folders.end(), byName);
    std::sort(files.begin(), files.end(), byName);
    folders.insert(folders.end(), files.begin(), files.end());
    state.entries = std::move(folders);
    state.folder = folder.string();
    state.selected = -1;
    state.error.clear();
    return true;
}

bool refreshFolder(FileBrowserState& state) {
    return changeFolder(state, state.folder);
}

bool goToParent(FileBrowserState& state) {
    fs::path const p(state.folder);
    if (p == p.root_path()) return false;
    return changeFolder(state, p.parent_path().string());
}

bool enterFolder(FileBrowserState& state, std::string const& name) {
    return changeFolder(state, (fs::path(state.folder) / name).string());
}

void openFileBrowser(FileBrowserState& state, FileBrowserPurpose purpose, std::string const& hint) {
    state.open = true;
    state.justOpened = true;
    state.purpose = purpose;
    state.extensions = extensionsFor(purpose);
    state.fileName.clear();
    std::error_code ec;
    if (!hint.empty() && !fs::is_directory(hint, ec)) {
        fs::path const name = fs::path(hint).filename();
        if (purpose == FileBrowserPurpose::SaveSession || fs::exists(hint, ec)) state.fileName = name.string();
    }
    if (!changeFolder(state, defaultFolder(hint))) changeFolder(state, defaultFolder());
}

std::optional<std::string> confirmFileBrowser(FileBrowserState& state) {
    // A G-buffer may be a folder (a `render --out` folder, or one holding manifest.json).
    bool const folderOk = state.purpose == FileBrowserPurpose::OpenGBuffer;
    if (state.fileName.empty() && folderOk) {
        state.error.clear();
        rememberPlace(state.recentPlaces, state.folder);
        return state.folder;
    }
    if (state.fileName.empty()) {
        state.error = "Choose a file in the list or type a name.";
        return std::nullopt;
    }
    fs::path const typed(state.fileName);
    fs::path const path = (typed.is_absolute() ? typed : fs::path(state.folder) / typed).lexically_normal();
    std::error_code ec;
    if (fs::is_directory(path, ec) && folderOk) {
        state.error.clear();
        rememberPlace(state.recentPlaces, path.string());
        return path.string();
    }
    if (fs::is_directory(path, ec)) {
        state.error = path.string() + " is a folder; choose a file in it.";
        return std::nullopt;
    }
    bool const saving = state.purpose == FileBrowserPurpose::SaveSession;
    if (!saving && !fs::exists(path, ec)) {
        state.error = path.string() + " does not exist.";
        return std::nullopt;
    }
    if (saving && !fs::is_directory(path.parent_path(), ec)) {
        state.error = "The folder " + path.parent_path().string() + " does not exist.";
        return std::nullopt;
    }
    state.error.clear();
    rememberPlace(state.recentPlaces, path.parent_path().string());
    return path.string();
}

void rememberPlace(std::vector<std::string>& places, std::string const& folder) {
    places.erase(std::remove(places.begin(), places.end(), folder), places.end());
    places.insert(places.begin(), folder);
    if (places.size() > kMaxRecentPlaces) places.resize(kMaxRecentPlaces);
}

}  // namespace gbl::ui
