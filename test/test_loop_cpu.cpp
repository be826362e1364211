// Where a lock-step loop runs (core/loop_cpu.hpp): the setting, /proc/stat's counters, the
// idlest CPU between two readings, and moving every thread of a process to one CPU (checked
// with the kernel's own record of each thread's CPUs).
#include <gtest/gtest.h>
#include <sched.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>
#include <stdexcept>
#include <thread>

#include "expect_invalid_argument.hpp"
#include "spherical_robots/core/loop_cpu.hpp"

using spherical_robots::CpuTicks;
using spherical_robots::LoopCpuSetting;

namespace {

// A machine's /proc/stat (Linux 6.1, 2 CPUs) cut short: "cpu" sums, then one line per CPU.
const char* const kProcStat =
    "cpu  2255 34 2290 22625563 6290 127 456 0 0 0\n"
    "cpu0 1132 34 1441 11311718 4166 63 273 7 0 0\n"
    "cpu1 1123 0 849 11313845 2124 64 183 0 0 0\n"
    "intr 114930548 113199788 3 0 5 263 0 4 [...]\n"
    "ctxt 1990473\n";

std::vector<int> cpusOfThread(pid_t tid) {
  cpu_set_t set;
  CPU_ZERO(&set);
  EXPECT_EQ(sched_getaffinity(tid, sizeof(set), &set), 0);
  std::vector<int> cpus;
  for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu)
    if (CPU_ISSET(cpu, &set)) cpus.push_back(cpu);
  return cpus;
}

void setCpusOfProcess(const std::vector<int>& cpus) {
  cpu_set_t set;
  CPU_ZERO(&set);
  for (const int cpu : cpus) CPU_SET(cpu, &set);
  ASSERT_EQ(sched_setaffinity(0, sizeof(set), &set), 0);
}

}  // namespace

TEST(LoopCpuSetting, WordsAndNumbers) {
  EXPECT_EQ(LoopCpuSetting::fromString("auto").kind, LoopCpuSetting::Kind::kAuto);
  EXPECT_EQ(LoopCpuSetting::fromString("none").kind, LoopCpuSetting::Kind::kNone);
  const LoopCpuSetting fixed = LoopCpuSetting::fromString("12");
  EXPECT_EQ(fixed.kind, LoopCpuSetting::Kind::kFixed);
  EXPECT_EQ(fixed.cpu, 12);
  for (const char* text : {"auto", "none", "0", "7"})
    EXPECT_EQ(LoopCpuSetting::fromString(text).toString(), text);
  for (const char* bad : {"", "-1", "1.5", "cpu1", "Auto", "99999999999"})
    EXPECT_INVALID_ARGUMENT(LoopCpuSetting::fromString(bad), "auto, none or a CPU number");
}

TEST(ProcStat, PerCpuLinesBusyIsAllButIdleAndIowait) {
  const auto cpus = spherical_robots::parseProcStat(kProcStat);
  ASSERT_EQ(cpus.size(), 2u);  // the "cpu" sum is not a CPU
  // cpu0: user 1132 + nice 34 + system 1441 + irq 63 + softirq 273 + steal 7; idle 11311718,
  // iowait 4166; guest and guest_nice are already in user and nice.
  EXPECT_EQ(cpus.at(0).busy, 1132u + 34 + 1441 + 63 + 273 + 7);
  EXPECT_EQ(cpus.at(0).total, 1132u + 34 + 1441 + 11311718 + 4166 + 63 + 273 + 7);
  EXPECT_EQ(cpus.at(1).busy, 1123u + 849 + 64 + 183);
  EXPECT_INVALID_ARGUMENT(spherical_robots::parseProcStat("cpu0 1 2 x 4\n"), "cpu0 1 2 x 4");
  EXPECT_INVALID_ARGUMENT(spherical_robots::parseProcStat("cpu3 1 2\n"), "4 or more");
}

TEST(ProcStat, ThisMachinesHasEveryAllowedCpu) {
  const auto cpus = spherical_robots::readCpuTicks();
  for (const int cpu : spherical_robots::allowedCpus()) {
    ASSERT_EQ(cpus.count(cpu), 1u) << cpu;
    EXPECT_GT(cpus.at(cpu).total, cpus.at(cpu).busy) << cpu;
  }
}

TEST(IdlestCpu, LeastBusyShareBetweenReadingsAmongTheAllowed) {
  const std::map<int, CpuTicks> before{{0, {100, 1000}}, {1, {100, 1000}}, {2, {500, 1000}}};
  // Between the readings: CPU 0 busy 90 of 100 ticks, CPU 1 40 of 100, CPU 2 10 of 200 (its
  // counters since boot say it was the busiest: only the interval counts).
  const std::map<int, CpuTicks> after{{0, {190, 1100}}, {1, {140, 1100}}, {2, {510, 1200}}};
  EXPECT_EQ(spherical_robots::idlestCpu(before, after, {0, 1, 2}), 2);
  EXPECT_EQ(spherical_robots::idlestCpu(before, after, {0, 1}), 1);
  EXPECT_EQ(spherical_robots::idlestCpu(before, after, {0}), 0);
  EXPECT_EQ(spherical_robots::idlestCpu(before, after, {}), -1);
  EXPECT_EQ(spherical_robots::idlestCpu(before, after, {5}), -1);
  // Equally idle: the lowest number.
  EXPECT_EQ(spherical_robots::idlestCpu(before, before, {2, 1}), 1);
}

TEST(LoopCpuFor, NoneFixedAndAuto) {
  using Kind = LoopCpuSetting::Kind;
  const std::map<int, CpuTicks> before{{0, {0, 100}}, {1, {0, 100}}};
  const std::map<int, CpuTicks> after{{0, {50, 200}}, {1, {10, 200}}};
  EXPECT_EQ(spherical_robots::loopCpuFor({Kind::kNone, -1}, {0, 1}, before, after), -1);
  EXPECT_EQ(spherical_robots::loopCpuFor({Kind::kAuto, -1}, {0, 1}, before, after), 1);
  EXPECT_EQ(spherical_robots::loopCpuFor({Kind::kFixed, 0}, {0, 1}, before, after), 0);
  EXPECT_INVALID_ARGUMENT(spherical_robots::loopCpuFor({Kind::kFixed, 4}, {0, 1}, {}, {}),
                          "loop_cpu 4", "0, 1");
}

// Every thread, including one started before the move, ends up on the one CPU; a thread
// started after it inherits it.
TEST(PinProcessToCpu, MovesEveryThread) {
  const std::vector<int> allowed = spherical_robots::allowedCpus();
  ASSERT_FALSE(allowed.empty());
  const int target = allowed.back();
  std::atomic<pid_t> earlier_tid{0};
  std::atomic<bool> stop{false};
  std::thread earlier([&] {
    earlier_tid = static_cast<pid_t>(syscall(SYS_gettid));
    while (!stop) std::this_thread::yield();
  });
  while (earlier_tid == 0) std::this_thread::yield();
  ASSERT_EQ(spherical_robots::pinProcessToCpu(target), "");
  EXPECT_EQ(cpusOfThread(0), std::vector<int>{target});
  EXPECT_EQ(cpusOfThread(earlier_tid), std::vector<int>{target});
  std::vector<int> later_cpus;
  std::thread later([&] { later_cpus = cpusOfThread(0); stop = true; });
  later.join();
  earlier.join();
  EXPECT_EQ(later_cpus, std::vector<int>{target});
  EXPECT_EQ(spherical_robots::allowedCpus(), std::vector<int>{target});
  EXPECT_EQ(sched_getcpu(), target);
  setCpusOfProcess(allowed);
  EXPECT_NE(spherical_robots::pinProcessToCpu(CPU_SETSIZE), "");
}

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
