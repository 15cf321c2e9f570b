#!/usr/bin/python3
"""Every C++ file of the stack is clean under the root .clang-format, as one JUnit test case (make test
counts it, so CI fails on a formatting difference).

Usage: format_check.py OUT.xml
Runs `clang-format --dry-run` on every .h and .cpp under src/ and asv_*/ and fails the case with each
file and its first differences. `make format` rewrites them. Exit status 1 on a finding, 2 when
clang-format is not installed (scripts/setup installs it).
"""
import glob
import os
import shutil
import subprocess
import sys

import junit_case

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))


def sources():
    """The files `make format` formats, relative to the root."""
    files = []
    for top in ["src"] + sorted(glob.glob(os.path.join(ROOT, "asv_*"))):
        for dirpath, _, names in os.walk(os.path.join(ROOT, top)):
            files += [os.path.relpath(os.path.join(dirpath, n), ROOT) for n in names if n.endswith((".h", ".cpp"))]
    return sorted(files)


def check(finding):
    exe = shutil.which("clang-format")
    if exe is None:
        print("format_check: clang-format not installed (scripts/setup installs it)")
        sys.exit(2)
    files = sources()
    if not files:
        finding("no C++ file found under src/ and asv_*/")
    p = subprocess.run([exe, "--dry-run", "--style=file"] + files, cwd=ROOT, capture_output=True, text=True)
    bad = {}
    for line in p.stderr.splitlines():
        if ": warning:" in line or ": error:" in line:
            bad.setdefault(line.split(":", 1)[0], []).append(line)
    for path, lines in sorted(bad.items()):
        finding("%s: %d difference(s), first: %s" % (path, len(lines), lines[0]))
    if bad:
        finding("make format rewrites these %d file(s)" % len(bad))


if __name__ == "__main__":
    sys.exit(junit_case.run(__doc__, "format", "clang_format", [check],
                            "every C++ file is clean under .clang-format (%d files)" % len(sources())))
