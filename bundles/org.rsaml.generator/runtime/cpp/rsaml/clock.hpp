/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// The clock every time of the runtime is read on.
#pragma once

#include <chrono>

namespace rsaml {

using Clock = std::chrono::steady_clock;
using Nanos = std::chrono::nanoseconds;

}  // namespace rsaml
