// A spare CPU (haptics/spare_cpu.h): the choice, its errors, and that the calling thread and every
// thread it starts afterwards — the haptic thread among them — really stay off the spare CPU. No GL.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "devices/sample_log.h"
#include "haptics/haptic_loop.h"
#include "haptics/spare_cpu.h"

namespace ps {
namespace {

TEST(SpareCpuTest, AutoLeavesTheHighestAllowedCpuAndRunsOnTheRest) {
  auto r = plan_spare_cpu("auto", {0, 1});
  ASSERT_TRUE(r) << r.error().message;
  EXPECT_EQ(r->spare, 1);
  EXPECT_EQ(r->ours, (std::vector<int>{0}));
  EXPECT_EQ(r->description, "CPU 1 (the program runs on 0)");
  r = plan_spare_cpu("auto", {2, 5, 7});  // a cpuset with gaps (a container given CPUs 2, 5 and 7)
  ASSERT_TRUE(r);
  EXPECT_EQ(r->spare, 7);
  EXPECT_EQ(r->ours, (std::vector<int>{2, 5}));
}

TEST(SpareCpuTest, OneCpuOrOffLeavesNothing) {
  auto r = plan_spare_cpu("auto", {3});
  ASSERT_TRUE(r);
  EXPECT_EQ(r->spare, -1);
  EXPECT_TRUE(r->ours.empty());
  EXPECT_NE(r->description.find("1 CPU"), std::string::npos) << r->description;
  r = plan_spare_cpu("off", {0, 1, 2, 3});
  ASSERT_TRUE(r);
  EXPECT_EQ(r->spare, -1);
  EXPECT_TRUE(r->ours.empty());
}

TEST(SpareCpuTest, ANamedCpuMustBeAllowedAndNotTheOnlyOne) {
  auto r = plan_spare_cpu("0", {0, 1, 2});
  ASSERT_TRUE(r);
  EXPECT_EQ(r->spare, 0);
  EXPECT_EQ(r->ours, (std::vector<int>{1, 2}));
  for (const char* bad : {"3", "-1", "x", "1.5", ""}) {
    r = plan_spare_cpu(bad, {0, 1, 2});
    ASSERT_FALSE(r) << bad;
    EXPECT_NE(r.error().message.find("allowed"), std::string::npos) << r.error().message;
    EXPECT_NE(r.error().message.find("0,1,2"), std::string::npos) << r.error().message;
  }
  r = plan_spare_cpu("4", {4});
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("only one"), std::string::npos) << r.error().message;
}

// Cpus_allowed_list of the process's thread named `name` ("" when there is none).
std::string cpus_allowed_of(const std::string& name) {
  for (const auto& task : std::filesystem::directory_iterator("/proc/self/task")) {
    std::ifstream comm(task.path() / "comm");
    std::string c;
    std::getline(comm, c);
    if (c != name) continue;
    std::ifstream status(task.path() / "status");
    for (std::string line; std::getline(status, line);)
      if (line.rfind("Cpus_allowed_list:", 0) == 0) return line.substr(line.find_first_not_of(" \t", 18));
  }
  return "";
}

std::string list(const std::vector<int>& cpus) {  // as the kernel writes a list of single CPUs
  std::string out;
  for (std::size_t i = 0; i < cpus.size(); ++i) out += (i ? "," : "") + std::to_string(cpus[i]);
  return out;
}

// On a thread of its own, so the test runner's main thread keeps its CPUs.
TEST(SpareCpuTest, TheCallerAndEveryThreadItStartsStayOffTheSpareCpu) {
  const std::vector<int> all = allowed_cpus();
  if (all.size() < 2) GTEST_SKIP() << "needs at least two CPUs";
  std::thread([&] {
    auto r = leave_spare_cpu("auto");
    ASSERT_TRUE(r) << r.error().message;
    ASSERT_EQ(r->spare, all.back()) << r->description;
    EXPECT_EQ(allowed_cpus(), r->ours);
    std::vector<int> inherited;
    std::thread([&] { inherited = allowed_cpus(); }).join();
    EXPECT_EQ(inherited, r->ours);

    LogDevice device({{0.0, {0, 0, 20}, 0, true}, {1.0, {1, 0, 20}, 0, true}}, true, "still");
    SteadyClock clock;
    HapticLoop loop(device, clock, HapticLoopParams{});
    loop.start();
    for (int i = 0; i < 200 && loop.state().read().tick < 5; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    // One CPU in `ours` is listed as "0"; consecutive ones as a range ("0-2"), which this machine-
    // independent check accepts by comparing with both spellings.
    const std::string haptic = cpus_allowed_of("ps-haptic");
    const std::string range = std::to_string(r->ours.front()) + "-" + std::to_string(r->ours.back());
    EXPECT_TRUE(haptic == list(r->ours) || (haptic == range && r->ours.back() - r->ours.front() + 1 ==
                                                                    static_cast<int>(r->ours.size())))
        << "ps-haptic may run on " << haptic << ", expected " << list(r->ours);
    loop.stop();
  }).join();
  EXPECT_EQ(allowed_cpus(), all);  // this thread was never touched
}

}  // namespace
}  // namespace ps
