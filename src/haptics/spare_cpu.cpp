#include "haptics/spare_cpu.h"

#include <pthread.h>
#include <sched.h>

#include <algorithm>
#include <charconv>
#include <cstring>

namespace ps {

namespace {

std::string cpu_list(const std::vector<int>& cpus) {
  std::string out;
  for (std::size_t i = 0; i < cpus.size(); ++i) out += (i ? "," : "") + std::to_string(cpus[i]);
  return out;
}

}  // namespace

std::vector<int> allowed_cpus() {
  cpu_set_t set;
  CPU_ZERO(&set);
  std::vector<int> out;
  if (pthread_getaffinity_np(pthread_self(), sizeof set, &set) != 0) return out;
  for (int c = 0; c < CPU_SETSIZE; ++c)
    if (CPU_ISSET(c, &set)) out.push_back(c);
  return out;
}

Result<SpareCpu> plan_spare_cpu(const std::string& request, const std::vector<int>& allowed) {
  SpareCpu r;
  if (request == "off") {
    r.description = "off (the scheduler places every thread)";
    return r;
  }
  int cpu = -1;
  if (request == "auto") {
    if (allowed.size() < 2) {
      r.description = "none (this process may use " + std::to_string(allowed.size()) + " CPU)";
      return r;
    }
    cpu = allowed.back();
  } else {
    const char* end = request.data() + request.size();
    const auto [ptr, ec] = std::from_chars(request.data(), end, cpu);
    if (ec != std::errc{} || ptr != end || cpu < 0)
      return make_error("--spare-cpu: '" + request + "' is not auto, off or a CPU number (allowed CPUs: " +
                        cpu_list(allowed) + ")");
    if (std::find(allowed.begin(), allowed.end(), cpu) == allowed.end())
      return make_error("--spare-cpu: CPU " + request + " is not one this process may use (allowed: " +
                        cpu_list(allowed) + ")");
    if (allowed.size() < 2)
      return make_error("--spare-cpu: CPU " + request +
                        " is the only one this process may use; leaving a CPU spare needs two (use auto or off)");
  }
  r.spare = cpu;
  for (int c : allowed)
    if (c != cpu) r.ours.push_back(c);
  r.description = "CPU " + std::to_string(cpu) + " (the program runs on " + cpu_list(r.ours) + ")";
  return r;
}

Result<SpareCpu> leave_spare_cpu(const std::string& request) {
  auto plan = plan_spare_cpu(request, allowed_cpus());
  if (!plan || plan->spare < 0) return plan;
  cpu_set_t set;
  CPU_ZERO(&set);
  for (int c : plan->ours) CPU_SET(c, &set);
  if (const int err = pthread_setaffinity_np(pthread_self(), sizeof set, &set); err != 0) {
    SpareCpu none;  // nothing changed: carry on as the scheduler would, and say why
    none.description = std::string("none (sched_setaffinity refused: ") + std::strerror(err) + ")";
    return none;
  }
  return plan;
}

}  // namespace ps
