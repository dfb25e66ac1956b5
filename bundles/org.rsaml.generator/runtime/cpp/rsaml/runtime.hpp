/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// RsaML's runtime for generated architectures: timed releases, data flow between modules,
// inhibitors and suppressors, and a trace of the run on standard output. Generated code includes
// this header alone; each part of the runtime has a header of its own:
//   clock.hpp     the clock and its durations
//   options.hpp   the command line of a generated program
//   trace.hpp     the run's trace on standard output
//   measure.hpp   what each job is measured against, and what was measured
//   module.hpp    the base of every module class, its activations and reactions
//   ports.hpp     output and entry ports, inhibitors and suppressors
//   system.hpp    the running architecture: timed releases, scheduling, the start and the stop
#pragma once

#include "rsaml/clock.hpp"
#include "rsaml/measure.hpp"
#include "rsaml/module.hpp"
#include "rsaml/options.hpp"
#include "rsaml/ports.hpp"
#include "rsaml/system.hpp"
#include "rsaml/trace.hpp"
