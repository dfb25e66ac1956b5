/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// What the runtime's sources share and generated code does not use: the thread's CPU time, busy
// work, durations as the trace says them. Not included by rsaml/runtime.hpp.
#pragma once

#include <cstdint>
#include <string>

#include "rsaml/clock.hpp"

namespace rsaml {

namespace internal {

/** The calling thread's CPU time. */
Nanos thread_cpu_time();

/**
 * The stall of a job that took the module's lock at `locked` with the thread's CPU time at `cpu`:
 * its wall time since then, minus the CPU time it used and `waited` (lock given up for actions'
 * start dates): the time it was ready and not running. Never negative.
 */
Nanos stall_since(Clock::time_point locked, Nanos cpu, Nanos waited);

/** The calling thread's context switches so far, voluntary and involuntary (0 where the platform does not say). */
long thread_switches();

/** Consumes CPU time on the calling thread: busy work standing in for user code. */
void consume(Nanos amount);

/**
 * How many times the kernel has signalled (SIGXCPU, SCHED_FLAG_DL_OVERRUN) that the calling deadline thread's runtime
 * ran out; 0 on a thread that is not one.
 */
unsigned long deadline_overruns();

/** Installs the handler that counts those signals, and blocks them on the calling thread (and the threads it starts). */
void count_deadline_overruns();

/**
 * The line that says a module's full mailbox dropped messages, worded here once: `dropped` of them since it last said so
 * (`in_all` so far), said by its worker when it takes its next message; or, `closing`, all of them (`in_all`), said
 * after the summary.
 */
std::string mailbox_dropped(const std::string& module, std::uint64_t dropped, std::uint64_t in_all, bool closing);

/** A duration as the trace says it: 1.250 ms. */
std::string millis(Nanos t);

}  // namespace internal

}  // namespace rsaml
