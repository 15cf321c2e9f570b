#!/usr/bin/python3
"""catkin_lint -W1 over the workspace's packages, as one JUnit test case (make test counts it).

Usage: catkin_lint_check.py OUT.xml
Every error or warning catkin_lint reports (install rules that name missing folders, exported include
folders that are not installed, launch files that need a package the manifest does not name, ...) fails
the case with the lines it printed. Exit status 1 on a finding, 2 when catkin_lint is not installed
(scripts/setup installs Debian's catkin-lint).
"""
import os
import shutil
import subprocess
import sys
from xml.sax.saxutils import escape, quoteattr

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")


def main():
    if len(sys.argv) != 2 or sys.argv[1] in ("-h", "--help"):
        print(__doc__)
        return 0 if len(sys.argv) == 2 else 2
    out = sys.argv[1]
    os.makedirs(os.path.dirname(out) or ".", exist_ok=True)
    exe = shutil.which("catkin_lint")
    if exe is None:
        lines, rc = ["catkin_lint not installed (scripts/setup installs Debian's catkin-lint)"], 2
    else:
        # No rosdep database offline: catkin_lint then ignores unknown dependencies, and says so.
        p = subprocess.run([exe, "-W1", "--strict", ROOT], capture_output=True, text=True)
        lines = [l for l in (p.stdout + p.stderr).splitlines()
                 if ": error:" in l or ": warning:" in l or l.startswith("catkin_lint: checked")]
        rc = 0 if p.returncode == 0 else 1
    findings = [l for l in lines if not l.startswith("catkin_lint: checked")]
    body = "" if rc == 0 else "<failure message=%s>%s</failure>" % (
        quoteattr("%d finding(s)" % len(findings) if rc == 1 else lines[0]), escape("\n".join(lines)))
    with open(out, "w") as f:
        f.write('<?xml version="1.0" encoding="utf-8"?>\n<testsuite name="catkin_lint" tests="1" '
                'failures="%d"><testcase classname="catkin_lint" name="W1_clean">%s</testcase></testsuite>\n'
                % (0 if rc == 0 else 1, body))
    print("catkin_lint -W1: " + ("clean" if rc == 0 else "; ".join(findings) or lines[0]))
    return rc


if __name__ == "__main__":
    sys.exit(main())
