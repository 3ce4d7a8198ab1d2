#pragma once
// A spare CPU: one CPU that none of the program's threads use (docs/haptics.md, "A spare CPU").
//
// On a kernel without kernel preemption (PREEMPT_NONE, the default of many server and
// virtual-machine kernels) a kernel thread that runs for milliseconds — memory compaction, access
// monitoring, a per-CPU worker — cannot be preempted, and a woken haptic thread whose CPU it holds
// waits until it yields: that was the 2–6 ms tail of the 1 kHz loop. Such work is placed on idle
// CPUs first. Keeping one CPU free of every thread of the program gives it a place to land away
// from the haptic thread, which shares the other CPUs with the renderer and preempts it on wake-up
// (its short scheduler slice, HapticLoopParams::sched_slice_us; user-space threads can always be
// preempted). Measured on 2 cores: the haptic thread alone on a CPU of its own did worse, because
// that idle CPU is exactly where the kernel's work lands. CPU affinity of one's own threads needs
// no privilege (sched_setaffinity(2)).
#include <string>
#include <vector>

#include "core/result.h"

namespace ps {

struct SpareCpu {
  int spare = -1;            // the CPU left free; -1: none (fewer than two CPUs allowed, or "off")
  std::vector<int> ours;     // the CPUs the program's threads run on (empty: unchanged)
  std::string description;   // for a command's report: "CPU 1 (the program runs on 0)"
};

// The CPUs the calling thread may run on, in increasing order (sched_getaffinity).
std::vector<int> allowed_cpus();

// Parses `request` ("auto", "off" or a CPU number) against `allowed` without touching any thread:
// "auto" leaves the highest allowed CPU spare when at least two are allowed; a number must be one
// of them and not the only one. Errors say which CPUs are allowed.
Result<SpareCpu> plan_spare_cpu(const std::string& request, const std::vector<int>& allowed);

// plan_spare_cpu on the calling thread's CPUs, then confines the calling thread — and so every
// thread it starts afterwards: llvmpipe's rasterisers, the haptic thread, audio — to `ours`. Call
// it before the GL context exists (llvmpipe starts its threads with the context).
Result<SpareCpu> leave_spare_cpu(const std::string& request);

}  // namespace ps
