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

import junit_case

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")


def main():
    out = junit_case.out_path(__doc__)
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
    junit_case.write(out, "catkin_lint", "W1_clean",
                     None if rc == 0 else ("%d finding(s)" % len(findings) if rc == 1 else lines[0]),
                     "\n".join(lines))
    print("catkin_lint -W1: " + ("clean" if rc == 0 else "; ".join(findings) or lines[0]))
    return rc


if __name__ == "__main__":
    sys.exit(main())
