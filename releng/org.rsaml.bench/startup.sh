#!/usr/bin/env bash
# Start-up benchmark of the rsaml command: whole processes, as CI runs them, timed by hyperfine
# (Debian package hyperfine). Run from anywhere; the jar is built first if it is missing.
# Usage: releng/org.rsaml.bench/startup.sh [runs]
set -euo pipefail
cd "$(dirname "$0")/../.."
runs="${1:-20}"
command -v hyperfine >/dev/null || { echo "startup.sh: needs hyperfine (apt-get install hyperfine)" >&2; exit 2; }
[ -f bundles/org.rsaml.cli/target/rsaml.jar ] || ./mvnw -q -B -DskipTests -pl bundles/org.rsaml.cli -am package
./rsaml validate examples/exp2-defects.rsaml >/dev/null || true   # makes the class-data archive once
model=examples/exp2-defects.rsaml
hyperfine -N -i --warmup 3 --runs "$runs" --export-markdown target-startup.md \
  -n 'java -version (the floor)' 'java -version' \
  -n './rsaml validate (launcher: CDS archive, C1, serial GC)' "./rsaml validate $model" \
  -n 'java -jar rsaml.jar validate (no tuning)' "java -jar bundles/org.rsaml.cli/target/rsaml.jar validate $model" \
  -n './rsaml --version' './rsaml --version'
cat target-startup.md && rm -f target-startup.md
