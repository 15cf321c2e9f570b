#!/usr/bin/env bash
# Short libFuzzer runs with AddressSanitizer and UndefinedBehaviorSanitizer, for `make test`.
# Usage: scripts/fuzz_smoke.sh                 (each target for its fixed number of executions)
#        scripts/fuzz_smoke.sh --build         (only build the targets and seed their corpora;
#                                               scripts/fuzz_long.sh uses it)
#        scripts/fuzz_smoke.sh --flags TARGET  (print the target's extra libFuzzer flags)
# A smoke run is reproducible: fixed random seed, fixed number of executions, a fresh corpus of the
# seed files only, so it passes or fails the same way on every machine and every run (a time limit
# would let a faster machine reach inputs a slower one never tries). Exploring new inputs is the job of
# `make fuzz-long`; what it finds becomes a unit test and a fix.
# Writes a JUnit result per target to build/test_results/fuzz/ so the test summary counts it.
# Skipped (reported as skipped) when clang is not installed. A target is rebuilt only when a source
# under src/ is newer than its binary.
set -uo pipefail
cd "$(dirname "$0")/.."
build_only=0
if [ "${1:-}" = "--build" ]; then build_only=1; shift; fi
out=build/fuzz
res=build/test_results/fuzz
mkdir -p "$out" "$res"
junit() {  # name status(pass|fail|skip) message
  [ "$build_only" = 1 ] && return
  local body=""
  case $2 in
    fail) body="<failure message=\"$3\"/>" ;;
    skip) body="<skipped message=\"$3\"/>" ;;
  esac
  printf '<?xml version="1.0"?>\n<testsuite name="fuzz" tests="1"><testcase classname="fuzz" name="%s">%s</testcase></testsuite>\n' \
    "$1" "$body" > "$res/fuzz-$1.xml"
}
# Target name -> sources and libraries (the library files each target needs, nothing more).
declare -A targets=(
  [fuzz_nmea]="src/fuzz/fuzz_nmea.cpp src/lib/codec/nmea.cpp src/lib/codec/ais.cpp src/lib/codec/ais_json.cpp
               src/lib/codec/ais_json_type6.cpp src/lib/codec/ais_json_type8.cpp src/lib/codec/arpa.cpp"
  [fuzz_arpa]="src/fuzz/fuzz_arpa.cpp src/lib/codec/nmea.cpp src/lib/codec/arpa.cpp src/lib/codec/gnss.cpp src/lib/common/param_map.cpp"
  [fuzz_scenario]="src/fuzz/fuzz_scenario.cpp src/lib/world/scenario.cpp src/lib/world/obstacles.cpp
                   src/lib/common/obstacle_index.cpp src/lib/common/geodesy.cpp
                   src/lib/common/param_map.cpp src/lib/common/geometry.cpp src/lib/risk/domain.cpp
                   -lyaml-cpp -lGeographicLib"
)
# Seed corpus of each target (copied at run time, so nothing is duplicated in the repository).
seed() {  # name corpus_dir
  case $1 in
    fuzz_nmea) cp ../shared/data/ais/libais/*.nmea ../shared/data/ais/gpsd-3.22/sample.aivdm "$2/" 2>/dev/null ;;
    fuzz_arpa) cp src/fuzz/corpus/arpa/*.nmea "$2/" ;;
    # The scenario files under 2.5 KB (13 of 16; obstacles, waypoints and planner targets among them):
    # the YAML parser's cost grows with the input, and larger seeds would raise the size limit.
    fuzz_scenario) find asv_bringup/scenarios -name '*.yaml' -size -2560c -exec cp {} "$2/" \; ;;
  esac
  return 0
}
# Extra libFuzzer flags of each target (scripts/fuzz_long.sh uses them too). fuzz_nmea: the AIS log
# seeds are up to 47 KB, which would set the input size limit and slow it 10-fold; 4 KB (dozens of
# lines) is plenty for the reassembly state.
flags() {
  case $1 in
    fuzz_nmea) echo "-max_len=4096" ;;
    fuzz_scenario) echo "-dict=src/fuzz/scenario.dict" ;;
  esac
}
[ "${1:-}" = "--flags" ] && { flags "$2"; exit 0; }
# Executions per target in a smoke run: 15-20 s each on one core with the sanitizers (from the seeds
# arpa runs 55 k/s, nmea 14 k/s, scenario 4.6 k/s). A run stopped by the time cap counts as a
# failure: the remaining executions were never tried.
declare -A smoke_runs=([fuzz_arpa]=1000000 [fuzz_nmea]=200000 [fuzz_scenario]=60000)
max_secs=300
# Short allocation stacks: see scripts/fuzz_long.sh (yaml-cpp's allocations would fill ASan's stack depot).
export ASAN_OPTIONS=${ASAN_OPTIONS:-malloc_context_size=2}
status=0
for name in $(printf '%s\n' "${!targets[@]}" | sort); do
  if ! command -v clang++ >/dev/null; then junit "$name" skip "clang++ not installed"; continue; fi
  if [ ! -x "$out/$name" ] || [ -n "$(find src/fuzz src/lib src/include -newer "$out/$name" -print -quit)" ]; then
    # shellcheck disable=SC2086  # the map value is a word list
    if ! clang++ -std=c++17 -O1 -g -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
        -I src/include -I /usr/include/eigen3 ${targets[$name]} -o "$out/$name" 2> "$out/$name.build.log"; then
      echo "fuzz: $name build FAILED, see $out/$name.build.log"
      rm -f "$out/$name"
      junit "$name" fail "build failed, see $out/$name.build.log"; status=1; continue
    fi
  fi
  rm -rf "$out/$name.corpus" && mkdir -p "$out/$name.corpus"
  seed "$name" "$out/$name.corpus"
  [ "$build_only" = 1 ] && continue
  runs=${smoke_runs[$name]}
  # The seeds are read from a copy: libFuzzer adds the inputs it finds to the first corpus folder.
  rm -rf "$out/$name.smoke" && mkdir -p "$out/$name.smoke"
  # shellcheck disable=SC2046
  if "$out/$name" "$out/$name.smoke" "$out/$name.corpus" $(flags "$name") -seed=1 -runs="$runs" \
       -max_total_time="$max_secs" -rss_limit_mb=1024 -timeout=5 -print_final_stats=1 \
       -artifact_prefix="$out/$name-" > "$out/$name.log" 2>&1; then
    done_runs=$(grep -o "stat::number_of_executed_units: *[0-9]*" "$out/$name.log" | grep -o "[0-9]*$")
    if [ "${done_runs:-0}" -lt "$runs" ]; then
      echo "fuzz: $name stopped by the $max_secs s cap after ${done_runs:-0} of $runs executions"
      junit "$name" fail "only ${done_runs:-0} of $runs executions in $max_secs s: see $out/$name.log"; status=1
      continue
    fi
    echo "fuzz: $name clean for $runs executions (seed 1)"
    junit "$name" pass ""
  else
    echo "fuzz: $name FOUND A PROBLEM, see $out/$name.log"
    junit "$name" fail "crash, leak or hang: see $out/$name.log"; status=1
  fi
done
exit $status
