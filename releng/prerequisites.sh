#!/bin/sh
# SPDX-License-Identifier: EPL-2.0
# Run by the root pom before anything is built: the tests compile and run generated C++ (CMake, g++,
# make) and read ROS 2 package.xml files with Python's catkin_pkg. Say at once what is missing.
missing=""
for tool in cmake g++ make python3; do
  command -v "$tool" >/dev/null 2>&1 || missing="$missing $tool"
done
if command -v python3 >/dev/null 2>&1 && ! python3 -c 'import catkin_pkg' >/dev/null 2>&1; then
  missing="$missing catkin_pkg(Python)"
fi
if [ -n "$missing" ]; then
  echo "[ERROR] RsaML's tests need tools this machine lacks:$missing"
  echo "[ERROR] On Debian or Ubuntu: sudo apt-get install -y cmake g++ make python3 python3-catkin-pkg"
  echo "[ERROR] (elsewhere: pip install catkin_pkg for catkin_pkg). To build without the tests: ./mvnw install -DskipTests"
  exit 1
fi
