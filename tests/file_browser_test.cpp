// The file browser model on a temporary folder: absolute paths, folders first, extension filter,
// navigation, recent places and one-sentence errors.
#include "model/file_browser.h"

#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>

using namespace gbl::ui;
namespace fs = std::filesystem;

namespace {
struct TempTree : ::testing::Test {
    fs::path root;
    void SetUp() override {
        root = fs::temp_directory_path() / ("gbl_file_browser_" + std::to_string(::getpid()));
        fs::remove_all(root);
        fs::create_directories(root / "scenes" / "deep");
        fs::create_directories(root / "Alpha");
        fs::create_directories(root / ".hidden");
        for (char const* name : {"b.gltf", "A.GLB", "notes.txt", "session.json", "z.gltf"})
            std::ofstream(root / name) << "12345";
    }
    void TearDown() override { fs::remove_all(root); }
    std::vector<std::string> names(FileBrowserState const& s) {
        std::vector<std::string> out;
        for (auto const& e : s.entries) out.push_back(e.name + (e.folder ? "/" : ""));
        return out;
    }
};
}  // namespace

TEST_F(TempTree, ListsFoldersFirstThenMatchingFilesSortedByName) {
    FileBrowserState s;
    openFileBrowser(s, FileBrowserPurpose::OpenScene, (root / "b.gltf").string());
    EXPECT_EQ(s.folder, root.string());
    EXPECT_EQ(s.fileName, "b.gltf");
    EXPECT_EQ(names(s), (std::vector<std::string>{"Alpha/", "scenes/", "A.GLB", "b.gltf", "z.gltf"}));
    EXPECT_EQ(s.entries[2].bytes, 5u);
    EXPECT_TRUE(s.error.empty());

    openFileBrowser(s, FileBrowserPurpose::OpenSession, root.string());
    EXPECT_EQ(names(s), (std::vector<std::string>{"Alpha/", "scenes/", "session.json"}));
    EXPECT_TRUE(s.fileName.empty()) << "a folder hint prefills no name";
}

TEST_F(TempTree, NavigatesToChildrenAndParentsWithAbsolutePaths) {
    FileBrowserState s;
    s.extensions = extensionsFor(FileBrowserPurpose::OpenScene);
    ASSERT_TRUE(changeFolder(s, root.string() + "/scenes/../scenes/"));
    EXPECT_EQ(s.folder, (root / "scenes").string());
    ASSERT_TRUE(enterFolder(s, "deep"));
    EXPECT_EQ(s.folder, (root / "scenes" / "deep").string());
    EXPECT_TRUE(s.entries.empty());
    ASSERT_TRUE(goToParent(s));
    ASSERT_TRUE(goToParent(s));
    EXPECT_EQ(s.folder, root.string());
    EXPECT_TRUE(fs::path(s.folder).is_absolute());
    FileBrowserState top;
    ASSERT_TRUE(changeFolder(top, "/"));
    EXPECT_EQ(top.folder, "/");
    EXPECT_FALSE(goToParent(top)) << "the root has no parent";
}

TEST_F(TempTree, AMissingFolderKeepsTheListingAndSaysWhyInOneSentence) {
    FileBrowserState s;
    ASSERT_TRUE(changeFolder(s, root.string()));
    auto const before = s.entries;
    EXPECT_FALSE(enterFolder(s, "nope"));
    EXPECT_EQ(s.folder, root.string());
    EXPECT_EQ(s.entries.size(), before.size());
    EXPECT_NE(s.error.find((root / "nope").string()), std::string::npos) << s.error;
    EXPECT_EQ(s.error.back(), '.');
}

TEST_F(TempTree, ConfirmGivesAnAbsolutePathAndRemembersThePlace) {
    FileBrowserState s;
    openFileBrowser(s, FileBrowserPurpose::OpenScene, root.string());
    EXPECT_FALSE(confirmFileBrowser(s)) << "no name yet";
    EXPECT_FALSE(s.error.empty());
    s.fileName = "missing.gltf";
    EXPECT_FALSE(confirmFileBrowser(s));
    EXPECT_NE(s.error.find("does not exist"), std::string::npos);
    s.fileName = "scenes";
    EXPECT_FALSE(confirmFileBrowser(s)) << "a folder is not a scene";
    s.fileName = "z.gltf";
    auto const chosen = confirmFileBrowser(s);
    ASSERT_TRUE(chosen);
    EXPECT_EQ(*chosen, (root / "z.gltf").string());
    ASSERT_FALSE(s.recentPlaces.empty());
    EXPECT_EQ(s.recentPlaces.front(), root.string());

    // Saving accepts a new name in an existing folder only.
    openFileBrowser(s, FileBrowserPurpose::SaveSession, (root / "new.json").string());
    EXPECT_EQ(s.fileName, "new.json");
    auto const saved = confirmFileBrowser(s);
    ASSERT_TRUE(saved);
    EXPECT_EQ(*saved, (root / "new.json").string());
    s.fileName = (root / "absent" / "x.json").string();
    EXPECT_FALSE(confirmFileBrowser(s));
}

TEST(FileBrowser, DefaultFolderIsAbsolute) {
    EXPECT_TRUE(fs::path(defaultFolder()).is_absolute());
    EXPECT_EQ(defaultFolder(), fs::current_path().string());
    EXPECT_EQ(defaultFolder("session.json"), fs::current_path().string())
        << "a relative name starts in the working folder";
}

TEST(FileBrowser, RecentPlacesAreUniqueNewestFirstAndBounded) {
    std::vector<std::string> places;
    for (int i = 0; i < 12; ++i) rememberPlace(places, "/p" + std::to_string(i));
    rememberPlace(places, "/p5");
    EXPECT_EQ(places.size(), kMaxRecentPlaces);
    EXPECT_EQ(places.front(), "/p5");
    EXPECT_EQ(std::count(places.begin(), places.end(), "/p5"), 1);
}

TEST(FileBrowser, ExtensionsMatchCaseInsensitivelyAndNeedANameBeforeThem) {
    EXPECT_TRUE(matchesExtension("x.GLTF", {".gltf"}));
    EXPECT_FALSE(matchesExtension(".gltf", {".gltf"}));
    EXPECT_FALSE(matchesExtension("x.gltf.txt", {".gltf"}));
    EXPECT_TRUE(matchesExtension("anything", {}));
}
