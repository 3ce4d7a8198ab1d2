// The event log (JSON lines that parse, in order, flushed before close), the dispatcher's
// fan-out, and the live player without a device (one warning line, nothing on stderr).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/session/event_dispatch.h"
#include "app/session/event_log.h"
#include "app/session/replay_events.h"
#include "audio/live_audio.h"
#include "audio/wav_reader.h"

namespace ps {
namespace {

HapticEvent make(EventKind kind, std::uint64_t tick, double value, std::string_view label = "") {
  HapticEvent e;
  e.kind = kind;
  e.tick = tick;
  e.time_s = static_cast<double>(tick) * 1e-3;
  e.value = value;
  e.index = static_cast<int>(tick % 7);
  e.position_mm = {1.5, -2.0, 8.25};
  e.set_label(label);
  return e;
}

std::vector<std::string> lines_of(const std::string& path) {
  std::ifstream f(path);
  std::vector<std::string> out;
  for (std::string line; std::getline(f, line);) out.push_back(line);
  return out;
}

TEST(EventLogTest, LinesParseAsJsonInOrderAndAppearOnlyWhenClosed) {
  const std::string path = testing::TempDir() + "ps_event_log_test.jsonl";
  std::filesystem::remove(path);
  auto log = EventLog::open(path);
  ASSERT_TRUE(log.ok()) << log.error().message;
  const std::vector<HapticEvent> events = {make(EventKind::contact_start, 241, 33.5),
                                           make(EventKind::button_fired, 500, 0.0, "scene \"b\".toml"),
                                           make(EventKind::body_impact, 1234, 812.25),
                                           make(EventKind::contact_end, 1361, 0.0)};
  log.value()->append(events[0]);
  log.value()->append(events[1]);
  ASSERT_TRUE(log.value()->flush().ok());
  // A crash now would leave these two lines in the .partial file.
  EXPECT_EQ(lines_of(log.value()->partial_path()).size(), 2u);
  EXPECT_FALSE(std::filesystem::exists(path));
  log.value()->append(events[2]);
  log.value()->append(events[3]);
  ASSERT_TRUE(log.value()->close().ok());
  EXPECT_FALSE(std::filesystem::exists(path + ".partial"));
  const std::vector<std::string> lines = lines_of(path);
  ASSERT_EQ(lines.size(), events.size());
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const nlohmann::json j = nlohmann::json::parse(lines[i]);  // throws (fails) on bad JSON
    EXPECT_EQ(j.at("event").get<std::string>(), event_name(events[i].kind));
    EXPECT_EQ(j.at("tick").get<std::uint64_t>(), events[i].tick);
    EXPECT_EQ(j.at("t").get<double>(), events[i].time_s) << "17 significant digits round-trip a double";
    EXPECT_EQ(j.at("value").get<double>(), events[i].value);
    EXPECT_EQ(j.at("index").get<int>(), events[i].index);
    EXPECT_EQ(j.at("pos").at(2).get<double>(), 8.25);
    EXPECT_EQ(j.at("label").get<std::string>(), events[i].label_view());
  }
  std::filesystem::remove(path);
}

TEST(EventLogTest, BadDirectoryIsAnErrorNamingThePath) {
  auto log = EventLog::open("/nonexistent-dir/sub/events.jsonl");
  ASSERT_FALSE(log.ok());
  EXPECT_NE(log.error().message.find("/nonexistent-dir/sub"), std::string::npos) << log.error().message;
}

TEST(EventLogTest, AFailedReplayLeavesNoLogBehind) {
  const std::string path = testing::TempDir() + "ps_event_log_failed.jsonl";
  {
    ReplayEventsDesc desc;
    desc.log_path = path;
    auto ev = ReplayEvents::open(desc);
    ASSERT_TRUE(ev.ok());
    ev.value()->dispatcher().dispatch(make(EventKind::contact_start, 3, 1.0));
    // Flushed per event: a crash here would leave the line in the .partial file.
    EXPECT_EQ(lines_of(path + ".partial").size(), 1u);
  }  // destroyed without finish(): the replay failed
  EXPECT_FALSE(std::filesystem::exists(path + ".partial"));
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(EventDispatcherTest, PumpDrainsTheQueueOnceToEverySubscriberInOrder) {
  EventQueue queue(8);
  for (std::uint64_t t : {5u, 9u, 12u}) ASSERT_TRUE(queue.push(make(EventKind::contact_start, t, 1.0)));
  EventDispatcher d;
  std::vector<std::string> seen;
  d.subscribe("a", [&](const HapticEvent& e) { seen.push_back("a" + std::to_string(e.tick)); });
  d.subscribe("b", [&](const HapticEvent& e) { seen.push_back("b" + std::to_string(e.tick)); });
  EXPECT_EQ(d.pump(queue), 3u);
  EXPECT_EQ(seen, (std::vector<std::string>{"a5", "b5", "a9", "b9", "a12", "b12"}));
  EXPECT_EQ(d.pump(queue), 0u) << "drained: nothing twice";
  d.dispatch(make(EventKind::charge_added, 20, 1.0));  // a render-thread event skips the queue
  EXPECT_EQ(seen.back(), "b20");
  EXPECT_EQ(d.dispatched(), 4u);
}

// OpenAL Soft reads ALSOFT_DRIVERS when it first opens a device; ctest runs each test in its own
// process, so the setting holds for the test that sets it.
TEST(LiveAudioTest, NoDeviceIsOneWarningLineAndNothingElseOnStderr) {
  setenv("ALSOFT_DRIVERS", "alsa", 1);  // an ALSA device that does not exist: libasound complains
  testing::internal::CaptureStderr();
  audio::LiveAudioDesc desc;
  desc.device = "ps-no-such-device";
  auto a = audio::LiveAudio::open(desc);
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_EQ(err, "") << "the libraries' own messages must not reach stderr";
  ASSERT_NE(a, nullptr);
  EXPECT_FALSE(a->active());
  EXPECT_NE(a->warning().find("no audio device"), std::string::npos) << a->warning();
  EXPECT_EQ(a->warning().find('\n'), std::string::npos) << "one line";
  a->play(make(EventKind::contact_start, 1, 10.0));  // silently nothing
  EXPECT_EQ(a->started(), 0u);
}

TEST(LiveAudioTest, MuteIsOneWarningLineWithoutOpeningADevice) {
  audio::LiveAudioDesc desc;
  desc.mute = true;
  auto a = audio::LiveAudio::open(desc);
  EXPECT_FALSE(a->active());
  EXPECT_NE(a->warning().find("--mute"), std::string::npos) << a->warning();
  EXPECT_EQ(a->warning().find('\n'), std::string::npos);
}

TEST(LiveAudioTest, NullDevicePlaysEveryQueuedEvent) {
  setenv("ALSOFT_DRIVERS", "null", 1);  // OpenAL Soft's "No Output" device: mixes, plays nothing
  audio::LiveAudioDesc desc;
  desc.voices = 4;  // fewer voices than events: the oldest are cut, none is lost before starting
  auto a = audio::LiveAudio::open(desc);
  ASSERT_TRUE(a->active()) << a->warning();
  EXPECT_TRUE(a->warning().empty());
  for (std::uint64_t t = 0; t < 20; ++t)
    a->play(make(t % 2 ? EventKind::body_impact : EventKind::contact_start, t, 100.0 + t));
  a->close();  // starts what is queued, then joins the audio thread
  EXPECT_EQ(a->started() + a->dropped(), 20u);
  EXPECT_EQ(a->dropped(), 0u) << "20 events fit the 256-event queue";
}

// The output going away while the event sounds run (a USB card unplugged, the sound server
// ended): OpenAL Soft's wave writer on /dev/full, where every write fails (ENOSPC). The device
// opens, then OpenAL reports it disconnected (ALC_EXT_disconnect) at its first mix, as for a card
// that goes away. One notice; the events after it are taken and counted as not played (none
// waits, none is lost from the count); play() never blocks.
TEST(LiveAudioTest, OutputGoneIsOneNoticeAndTheEventsAreCountedNotPlayed) {
  const std::filesystem::path conf = std::filesystem::temp_directory_path() / "ps_live_audio_full.conf";
  std::ofstream(conf) << "drivers = wave\n[wave]\nfile = /dev/full\n";
  setenv("ALSOFT_CONF", conf.c_str(), 1);
  unsetenv("ALSOFT_DRIVERS");
  audio::LiveAudioDesc desc;
  std::mutex m;
  std::vector<std::string> said;
  desc.notice = [&](const std::string& line) {
    std::lock_guard<std::mutex> lock(m);
    said.push_back(line);
  };
  auto a = audio::LiveAudio::open(desc);
  unsetenv("ALSOFT_CONF");
  ASSERT_TRUE(a->active()) << a->warning();
  // The mixer's first write fails within a period (OpenAL Soft's default: 20 ms): events go on
  // coming until the audio thread has seen it (at most 3 s), then 10 more.
  std::uint64_t sent = 0;
  for (; sent < 600 && !a->lost(); ++sent) {
    a->play(make(EventKind::contact_start, sent, 100.0));
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_TRUE(a->lost()) << "OpenAL never reported the wave writer on /dev/full disconnected";
  for (int i = 0; i < 10; ++i, ++sent) a->play(make(EventKind::body_impact, sent, 100.0));
  a->close();
  const std::vector<std::string> notices = a->notices();
  ASSERT_EQ(notices.size(), 1u) << a->summary();
  EXPECT_NE(notices[0].find("audio output"), std::string::npos) << notices[0];
  EXPECT_NE(notices[0].find("went away"), std::string::npos) << notices[0];
  EXPECT_EQ(said, notices);
  EXPECT_EQ(a->started() + a->unplayed() + a->dropped(), sent) << "every event accounted for";
  EXPECT_GE(a->unplayed(), 10u) << "nothing is started once the device is gone";
  EXPECT_NE(a->summary().find("the output went away, " + std::to_string(a->unplayed()) + " not played"),
            std::string::npos)
      << a->summary();
  std::filesystem::remove(conf);
}

}  // namespace
}  // namespace ps
