// The deterministic session's schedule (haptics/session_driver.h): which tick each frame is
// drawn after, every tick's record in order, the recording flushed once per second of session
// time and published at the end, a stop between ticks; the loop with its recording and tick feed
// as a live window ticks it (RecordedLoop). No GL.
#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "devices/sample_log.h"
#include "haptics/session_driver.h"

namespace ps {
namespace {

namespace fs = std::filesystem;

std::vector<DeviceSample> line_samples() {  // 0 -> 100 mm along x in 1 s
  return {{0.0, {0, 0, 20}, 0, true}, {1.0, {100, 0, 20}, 0, true}};
}

// Lines of `path`, -1 when there is no such file.
int line_count(const fs::path& path) {
  std::ifstream in(path);
  if (!in) return -1;
  int n = 0;
  for (std::string line; std::getline(in, line);) ++n;
  return n;
}

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::path(::testing::TempDir()) / (name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(FrameScheduleTest, FrameIsDrawnAfterTheTickAtOrBeforeItsTime) {
  const FrameSchedule s{30.0, 1000.0};
  EXPECT_EQ(s.tick_of_frame(0), 0u);
  EXPECT_EQ(s.tick_of_frame(1), 33u);   // 33.3 ms
  EXPECT_EQ(s.tick_of_frame(2), 66u);   // 66.7 ms
  EXPECT_EQ(s.tick_of_frame(3), 100u);  // exactly 100 ms, not 99 by rounding
  EXPECT_EQ(s.tick_of_frame(30), 1000u);
  EXPECT_EQ(s.frames_in(1.0), 31);  // one per 1/30 s, plus the first
  EXPECT_EQ(s.frames_in(-1.0), 1);
  EXPECT_EQ(s.ticks_in(1.0), 1001u);
  EXPECT_EQ(s.ticks_in(0.0), 1u);
  const FrameSchedule fast{2000.0, 1000.0};  // more frames than ticks: two after each tick
  EXPECT_EQ(fast.tick_of_frame(1), 0u);
  EXPECT_EQ(fast.tick_of_frame(2), 1u);
  EXPECT_EQ(fast.tick_of_frame(3), 1u);
}

// What the hooks saw: per frame the last tick run, per tick its record's index.
struct Seen {
  std::vector<std::uint64_t> frame_after_tick;
  std::vector<std::uint64_t> tick_records;
  std::uint64_t last_tick = 0;
  std::vector<double> frame_time_s;
};

DriverHooks watching(Seen& seen, SessionDriver** driver) {
  DriverHooks h;
  h.after_tick = [&seen](std::uint64_t k, const HapticState&) {
    seen.last_tick = k;
    return ok_status();
  };
  h.on_tick = [&seen](const TickSample& t) { seen.tick_records.push_back(t.tick); };
  h.on_frame = [&seen, driver](int) {
    seen.frame_after_tick.push_back(seen.last_tick);
    seen.frame_time_s.push_back((*driver)->loop().state().read().time_s);
    return ok_status();
  };
  return h;
}

TEST(SessionDriverTest, DrawsEachFrameRightAfterItsTick) {
  LogDevice device(line_samples(), true, "line");
  Seen seen;
  SessionDriver* self = nullptr;
  const FrameSchedule schedule{30.0, 1000.0};
  SessionDriver driver(device, HapticLoopParams{}, nullptr, "", schedule, watching(seen, &self));
  self = &driver;
  const int frames = schedule.frames_in(device.duration_s());
  auto r = driver.run(schedule.tick_of_frame(frames - 1) + 1, frames);
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->ticks, 1001u);
  EXPECT_EQ(r->frames, 31);
  EXPECT_FALSE(r->stopped);
  ASSERT_EQ(seen.frame_after_tick.size(), 31u);
  for (int i = 0; i < 31; ++i) {
    EXPECT_EQ(seen.frame_after_tick[static_cast<std::size_t>(i)], schedule.tick_of_frame(i)) << "frame " << i;
    EXPECT_NEAR(seen.frame_time_s[static_cast<std::size_t>(i)], schedule.tick_of_frame(i) * 1e-3, 1e-9);
  }
  ASSERT_EQ(seen.tick_records.size(), 1001u);  // every tick's record, in order
  for (std::size_t k = 0; k < seen.tick_records.size(); ++k) EXPECT_EQ(seen.tick_records[k], k);
  EXPECT_TRUE(driver.finish().ok());
}

TEST(SessionDriverTest, MaxFramesCapsTheFramesNotTheTicks) {
  LogDevice device(line_samples(), true, "line");
  Seen seen;
  SessionDriver* self = nullptr;
  SessionDriver driver(device, HapticLoopParams{}, nullptr, "", FrameSchedule{30.0, 1000.0}, watching(seen, &self));
  self = &driver;
  auto r = driver.run(1001, 5);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r->ticks, 1001u);
  EXPECT_EQ(r->frames, 5);
  EXPECT_EQ(seen.frame_after_tick.back(), 133u);
}

TEST(SessionDriverTest, RecordingIsFlushedEachSecondAndPublishedAtTheEnd) {
  const fs::path dir = fresh_dir("session_driver_flush");
  const fs::path log = dir / "device.log";
  LogDevice device(line_samples(), true, "line");
  std::vector<int> partial_lines;  // at each frame, the recording's lines on disk so far
  DriverHooks h;
  h.on_frame = [&](int) {
    partial_lines.push_back(line_count(log.string() + ".partial"));
    return ok_status();
  };
  SessionDriver driver(device, HapticLoopParams{}, nullptr, log.string(), FrameSchedule{30.0, 1000.0}, std::move(h));
  auto r = driver.run(1001, 31);
  ASSERT_TRUE(r.ok()) << r.error().message;
  ASSERT_EQ(partial_lines.size(), 31u);
  EXPECT_EQ(partial_lines[29], -1);    // tick 966: nothing written before the first whole second
  EXPECT_EQ(partial_lines[30], 1001);  // tick 1000: the header and ticks 0..999, flushed after tick 999
  EXPECT_EQ(line_count(log), -1);      // not published before finish()
  ASSERT_TRUE(driver.finish().ok());
  EXPECT_EQ(line_count(log), 1002);  // the header and every tick's sample
  EXPECT_FALSE(fs::exists(log.string() + ".partial"));
  fs::remove_all(dir);
}

// The live window's use (app/maze/maze_window.cpp): its own thread ticks the loop, and each frame
// asks flush_due with the session time it drew; the flush comes once a whole second has passed
// since the last (a resumed session's first frame, past 0 already, flushes at once), and the tick
// feed holds every tick for the tracker to drain.
TEST(RecordedLoopTest, FlushesAtFramesOnceASecondOfSessionTime) {
  const fs::path dir = fresh_dir("recorded_loop_flush");
  const std::string log = (dir / "device.log").string();
  LogDevice device(line_samples(), true, "line");
  FakeClock clock;
  RecordedLoop r(device, clock, HapticLoopParams{}, nullptr, log, 2048);
  r.loop().run_ticks(1000);
  ASSERT_TRUE(r.flush_due(0.999).ok());
  EXPECT_EQ(line_count(log + ".partial"), -1);
  ASSERT_TRUE(r.flush_due(1.0).ok());
  EXPECT_EQ(line_count(log + ".partial"), 1001);  // the header and ticks 0..999
  r.loop().run_ticks(500);
  ASSERT_TRUE(r.flush_due(1.99).ok());
  EXPECT_EQ(line_count(log + ".partial"), 1001);
  ASSERT_TRUE(r.flush_due(2.0).ok());
  EXPECT_EQ(line_count(log + ".partial"), 1501);
  int fed = 0;
  r.feed()->drain([&fed](const TickSample&) { ++fed; });
  EXPECT_EQ(fed, 1500);
  ASSERT_TRUE(r.finish().ok());
  EXPECT_EQ(line_count(log), 1501);
  EXPECT_FALSE(fs::exists(log + ".partial"));

  LogDevice again(line_samples(), true, "line");
  FakeClock resumed_clock;
  RecordedLoop resumed(again, resumed_clock, HapticLoopParams{}, nullptr, (dir / "resumed.log").string(), 0);
  EXPECT_EQ(resumed.feed(), nullptr);
  resumed.loop().run_ticks(10);
  ASSERT_TRUE(resumed.flush_due(120.0).ok());  // a session resumed at 120 s: at its first frame
  EXPECT_EQ(line_count((dir / "resumed.log.partial").string()), 11);
  ASSERT_TRUE(resumed.finish().ok());
  fs::remove_all(dir);
}

// Lines of `path` once there are `want` of them, or after 3 s (the flushing thread's 1 s and
// room for a loaded machine).
int lines_within_3s(const fs::path& path, int want) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(3);
  int n = line_count(path);
  while (n != want && std::chrono::steady_clock::now() < end) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    n = line_count(path);
  }
  return n;
}

// A live window that draws no frame for a while (minimised, covered, its swap blocked): the
// haptic loop goes on recording, and the recording's own thread flushes it once a second of wall
// time with no frame asking. flush_due at the next frame only reports that thread's failure.
TEST(RecordedLoopTest, ItsOwnThreadFlushesWhileNoFrameComes) {
  const fs::path dir = fresh_dir("recorded_loop_no_frames");
  const std::string log = (dir / "device.log").string();
  LogDevice device(line_samples(), true, "line");
  FakeClock clock;
  RecordedLoop r(device, clock, HapticLoopParams{}, nullptr, log, 0);
  r.start_flushing();
  r.loop().run_ticks(1000);
  EXPECT_EQ(lines_within_3s(log + ".partial", 1001), 1001);  // the header and ticks 0..999
  r.loop().run_ticks(500);
  EXPECT_EQ(lines_within_3s(log + ".partial", 1501), 1501);
  ASSERT_TRUE(r.flush_due(0.5).ok());
  r.loop().run_ticks(10);
  ASSERT_TRUE(r.finish().ok());  // stops the thread, then the last samples and the rename
  EXPECT_EQ(line_count(log), 1511);
  EXPECT_FALSE(fs::exists(log + ".partial"));
  fs::remove_all(dir);
}

TEST(SessionDriverTest, StopEndsBetweenTicksAndTheRecordingIsStillPublished) {
  const fs::path dir = fresh_dir("session_driver_stop");
  const fs::path log = dir / "device.log";
  LogDevice device(line_samples(), true, "line");
  std::uint64_t ticks_seen = 0;
  int frames = 0;
  DriverHooks h;
  h.stop = [&] { return ticks_seen == 500; };
  h.after_tick = [&](std::uint64_t, const HapticState&) {
    ++ticks_seen;
    return ok_status();
  };
  h.on_frame = [&](int) {
    ++frames;
    return ok_status();
  };
  SessionDriver driver(device, HapticLoopParams{}, nullptr, log.string(), FrameSchedule{30.0, 1000.0}, std::move(h));
  auto r = driver.run(1001, 31);
  ASSERT_TRUE(r.ok());
  EXPECT_TRUE(r->stopped);
  EXPECT_EQ(r->ticks, 500u);
  EXPECT_EQ(r->frames, 15);  // frames 0..14 (tick 466); frame 15 falls on tick 500, never run
  EXPECT_EQ(frames, 15);
  ASSERT_TRUE(driver.finish().ok());
  EXPECT_EQ(line_count(log), 501);  // the header and ticks 0..499
  fs::remove_all(dir);
}

TEST(SessionDriverTest, NoFramesWithoutAFrameRate) {
  LogDevice device(line_samples(), true, "line");
  int frames = 0;
  DriverHooks h;
  h.on_frame = [&](int) {
    ++frames;
    return ok_status();
  };
  SessionDriver driver(device, HapticLoopParams{}, nullptr, "", FrameSchedule{0.0, 1000.0}, std::move(h));
  auto r = driver.run(100, 1000);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r->ticks, 100u);
  EXPECT_EQ(r->frames, 0);
  EXPECT_EQ(frames, 0);
}

TEST(SessionDriverTest, AFrameErrorEndsTheRun) {
  LogDevice device(line_samples(), true, "line");
  DriverHooks h;
  h.on_frame = [](int i) { return i == 2 ? Status(make_error("frame 2 failed")) : ok_status(); };
  SessionDriver driver(device, HapticLoopParams{}, nullptr, "", FrameSchedule{30.0, 1000.0}, std::move(h));
  auto r = driver.run(1001, 31);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().message, "frame 2 failed");
}

}  // namespace
}  // namespace ps
