/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// The command line of a generated program.
#include "rsaml/options.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace rsaml {

namespace {

// The longest run the clock arithmetic can hold without overflow: 2^60 ns (about 36 years), as
// the generator's limit for modeled times.
constexpr long long kMaxRunMs = (1LL << 60) / 1000000;

void usage(std::FILE* out, const char* program) {
  std::fprintf(out,
               "Usage: %s [--run-for-ms N] [--quiet] [--no-realtime] [--busy-work PERCENT]\n"
               "  --run-for-ms N        stop after N milliseconds (default: run until interrupted)\n"
               "  --quiet               no trace of releases and data flow (misses, overruns and the\n"
               "                        summary are still reported)\n"
               "  --no-realtime         do not ask for real-time priorities\n"
               "  --busy-work PERCENT   each timed job first consumes PERCENT %% of its modeled execution\n"
               "                        time on the CPU, standing in for user code (100: as modeled)\n",
               program);
}

}  // namespace

Options parse_options(int argc, char** argv, const char* program) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--run-for-ms" && i + 1 < argc) {
      char* end = nullptr;
      errno = 0;
      const long long value = std::strtoll(argv[++i], &end, 10);
      if (end == argv[i] || *end != '\0' || errno == ERANGE || value < 0 || value > kMaxRunMs) {
        std::fprintf(stderr, "%s: --run-for-ms needs a number of milliseconds from 0 to %lld, not '%s'\n", program, kMaxRunMs,
                     argv[i]);
        options.exit = true;
        options.status = 2;
        return options;
      }
      options.run_for_ms = value;
    } else if (arg == "--quiet") {
      options.trace = false;
    } else if (arg == "--no-realtime") {
      options.realtime = false;
    } else if (arg == "--busy-work" && i + 1 < argc) {
      char* end = nullptr;
      errno = 0;
      const long long value = std::strtoll(argv[++i], &end, 10);
      if (end == argv[i] || *end != '\0' || errno == ERANGE || value < 0 || value > 1000) {
        std::fprintf(stderr, "%s: --busy-work needs a percentage of the modeled execution time from 0 to 1000, not '%s'\n",
                     program, argv[i]);
        options.exit = true;
        options.status = 2;
        return options;
      }
      options.busy_work_percent = value;
    } else if (arg == "--help" || arg == "-h") {
      usage(stdout, program);
      options.exit = true;
      return options;
    } else {
      std::fprintf(stderr, "%s: unknown argument '%s'\n", program, arg.c_str());
      usage(stderr, program);
      options.exit = true;
      options.status = 2;
      return options;
    }
  }
  return options;
}

}  // namespace rsaml
