// The command-line options that more than one command takes, each defined once: its name and a
// help line true in every command that has it. The commands add them with addShared() and refer
// to them by these names (never a second string literal), and tests/cli_readme_test.cpp checks
// that the README's command list names exactly the options the program accepts.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <string_view>

namespace gbl::cli {

struct SharedOption {
    char const* name;
    char const* help;
};

inline constexpr SharedOption kSize{"--size", "Frame size WxH (the editor: its window size)"};
inline constexpr SharedOption kLights{
    "--lights", "Lights in the default scene (32 when not given; bench: counts, comma-separated)"};
inline constexpr SharedOption kScene{"--scene", "A glTF 2.0 scene (.gltf or .glb) instead of the default scene"};
inline constexpr SharedOption kSession{"--session",
                                       "A session file: its scene, camera, lights and settings (options given "
                                       "beside it override them)"};
inline constexpr SharedOption kGl{"--gl", "Pretend the context is at most this OpenGL version, e.g. 3.3"};
inline constexpr SharedOption kAllowOutsideUris{"--allow-outside-uris",
                                                "Let glTF files read files outside their own folder"};
inline constexpr SharedOption kLesson{"--lesson", "A lesson step: ID or ID:STEP (see `gbuffer-lab lessons`)"};
inline constexpr SharedOption kLessonsDir{"--lessons-dir", "Read lessons from this folder instead of the shipped ones"};
inline constexpr SharedOption kOut{"--out", "Directory for the images and JSON files"};

// Adds `option` to `app`, bound to `value` (an option taking a value, or a flag for bool).
template <class T>
CLI::Option* addShared(CLI::App& app, SharedOption const& option, T& value) {
    return app.add_option(option.name, value, option.help);
}
inline CLI::Option* addShared(CLI::App& app, SharedOption const& option, bool& value) {
    return app.add_flag(option.name, value, option.help);
}

}  // namespace gbl::cli
