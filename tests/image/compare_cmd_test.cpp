// CompareCmdTest: exit codes and output of `pseudoshadow compare`, called as ps::run_compare.
// No GL needed.
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/commands/compare_cmd.h"
#include "image/image.h"
#include "image_test_util.h"

namespace ps {
namespace {

namespace fs = std::filesystem;

using CmdRun = test::CompareRun;
CmdRun run_cmd(std::vector<std::string> args) { return test::run_compare_captured(std::move(args)); }

// golden.png and a copy with one of 100 pixels off by 0.1 (well above 1/255 after quantization).
class CompareCmdTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::scratch_dir();
    Image a = test::constant_image(10, 10, 3, 0.5f);
    Image b = a;
    b.at(2, 5, 0) += 0.1f;
    ASSERT_TRUE(write_image(golden(), a).ok());
    ASSERT_TRUE(write_image(same(), a).ok());
    ASSERT_TRUE(write_image(changed(), b).ok());
    ASSERT_TRUE(write_image(small(), test::constant_image(5, 10, 3, 0.5f)).ok());
  }
  std::string golden() const { return (dir_ / "golden.png").string(); }
  std::string same() const { return (dir_ / "same.png").string(); }
  std::string changed() const { return (dir_ / "changed.png").string(); }
  std::string small() const { return (dir_ / "small.png").string(); }
  fs::path dir_;
};

TEST_F(CompareCmdTest, IdenticalPassesWithExitZero) {
  CmdRun r = run_cmd({golden(), same()});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("compare: PASS  max_abs=0 mean_abs=0 failing=0 (0.00%) max_levels=0  [limits: fail=", 0), 0u)
      << r.out;
  EXPECT_TRUE(r.err.empty()) << r.err;
}

TEST_F(CompareCmdTest, ChangedPixelFailsWithExitOne) {
  CmdRun r = run_cmd({golden(), changed(), "--fail", "0.05"});
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.out.find("compare: FAIL"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("failing=1 (1.00%)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("[limits: fail=0.05 failpercent=0]"), std::string::npos) << r.out;
}

TEST_F(CompareCmdTest, FailPercentBudgetPasses) {
  EXPECT_EQ(run_cmd({golden(), changed(), "--fail", "0.05", "--failpercent", "1.5"}).code, 0);
  EXPECT_EQ(run_cmd({golden(), changed(), "--fail=0.05", "--failpercent=0.5"}).code, 1);
  EXPECT_EQ(run_cmd({golden(), changed(), "--fail", "0.2"}).code, 0);
}

TEST_F(CompareCmdTest, DiffIsWrittenEvenOnPass) {
  const fs::path diff = dir_ / "sub" / "diff.png";
  EXPECT_EQ(run_cmd({golden(), same(), "--diff", diff.string()}).code, 0);
  Result<Image> d = read_image(diff.string());
  ASSERT_TRUE(d.ok()) << d.error().message;
  EXPECT_EQ(d->width, 10);
}

TEST_F(CompareCmdTest, ErrorsExitTwoWithOneLine) {
  const std::vector<std::vector<std::string>> bad = {
      {golden(), small()},                         // size mismatch
      {golden(), (dir_ / "missing.png").string()},  // unreadable
      {golden()},                                  // one image
      {golden(), same(), same()},                  // three images
      {golden(), same(), "--fail", "1.5x"},        // trailing junk
      {golden(), same(), "--fail", "nan"},
      {golden(), same(), "--fail", "-0.1"},
      {golden(), same(), "--fail", "2"},           // 0..255 scale by mistake
      {golden(), same(), "--failpercent", "101"},
      {golden(), same(), "--failpercent"},         // missing value
      {golden(), same(), "--bogus"},
  };
  for (const auto& args : bad) {
    CmdRun r = run_cmd(args);
    EXPECT_EQ(r.code, 2) << args.back();
    EXPECT_EQ(r.err.rfind("pseudoshadow compare: ", 0), 0u) << r.err;  // the prefix every command uses
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
  }
}

TEST_F(CompareCmdTest, SizeMismatchNamesBothSizes) {
  CmdRun r = run_cmd({golden(), small()});
  EXPECT_NE(r.err.find("10x10x3 vs 5x10x3"), std::string::npos) << r.err;
}

TEST_F(CompareCmdTest, HelpExitsZero) {
  CmdRun r = run_cmd({"--help"});
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("--failpercent"), std::string::npos);
  EXPECT_NE(r.out.find("Exit codes"), std::string::npos);
  EXPECT_EQ(run_cmd({"-h"}).code, 0);
}

TEST_F(CompareCmdTest, HardFailFailsWhateverTheBudget) {
  // changed.png: one pixel of 100 off by 0.1 (26 levels), within a 1.5 % budget.
  EXPECT_EQ(run_cmd({golden(), changed(), "--fail", "0.05", "--failpercent", "1.5"}).code, 0);
  CmdRun r = run_cmd({golden(), changed(), "--fail", "0.05", "--failpercent", "1.5", "--hardfail", "0.05"});
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.out.find("beyond_hardfail=1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("hardfail=0.05]"), std::string::npos) << r.out;
  EXPECT_EQ(run_cmd({golden(), changed(), "--hardfail", "0.2", "--failpercent", "1.5"}).code, 0);
  EXPECT_EQ(run_cmd({golden(), same(), "--hardfail", "2"}).code, 2);  // 0..255 scale by mistake
}

TEST_F(CompareCmdTest, EightBitInputsReportLevels) {
  CmdRun r = run_cmd({golden(), changed(), "--fail", "0.05"});
  // PNG stores v*255+0.5 truncated: 0.5 -> 128, 0.6 -> 153 (153.5 truncated): 25 levels.
  EXPECT_NE(r.out.find("max_levels=25"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace ps
