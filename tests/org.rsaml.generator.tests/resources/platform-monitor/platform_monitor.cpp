/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// The platform monitor of the timing tests (docs/timing.md, "The platform's allowance").
//
// One thread per CPU this process may use, pinned to it, under SCHED_FIFO at the highest priority,
// above every thread of a generated program (their ranks map to the lowest priorities). Each wakes
// every period on an absolute CLOCK_MONOTONIC time and records its nominal wake-up and the moment
// it finished recording: in between the CPU ran something other than the measured program (the
// kernel, the hypervisor, another program, or the monitor itself). On SIGTERM or SIGINT (or after
// --run-for-ms) the records are written to the output file.
//
//   rsaml-platform-monitor --out FILE [--period-us 1000] [--max-ms 600000] [--run-for-ms N]
//                          [--hiccup-ms H --hiccup-every-ms E]
//
// --hiccup-ms makes each thread busy-loop H ms every E ms inside its record: a synthetic platform
// delay, for the test that checks the loss is found and counted.
#include <pthread.h>
#include <sched.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <time.h>
#include <unistd.h>

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
};

std::atomic<bool> stopping{false};
std::int64_t period_ns = 1000000;
std::int64_t hiccup_ns = 0;
std::int64_t hiccup_every_ns = 0;

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

void watch(Cpu* c, std::int64_t start, std::atomic<int>* ready) {
  cpu_set_t set;
  CPU_ZERO(&set);
  CPU_SET(c->cpu, &set);
  const int pinned = pthread_setaffinity_np(pthread_self(), sizeof set, &set);
  sched_param param{};
  param.sched_priority = sched_get_priority_max(SCHED_FIFO);
  const int error = pthread_setschedparam(pthread_self(), SCHED_FIFO, &param);
  if (pinned != 0) {
    c->sched = std::string("default: not pinned (") + std::strerror(pinned) + ")";
  } else if (error != 0) {
    c->sched = std::string("default: SCHED_FIFO not permitted (") + std::strerror(error) + ")";
  } else {
    c->sched = "SCHED_FIFO " + std::to_string(param.sched_priority);
  }
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
    std::fprintf(stderr, "usage: %s --out FILE [--period-us 1000] [--max-ms 600000] [--run-for-ms N] [--hiccup-ms H --hiccup-every-ms E]\n",
                 argv[0]);
    return 2;
  }
  period_ns = option(argc, argv, "--period-us", 1000) * 1000;
  const std::int64_t max_ms = option(argc, argv, "--max-ms", 600000);
  const std::int64_t run_for_ms = option(argc, argv, "--run-for-ms", 0);
  hiccup_ns = option(argc, argv, "--hiccup-ms", 0) * 1000000;
  hiccup_every_ns = option(argc, argv, "--hiccup-every-ms", 200) * 1000000;
  if (period_ns <= 0 || max_ms <= 0 || hiccup_every_ns <= 0) {
    std::fprintf(stderr, "rsaml-platform-monitor: the period, --max-ms and --hiccup-every-ms must be positive\n");
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
      cpus.push_back(std::move(c));
    }
  }
  const bool locked = mlockall(MCL_CURRENT | MCL_FUTURE) == 0;

  std::atomic<int> ready{0};
  const std::int64_t start = (now() / period_ns + 2) * period_ns;
  std::vector<std::thread> threads;
  for (Cpu& c : cpus) {
    threads.emplace_back(watch, &c, start, &ready);
  }
  while (ready.load() < static_cast<int>(cpus.size())) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  std::printf("ready %zu cpus period %lld ns priority %d min %d memory %s\n", cpus.size(), static_cast<long long>(period_ns),
              sched_get_priority_max(SCHED_FIFO), sched_get_priority_min(SCHED_FIFO), locked ? "locked" : "not locked");
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
  }
  for (const Cpu& c : cpus) {
    for (std::size_t i = 0; i < c.count; ++i) {
      std::fprintf(f, "%d %lld %lld\n", c.cpu, static_cast<long long>(c.records[i].nominal), static_cast<long long>(c.records[i].end));
    }
  }
  return std::fclose(f) == 0 ? 0 : 1;
}
