#!/usr/bin/env bash
# make lint: clang-tidy (the checks of .clang-tidy) over every C++ source of the stack in
# build/compile_commands.json (generated sources in build/ left out). Prints each finding and a summary
# line; exit status 1 on any finding. Usage: scripts/lint.sh [JOBS]
set -uo pipefail
cd "$(dirname "$0")/.."
jobs=${1:-2}
db=build/compile_commands.json
[ -f "$db" ] || { echo "lint: $db missing (make build writes it)"; exit 1; }
mapfile -t files < <(python3 -c "import json,sys
for e in json.load(open(sys.argv[1])):
    if '/build/' not in e['file']: print(e['file'])" "$db" | sort -u)
echo "lint: clang-tidy on ${#files[@]} files with $jobs jobs (log build/lint.log) ..."
run-clang-tidy -p build -j "$jobs" -quiet "${files[@]}" > build/lint.log 2>&1
rc=$?
findings=$(grep -cE "(warning|error): .*\[[a-z]+-" build/lint.log)
grep -E "(warning|error): .*\[[a-z]+-" build/lint.log | sed "s|$PWD/||" | sort -u
echo "lint: ${#files[@]} files, $findings finding(s)"
[ "$rc" -eq 0 ] && [ "$findings" -eq 0 ]
