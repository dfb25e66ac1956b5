#!/usr/bin/env bash
# SPDX-License-Identifier: EPL-2.0
# Start-up benchmark of the rsaml command: whole processes, as CI runs them, timed by hyperfine
# (Debian package hyperfine). Run from anywhere; the jar is built first if it is missing. Prints wall and
# CPU times, each with its ratio to java -version's (on a shared machine the CPU ratio is the steadier one).
# Usage: releng/org.rsaml.bench/startup.sh [runs]
set -euo pipefail
cd "$(dirname "$0")/../.."
runs="${1:-20}"
command -v hyperfine >/dev/null || { echo "startup.sh: needs hyperfine (apt-get install hyperfine)" >&2; exit 2; }
[ -f cli/org.rsaml.cli/target/rsaml.jar ] || ./mvnw -q -B -DskipTests -pl cli/org.rsaml.cli -am package
./rsaml validate examples/exp2-defects.rsaml >/dev/null || true   # makes the class-data archive once (or again, if it no longer fits)
model=examples/exp2-defects.rsaml
out="$(mktemp)"
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo '?')"
hyperfine -N -i --warmup 3 --runs "$runs" --export-json "$out" \
  -n 'java -version (the floor)' 'java -version' \
  -n './rsaml validate (launcher: CDS archive, C1 alone for small inputs, serial GC)' "./rsaml validate $model" \
  -n 'java -jar rsaml.jar validate (no tuning)' "java -jar cli/org.rsaml.cli/target/rsaml.jar validate $model" \
  -n './rsaml --version' './rsaml --version'
python3 - "$out" <<'PY'
import json, sys
results = json.load(open(sys.argv[1]))["results"]
floor = results[0]["median"]
print("| command | median (wall) | ÷ java -version | CPU (user + system, mean) | ÷ java -version | mean ± σ | min | max |")
print("|---|---:|---:|---:|---:|---:|---:|---:|")
cpu_floor = results[0]["user"] + results[0]["system"]
for r in results:
    ms = lambda v: f"{v * 1000:,.0f} ms"
    cpu = r["user"] + r["system"]
    print(f"| {r['command']} | {ms(r['median'])} | {r['median'] / floor:.1f}× | {ms(cpu)} | {cpu / cpu_floor:.1f}× "
          f"| {ms(r['mean'])} ± {r['stddev'] * 1000:,.0f} | {ms(r['min'])} | {ms(r['max'])} |")
PY
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo '?')"
rm -f "$out"
