#include "spherical_robots/core/loop_cpu.hpp"

#include <dirent.h>
#include <sched.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace spherical_robots {
namespace {

std::string joinedCpus(const std::vector<int>& cpus) {
  std::string text;
  for (const int cpu : cpus) text += (text.empty() ? "" : ", ") + std::to_string(cpu);
  return text.empty() ? "none" : text;
}

}  // namespace

LoopCpuSetting LoopCpuSetting::fromString(const std::string& text) {
  if (text == "auto") return {Kind::kAuto, -1};
  if (text == "none") return {Kind::kNone, -1};
  const bool digits = !text.empty() && text.size() <= 6 &&
                      std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
  if (!digits)
    throw std::invalid_argument("loop_cpu '" + text + "' is not auto, none or a CPU number (0, 1, ...)");
  return {Kind::kFixed, std::stoi(text)};
}

std::string LoopCpuSetting::toString() const {
  switch (kind) {
    case Kind::kAuto: return "auto";
    case Kind::kNone: return "none";
    case Kind::kFixed: return std::to_string(cpu);
  }
  return "?";
}

std::map<int, CpuTicks> parseProcStat(const std::string& text) {
  std::map<int, CpuTicks> cpus;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    // "cpu " is the sum over CPUs; "cpuN" one CPU.
    if (line.size() < 4 || line.compare(0, 3, "cpu") != 0 || line[3] < '0' || line[3] > '9') continue;
    std::istringstream fields(line.substr(3));
    int cpu = -1;
    fields >> cpu;
    std::vector<std::uint64_t> ticks;
    std::uint64_t value = 0;
    while (fields >> value) ticks.push_back(value);
    // user nice system idle iowait irq softirq steal [guest guest_nice, already in user and nice]
    if (cpu < 0 || ticks.size() < 4 || !fields.eof())
      throw std::invalid_argument("/proc/stat line '" + line + "' is not 'cpuN' and 4 or more tick counts");
    CpuTicks counted;
    for (std::size_t i = 0; i < ticks.size() && i < 8; ++i) {
      counted.total += ticks[i];
      if (i != 3 && i != 4) counted.busy += ticks[i];  // 3 idle, 4 iowait
    }
    cpus[cpu] = counted;
  }
  return cpus;
}

int idlestCpu(const std::map<int, CpuTicks>& before, const std::map<int, CpuTicks>& after,
              const std::vector<int>& allowed) {
  int idlest = -1;
  double least_busy = 2.0;
  for (const int cpu : allowed) {
    const auto b = before.find(cpu), a = after.find(cpu);
    if (b == before.end() || a == after.end()) continue;
    const std::uint64_t total = a->second.total - b->second.total;
    const double busy = total == 0 ? 0.0 : double(a->second.busy - b->second.busy) / double(total);
    if (busy < least_busy || (busy == least_busy && cpu < idlest)) {
      least_busy = busy;
      idlest = cpu;
    }
  }
  return idlest;
}

std::map<int, CpuTicks> readCpuTicks() {
  std::ifstream file("/proc/stat");
  std::stringstream text;
  text << file.rdbuf();
  if (!file) return {};
  try {
    return parseProcStat(text.str());
  } catch (const std::invalid_argument&) {
    return {};  // a kernel whose lines this does not know: no choice, rather than a dead plant
  }
}

std::vector<int> allowedCpus() {
  cpu_set_t set;
  CPU_ZERO(&set);
  std::vector<int> cpus;
  if (sched_getaffinity(0, sizeof(set), &set) != 0) return cpus;
  for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu)
    if (CPU_ISSET(cpu, &set)) cpus.push_back(cpu);
  return cpus;
}

std::string pinProcessToCpu(int cpu) {
  if (cpu < 0 || cpu >= CPU_SETSIZE) return "CPU " + std::to_string(cpu) + " is out of range";
  cpu_set_t set;
  CPU_ZERO(&set);
  CPU_SET(cpu, &set);
  // sched_setaffinity moves one thread: every thread listed in /proc/self/task, listed again
  // until no new one appears (a thread started meanwhile inherits its starter's set, or is
  // caught by the next listing).
  std::vector<long> moved;
  for (bool found_new = true; found_new;) {
    found_new = false;
    DIR* tasks = opendir("/proc/self/task");
    if (!tasks) return std::string("/proc/self/task: ") + std::strerror(errno);
    while (const dirent* entry = readdir(tasks)) {
      if (entry->d_name[0] == '.') continue;
      const long tid = std::strtol(entry->d_name, nullptr, 10);
      if (std::find(moved.begin(), moved.end(), tid) != moved.end()) continue;
      // A thread that ended since the listing (ESRCH) has nothing to move.
      if (sched_setaffinity(static_cast<pid_t>(tid), sizeof(set), &set) != 0 && errno != ESRCH) {
        const std::string reason = std::strerror(errno);
        closedir(tasks);
        return "CPU " + std::to_string(cpu) + ", thread " + std::to_string(tid) + ": " + reason;
      }
      moved.push_back(tid);
      found_new = true;
    }
    closedir(tasks);
  }
  return "";
}

int loopCpuFor(const LoopCpuSetting& setting, const std::vector<int>& allowed,
               const std::map<int, CpuTicks>& before, const std::map<int, CpuTicks>& after) {
  switch (setting.kind) {
    case LoopCpuSetting::Kind::kNone:
      return -1;
    case LoopCpuSetting::Kind::kFixed:
      if (std::find(allowed.begin(), allowed.end(), setting.cpu) == allowed.end())
        throw std::invalid_argument("loop_cpu " + std::to_string(setting.cpu) +
                                    " is not one of the CPUs this process may run on (" +
                                    joinedCpus(allowed) + ")");
      return setting.cpu;
    case LoopCpuSetting::Kind::kAuto:
      return idlestCpu(before, after, allowed);
  }
  return -1;
}

}  // namespace spherical_robots
