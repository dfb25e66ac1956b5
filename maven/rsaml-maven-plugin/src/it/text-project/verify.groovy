/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// A textual model is selected beside an XMI one; its finding names the .rsa file and the line of the connection.
def log = new File(basedir, 'build.log').text
assert log.contains('BUILD FAILURE')
assert log.contains("[ERROR] src/main/rsaml/robot.rsa:23:3: error RSA-02: Connection from output port 'lidarDriver.scan' (LaserScan) to entry port 'localCostmap.scan' (PointCloud2) joins different data types")
assert log.contains('RsaML validation failed: 2 files checked: 1 error, 0 warnings (fail on error)') : 'both clean.rsaml and robot.rsa are checked'
assert !log.contains('log4j:') : 'Xtext logging stays quiet'
assert !(log =~ /(?m)^\s+at [a-z]/) : 'no stack trace'
def sarif = new groovy.json.JsonSlurper().parse(new File(basedir, 'target/rsaml/rsaml.sarif'))
assert sarif.runs[0].results.size() == 1
def result = sarif.runs[0].results[0]
assert result.ruleId == 'RSA-02'
assert result.locations[0].physicalLocation.artifactLocation.uri == 'src/main/rsaml/robot.rsa'
assert result.locations[0].physicalLocation.region.startLine == 23
return true
