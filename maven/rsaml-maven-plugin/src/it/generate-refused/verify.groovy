/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// A model with errors is refused: the finding is logged, the build fails, nothing is generated.
def log = new File(basedir, 'build.log').text
assert log.contains('BUILD FAILURE')
assert log.contains("[ERROR] model/rover.rsaml:8:5: error RSA-08: Module 'planner' takes 20.0 ms but layer 'decision' allows at most 2.0 ms")
assert log.contains('RsaML: model/rover.rsaml: error: generation refused: the model has 1 error finding; fix it or set force')
assert !new File(basedir, 'rover-cpp').exists()
return true
