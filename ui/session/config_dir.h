// The user's configuration folder for gbuffer-lab, where the layout (imgui.ini) and crash recovery live.
#pragma once

#include <optional>
#include <string>

namespace gbl::ui {

// $XDG_CONFIG_HOME/gbuffer-lab, else $HOME/.config/gbuffer-lab; nullopt when neither is usable.
// Pure: the two variables are passed in (null or empty means unset). A relative XDG_CONFIG_HOME is
// ignored, as the XDG base directory specification asks, so the folder never depends on the cwd.
std::optional<std::string> configDirFrom(char const* xdgConfigHome, char const* home);

// configDirFrom() over this process's environment.
std::optional<std::string> configDir();

// A file in the config folder, e.g. configFile(dir, "imgui.ini").
std::string configFile(std::string const& dir, std::string const& name);

// Creates the folder (and its parents) when missing; one sentence saying why when it cannot.
std::optional<std::string> ensureConfigDir(std::string const& dir);

}  // namespace gbl::ui
