#!/usr/bin/env bash
# Long libFuzzer runs (`make fuzz-long`): every target of scripts/fuzz_smoke.sh for RUNS executions
# (default 10 million), one after the other, with AddressSanitizer, LeakSanitizer and
# UndefinedBehaviorSanitizer. Usage: scripts/fuzz_long.sh [RUNS] [TARGET...]
# Per target: log out/fuzz/<target>.log, the grown corpus in out/fuzz/<target>.corpus/, any crash,
# leak or timeout input as out/fuzz/<target>-crash-*/leak-*/timeout-*. One line per target (executions,
# wall time, executions per second, findings) in out/fuzz/summary.txt. Exit status 1 when anything
# was found. The machine is shared: run it under `nice` (the Makefile target does).
# FUZZ_MAX_TIME=SECONDS (environment) also stops each target after that long; the summary then says
# how many of the RUNS executions it reached.
set -uo pipefail
cd "$(dirname "$0")/.."
runs=${1:-10000000}
shift || true
out=out/fuzz
mkdir -p "$out"
scripts/fuzz_smoke.sh --build || { echo "fuzz-long: a target failed to build (build/fuzz/*.build.log)"; exit 1; }
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=($(ls src/fuzz/fuzz_*.cpp | xargs -n1 basename | sed 's/\.cpp$//' | sort))
# Allocation stacks of 2 frames: yaml-cpp (not built with frame pointers) gives ASan's fast unwinder
# a new "stack" for nearly every allocation, and the default 30-frame depot then grows without bound
# (1 GB, exec/s halving within minutes). Re-run a finding's input for full allocation stacks.
export ASAN_OPTIONS=${ASAN_OPTIONS:-malloc_context_size=2}
summary=$out/summary.txt
# Lines of targets not run this time are kept from the previous summary.
kept=$( [ -f "$summary" ] && grep -v "^#" "$summary" | grep -v -E "^($(IFS='|'; echo "${targets[*]}")) " )
{
  echo "# fuzz-long $(date -u +%Y-%m-%dT%H:%M:%SZ), $(nproc) cores, $(clang++ --version | head -1)"
  echo "# git $(git rev-parse --short HEAD 2>/dev/null)$(git diff --quiet HEAD -- src 2>/dev/null || echo '+local changes')"
  echo "# target runs wall_s exec_per_s corpus findings"
  [ -n "$kept" ] && echo "$kept"
} > "$summary"
status=0
for name in "${targets[@]}"; do
  bin=build/fuzz/$name
  [ -x "$bin" ] || { echo "fuzz-long: no $bin"; status=1; continue; }
  rm -f "$out/$name"-crash-* "$out/$name"-leak-* "$out/$name"-timeout-* "$out/$name"-oom-*
  mkdir -p "$out/$name.corpus"
  flags=$(scripts/fuzz_smoke.sh --flags "$name")
  echo "fuzz-long: $name, $runs executions ..."
  start=$(date +%s.%N)
  # New inputs go into out/fuzz/<name>.corpus (kept between runs); build/fuzz/<name>.corpus holds the seeds.
  [ -n "${FUZZ_MAX_TIME:-}" ] && flags="$flags -max_total_time=$FUZZ_MAX_TIME"
  # shellcheck disable=SC2086
  "$bin" "$out/$name.corpus" "build/fuzz/$name.corpus" $flags -runs="$runs" -rss_limit_mb=2048 -timeout=10 \
    -print_final_stats=1 -artifact_prefix="$out/$name-" > "$out/$name.log" 2>&1
  rc=$?
  wall=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
  done_runs=$(grep -o "Done [0-9]* runs" "$out/$name.log" | tail -1 | grep -o "[0-9]*")
  [ -z "$done_runs" ] && done_runs=$(grep -o "stat::number_of_executed_units: *[0-9]*" "$out/$name.log" | grep -o "[0-9]*$" | tail -1)
  done_runs=${done_runs:-0}
  eps=$(awk -v n="$done_runs" -v t="$wall" 'BEGIN { printf "%d", (t > 0 ? n / t : 0) }')
  corpus=$(ls "$out/$name.corpus" | wc -l)
  findings=$(ls "$out/$name"-crash-* "$out/$name"-leak-* "$out/$name"-timeout-* "$out/$name"-oom-* 2>/dev/null | xargs -r -n1 basename | tr '\n' ' ')
  if [ "$rc" -ne 0 ] || [ -n "$findings" ]; then
    status=1
    what=$(grep -m1 -oE "ERROR: (AddressSanitizer|LeakSanitizer|libFuzzer): [a-z-]+[^ ]*|runtime error: .*" "$out/$name.log")
    findings="FOUND (exit $rc): ${what:-see log} ${findings}"
  else
    findings="none"
  fi
  [ "$done_runs" -lt "$runs" ] && [ "$findings" = none ] && findings="none (stopped by FUZZ_MAX_TIME before $runs runs)"
  line=$(printf '%s runs=%s wall_s=%.0f exec_per_s=%s corpus=%s findings=%s' "$name" "$done_runs" "$wall" "$eps" "$corpus" "$findings")
  echo "fuzz-long: $line"
  echo "$line" >> "$summary"
done
echo "fuzz-long: summary in $summary"
exit $status
