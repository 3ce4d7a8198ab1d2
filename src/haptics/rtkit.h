// Real-time priority without root, through RealtimeKit (rtkit): the system D-Bus service that
// audio servers use to get SCHED_RR for threads of unprivileged processes, within limits the
// administrator sets (a maximum priority, RLIMIT_RTTIME, a per-user budget, a watchdog that
// demotes everything if the machine starves). docs/haptics.md, "Real-time priority".
#pragma once

#include <sys/types.h>

#include "core/result.h"

namespace ps::rtkit {

// The CPU time a real-time thread may use without sleeping before the kernel signals it
// (RLIMIT_RTTIME, which rtkit requires every client to set no higher than its own limit, 200 ms
// by default). The haptic thread sleeps every tick, using a few us of each 1 ms.
inline constexpr long kRtTimeUsec = 100'000;

// Asks RealtimeKit on the system bus to run thread `tid` (of this process) as SCHED_RR at
// `priority`, lowered to the daemon's MaxRealtimePriority. Returns the priority granted, or one
// line saying why not ("RealtimeKit is not available: ..."). Blocks up to ~1 s on the bus.
Result<int> make_thread_realtime(pid_t tid, int priority);

}  // namespace ps::rtkit
