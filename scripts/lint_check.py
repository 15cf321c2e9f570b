#!/usr/bin/python3
"""make lint (clang-tidy with the root .clang-tidy over every C++ source the build compiles) as one JUnit
test case, so that make test, and CI with it, fails on a finding.

Usage: lint_check.py OUT.xml     (environment: JOBS, clang-tidy jobs, default 2)
Runs scripts/lint.sh after the build (it reads build/compile_commands.json) and fails the case with
each finding (file:line: message [check]). Exit status 1 on a finding or when clang-tidy cannot run.
"""
import os
import subprocess
import sys

import junit_case

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))


def check(finding):
    p = subprocess.run([os.path.join(ROOT, "scripts", "lint.sh"), os.environ.get("JOBS", "2")], cwd=ROOT,
                       capture_output=True, text=True)
    lines = p.stdout.splitlines()
    for line in lines:
        if "warning:" in line or "error:" in line:
            finding(line)
    if p.returncode != 0 and not any("warning:" in l or "error:" in l for l in lines):
        finding("lint.sh failed (exit %d): %s" % (p.returncode, (p.stdout + p.stderr)[-2000:]))
    summary = [l for l in lines if l.startswith("lint: ") and "finding" in l]
    print(summary[-1] if summary else "lint: no summary line")


if __name__ == "__main__":
    sys.exit(junit_case.run(__doc__, "lint", "clang_tidy", [check], "no clang-tidy finding"))
