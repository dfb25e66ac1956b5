/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// The platform monitor of the timing tests (docs/timing.md, "The platform's allowance").
//
// Two threads per CPU this process may use, each pinned to it:
//
// The waker, under SCHED_FIFO at the highest priority, above every thread of a generated program (their
// ranks map to the lowest priorities). It wakes every period on an absolute CLOCK_MONOTONIC time and
// records its nominal wake-up and the moment it finished recording: in between the CPU ran something
// other than the measured program (the kernel, the hypervisor, another program, or the monitor itself).
//
// The spinner, under SCHED_IDLE, below every other thread: it runs only while no thread of the program
// (nor any other) wants its CPU, and then reads the clock without pause. A gap between two of its reads
// longer than --gap-ns during which it was not switched out (its context switches unchanged) is time
// its CPU ran no thread at all (an interrupt, the kernel, the hypervisor taking the virtual CPU): it
// records the whole gap. A gap during which it was switched out (a thread of the program, the waker or
// another program ran) is its to say only in part: the time it was neither running (its CPU time) nor
// waiting to run (its run delay, /proc/thread-self/schedstat) was taken from the CPU while it was the
// thread there (the hypervisor stopping the virtual CPU, whose accounting leaves that time out of the
// thread's CPU time), e.g. a stop during which a thread of the program was due and that delayed its
// start; it records that much from the gap's start. What is taken while another thread runs, it cannot
// see. It takes no CPU time from any thread that wants it: a woken thread of any other class preempts it
// at once.
//
// On SIGTERM or SIGINT (or after --run-for-ms) the records are written to the output file.
//
//   rsaml-platform-monitor --out FILE [--period-us 1000] [--max-ms 600000] [--run-for-ms N] [--gap-ns 2000]
//                          [--no-spin] [--hiccup-ms H --hiccup-every-ms E]
//
// --no-spin leaves the spinners out (the waker alone). --hiccup-ms makes each waker busy-loop H ms every E
// ms inside its record: a synthetic platform delay, for the test that checks the loss is found and counted.
#include <pthread.h>
#include <sched.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <fcntl.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

namespace {

struct Record {
  std::int64_t nominal;
  std::int64_t end;
};

struct Cpu {
  int cpu = 0;
  std::vector<Record> records;
  std::size_t count = 0;
  bool overflow = false;
  std::string sched;
  // the spinner's: the gaps it recorded (from, to), and the CPU time it ran (what of the run it watched)
  std::vector<Record> gaps;
  std::size_t gap_count = 0;
  bool gap_overflow = false;
  std::string spin_sched;
  std::int64_t spun_ns = 0;
  bool waits_read = false;
};

std::atomic<bool> stopping{false};
std::int64_t period_ns = 1000000;
std::int64_t hiccup_ns = 0;
std::int64_t hiccup_every_ns = 0;
std::int64_t gap_ns = 2000;

std::int64_t now() {
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC, &t);
  return static_cast<std::int64_t>(t.tv_sec) * 1000000000LL + t.tv_nsec;
}

timespec at(std::int64_t ns) {
  timespec t{};
  t.tv_sec = static_cast<time_t>(ns / 1000000000LL);
  t.tv_nsec = static_cast<long>(ns % 1000000000LL);
  return t;
}

// Pins the calling thread to `cpu` under `policy` at `priority`: `name` when both were granted, else why not.
std::string place(int cpu, int policy, int priority, const std::string& name) {
  cpu_set_t set;
  CPU_ZERO(&set);
  CPU_SET(cpu, &set);
  const int pinned = pthread_setaffinity_np(pthread_self(), sizeof set, &set);
  sched_param param{};
  param.sched_priority = priority;
  const int error = pthread_setschedparam(pthread_self(), policy, &param);
  if (pinned != 0) {
    return std::string("default: not pinned (") + std::strerror(pinned) + ")";
  }
  if (error != 0) {
    return std::string("default: ") + name.substr(0, name.find(' ')) + " not permitted (" + std::strerror(error) + ")";
  }
  return name;
}

std::int64_t thread_cpu_ns() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<std::int64_t>(t.tv_sec) * 1000000000LL + t.tv_nsec;
}

// The calling thread's run delay so far (the time it waited to run, the second field of its schedstat), -1 when unknown.
long long run_delay(int fd) {
  char buf[128];
  const ssize_t n = fd < 0 ? -1 : pread(fd, buf, sizeof buf - 1, 0);
  if (n <= 0) {
    return -1;
  }
  buf[n] = '\0';
  unsigned long long ran = 0;
  unsigned long long waited = 0;
  return std::sscanf(buf, "%llu %llu", &ran, &waited) == 2 ? static_cast<long long>(waited) : -1;
}

long thread_switches() {
  rusage r{};
  getrusage(RUSAGE_THREAD, &r);
  return r.ru_nvcsw + r.ru_nivcsw;
}

// The spinner of one CPU (see the top of this file). No pause instruction in its loop: a virtual CPU that
// pauses in a tight loop may be made to exit to the hypervisor (pause-loop exiting), which would add gaps
// of the monitor's own making.
void spin(Cpu* c, std::atomic<int>* ready) {
  c->spin_sched = place(c->cpu, SCHED_IDLE, 0, "SCHED_IDLE");
  const int schedstat = open("/proc/thread-self/schedstat", O_RDONLY | O_CLOEXEC);
  long long waited = run_delay(schedstat);
  c->waits_read = waited >= 0;
  ready->fetch_add(1);
  const std::int64_t cpu_start = thread_cpu_ns();
  long switches = thread_switches();
  std::int64_t ref_cpu = thread_cpu_ns();  // its CPU time at ref_wall, after its last bookkeeping
  std::int64_t last = now();
  std::int64_t ref_wall = last;
  while (!stopping.load(std::memory_order_relaxed)) {
    const std::int64_t t = now();
    if (t - last <= gap_ns) {
      last = t;
      continue;
    }
    const long s = thread_switches();
    const std::int64_t cpu = thread_cpu_ns();
    const long long w = run_delay(schedstat);
    std::int64_t lost = 0;
    if (s == switches) {  // not switched out: no thread ran on this CPU in between
      lost = t - last;
    } else if (w >= 0 && waited >= 0) {
      // switched out: the gap less its CPU time in it (what it ran since ref_wall less the spinning before the gap) and
      // less the time it waited to run
      const std::int64_t ran = std::max<std::int64_t>(0, (cpu - ref_cpu) - (last - ref_wall));
      lost = std::min<std::int64_t>(t - last, (t - last) - ran - (w - waited));
      if (lost <= gap_ns) {
        lost = 0;
      }
    }
    if (lost > 0) {
      if (c->gap_count < c->gaps.size()) {
        c->gaps[c->gap_count++] = Record{last, last + lost};
      } else {
        c->gap_overflow = true;
      }
    }
    switches = s;
    waited = w;
    ref_cpu = thread_cpu_ns();
    last = now();  // its own bookkeeping is not a gap
    ref_wall = last;
  }
  c->spun_ns = thread_cpu_ns() - cpu_start;
  if (schedstat >= 0) {
    close(schedstat);
  }
}

void watch(Cpu* c, std::int64_t start, std::atomic<int>* ready) {
  const int top = sched_get_priority_max(SCHED_FIFO);
  c->sched = place(c->cpu, SCHED_FIFO, top, "SCHED_FIFO " + std::to_string(top));
  ready->fetch_add(1);
  std::int64_t nominal = start;
  std::int64_t next_hiccup = start + hiccup_every_ns;
  while (!stopping.load(std::memory_order_relaxed)) {
    const timespec wake = at(nominal);
    while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &wake, nullptr) == EINTR) {
    }
    if (hiccup_ns > 0 && nominal >= next_hiccup) {
      next_hiccup += hiccup_every_ns;
      const std::int64_t until = now() + hiccup_ns;
      while (now() < until) {
      }
    }
    const std::int64_t end = now();
    if (c->count < c->records.size()) {
      c->records[c->count++] = Record{nominal, end};
    } else {
      c->overflow = true;
    }
    nominal += period_ns;
    if (nominal <= end) {  // late by a whole period or more: the record above covers what was lost
      nominal += ((end - nominal) / period_ns + 1) * period_ns;
    }
  }
}

std::int64_t option(int argc, char** argv, const char* name, std::int64_t fallback) {
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::strcmp(argv[i], name) == 0) {
      return std::strtoll(argv[i + 1], nullptr, 10);
    }
  }
  return fallback;
}

}  // namespace

int main(int argc, char** argv) {
  const char* out = nullptr;
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::strcmp(argv[i], "--out") == 0) {
      out = argv[i + 1];
    }
  }
  if (out == nullptr) {
    std::fprintf(stderr, "usage: %s --out FILE [--period-us 1000] [--max-ms 600000] [--run-for-ms N] [--gap-ns 2000] [--no-spin] [--hiccup-ms H --hiccup-every-ms E]\n",
                 argv[0]);
    return 2;
  }
  period_ns = option(argc, argv, "--period-us", 1000) * 1000;
  const std::int64_t max_ms = option(argc, argv, "--max-ms", 600000);
  const std::int64_t run_for_ms = option(argc, argv, "--run-for-ms", 0);
  hiccup_ns = option(argc, argv, "--hiccup-ms", 0) * 1000000;
  hiccup_every_ns = option(argc, argv, "--hiccup-every-ms", 200) * 1000000;
  gap_ns = option(argc, argv, "--gap-ns", 2000);
  bool spinners = true;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--no-spin") == 0) {
      spinners = false;
    }
  }
  if (period_ns <= 0 || max_ms <= 0 || hiccup_every_ns <= 0 || gap_ns <= 0) {
    std::fprintf(stderr, "rsaml-platform-monitor: the period, --max-ms, --gap-ns and --hiccup-every-ms must be positive\n");
    return 2;
  }

  // SIGTERM and SIGINT are taken by the main thread alone, with sigwait; the watchers never see them.
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGTERM);
  sigaddset(&signals, SIGINT);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);
  // Never outlive the test that started it: a monitor left running at the top priority on every CPU would take
  // time from every later run. Its parent's death sends SIGTERM (taken as a stop); a parent already gone stops it now.
  const pid_t parent = getppid();
  if (prctl(PR_SET_PDEATHSIG, SIGTERM) != 0 || getppid() != parent) {
    std::fprintf(stderr, "rsaml-platform-monitor: its parent is gone (or cannot be watched): not started\n");
    return 1;
  }

  cpu_set_t allowed;
  CPU_ZERO(&allowed);
  if (sched_getaffinity(0, sizeof allowed, &allowed) != 0) {
    std::perror("rsaml-platform-monitor: sched_getaffinity");
    return 1;
  }
  std::vector<Cpu> cpus;
  for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu) {
    if (CPU_ISSET(cpu, &allowed)) {
      Cpu c;
      c.cpu = cpu;
      c.records.assign(static_cast<std::size_t>(max_ms * 1000000 / period_ns + 16), Record{0, 0});  // written: in memory now
      if (spinners) {
        c.gaps.assign(static_cast<std::size_t>(max_ms * 4 + 16), Record{0, 0});  // 4 a millisecond (about 1 is seen)
      }
      cpus.push_back(std::move(c));
    }
  }
  const bool locked = mlockall(MCL_CURRENT | MCL_FUTURE) == 0;

  std::atomic<int> ready{0};
  const std::int64_t start = (now() / period_ns + 2) * period_ns;
  std::vector<std::thread> threads;
  for (Cpu& c : cpus) {
    threads.emplace_back(watch, &c, start, &ready);
    if (spinners) {
      threads.emplace_back(spin, &c, &ready);
    }
  }
  while (ready.load() < static_cast<int>(cpus.size() * (spinners ? 2 : 1))) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  std::printf("ready %zu cpus period %lld ns priority %d min %d memory %s%s\n", cpus.size(), static_cast<long long>(period_ns),
              sched_get_priority_max(SCHED_FIFO), sched_get_priority_min(SCHED_FIFO), locked ? "locked" : "not locked",
              spinners ? " spinners" : "");
  std::fflush(stdout);

  // Until SIGTERM or SIGINT, and never longer than --run-for-ms or, without it, --max-ms (its records are full then).
  const timespec wait = at((run_for_ms > 0 ? run_for_ms : max_ms) * 1000000);
  while (sigtimedwait(&signals, nullptr, &wait) < 0 && errno == EINTR) {
  }
  stopping = true;
  for (std::thread& t : threads) {
    t.join();
  }

  std::FILE* f = std::fopen(out, "w");
  if (f == nullptr) {
    std::perror(out);
    return 1;
  }
  std::fprintf(f, "rsaml-platform-monitor period %lld ns priority %d min %d memory %s\n", static_cast<long long>(period_ns),
               sched_get_priority_max(SCHED_FIFO), sched_get_priority_min(SCHED_FIFO), locked ? "locked" : "not locked");
  for (const Cpu& c : cpus) {
    std::fprintf(f, "cpu %d records %zu%s sched %s\n", c.cpu, c.count, c.overflow ? " overflow" : "", c.sched.c_str());
    if (spinners) {
      std::fprintf(f, "spin %d gaps %zu%s over %lld ns ran %lld ns waits %s sched %s\n", c.cpu, c.gap_count, c.gap_overflow ? " overflow" : "",
                   static_cast<long long>(gap_ns), static_cast<long long>(c.spun_ns), c.waits_read ? "read" : "unread", c.spin_sched.c_str());
    }
  }
  for (const Cpu& c : cpus) {
    for (std::size_t i = 0; i < c.count; ++i) {
      std::fprintf(f, "%d %lld %lld\n", c.cpu, static_cast<long long>(c.records[i].nominal), static_cast<long long>(c.records[i].end));
    }
    for (std::size_t i = 0; i < c.gap_count; ++i) {
      std::fprintf(f, "gap %d %lld %lld\n", c.cpu, static_cast<long long>(c.gaps[i].nominal), static_cast<long long>(c.gaps[i].end));
    }
  }
  return std::fclose(f) == 0 ? 0 : 1;
}
