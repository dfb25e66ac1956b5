#!/bin/sh
# SPDX-License-Identifier: EPL-2.0
# Run by the root pom before anything is built: the tests need the tools of releng/prerequisites.txt
# (cmake, g++, ... for the generated code). Say at once what is missing and how to install it.
# With --missing: print only the missing Debian/Ubuntu packages, one a line (.ci/run installs them).
list="$(dirname "$0")/prerequisites.txt"
# The Python with Debian's packages (python3-catkin-pkg, python3-rosidl); the checks use it, not the PATH's python3.
RSAML_PYTHON=${RSAML_PYTHON:-/usr/bin/python3}
export RSAML_PYTHON
missing=""
reasons=""
all=""
while IFS='|' read -r package check why; do
  package=$(echo "$package" | tr -d ' ')
  case "$package" in ''|'#'*) continue ;; esac
  all="$all $package"
  if ! sh -c "$check" >/dev/null 2>&1; then
    missing="$missing $package"
    reasons="$reasons
[ERROR]   $package ($(echo "$why" | sed 's/^ *//; s/ *$//'))"
  fi
done < "$list"
if [ "$1" = "--missing" ]; then
  for package in $missing; do echo "$package"; done
  exit 0
fi
if [ -n "$missing" ]; then
  echo "[ERROR] RsaML's tests need tools this machine lacks:$reasons"
  echo "[ERROR] On Debian or Ubuntu: sudo apt-get install -y$all"
  echo "[ERROR] (catkin_pkg elsewhere: $RSAML_PYTHON -m pip install catkin_pkg, or -Drsaml.python=<a python3 that has it>). To build without the tests: ./mvnw install -DskipTests"
  exit 1
fi
