#!/usr/bin/env bash
# make test and make check: every phase timed, the slowest tests named, the summary line last.
# Usage: scripts/test_all.sh [--check]     (run by make, which exports ASV_CATKIN, JOBS and ASAN)
#   make test:  setup, build, test build, unit tests, rostests (with the ASan+UBSan unit tests and the fuzz
#               smoke runs beside them at idle priority), checks (clang-format, the layering allow-list, clang-tidy, catkin_lint, README, plots,
#               papers, install space)
#   make check: build, test build and the unit tests alone (the inner loop: no master, no ASan)
# Independent test executables run JOBS at a time under ctest (each writes its own JUnit XML and a
# rostest starts its own master on a free port). The last line is scripts/test_summary.py's
# `N passed, N failed, N skipped`; exit status 1 when anything failed.
set -uo pipefail
cd "$(dirname "$0")/.."
: "${ASV_CATKIN:?run through make test or make check (the Makefile sets ASV_CATKIN)}"
JOBS=${JOBS:-2}
ASAN=${ASAN:-1}
mode=test
[ "${1:-}" = "--check" ] && mode=check
logs=build/test_logs
results=build/test_results

phase_names=()
phase_secs=()
# phase NAME COMMAND...: runs the command, records its wall time; returns the command's status.
phase() {
  local name=$1 t0=$SECONDS rc
  shift
  echo "== $name"
  "$@"
  rc=$?
  phase_names+=("$name")
  phase_secs+=($((SECONDS - t0)))
  return $rc
}

build_tests() { eval "$ASV_CATKIN -j$JOBS tests"; }

# ctest_group NAME REGEX: the catkin tests whose ctest name matches, JOBS at a time; the log keeps each
# test's time (Test #n: name ... sec) and the output of the failures. scripts/ctest_resources.json:
# 4 slots of `load`, which a whole-pipeline rostest (2) and a test timed in wall seconds (3) ask for
# (asv_bringup/CMakeLists.txt), so a timed test only ever runs beside a single node's test.
ctest_group() {
  local name=$1 regex=$2
  ctest --test-dir build -j"$JOBS" -R "$regex" --timeout 1800 --output-on-failure \
    --resource-spec-file "$PWD/scripts/ctest_resources.json" > "$logs/$name.log" 2>&1
  grep -E "tests passed|tests failed" "$logs/$name.log"
  grep -E "\*\*\*|Failed|Timeout" "$logs/$name.log" | grep -E "^ *[0-9]+/[0-9]+ Test" || true
  return 0
}

checks() {
  scripts/format_check.py "$results/format_check.xml" || true
  scripts/layers_check.py "$results/layers_check.xml" || true
  JOBS=$JOBS scripts/lint_check.py "$results/lint_check.xml" || true
  scripts/catkin_lint_check.py "$results/catkin_lint.xml" || true
  (source devel/setup.bash && scripts/readme_check.py "$results/readme_check.xml") || true
  scripts/plot_check.py "$results/plot_check.xml" || true
  scripts/real_traffic_check.py "$results/real_traffic_check.xml" || true
  (source devel/setup.bash && scripts/papers_check.py "$results/papers_check.xml") || true
  JOBS=$JOBS scripts/install_check.py "$results/install_check.xml" || true
}

asan() {
  echo "asv_core unit tests under ASan+UBSan (build_asan/, log $logs/asan.log)"
  JOBS=$JOBS scripts/asan_tests.sh > "$logs/asan.log" 2>&1
  local rc=$?
  grep -E "FAILED|MISSING|executables" "$logs/asan.log"
  [ "$rc" -gt 128 ] && junit_failure asan "asan_tests.sh killed by signal $((rc - 128)), see $logs/asan.log"
  return 0
}

# junit_failure NAME MESSAGE: one failed case in $results/NAME-died.xml (a run that left no results).
junit_failure() {
  printf '<?xml version="1.0"?>\n<testsuite name="%s" tests="1" failures="1"><testcase classname="%s" name="%s"><failure message="%s"/></testcase></testsuite>\n' \
    "$1" "$1" "$1" "$2" > "$results/$1-died.xml"
}

# beside: the ASan+UBSan unit tests and the fuzz smoke runs, started with the rostests and run under
# SCHED_IDLE (nice 19 where chrt is refused). A lockstep pipeline leaves about a quarter of the cores
# idle while its nodes wait on each other's messages, and a test timed in wall seconds runs beside
# single-node tests only, so one core idles for minutes: the sanitized tests take that time, and lose
# the core at once whenever a ROS node wakes (an idle-class task never delays a normal one). A starved
# run is only slower: the fuzz runs a fixed number of executions, and the planner tests plan to
# completion (a budget no run reaches), so no wall-clock deadline changes a result. Their output goes
# to $logs/beside.out, their phase times to $logs/beside.times. It runs in a process group of its own,
# killed when make test stops early; when it dies, a failure is recorded.
beside() {
  chrt -i -p 0 "$BASHPID" > /dev/null 2>&1 || renice -n 19 -p "$BASHPID" > /dev/null
  local t0
  if [ "$ASAN" = 1 ]; then
    t0=$SECONDS; asan; echo "ASan+UBSan $((SECONDS - t0))" >> "$logs/beside.times"
  fi
  t0=$SECONDS; FUZZ_MAX_SECS=1500 FUZZ_INPUT_TIMEOUT=60 scripts/fuzz_smoke.sh; echo "fuzz $((SECONDS - t0))" >> "$logs/beside.times"
}

# The slowest tests of every ctest log, for the table below.
slowest() {
  cat "$logs"/unit.log "$logs"/rostest.log 2>/dev/null \
    | sed -nE 's/^ *[0-9]+\/[0-9]+ Test +#[0-9]+: _ctest_([a-z_]+)_(gtest|rostest)_([^ ]+) .* ([0-9.]+) sec$/\4 \1 \3/p' \
    | sort -rn | head -"$1"
}

mkdir -p "$logs"
rm -f "$logs"/*.log "$logs"/beside.*
if [ "$mode" = test ]; then
  phase setup scripts/setup || exit 1
fi
phase build make --no-print-directory build-nosetup || { echo "0 passed, 1 failed (the build)"; exit 1; }
phase "test build" build_tests || { echo "0 passed, 1 failed (the test build)"; exit 1; }
rm -rf "$results"
mkdir -p "$results"
phase "unit tests" ctest_group unit "_gtest_"
if [ "$mode" = test ]; then
  set -m  # its own process group, signals not ignored: the traps can stop all of it
  beside < /dev/null > "$logs/beside.out" 2>&1 &
  beside_pid=$!
  set +m
  trap 'kill -- -"$beside_pid" 2> /dev/null' EXIT
  trap 'kill -- -"$beside_pid" 2> /dev/null; exit 130' INT TERM
  phase rostests ctest_group rostest "_rostest_"
  phase "beside rest" wait "$beside_pid" || junit_failure beside "the ASan/fuzz job beside the rostests failed or died, see $logs/beside.out"
  trap - EXIT INT TERM
  echo "== ASan+UBSan and fuzz smoke (beside the rostests, idle priority; log $logs/beside.out)"
  grep -vE "^fuzz: .* clean for" "$logs/beside.out"
  phase checks checks
fi

total=0
echo
echo "== time per phase ($(nproc) cores, JOBS=$JOBS)"
for i in "${!phase_names[@]}"; do
  printf '  %-12s %5d s\n' "${phase_names[$i]}" "${phase_secs[$i]}"
  total=$((total + phase_secs[i]))
done
printf '  %-12s %5d s (%d min)\n' total "$total" $((total / 60))
if [ -s "$logs/beside.times" ]; then
  echo "  beside the rostests (idle priority, in the rostests' time; 'beside rest' is the wait after them):"
  while read -r n s; do printf '    %-10s %5d s\n' "$n" "$s"; done < "$logs/beside.times"
fi
echo "== slowest test executables (s, package, name)"
slowest 8 | sed 's/^/  /'
echo
scripts/test_summary.py "$results"
