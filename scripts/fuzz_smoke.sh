#!/usr/bin/env bash
# Short libFuzzer runs with AddressSanitizer and UndefinedBehaviorSanitizer, for `make test`.
# Usage: scripts/fuzz_smoke.sh [SECONDS_PER_TARGET]   (default 20)
#        scripts/fuzz_smoke.sh --build                 (only build the targets and seed their corpora;
#                                                       scripts/fuzz_long.sh uses it)
#        scripts/fuzz_smoke.sh --flags TARGET          (print the target's extra libFuzzer flags)
# Writes a JUnit result per target to build/test_results/fuzz/ so the test summary counts it.
# Skipped (reported as skipped) when clang is not installed. A target is rebuilt only when a source
# under src/ is newer than its binary.
set -uo pipefail
cd "$(dirname "$0")/.."
build_only=0
if [ "${1:-}" = "--build" ]; then build_only=1; shift; fi
secs=${1:-20}
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
  [fuzz_nmea]="src/fuzz/fuzz_nmea.cpp src/lib/nmea.cpp src/lib/ais.cpp src/lib/arpa.cpp"
  [fuzz_arpa]="src/fuzz/fuzz_arpa.cpp src/lib/nmea.cpp src/lib/arpa.cpp"
  [fuzz_scenario]="src/fuzz/fuzz_scenario.cpp src/lib/scenario.cpp src/lib/geodesy.cpp src/lib/param_map.cpp
                   src/lib/domain.cpp -lyaml-cpp -lGeographicLib"
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
  mkdir -p "$out/$name.corpus"
  seed "$name" "$out/$name.corpus"
  [ "$build_only" = 1 ] && continue
  # shellcheck disable=SC2046
  if "$out/$name" "$out/$name.corpus" $(flags "$name") -max_total_time="$secs" -rss_limit_mb=1024 -timeout=5 \
       -artifact_prefix="$out/$name-" > "$out/$name.log" 2>&1; then
    runs=$(grep -o "Done [0-9]* runs" "$out/$name.log" | tail -1)
    echo "fuzz: $name clean for ${secs} s ($runs)"
    junit "$name" pass ""
  else
    echo "fuzz: $name FOUND A PROBLEM, see $out/$name.log"
    junit "$name" fail "crash, leak or hang: see $out/$name.log"; status=1
  fi
done
exit $status
