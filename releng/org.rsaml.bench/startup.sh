#!/usr/bin/env bash
# SPDX-License-Identifier: EPL-2.0
# Start-up benchmark of the rsaml command: whole processes, as CI runs them, timed by hyperfine
# (Debian package hyperfine). Run from anywhere; the jar is built first if it is missing. Prints wall and
# CPU times, each with its ratio to java -version's of the same JDK (on a shared machine the CPU ratio is the
# steadier one), and the load average before and after.
# The rows marked "resident process" run ./rsaml with RSAML_DAEMON=1, served by a resident process started before
# the runs (./rsaml daemon start, with the heap of one started by default: RSAML_DAEMON_HEAP=1g) and stopped after:
# their CPU is the client's process alone; the resident process's own CPU per command, read from /proc before and
# after the runs, is printed below each. The rows marked "at a terminal" run under util-linux script, which gives
# the command a terminal as when typed: there ./rsaml uses the resident process by default, and with CI=true a JVM
# of its own; their floor is java -version under script too (script's own cost is in both).
# Usage: releng/org.rsaml.bench/startup.sh [runs]
# RSAML_BENCH_JDKS: more JDKs (their homes, separated by spaces) to run ./rsaml with beside the java on the PATH,
# e.g. RSAML_BENCH_JDKS=/usr/lib/jvm/temurin-25-jdk-amd64 (./rsaml then uses that JDK's AOT cache).
# RSAML_BENCH_BASELINE: another tree with its jar built (e.g. a copy of main before a change, made by
# git worktree add and ./rsaml --version there): its ./rsaml validate runs beside this tree's, on each JDK, in the
# same hyperfine run, so that before and after are measured side by side; then the two again, with java -version,
# in interleaved rounds (hyperfine runs one command's runs after the other's, so a burst of load from elsewhere
# lands on one row; in rounds that each run the three in a new order it lands on all alike).
set -euo pipefail
cd "$(dirname "$0")/../.."
runs="${1:-20}"
command -v hyperfine >/dev/null || { echo "startup.sh: needs hyperfine (apt-get install hyperfine)" >&2; exit 2; }
[ -f cli/org.rsaml.cli/target/rsaml.jar ] || ./mvnw -q -B -DskipTests -pl cli/org.rsaml.cli -am package
model=examples/exp2-defects.rsaml
# Each JDK's class data is made once (or again, if it no longer fits) before anything is timed.
./rsaml validate "$model" >/dev/null || true
baseline="${RSAML_BENCH_BASELINE:-}"
if [ -n "$baseline" ]; then
  [ -x "$baseline/rsaml" ] && [ -f "$baseline/cli/org.rsaml.cli/target/rsaml.jar" ] ||
    { echo "startup.sh: RSAML_BENCH_BASELINE=$baseline has no rsaml launcher and built jar" >&2; exit 2; }
  baseline="$(cd "$baseline" && pwd)"
  "$baseline/rsaml" validate "$model" >/dev/null || true
fi
# resident JDK_HOME: starts the resident process of that JDK (or of the java on the PATH) and prints its process id.
resident() {
  local status
  status="$(env ${1:+JAVA_HOME=$1} RSAML_DAEMON_HEAP=1g ./rsaml daemon start)"
  [[ "$status" =~ resident\ process\ ([0-9]+)\ running ]] || { echo "startup.sh: no resident process: $status" >&2; exit 2; }
  echo "${BASH_REMATCH[1]}"
}
# cpu PID: the process's CPU time so far (user + system), in clock ticks.
cpu() { awk '{ print $14 + $15 }' "/proc/$1/stat"; }
pid="$(resident '')"   # an assignment: a failed start stops the script (set -e)
residents=("$pid")
trap 'for jdk in "" ${RSAML_BENCH_JDKS:-}; do env ${jdk:+JAVA_HOME=$jdk} ./rsaml daemon stop >/dev/null || true; done' EXIT
commands=(-n 'java -version (the floor)' 'java -version'
  -n './rsaml validate' "./rsaml validate $model"
  -n './rsaml validate, resident process' "env RSAML_DAEMON=1 ./rsaml validate $model"
  -n 'java -jar rsaml.jar validate (no tuning)' "java -jar cli/org.rsaml.cli/target/rsaml.jar validate $model"
  -n './rsaml --version' './rsaml --version')
[ -z "$baseline" ] || commands+=(-n 'baseline: ./rsaml validate' "$baseline/rsaml validate $model")
# terminal [JDK_HOME] [SUFFIX]: the rows at a terminal, after the others of their JDK (their own floor first).
terminal() {
  local env="env${1:+ JAVA_HOME=$1}"
  commands+=(-n "java -version at a terminal (the floor of the terminal rows)$2" "script -qec '${1:+$1/bin/}java -version' /dev/null"
    -n "./rsaml validate at a terminal (by default: resident process)$2" "script -qec '$env ./rsaml validate $model' /dev/null"
    -n "./rsaml validate at a terminal, CI=true (a JVM of its own)$2" "script -qec '$env CI=true ./rsaml validate $model' /dev/null")
}
terminal "" ""
for jdk in ${RSAML_BENCH_JDKS:-}; do
  JAVA_HOME="$jdk" ./rsaml validate "$model" >/dev/null || true
  v="$(sed -n 's/^JAVA_VERSION="\([0-9]*\).*/\1/p' "$jdk/release" 2>/dev/null)"
  commands+=(-n "java -version (the floor), Java ${v:-?}" "$jdk/bin/java -version"
    -n "./rsaml validate, Java ${v:-?}" "env JAVA_HOME=$jdk ./rsaml validate $model"
    -n "./rsaml validate, resident process, Java ${v:-?}" "env JAVA_HOME=$jdk RSAML_DAEMON=1 ./rsaml validate $model")
  pid="$(resident "$jdk")"
  residents+=("$pid")
  if [ -n "$baseline" ]; then
    JAVA_HOME="$jdk" "$baseline/rsaml" validate "$model" >/dev/null || true
    commands+=(-n "baseline: ./rsaml validate, Java ${v:-?}" "env JAVA_HOME=$jdk $baseline/rsaml validate $model")
  fi
  terminal "$jdk" ", Java ${v:-?}"
done
out="$(mktemp)"
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo '?')"
before=(); for pid in "${residents[@]}"; do before+=("$(cpu "$pid")"); done
hyperfine -N -i --warmup 3 --runs "$runs" --export-json "$out" "${commands[@]}"
served=""
for i in "${!residents[@]}"; do served+=" $(( $(cpu "${residents[$i]}") - ${before[$i]} ))"; done
python3 - "$out" "$((runs + 3))" "$(getconf CLK_TCK)" $served <<'PY'
import json, sys
results = json.load(open(sys.argv[1]))["results"]
commands, tick, served = int(sys.argv[2]), int(sys.argv[3]), [int(t) for t in sys.argv[4:]]
# Each JDK's resident process serves two rows (RSAML_DAEMON=1, and at a terminal by default): its CPU is shared out.
rows = sum("resident process" in r["command"] for r in results)
per = rows // max(len(served), 1) or 1
seen = 0
print("| command | median (wall) | ÷ java -version | CPU (user + system, mean) | ÷ java -version | mean ± σ | min | max |")
print("|---|---:|---:|---:|---:|---:|---:|---:|")
for r in results:
    if r["command"].startswith("java -version"):
        floor, cpu_floor = r["median"], r["user"] + r["system"]   # the floor of the rows that follow (same JDK)
    ms = lambda v: f"{v * 1000:,.0f} ms"
    cpu = r["user"] + r["system"]
    print(f"| {r['command']} | {ms(r['median'])} | {r['median'] / floor:.1f}× | {ms(cpu)} | {cpu / cpu_floor:.1f}× "
          f"| {ms(r['mean'])} ± {r['stddev'] * 1000:,.0f} | {ms(r['min'])} | {ms(r['max'])} |")
    if "resident process" in r["command"]:
        server = served[seen // per] / tick / (commands * per)   # the resident process's CPU per command, not in the row
        seen += 1
        print(f"| … its resident process's own CPU per command (not in the row above), and the two together "
              f"| | | {ms(server)} | {server / cpu_floor:.1f}× | {ms(cpu + server)}: {(cpu + server) / cpu_floor:.1f}× | | |")
PY
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo '?')"
rm -f "$out"
[ -n "$baseline" ] || exit 0
echo "Interleaved: $runs rounds of java -version, the baseline's and this tree's ./rsaml validate, per JDK"
python3 - "$runs" "$model" "$baseline" ${RSAML_BENCH_JDKS:-} <<'PY'
import os, random, statistics, subprocess, sys, time
runs, model, baseline, jdks = int(sys.argv[1]), sys.argv[2], sys.argv[3], sys.argv[4:]

def run(command, env):
    """Wall and CPU time (user + system) of one run, and what it did: its exit status and output."""
    with open(os.devnull, "w") as null:
        start = time.perf_counter()
        process = subprocess.Popen(command, env=env, stdout=subprocess.PIPE, stderr=null)
        output = process.stdout.read()
        status, usage = os.wait4(process.pid, 0)[1:]
        wall = time.perf_counter() - start
    return (wall, usage.ru_utime + usage.ru_stime), (os.waitstatus_to_exitcode(status), output)

print("| JDK | command | median (wall) | ÷ java -version | CPU (user + system, mean) | ÷ java -version | load before → after |")
print("|---|---|---:|---:|---:|---:|---|")
for jdk in [None] + jdks:
    env = dict(os.environ)
    env.pop("JAVA_HOME", None)
    if jdk:
        env["JAVA_HOME"] = jdk
    commands = {"java -version": [os.path.join(jdk, "bin", "java") if jdk else "java", "-version"],
                "baseline: ./rsaml validate": [os.path.join(baseline, "rsaml"), "validate", model],
                "./rsaml validate": ["./rsaml", "validate", model]}
    times = {name: [] for name in commands}
    expected = {name: run(command, env)[1] for name, command in commands.items()}   # a warm-up run each
    load = open("/proc/loadavg").read().split()[0]
    for _ in range(runs):
        names = list(commands)
        random.shuffle(names)
        for name in names:
            measured, outcome = run(commands[name], env)
            if outcome != expected[name]:
                sys.exit(f"startup.sh: '{name}' ({jdk or 'java on the PATH'}) exited {outcome[0]} with other output "
                         f"than its warm-up run (exit {expected[name][0]}): a timed run must do what the warm-up did")
            times[name].append(measured)
    load += " → " + open("/proc/loadavg").read().split()[0]
    wall = {name: statistics.median(w for w, _ in t) for name, t in times.items()}
    cpu = {name: statistics.mean(c for _, c in t) for name, t in times.items()}
    for name in commands:
        print(f"| {os.path.basename(jdk) if jdk else 'java on the PATH'} | {name} | {wall[name] * 1000:,.0f} ms "
              f"| {wall[name] / wall['java -version']:.1f}× | {cpu[name] * 1000:,.0f} ms | {cpu[name] / cpu['java -version']:.1f}× | {load} |")
PY
