// Device strings parsed once (devices/device_spec.h): every form, the kinds a command takes,
// and the error that names the bad string and the forms it could have been. No GL.
#include <gtest/gtest.h>

#include <string>

#include "devices/device_spec.h"
#include "devices/sample_log.h"

namespace ps {
namespace {

DeviceSpec parsed(const std::string& text) {
  auto d = parse_device_spec(text);
  EXPECT_TRUE(d.ok()) << text << ": " << (d.ok() ? "" : d.error().message);
  return d.ok() ? d.value() : DeviceSpec{};
}

std::string error_of(const std::string& text, std::initializer_list<DeviceKind> accepted = kAllDeviceKinds) {
  auto d = parse_device_spec(text, accepted);
  return d.ok() ? "(parsed)" : d.error().message;
}

TEST(DeviceSpecTest, ParsesEveryForm) {
  EXPECT_EQ(parsed("mouse").kind, DeviceKind::kMouse);
  EXPECT_EQ(parsed("gamepad").kind, DeviceKind::kGamepad);
  const DeviceSpec traj = parsed("trajectory:walk.traj");
  EXPECT_EQ(traj.kind, DeviceKind::kTrajectory);
  EXPECT_EQ(traj.file, "walk.traj");
  EXPECT_EQ(parsed("playback:run/device.log").kind, DeviceKind::kPlayback);
  EXPECT_EQ(parsed("playback:run/device.log").file, "run/device.log");
  EXPECT_EQ(parsed("pointer:sweep.ptr").kind, DeviceKind::kPointer);
  EXPECT_EQ(parsed("mouse").file, "");
}

TEST(DeviceSpecTest, TheFileIsEverythingAfterTheFirstColon) {
  EXPECT_EQ(parsed("trajectory:dir:with:colons/a.traj").file, "dir:with:colons/a.traj");
}

TEST(DeviceSpecTest, LogsAreTheKindsWithAFile) {
  EXPECT_FALSE(parsed("mouse").is_log());
  EXPECT_FALSE(parsed("gamepad").is_log());
  EXPECT_TRUE(parsed("trajectory:a").is_log());
  EXPECT_TRUE(parsed("playback:a").is_log());
  EXPECT_TRUE(parsed("pointer:a").is_log());
}

TEST(DeviceSpecTest, TextGivesBackWhatWasParsed) {
  for (const char* text : {"mouse", "gamepad", "trajectory:a.traj", "playback:b.log", "pointer:c:d.ptr"})
    EXPECT_EQ(parsed(text).text(), text);
  EXPECT_EQ(DeviceSpec{}.text(), "mouse");  // the default device
}

TEST(DeviceSpecTest, ErrorNamesTheStringAndTheValidForms) {
  EXPECT_EQ(error_of("joystick"),
            "device 'joystick': expected mouse, gamepad, trajectory:FILE, playback:FILE or pointer:FILE");
  EXPECT_EQ(error_of(""), "device '': expected mouse, gamepad, trajectory:FILE, playback:FILE or pointer:FILE");
}

TEST(DeviceSpecTest, ALogNeedsItsFileAndMouseTakesNone) {
  EXPECT_NE(error_of("trajectory:"), "(parsed)");
  EXPECT_NE(error_of("pointer:"), "(parsed)");
  EXPECT_NE(error_of("trajectory"), "(parsed)");
  EXPECT_NE(error_of("mouse:"), "(parsed)");
  EXPECT_NE(error_of("gamepad:x"), "(parsed)");
  EXPECT_NE(error_of("Mouse"), "(parsed)");  // the words are exact
}

TEST(DeviceSpecTest, OnlyTheAcceptedKindsAndTheErrorListsThem) {
  EXPECT_TRUE(parse_device_spec("pointer:p.ptr", kLogDeviceKinds).ok());
  EXPECT_EQ(error_of("mouse", kLogDeviceKinds), "device 'mouse': expected trajectory:FILE, playback:FILE or pointer:FILE");
  EXPECT_EQ(error_of("pointer:p.ptr", {DeviceKind::kTrajectory, DeviceKind::kPlayback}),
            "device 'pointer:p.ptr': expected trajectory:FILE or playback:FILE");
  EXPECT_EQ(error_of("gamepad", {DeviceKind::kMouse}), "device 'gamepad': expected mouse");
}

TEST(DeviceSpecTest, DeviceFormsAreTheWordsOfTheHelp) {
  EXPECT_EQ(device_form(DeviceKind::kMouse), "mouse");
  EXPECT_EQ(device_form(DeviceKind::kPlayback), "playback:FILE");
}

TEST(DeviceSpecTest, OpeningALogOfTheWrongKindNamesTheFormsItTakes) {
  auto log = open_log_device(DeviceSpec{DeviceKind::kPointer, "p.ptr"});
  ASSERT_FALSE(log.ok());
  EXPECT_EQ(log.error().message, "device 'pointer:p.ptr': expected trajectory:FILE or playback:FILE");
  auto pointer = open_pointer_device(std::string("trajectory:t.traj"));
  ASSERT_FALSE(pointer.ok());
  EXPECT_EQ(pointer.error().message, "device 'trajectory:t.traj': expected pointer:FILE");
}

}  // namespace
}  // namespace ps
