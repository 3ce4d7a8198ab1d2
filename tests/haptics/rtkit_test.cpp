// RealtimeKit's client (haptics/rtkit.h). Without a daemon: one line saying it is not available.
// With one (PS_TEST_RTKIT=1, set by tests/haptics/rtkit_check.sh, which starts a private system
// bus and rtkit-daemon on it): a thread of ours asked for priority 50 gets SCHED_RR at the
// daemon's maximum (20), as the kernel reports it, and the haptic loop's priority() says so when
// SCHED_FIFO is refused.
#include <gtest/gtest.h>

#include <pthread.h>
#include <sched.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <thread>

#include "haptics/rtkit.h"

namespace ps {
namespace {

bool daemon_running() { return std::getenv("PS_TEST_RTKIT") != nullptr; }

TEST(RtkitTest, WithoutADaemonTheErrorSaysSo) {
  if (daemon_running()) GTEST_SKIP() << "a daemon is running";
  ::setenv("DBUS_SYSTEM_BUS_ADDRESS", "unix:path=/nonexistent/ps-test-bus", 1);
  const Result<int> r = rtkit::make_thread_realtime(static_cast<pid_t>(syscall(SYS_gettid)), 10);
  ::unsetenv("DBUS_SYSTEM_BUS_ADDRESS");
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().message.rfind("RealtimeKit is not available: ", 0), 0u) << r.error().message;
}

TEST(RtkitTest, ADaemonGrantsSchedRrAtItsMaximum) {
  if (!daemon_running()) GTEST_SKIP() << "no rtkit-daemon (run through rtkit_check.sh)";
  std::atomic<pid_t> tid{0};
  std::atomic<bool> done{false};
  std::thread t([&] {
    tid.store(static_cast<pid_t>(syscall(SYS_gettid)));
    while (!done.load()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  });
  while (tid.load() == 0) std::this_thread::yield();
  const Result<int> r = rtkit::make_thread_realtime(tid.load(), 50);
  int policy = -1;
  sched_param sp{};
  pthread_getschedparam(t.native_handle(), &policy, &sp);
  done.store(true);
  t.join();
  ASSERT_TRUE(r) << r.error().message;
  EXPECT_EQ(r.value(), 20);  // the daemon's --max-realtime-priority default
  EXPECT_EQ(policy & ~SCHED_RESET_ON_FORK, SCHED_RR);
  EXPECT_EQ(sp.sched_priority, 20);
}

}  // namespace
}  // namespace ps
