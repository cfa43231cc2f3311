// What CPU a benchmark's threads got, and whether other processes were
// using the machine meanwhile: a two-thread speed-up is only evidence when
// the second core was free for the second thread.  Linux /proc only.
// A header, as each benchmarks/*.cc builds into an executable of its own.
#ifndef PFDM_BENCHMARKS_THREAD_CPU_H_
#define PFDM_BENCHMARKS_THREAD_CPU_H_

#include <dirent.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "benchmark/benchmark.h"

namespace pfdm {

// Other processes using less than this many cores' worth of CPU over a
// run leave the second of two cores free enough for a speed-up to mean
// something (a tenth of a core: daemons, the shell).
constexpr double kIdleOthersCores = 0.1;

struct CpuSnapshot {
  std::chrono::steady_clock::time_point when;
  std::map<int, double> thread_seconds;  // This process's threads, by tid.
  // This process, its exited threads included (/proc/self/stat).
  double self_seconds = 0.0;
  // Its waited-for children (gnuplot).
  double children_seconds = 0.0;
  double machine_busy_seconds = 0.0;  // Every CPU, every process.
};

// utime + stime of a /proc stat line, in seconds: fields 14 and 15, after
// the command name in parentheses (which may hold spaces).
inline double StatCpuSeconds(const std::string& line) {
  std::istringstream fields(line.substr(line.rfind(')') + 2));
  std::string field;
  double ticks = 0.0;
  for (int i = 3; i <= 15 && fields >> field; ++i) {
    if (i >= 14) ticks += std::stod(field);
  }
  return ticks / static_cast<double>(sysconf(_SC_CLK_TCK));
}

inline std::string FirstLine(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  return line;
}

inline CpuSnapshot TakeCpuSnapshot() {
  CpuSnapshot s;
  s.when = std::chrono::steady_clock::now();
  if (DIR* tasks = opendir("/proc/self/task")) {
    while (const dirent* entry = readdir(tasks)) {
      if (entry->d_name[0] == '.') continue;
      const std::string line =
          FirstLine(std::string("/proc/self/task/") + entry->d_name + "/stat");
      if (!line.empty()) {
        s.thread_seconds[std::stoi(entry->d_name)] = StatCpuSeconds(line);
      }
    }
    closedir(tasks);
  }
  rusage children{};
  getrusage(RUSAGE_CHILDREN, &children);
  s.self_seconds = StatCpuSeconds(FirstLine("/proc/self/stat"));
  for (const timeval& t : {children.ru_utime, children.ru_stime}) {
    s.children_seconds += t.tv_sec + 1e-6 * t.tv_usec;
  }
  // "cpu  user nice system idle iowait irq softirq steal ...": busy is all
  // but idle and iowait.
  std::istringstream cpu(FirstLine("/proc/stat"));
  std::string name;
  cpu >> name;
  double ticks = 0.0, value = 0.0;
  for (int i = 0; i < 8 && cpu >> value; ++i) {
    if (i != 3 && i != 4) ticks += value;
  }
  s.machine_busy_seconds = ticks / static_cast<double>(sysconf(_SC_CLK_TCK));
  return s;
}

// Counters of the run since `start`: thread1_cpu_share, the CPU the
// busiest thread got over the wall time (1: a whole core);
// thread2_cpu_share, what all of the process's other threads got, those
// that exited before the run ended included (a solver's workers are
// joined when its call returns, so they are gone from /proc/self/task by
// then); process_cores, this process's CPU and its children's over the
// wall time; others_cores, every other process's (the machine's busy time less
// this process's); second_core_idle, 1 when others_cores was under
// kIdleOthersCores.  Clock ticks are 10 ms: runs of a second or more.
inline void CountThreadCpu(const CpuSnapshot& start, benchmark::State& state) {
  const CpuSnapshot end = TakeCpuSnapshot();
  const double wall =
      std::chrono::duration<double>(end.when - start.when).count();
  std::vector<double> threads;
  for (const auto& [tid, seconds] : end.thread_seconds) {
    const auto before = start.thread_seconds.find(tid);
    threads.push_back(seconds - (before == start.thread_seconds.end()
                                     ? 0.0
                                     : before->second));
  }
  std::sort(threads.begin(), threads.end(), std::greater<double>());
  threads.resize(std::max<size_t>(threads.size(), 2), 0.0);
  const double self = end.self_seconds - start.self_seconds;
  const double process =
      self + end.children_seconds - start.children_seconds;
  const double others = std::max(
      0.0, end.machine_busy_seconds - start.machine_busy_seconds - process);
  state.counters["thread1_cpu_share"] = threads[0] / wall;
  state.counters["thread2_cpu_share"] =
      std::max(threads[1], self - threads[0]) / wall;
  state.counters["process_cores"] = process / wall;
  state.counters["others_cores"] = others / wall;
  state.counters["second_core_idle"] = others / wall < kIdleOthersCores;
}

}  // namespace pfdm

#endif  // PFDM_BENCHMARKS_THREAD_CPU_H_
