// Which files a scene may read (scene/path_policy.h, docs/scene-format.md "Files a scene may
// read"): its own folder tree, the shipped data and --allow-path folders; never a file elsewhere,
// whether named absolutely, through `..` or through a link, and never by quoting that file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "scene/path_policy.h"
#include "scene/scene_io.h"
#include "scene_test_util.h"

namespace ps {
namespace {

namespace fs = std::filesystem;

constexpr const char* kLut = "lut distance_mm intensity\n0 1\n2 0\n";
constexpr const char* kSecret = "root:x:0:0:SECRET-REST-OF-THE-LINE\n";

// <tmp>/scene/ (the scene's tree, with a sub-folder) and <tmp>/elsewhere/ (a folder outside it,
// holding a valid table, a secret and a scene).
class PathPolicyTest : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / ("ps_path_policy_" + std::to_string(::getpid()));
    fs::remove_all(root_);
    fs::create_directories(scene_dir() / "sub");
    fs::create_directories(elsewhere());
    write(scene_dir() / "sub" / "inside.lut", kLut);
    write(elsewhere() / "outside.lut", kLut);
    write(elsewhere() / "secret", kSecret);
    write(elsewhere() / "lib.toml", "[materials.stone]\nlambda_min = 0.2\n");
  }
  void TearDown() override { fs::remove_all(root_); }

  fs::path scene_dir() const { return root_ / "scene"; }
  fs::path elsewhere() const { return root_ / "elsewhere"; }
  static void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

  // The minimal scene with `extra` lines in its [materials.wood] table, parsed from scene_dir().
  Result<Scene> parse(const std::string& wood_lines, const std::vector<std::string>& sets = {},
                      const std::vector<std::string>& allow = {}) const {
    const std::string text = "[materials.wood]\nlambda_min = 0.1\n" + wood_lines +
                             "\n[[surfaces]]\nmaterial = \"wood\"\n";
    return parse_scene(text, "s.toml", scene_dir().string(), sets, allow);
  }

  fs::path root_;
};

TEST_F(PathPolicyTest, FilesInTheScenesTreeAreRead) {
  Result<Scene> s = parse("intensity_lut = \"sub/inside.lut\"");
  ASSERT_TRUE(s) << s.error().message;
  EXPECT_EQ(s->materials[0].intensity_lut.points.size(), 2u);
}

TEST_F(PathPolicyTest, AnAbsolutePathElsewhereIsRefusedWithTheWayToAllowIt) {
  const std::string file = (elsewhere() / "outside.lut").string();
  Result<Scene> s = parse("intensity_lut = \"" + file + "\"");
  ASSERT_FALSE(s);
  const std::string& m = s.error().message;
  EXPECT_NE(m.find("s.toml:3: 'intensity_lut' names '" + file + "', outside the scene's folder"), std::string::npos) << m;
  EXPECT_NE(m.find("--allow-path " + elsewhere().string()), std::string::npos) << m;
}

TEST_F(PathPolicyTest, DotDotThatLeavesTheTreeIsRefused) {
  Result<Scene> s = parse("intensity_lut = \"sub/../../elsewhere/outside.lut\"");
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().message.find("outside the scene's folder"), std::string::npos) << s.error().message;
}

TEST_F(PathPolicyTest, ALinkInsideTheTreeDoesNotEscapeIt) {
  fs::create_symlink(elsewhere() / "outside.lut", scene_dir() / "link.lut");
  Result<Scene> s = parse("intensity_lut = \"link.lut\"");
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().message.find("outside the scene's folder"), std::string::npos) << s.error().message;
}

// Refused before its existence is checked: the message is the same for a file that is there and
// one that is not, so a scene cannot probe which files exist.
TEST_F(PathPolicyTest, AMissingFileElsewhereIsRefusedTheSameWay) {
  Result<Scene> s = parse("intensity_lut = \"" + (elsewhere() / "nope.lut").string() + "\"");
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().message.find("outside the scene's folder"), std::string::npos) << s.error().message;
  EXPECT_EQ(s.error().message.find("not found"), std::string::npos) << s.error().message;
}

TEST_F(PathPolicyTest, IncludesAndButtonScenesAreConfinedToo) {
  const std::string lib = (elsewhere() / "lib.toml").string();
  Result<Scene> inc = parse_scene("include = [\"" + lib + "\"]\n[materials.wood]\n[[surfaces]]\nmaterial = \"wood\"\n",
                                  "s.toml", scene_dir().string());
  ASSERT_FALSE(inc);
  EXPECT_NE(inc.error().message.find("s.toml:1: 'include' names '" + lib + "', outside"), std::string::npos)
      << inc.error().message;
  write(elsewhere() / "other.toml", "[materials.wood]\n[[surfaces]]\nmaterial = \"wood\"\n");
  const std::string button = "[materials.wood]\n[[surfaces]]\nmaterial = \"wood\"\n[[buttons]]\naction = \"scene:" +
                             (elsewhere() / "other.toml").string() + "\"\n";
  Result<Scene> b = parse_scene(button, "s.toml", scene_dir().string());
  ASSERT_FALSE(b);
  EXPECT_NE(b.error().message.find("'action' names"), std::string::npos) << b.error().message;
}

// A scene copied out of scenes/ keeps "../textures/..." references that now point nowhere: the
// refusal names the shipped file of that name, and writing that path in the scene works.
TEST_F(PathPolicyTest, ARefusalNamesTheShippedFileOfThatName) {
  Result<Scene> s = parse("intensity_lut = \"../textures/intensity_thesis.lut\"");
  ASSERT_FALSE(s);
  const std::string& m = s.error().message;
  const std::string marker = "The shipped data has a file of that name, ";
  const std::size_t at = m.find(marker);
  ASSERT_NE(at, std::string::npos) << m;
  const std::size_t from = at + marker.size();
  const std::string shipped = m.substr(from, m.find(": write that path", from) - from);
  EXPECT_EQ(fs::path(shipped).filename(), "intensity_thesis.lut") << m;
  EXPECT_EQ(fs::path(shipped).parent_path().filename(), "textures") << m;
  Result<Scene> fixed = parse("intensity_lut = \"" + shipped + "\"");
  ASSERT_TRUE(fixed) << fixed.error().message;
  EXPECT_GT(fixed->materials[0].intensity_lut.points.size(), 1u);
}

// A name the shipped data lacks gets no such line, only the --allow-path way.
TEST_F(PathPolicyTest, ARefusalWithoutAShippedNamesakeOnlyOffersAllowPath) {
  Result<Scene> s = parse("intensity_lut = \"" + (elsewhere() / "outside.lut").string() + "\"");
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error().message.find("shipped data has"), std::string::npos) << s.error().message;
  EXPECT_NE(s.error().message.find("--allow-path"), std::string::npos) << s.error().message;
}

TEST_F(PathPolicyTest, AllowPathAdmitsAFolder) {
  const std::string file = (elsewhere() / "outside.lut").string();
  Result<Scene> s = parse("intensity_lut = \"" + file + "\"", {}, {elsewhere().string()});
  ASSERT_TRUE(s) << s.error().message;
  EXPECT_EQ(s->materials[0].intensity_lut.points.size(), 2u);
}

// --set and --overrides values are the user's own (they chose the file), not the scene's.
TEST_F(PathPolicyTest, AValueTheUserSetIsNotConfined) {
  Result<Scene> s = parse("", {"materials.wood.intensity_lut=" + (elsewhere() / "outside.lut").string()});
  ASSERT_TRUE(s) << s.error().message;
  EXPECT_EQ(s->materials[0].intensity_lut.points.size(), 2u);
}

// A file of another kind, read where it is allowed, is quoted only in part: the header line's
// first 16 characters, never the rest of the line.
TEST_F(PathPolicyTest, AFileOfAnotherKindIsQuotedOnlyInPart) {
  Result<Scene> s = parse("intensity_lut = \"" + (elsewhere() / "secret").string() + "\"", {}, {elsewhere().string()});
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().message.find("got 'root:x:0:0:SECRE...'"), std::string::npos) << s.error().message;
  EXPECT_EQ(s.error().message.find("REST-OF-THE-LINE"), std::string::npos) << s.error().message;
}

TEST(PathPolicyExcerptTest, CutsAndMasksBytes) {
  EXPECT_EQ(excerpt("short"), "short");
  EXPECT_EQ(excerpt("abcdefghij", 4), "abcd...");
  EXPECT_EQ(excerpt(std::string("a\x1b[2Jb\xff", 7)), "a?[2Jb?");
}

// The shipped scenes need no allowance: each loads with the default rule.
TEST(PathPolicyShippedTest, EveryShippedSceneLoadsWithoutAnAllowance) {
  int scenes = 0;
  for (const char* sub : {"", "/universe", "/fourd"}) {
    for (const fs::directory_entry& e : fs::directory_iterator(test::scenes_dir() + sub)) {
      if (e.path().extension() != ".toml") continue;
      Result<Scene> s = load_scene(e.path().string());
      EXPECT_TRUE(s) << e.path() << ": " << (s ? "" : s.error().message);
      ++scenes;
    }
  }
  EXPECT_GE(scenes, 20);
}

}  // namespace
}  // namespace ps
