#!/usr/bin/env bash
# make lint: clang-tidy (the checks of .clang-tidy) over every C++ source of the stack in
# build/compile_commands.json, clean files remembered in a cache as ccache does (scripts/lint.py).
# Prints each finding and a summary line; exit status 1 on any finding. Usage: scripts/lint.sh [JOBS]
cd "$(dirname "$0")/.." || exit 1
exec /usr/bin/python3 scripts/lint.py "${1:-2}"
