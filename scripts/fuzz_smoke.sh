#!/usr/bin/env bash
# Short libFuzzer runs with AddressSanitizer and UndefinedBehaviorSanitizer, for `make test`.
# Usage: scripts/fuzz_smoke.sh [SECONDS_PER_TARGET]   (default 20)
# Writes a JUnit result per target to build/test_results/fuzz/ so the test summary counts it.
# Skipped (reported as skipped) when clang is not installed.
set -uo pipefail
cd "$(dirname "$0")/.."
secs=${1:-20}
out=build/fuzz
res=build/test_results/fuzz
mkdir -p "$out" "$res"
junit() {  # name status(pass|fail|skip) message
  local body=""
  case $2 in
    fail) body="<failure message=\"$3\"/>" ;;
    skip) body="<skipped message=\"$3\"/>" ;;
  esac
  printf '<?xml version="1.0"?>\n<testsuite name="fuzz" tests="1"><testcase classname="fuzz" name="%s">%s</testcase></testsuite>\n' \
    "$1" "$body" > "$res/fuzz-$1.xml"
}
declare -A targets=(
  [fuzz_nmea]="src/fuzz/fuzz_nmea.cpp src/lib/nmea.cpp src/lib/ais.cpp src/lib/arpa.cpp"
)
status=0
for name in "${!targets[@]}"; do
  if ! command -v clang++ >/dev/null; then junit "$name" skip "clang++ not installed"; continue; fi
  if ! clang++ -std=c++17 -O1 -g -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
      -I src/include -I /usr/include/eigen3 ${targets[$name]} -o "$out/$name" 2> "$out/$name.build.log"; then
    junit "$name" fail "build failed, see $out/$name.build.log"; status=1; continue
  fi
  mkdir -p "$out/$name.corpus"
  cp ../shared/data/ais/libais/*.nmea ../shared/data/ais/gpsd-3.22/sample.aivdm "$out/$name.corpus/" 2>/dev/null || true
  if "$out/$name" "$out/$name.corpus" -max_total_time="$secs" -rss_limit_mb=1024 -timeout=5 \
       > "$out/$name.log" 2>&1; then
    runs=$(grep -o "Done [0-9]* runs" "$out/$name.log" | tail -1)
    echo "fuzz: $name clean for ${secs} s ($runs)"
    junit "$name" pass ""
  else
    echo "fuzz: $name FOUND A PROBLEM, see $out/$name.log"
    junit "$name" fail "crash, leak or hang: see $out/$name.log"; status=1
  fi
done
exit $status
