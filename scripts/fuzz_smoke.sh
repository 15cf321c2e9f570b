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
                   src/lib/world/route.cpp src/lib/world/route_file.cpp
                   src/lib/common/obstacle_index.cpp src/lib/common/geodesy.cpp
                   src/lib/common/param_map.cpp src/lib/common/geometry.cpp src/lib/risk/domain.cpp
                   -lyaml-cpp -lGeographicLib -ltinyxml2"
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
# Both limits are wall seconds: FUZZ_MAX_SECS caps a run, FUZZ_INPUT_TIMEOUT one input (a hang).
# make test raises them when the runs go at idle priority beside the rostests, where a run may wait
# seconds for a core without hanging.
max_secs=${FUZZ_MAX_SECS:-300}
input_timeout=${FUZZ_INPUT_TIMEOUT:-5}
# Short allocation stacks: see scripts/fuzz_long.sh (yaml-cpp's allocations would fill ASan's stack depot).
export ASAN_OPTIONS=${ASAN_OPTIONS:-malloc_context_size=2}
cxxflags="-std=c++17 -O1 -g -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined -I src/include -I /usr/include/eigen3"
# Each source compiles once to an object (shared by the targets that use it), through ccache when it is
# installed: a fresh clone on the same machine then links from the cache. With -g ccache would hash the
# working directory too (every clone would miss), hence CCACHE_NOHASHDIR.
cc="clang++"
command -v ccache >/dev/null && cc="ccache clang++"
export CCACHE_NOHASHDIR=1 CCACHE_BASEDIR=$PWD

# object SOURCE: its object file.
object() { local f=${1%.cpp}; echo "$out/obj/$f.o"; }
# compile SOURCE: one object, when the source or a header is newer (the make-like test of the binaries).
compile() {  # shellcheck disable=SC2317  # called through xargs
  local o
  o=$(object "$1")
  mkdir -p "$(dirname "$o")"
  # shellcheck disable=SC2086  # cc and cxxflags are word lists
  $cc $cxxflags -c "$1" -o "$o"
}
export -f compile object
export out cc cxxflags
# link NAME: the target from its objects and libraries.
link() {
  local objs=() libs=() f
  for f in ${targets[$1]}; do
    case $f in
      -l*) libs+=("$f") ;;
      *) objs+=("$(object "$f")") ;;
    esac
  done
  # shellcheck disable=SC2086
  clang++ $cxxflags "${objs[@]}" "${libs[@]}" -o "$out/$1"
}

# smoke NAME: builds (when a source is newer than the binary), seeds and runs one target; writes its
# JUnit result and prints one line; returns 1 on a failure.
smoke() {
  local name=$1 runs done_runs
  if [ ! -x "$out/$name" ]; then
    echo "fuzz: $name build FAILED, see $out/build.log"
    junit "$name" fail "build failed, see $out/build.log"; return 1
  fi
  rm -rf "$out/$name.corpus" && mkdir -p "$out/$name.corpus"
  seed "$name" "$out/$name.corpus"
  [ "$build_only" = 1 ] && return 0
  runs=${smoke_runs[$name]}
  # The seeds are read from a copy: libFuzzer adds the inputs it finds to the first corpus folder.
  rm -rf "$out/$name.smoke" && mkdir -p "$out/$name.smoke"
  # shellcheck disable=SC2046
  if "$out/$name" "$out/$name.smoke" "$out/$name.corpus" $(flags "$name") -seed=1 -runs="$runs" \
       -max_total_time="$max_secs" -rss_limit_mb=1024 -timeout="$input_timeout" -print_final_stats=1 \
       -artifact_prefix="$out/$name-" > "$out/$name.log" 2>&1; then
    done_runs=$(grep -o "stat::number_of_executed_units: *[0-9]*" "$out/$name.log" | grep -o "[0-9]*$")
    if [ "${done_runs:-0}" -lt "$runs" ]; then
      echo "fuzz: $name stopped by the $max_secs s cap after ${done_runs:-0} of $runs executions"
      junit "$name" fail "only ${done_runs:-0} of $runs executions in $max_secs s: see $out/$name.log"; return 1
    fi
    echo "fuzz: $name clean for $runs executions (seed 1)"
    junit "$name" pass ""
  else
    echo "fuzz: $name FOUND A PROBLEM, see $out/$name.log"
    junit "$name" fail "crash, leak or hang: see $out/$name.log"; return 1
  fi
}

if ! command -v clang++ >/dev/null; then
  for name in "${!targets[@]}"; do junit "$name" skip "clang++ not installed"; done
  exit 0
fi
names=$(printf '%s\n' "${!targets[@]}" | sort)
# The build: when a source under src/ is newer than a target, every object is brought up to date (the
# distinct sources, JOBS at a time; ccache answers for the unchanged ones) and the targets relinked.
stale=0
for name in $names; do
  [ ! -x "$out/$name" ] || [ -n "$(find src/fuzz src/lib src/include -newer "$out/$name" -print -quit)" ] && stale=1
done
if [ "$stale" = 1 ]; then
  for name in $names; do rm -f "$out/$name"; done
  # shellcheck disable=SC2086
  if printf '%s\n' ${targets[*]} | grep -v '^-l' | sort -u | xargs -P "${JOBS:-2}" -I{} bash -c 'compile {}' \
       > "$out/build.log" 2>&1; then
    for name in $names; do link "$name" >> "$out/build.log" 2>&1 || rm -f "$out/$name"; done
  fi
fi

# The runs, JOBS (default 2) at a time: each is one process with a fixed number of executions, so
# running beside another changes its time, not its result.
status=0
for name in $names; do
  while [ "$(jobs -rp | wc -l)" -ge "${JOBS:-2}" ]; do wait -n || status=1; done
  smoke "$name" &
done
while true; do
  wait -n
  rc=$?
  [ "$rc" = 127 ] && break  # no job left
  [ "$rc" = 0 ] || status=1
done
exit $status
