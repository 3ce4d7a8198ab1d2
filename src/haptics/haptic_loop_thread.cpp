// The haptic loop's thread (HapticLoop::start): spawned, named, given a short scheduler slice and
// a small timer slack, and real-time priority where the system grants it (docs/haptics.md, the
// paragraphs on `--realtime`). The tick itself is haptic_loop.cpp.
#include "haptics/haptic_loop.h"

#include "haptics/rtkit.h"

#include <pthread.h>
#include <sched.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <future>

namespace ps {

namespace {

// sched_setattr(2) has no glibc wrapper; the struct is the kernel's (include/uapi/linux/sched/types.h).
struct SchedAttr {
  std::uint32_t size;
  std::uint32_t sched_policy;
  std::uint64_t sched_flags;
  std::int32_t sched_nice;
  std::uint32_t sched_priority;
  std::uint64_t sched_runtime, sched_deadline, sched_period;
  std::uint32_t sched_util_min, sched_util_max;
};

// Asks for a shorter EEVDF slice for the calling thread (SCHED_OTHER, nice unchanged). Returns
// 0 or an errno; kernels before 6.12 accept it and ignore the runtime.
int request_slice(std::int64_t slice_us) {
  SchedAttr attr{};
  attr.size = sizeof attr;
  attr.sched_policy = SCHED_OTHER;
  attr.sched_nice = getpriority(PRIO_PROCESS, 0);
  attr.sched_runtime = static_cast<std::uint64_t>(slice_us) * 1000u;
  return syscall(SYS_sched_setattr, 0, &attr, 0u) == 0 ? 0 : errno;
}

}  // namespace

void HapticLoop::start() {
  stop_.store(false);
  // The thread's id comes back through a promise the thread owns: a flag on this stack frame,
  // notified after its store, could be notified after start() returned and the frame was gone.
  std::promise<pid_t> id;
  std::future<pid_t> tid = id.get_future();
  thread_ = std::thread([this, id = std::move(id)]() mutable {
    id.set_value(static_cast<pid_t>(syscall(SYS_gettid)));
    pthread_setname_np(pthread_self(), "ps-haptic");  // shows in top -H, ps -L, /proc/<pid>/task/*/comm
    if (params_.sched_slice_us > 0) slice_error_.store(request_slice(params_.sched_slice_us));
    if (params_.timer_slack_ns > 0) prctl(PR_SET_TIMERSLACK, static_cast<unsigned long>(params_.timer_slack_ns), 0, 0, 0);
    while (!stop_.load(std::memory_order_relaxed)) scheduled_tick();
  });
  const pid_t thread_id = tid.get();
  if (params_.realtime_priority > 0) request_realtime(thread_id);
}

// SCHED_FIFO when this process may (CAP_SYS_NICE, RLIMIT_RTPRIO), else SCHED_RR through
// RealtimeKit where the system runs it (haptics/rtkit.h), else normal priority, saying why.
void HapticLoop::request_realtime(pid_t tid) {
  sched_param sp{};
  sp.sched_priority = std::min(params_.realtime_priority, 99);
  const int err = pthread_setschedparam(thread_.native_handle(), SCHED_FIFO, &sp);
  if (err == 0) {
    priority_ = "SCHED_FIFO " + std::to_string(sp.sched_priority);
    return;
  }
  const Result<int> rr = rtkit::make_thread_realtime(tid, sp.sched_priority);
  priority_ = rr ? "SCHED_RR " + std::to_string(rr.value()) + " (RealtimeKit)"
                 : std::string("normal (SCHED_FIFO refused: ") + std::strerror(err) + "; " + rr.error().message + ")";
}

std::string HapticLoop::scheduling() const {
  std::string out = priority_;
  if (params_.sched_slice_us > 0) {
    const int err = slice_error_.load();
    out += err == 0 ? ", slice " + std::to_string(params_.sched_slice_us) + " us"
                    : std::string(", slice refused (") + std::strerror(err) + ")";
  }
  out += params_.timer_slack_ns > 0 ? ", timer slack " + std::to_string(params_.timer_slack_ns) + " ns"
                                    : std::string(", timer slack: kernel default");
  out += ", wake spin " + std::to_string(std::max<std::int64_t>(params_.wake_spin_us, 0)) + " us";
  return out;
}

}  // namespace ps
