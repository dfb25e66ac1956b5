/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// A model with errors is refused: the finding is logged, the build fails, nothing is generated.
def log = new File(basedir, 'build.log').text
assert log.contains('BUILD FAILURE')
assert log.contains("[ERROR] model/rover.rsaml:8:5: error RSA-08: Module 'planner' takes 20.0 ms but layer 'decision' allows at most 2.0 ms")
assert log.contains('RsaML generation refused: model/rover.rsaml has 1 error finding; fix them or set force')
assert !new File(basedir, 'rover-cpp').exists()
return true
