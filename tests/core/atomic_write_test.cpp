// Nothing lost, nothing half-written (docs/hardening.md, docs/errors.md): the one writer every
// output goes through (core/file_io.h, core/output_set.h) and the device recorder.
//
// The kill tests never race a timer: the child writes part of a file, tells the parent through a
// pipe, then blocks on a pipe nobody writes. The parent checks the partial temp file is really
// there (so the kill provably lands mid-write), SIGKILLs the child and inspects what is left.
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/file_io.h"
#include "core/output_set.h"
#include "devices/sample_log.h"
#include "image/image.h"

namespace ps {
namespace {

namespace fs = std::filesystem;

fs::path scratch() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const auto dir = fs::path(PS_BINARY_DIR) / "test_scratch" / "hardening" /
                   (std::string(info->test_suite_name()) + "." + info->name());
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string read_all(const fs::path& path) {
  std::ifstream f(path, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

std::vector<std::string> entries(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// A child process that runs `work(report)`; `report(text)` sends text to the parent and then
// blocks forever, so the child is parked exactly where it called it. kill() SIGKILLs it.
class ParkedChild {
 public:
  template <class Work>
  explicit ParkedChild(Work work) {
    int to_parent[2], never[2];
    if (::pipe(to_parent) != 0 || ::pipe(never) != 0) return;
    pid_ = ::fork();
    if (pid_ == 0) {
      ::close(to_parent[0]);
      ::close(never[1]);
      work([&](const std::string& text) {
        const std::string line = text + "\n";
        (void)!::write(to_parent[1], line.data(), line.size());
        char c;
        for (;;) (void)!::read(never[0], &c, 1);  // parked until SIGKILL
      });
      _exit(3);  // `work` never reported: the parent sees an empty report
    }
    ::close(to_parent[1]);
    ::close(never[0]);
    never_write_ = never[1];
    char c;
    while (::read(to_parent[0], &c, 1) == 1 && c != '\n') report_ += c;
    ::close(to_parent[0]);
  }
  ~ParkedChild() {
    if (pid_ > 0) kill();
    if (never_write_ >= 0) ::close(never_write_);
  }
  const std::string& report() const { return report_; }  // what the child said, "" if it died
  // SIGKILLs the child; true if the signal is what ended it (it was still parked).
  bool kill() {
    ::kill(pid_, SIGKILL);
    int status = 0;
    const bool reaped = ::waitpid(pid_, &status, 0) == pid_;
    pid_ = -1;
    return reaped && WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL;
  }

 private:
  pid_t pid_ = -1;
  int never_write_ = -1;
  std::string report_;
};

TEST(AtomicWriteTest, ReplacesTheFileAndLeavesNoTemp) {
  const fs::path dir = scratch();
  const fs::path path = dir / "a.toml";
  ASSERT_TRUE(write_file_atomic(path.string(), "old\n").ok());
  ASSERT_TRUE(write_file_atomic(path.string(), "new\n").ok());
  EXPECT_EQ(read_all(path), "new\n");
  EXPECT_EQ(entries(dir), std::vector<std::string>{"a.toml"});
  struct stat st {};
  ASSERT_EQ(::stat(path.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0644u) << "readable by others, as a plain open() would make it";
}

TEST(AtomicWriteTest, KillDuringWriteKeepsTheOldFile) {
  const fs::path dir = scratch();
  const std::string path = (dir / "killed.overrides.toml").string();
  const std::string old_text = "probe.radius_mm = 3\n";
  ASSERT_TRUE(write_file_atomic(path, old_text).ok());
  // The child runs write_file_atomic's own steps and parks between the first half of the new
  // text and the rest: the state a SIGKILL in the middle of a large write leaves.
  ParkedChild child([&](auto report) {
    Result<TempFile> temp = TempFile::create(path);
    if (!temp || !temp->write("materials.wood.lambda_min = 0.4\n")) _exit(4);
    report(temp->path());
  });
  const std::string temp = child.report();
  ASSERT_FALSE(temp.empty()) << "the child failed before its partial write";
  ASSERT_EQ(read_all(temp), "materials.wood.lambda_min = 0.4\n") << "partial temp file must exist";
  ASSERT_TRUE(child.kill()) << "the kill must land while the writer is mid-file";
  EXPECT_EQ(read_all(path), old_text);
  // The only other entry is the killed writer's hidden temp file, never under the target name.
  EXPECT_EQ(entries(dir), (std::vector<std::string>{fs::path(temp).filename().string(), "killed.overrides.toml"}));
  EXPECT_EQ(fs::path(temp).filename().string().rfind(".killed.overrides.toml.", 0), 0u) << temp;
}

TEST(AtomicWriteTest, KilledOutputSetPublishesNothing) {
  const fs::path dir = scratch();
  const std::string image = (dir / "ok.png").string(), stats = (dir / "s.json").string();
  ASSERT_TRUE(write_file_atomic(stats, "{\"old\": 1}").ok());
  // ok.png staged completely, s.json half-written when the kill comes: as a render killed
  // between its outputs.
  ParkedChild child([&](auto report) {
    OutputSet out;
    Image im{4, 4, 3, std::vector<float>(48, 0.5f)};
    if (!out.add(image) || !out.add(stats) || !stage_image(out, image, im)) _exit(4);
    (void)out.stage(stats, [&](const std::string& file) -> Status {
      std::ofstream(file) << "{\"new\":";
      report(file);
      return ok_status();
    });
  });
  ASSERT_FALSE(child.report().empty());
  ASSERT_EQ(read_all(child.report()), "{\"new\":") << "partial temp file must exist";
  ASSERT_TRUE(child.kill());
  EXPECT_FALSE(fs::exists(image)) << "nothing is published before every output is complete";
  EXPECT_EQ(read_all(stats), "{\"old\": 1}");
}

TEST(AtomicWriteTest, FailedStagePublishesNothingAndCleansUp) {
  const fs::path dir = scratch();
  OutputSet out;
  ASSERT_TRUE(out.add((dir / "new" / "a.txt").string()).ok());  // creates new/
  ASSERT_TRUE(fs::is_directory(dir / "new"));
  ASSERT_TRUE(out.stage_text((dir / "new" / "a.txt").string(), "a").ok());
  Status failed = out.stage((dir / "new" / "b.txt").string(),
                            [](const std::string&) -> Status { return make_error("b.txt: encoder said no"); });
  ASSERT_FALSE(failed.ok());
  out.discard();  // what returning early does through the destructor
  EXPECT_EQ(entries(dir), std::vector<std::string>{}) << "temp files and the created directory are gone";
}

TEST(AtomicWriteTest, OutputSetPublishesAll) {
  const fs::path dir = scratch();
  OutputSet out;
  ASSERT_TRUE(out.stage_text((dir / "a.txt").string(), "a").ok());
  ASSERT_TRUE(out.stage_text((dir / "b.txt").string(), "b").ok());
  EXPECT_EQ(entries(dir).size(), 2u);  // the two hidden temps
  ASSERT_TRUE(out.publish().ok());
  EXPECT_EQ(entries(dir), (std::vector<std::string>{"a.txt", "b.txt"}));
  EXPECT_EQ(read_all(dir / "b.txt"), "b");
}

TEST(AtomicWriteTest, SamePathTwiceIsRefused) {
  const fs::path dir = scratch();
  OutputSet out;
  ASSERT_TRUE(out.add((dir / "x.png").string()).ok());
  Status twice = out.add((dir / "." / "x.png").string());
  ASSERT_FALSE(twice.ok());
  EXPECT_NE(twice.error().message.find("named as two outputs"), std::string::npos) << twice.error().message;
}

// The directory rule: only a missing LAST directory is created.
TEST(OutputDirTest, CreatesOnlyTheLastDirectory) {
  const fs::path dir = scratch();
  bool created = false;
  ASSERT_TRUE(prepare_output_dir((dir / "d" / "x.png").string(), &created).ok());
  EXPECT_TRUE(created);
  EXPECT_TRUE(fs::is_directory(dir / "d"));
  Status deep = prepare_output_dir((dir / "missing" / "deeper" / "x.png").string(), &created);
  ASSERT_FALSE(deep.ok());
  EXPECT_FALSE(created);
  EXPECT_NE(deep.error().message.find((dir / "missing").string() + " does not exist"), std::string::npos)
      << deep.error().message;
  EXPECT_FALSE(fs::exists(dir / "missing"));
}

TEST(OutputDirTest, ParentThatIsAFileOrTargetThatIsADirectoryFails) {
  const fs::path dir = scratch();
  std::ofstream(dir / "f.txt") << "x";
  // A regular file as the parent: fails for root too, unlike a read-only directory.
  Status file_parent = write_file_atomic((dir / "f.txt" / "s.json").string(), "{}");
  ASSERT_FALSE(file_parent.ok());
  EXPECT_EQ(file_parent.error().message,
            (dir / "f.txt" / "s.json").string() + ": cannot write: " + (dir / "f.txt").string() + " is not a directory");
  fs::create_directory(dir / "d.png");
  Status is_dir = write_image((dir / "d.png").string(), Image{1, 1, 1, {0.0f}});
  ASSERT_FALSE(is_dir.ok());
  EXPECT_NE(is_dir.error().message.find("is a directory, not a file"), std::string::npos) << is_dir.error().message;
}

TEST(SampleRecorderTest, KilledRecorderKeepsPreviousLogAndFlushedSamples) {
  const fs::path dir = scratch();
  const std::string path = (dir / "session.log").string();
  std::ofstream(path) << "0 1 2 3 0\n";  // a previous recording
  ParkedChild child([&](auto report) {
    SampleRecorder rec(path);
    for (int i = 0; i < 250; ++i) {
      DeviceSample s;
      s.valid = true;
      s.time_s = i * 1e-3;
      s.position_mm = {i * 0.1, 0.0, 5.0};
      rec.append(s);
      if (i % 100 == 99 && !rec.flush()) _exit(4);  // flushed after samples 100 and 200
    }
    report("appended");  // 50 samples pending, never flushed
  });
  ASSERT_EQ(child.report(), "appended");
  ASSERT_TRUE(child.kill());
  auto old_log = load_sample_log(path);
  ASSERT_TRUE(old_log.ok()) << old_log.error().message;
  ASSERT_EQ(old_log->size(), 1u);  // never replaced by a half-written recording
  EXPECT_EQ(old_log->front().position_mm.y, 2.0);
  auto flushed = load_sample_log(path + ".partial");
  ASSERT_TRUE(flushed.ok()) << flushed.error().message;
  EXPECT_EQ(flushed->size(), 200u);  // exactly the two flushes, as whole lines
}

TEST(SampleRecorderTest, CloseReplacesTheLogAndRemovesThePartialFile) {
  const fs::path dir = scratch();
  const std::string path = (dir / "session.log").string();
  SampleRecorder rec(path);
  DeviceSample s;
  s.valid = true;
  rec.append(s);
  ASSERT_TRUE(rec.close().ok());
  EXPECT_EQ(entries(dir), std::vector<std::string>{"session.log"});
  EXPECT_EQ(load_sample_log(path)->size(), 1u);
}

}  // namespace
}  // namespace ps
