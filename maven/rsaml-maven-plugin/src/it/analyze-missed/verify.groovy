/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// A latency requirement that can be missed fails the build; the log shows the verdict and the worst path.
def log = new File(basedir, 'build.log').text
assert log.contains('BUILD FAILURE')
assert log.contains("[ERROR]   verdict: MISSES: the worst-case reaction time can reach 57 ms, more than 50 ms")
assert log.contains("navigation/obstacleDetector: +44 ms (wait 40 ms + response 4 ms)")
assert log.contains('RsaML timing: a deadline or a latency requirement can be missed in src/main/rsaml/base.rsaml')
return true
