// Where the user's gbuffer-lab configuration lives (XDG base directories) and making sure it exists.
#include "session/config_dir.h"

#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace fs = std::filesystem;

namespace gbl::ui {

std::optional<std::string> configDirFrom(char const* xdgConfigHome, char const* home) {
    if (xdgConfigHome && *xdgConfigHome && fs::path(xdgConfigHome).is_absolute())
        return (fs::path(xdgConfigHome) / "gbuffer-lab").string();
    if (home && *home && fs::path(home).is_absolute()) return (fs::path(home) / ".config" / "gbuffer-lab").string();
    return std::nullopt;
}

std::optional<std::string> configDir() {
    return configDirFrom(std::getenv("XDG_CONFIG_HOME"), std::getenv("HOME"));
}

std::string configFile(std::string const& dir, std::string const& name) {
    return (fs::path(dir) / name).string();
}

std::optional<std::string> ensureConfigDir(std::string const& dir) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) return "cannot create the config folder " + dir + ": " + ec.message();
    if (!fs::is_directory(dir, ec)) return "the config folder " + dir + " is not a folder";
    return std::nullopt;
}

}  // namespace gbl::ui
