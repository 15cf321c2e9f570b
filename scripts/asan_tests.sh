#!/usr/bin/env bash
# Every asv_core unit test (src/test/test_*.cpp) built and run under AddressSanitizer (with
# LeakSanitizer) and UndefinedBehaviorSanitizer, for `make test-asan`.
# Usage: scripts/asan_tests.sh        (environment: JOBS build jobs, default 1; ASAN_CXX compiler,
#                                      default clang++, whose -fsanitize=undefined also covers
#                                      float-cast-overflow; ASAN_TEST_TIMEOUT seconds per executable)
# Builds in build_asan/ (its own catkin build and devel space, only the asv_core package; -O2 -g
# without NDEBUG, so Eigen's index and size assertions stay on; at -O1 clang does not inline Eigen's
# expression templates, and the generator's tests ran 85 times slower than unsanitized, 112 s), runs each test executable from
# src/test (the WORKING_DIRECTORY the CMake gives them) and writes one JUnit XML per executable to
# build/test_results/asan/. A sanitizer report makes the executable exit non-zero:
# when it left no XML (a crash) the XML is written here as a failure; when it left one and still failed
# (a sanitizer report after the tests, e.g. a leak at exit) a second file <name>-exit.xml records it.
# Logs: build_asan/test_logs/<name>.log. Exit status 1 when the build or any executable failed.
# The executables run JOBS at a time; compilations go through ccache when it is installed.
set -uo pipefail
cd "$(dirname "$0")/.."
root=$PWD
bdir=$root/build_asan
res=$root/build/test_results/asan
logs=$bdir/test_logs
# Debian's ROS 1 needs Debian's python (a pyenv python3 lacks catkin_pkg).
export PATH=/usr/bin:/bin:$PATH
cxx=${ASAN_CXX:-clang++}
command -v "$cxx" >/dev/null || cxx=g++
cc=$([ "${cxx#clang}" != "$cxx" ] && echo clang || echo gcc)
san="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined"
mkdir -p "$bdir" "$logs"
# ccache (as in the Makefile): the clone's paths made relative, so other clones share the entries.
# With -g ccache would also hash the working directory (it goes into the debug info), and every fresh
# clone would miss: not hashed, an object's debug info may name the clone that first compiled it.
export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$root}
export CCACHE_NOHASHDIR=1
launcher=""
command -v ccache >/dev/null && launcher="-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache"
rm -rf "$res" && mkdir -p "$res"

junit_fail() {  # file name message
  printf '<?xml version="1.0"?>\n<testsuite name="%s" tests="1" failures="1"><testcase classname="asan" name="%s"><failure message="%s"/></testcase></testsuite>\n' \
    "$2" "$2" "$3" > "$1"
}

# The tests and the command-line tools (test_ais_golden runs asv_ais_decode from the tests' directory).
tools=$(for t in src/tools/*.cpp; do basename "$t" .cpp; done)
echo "asan: building asv_core, its tests and tools in build_asan/ with $cxx ($san)"
if ! CC=$cc CXX=$cxx catkin_make --source "$root" --build "$bdir" \
    -DCATKIN_WHITELIST_PACKAGES="asv_core" -DCATKIN_DEVEL_PREFIX="$bdir/devel" \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O2 -g" \
    -DCMAKE_CXX_FLAGS="$san" -DCMAKE_C_FLAGS="$san" \
    -DCMAKE_EXE_LINKER_FLAGS="$san" -DCMAKE_SHARED_LINKER_FLAGS="$san" \
    -DPYTHON_EXECUTABLE=/usr/bin/python3 $launcher -j"${JOBS:-1}" tests $tools > "$bdir/build.log" 2>&1; then
  tail -30 "$bdir/build.log"
  echo "asan: build FAILED, see $bdir/build.log"
  junit_fail "$res/asan-build.xml" build "build failed, see build_asan/build.log"
  exit 1
fi

# LeakSanitizer on; stop at the first UB report with a stack trace.
export ASAN_OPTIONS=detect_leaks=1:check_initialization_order=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1

# run_one NAME: one test executable, its log and JUnit XML; prints one line; exit status 1 on a failure.
run_one() {
  local name=$1 exe=$bdir/devel/lib/asv_core/$1 xml=$res/$1.xml start=$SECONDS rc what msg
  if [ ! -x "$exe" ]; then
    junit_fail "$xml" "$name" "executable not built: $exe"
    echo "asan: $name MISSING"; return 1
  fi
  (cd src/test && timeout "${ASAN_TEST_TIMEOUT:-1800}" "$exe" --gtest_output="xml:$xml") > "$logs/$name.log" 2>&1
  rc=$?
  if [ "$rc" -eq 0 ]; then
    echo "asan: $name clean ($((SECONDS - start)) s)"
    return 0
  fi
  what=$(grep -m1 -oE "(ERROR: (AddressSanitizer|LeakSanitizer): [a-z-]+( memory leaks)?|runtime error: .{0,160})" "$logs/$name.log" \
         | tr '"<>&' "'___")
  [ "$rc" -eq 124 ] && what="timeout after ${ASAN_TEST_TIMEOUT:-1800} s"
  msg="exit status $rc: ${what:-see the log} (build_asan/test_logs/$name.log)"
  if [ -s "$xml" ]; then
    # A failing test case exits 1 and is in the XML already; record the exit only when it is not
    # explained by one (a sanitizer report, e.g. a leak at exit after every test passed).
    if [ -n "$what" ] || ! grep -q "<failure" "$xml"; then
      junit_fail "$res/$name-exit.xml" "$name" "$msg"
    else
      msg="failing test case(s), see the XML"
    fi
  else
    junit_fail "$xml" "$name" "no result: $msg"
  fi
  echo "asan: $name FAILED: $msg"
  return 1
}
export -f run_one junit_fail
export bdir res logs

# The executables JOBS at a time, the slow ones first (those that take a minute or more under ASan;
# the others take seconds): started last, one would run alone while the other job has nothing left.
slow="core_test_scenario_gen"
names=$(echo "$slow"; for src in src/test/test_*.cpp; do echo "core_$(basename "$src" .cpp)"; done | grep -vxF "$slow")
count=$(echo "$names" | wc -l)
echo "$names" | xargs -P "${JOBS:-1}" -I{} bash -c 'run_one "$@"' _ {}
status=$?
echo "asan: $count test executables, results in build/test_results/asan/"
[ "$status" -eq 0 ]
