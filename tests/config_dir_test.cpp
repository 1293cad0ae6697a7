// The config folder: XDG_CONFIG_HOME first, then ~/.config, never a relative path; creating it.
#include "session/config_dir.h"
#include "run_command.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

using namespace gbl::ui;
namespace fs = std::filesystem;

TEST(ConfigDir, XdgConfigHomeComesFirst) {
    EXPECT_EQ(configDirFrom("/tmp/xdg", "/home/ada"), "/tmp/xdg/gbuffer-lab");
}

TEST(ConfigDir, HomeWhenXdgIsUnsetOrEmpty) {
    EXPECT_EQ(configDirFrom(nullptr, "/home/ada"), "/home/ada/.config/gbuffer-lab");
    EXPECT_EQ(configDirFrom("", "/home/ada"), "/home/ada/.config/gbuffer-lab");
}

TEST(ConfigDir, RelativePathsAreIgnored) {
    // A relative XDG_CONFIG_HOME would put the layout wherever the editor was started.
    EXPECT_EQ(configDirFrom("config", "/home/ada"), "/home/ada/.config/gbuffer-lab");
    EXPECT_EQ(configDirFrom("config", "home"), std::nullopt);
}

TEST(ConfigDir, NoneWithoutEitherVariable) {
    EXPECT_EQ(configDirFrom(nullptr, nullptr), std::nullopt);
    EXPECT_EQ(configDirFrom("", ""), std::nullopt);
}

TEST(ConfigDir, FilesLieInTheFolder) {
    EXPECT_EQ(configFile("/tmp/xdg/gbuffer-lab", "imgui.ini"), "/tmp/xdg/gbuffer-lab/imgui.ini");
}

TEST(ConfigDir, EnvironmentIsRead) {
    char const* oldHome = std::getenv("HOME");
    std::string const savedHome = oldHome ? oldHome : "";
    ::setenv("XDG_CONFIG_HOME", "/tmp/from-env", 1);
    EXPECT_EQ(configDir(), "/tmp/from-env/gbuffer-lab");
    ::unsetenv("XDG_CONFIG_HOME");
    ::setenv("HOME", "/tmp/home-from-env", 1);
    EXPECT_EQ(configDir(), "/tmp/home-from-env/.config/gbuffer-lab");
    if (oldHome)
        ::setenv("HOME", savedHome.c_str(), 1);
    else
        ::unsetenv("HOME");
}

TEST(ConfigDir, CreatedWithItsParents) {
    std::string const dir = gbl::test::freshTempDir("config_dir_create") + "/a/b/gbuffer-lab";
    EXPECT_EQ(ensureConfigDir(dir), std::nullopt);
    EXPECT_TRUE(fs::is_directory(dir));
    // An existing folder is fine too.
    EXPECT_EQ(ensureConfigDir(dir), std::nullopt);
}

TEST(ConfigDir, RefusedWhenAFileIsInTheWay) {
    std::string const base = gbl::test::freshTempDir("config_dir_blocked");
    std::ofstream(base + "/gbuffer-lab") << "not a folder";
    auto const error = ensureConfigDir(base + "/gbuffer-lab");
    ASSERT_TRUE(error.has_value());
    EXPECT_NE(error->find(base + "/gbuffer-lab"), std::string::npos) << *error;
}
