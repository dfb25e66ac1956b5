/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// What the runtime's sources share and generated code does not use: the thread's CPU time, busy
// work, durations as the trace says them. Not included by rsaml/runtime.hpp.
#pragma once

#include <string>

#include "rsaml/clock.hpp"

namespace rsaml {

namespace internal {

/** The calling thread's CPU time. */
Nanos thread_cpu_time();

/** Consumes CPU time on the calling thread: busy work standing in for user code. */
void consume(Nanos amount);

/** A duration as the trace says it: 1.250 ms. */
std::string millis(Nanos t);

}  // namespace internal

}  // namespace rsaml
