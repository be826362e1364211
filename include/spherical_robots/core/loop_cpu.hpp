#pragma once
// The CPU a lock-step loop runs on (docs/lockstep.md, "One CPU for the loop"). A lock-step
// loop's nodes work one after another, never at once: the plant steps, then each participant in
// turn. Spread over CPUs, each hand-off wakes an idle CPU, which on a virtual machine (cpuidle
// haltpoll) costs more than a step's work; on one CPU it is a context switch. The terrain stack
// ran 41.7x real time as processes and 110x as nodelets spread, 92x and 465x on one CPU. The
// clock's owner picks the CPU (by default the idlest over its start-up, so that stacks started
// side by side take different CPUs) and names it in every step request; each node of the loop
// moves its threads there. Observers (robot_state_publisher, rosbag, rviz) stay where the kernel
// puts them. No ROS here: the choice is a function of /proc/stat's counters.

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace spherical_robots {

/// The loop_cpu setting: "auto" (the idlest CPU at start), "none" (the kernel places every
/// thread), or a CPU number.
struct LoopCpuSetting {
  enum class Kind { kAuto, kNone, kFixed };
  Kind kind = Kind::kAuto;
  int cpu = -1;  ///< kFixed: the CPU; else -1

  /// @throw std::invalid_argument naming the text and what is allowed.
  static LoopCpuSetting fromString(const std::string& text);
  std::string toString() const;
};

/// Busy and total time of one CPU since boot [clock ticks], as /proc/stat counts them.
struct CpuTicks {
  std::uint64_t busy = 0;
  std::uint64_t total = 0;
};

/// The per-CPU lines ("cpuN user nice system idle iowait irq softirq steal ...") of /proc/stat's
/// text, by CPU number; idle and iowait count as not busy.
/// @throw std::invalid_argument naming a cpuN line that is not one.
std::map<int, CpuTicks> parseProcStat(const std::string& text);

/// The CPU of `allowed` that was least busy between the two readings (ties: the lowest number);
/// -1 if `allowed` is empty or no allowed CPU is in both readings.
int idlestCpu(const std::map<int, CpuTicks>& before, const std::map<int, CpuTicks>& after,
              const std::vector<int>& allowed);

/// /proc/stat now; empty if it cannot be read or parsed (auto then chooses no CPU).
std::map<int, CpuTicks> readCpuTicks();

/// The CPUs this process may run on (sched_getaffinity), ascending.
std::vector<int> allowedCpus();

/// Moves every thread of this process to `cpu` (threads it starts later inherit it).
/// @return "" on success, else what failed (the CPU, the thread, the system's reason).
std::string pinProcessToCpu(int cpu);

/// Where `setting` puts the loop, for a process allowed on `allowed`: -1 for none.
/// @throw std::invalid_argument if a fixed CPU is not one of `allowed` (naming both).
int loopCpuFor(const LoopCpuSetting& setting, const std::vector<int>& allowed,
               const std::map<int, CpuTicks>& before, const std::map<int, CpuTicks>& after);

}  // namespace spherical_robots
