#!/usr/bin/python3
"""The layering rules' checker (src/cmake/check_layers.py, run by every build) refuses what its allow-list
does not allow, as one JUnit test case (make test counts it).

Usage: layers_check.py OUT.xml
On a small tree made here (an asv_core with stages, two ROS packages), each of these must be one
finding, named with its file and line, and nothing else may be: a ROS header in asv_core; yaml-cpp in
the common stage (allowed in world); a later stage's header; a relative include out of its folder; a
header of no stage; a ROS package including a package its package.xml does not name; a real-boat
package including the sim stage. The repository's own tree must have no finding.
"""
import os
import subprocess
import sys
import tempfile

import junit_case

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
CHECKER = os.path.join(ROOT, "src", "cmake", "check_layers.py")

FILES = {
    "src/lib/common/a.cpp": '#include <vector>\n#include <ros/ros.h>\n#include <yaml-cpp/yaml.h>\n'
                            '#include "asv_core/risk/cpa.h"\n#include "../secret.h"\n#include "local.h"\n',
    "src/lib/common/local.h": "#pragma once\n",
    "src/lib/world/w.cpp": '#include <yaml-cpp/yaml.h>\n#include "asv_core/risk/cpa.h"\n#include "asv_core/nostage.h"\n',
    "src/include/asv_core/risk/cpa.h": '#include <Eigen/Core>\n#include "asv_core/common/units.h"\n',
    "asv_foo/package.xml": '<package format="2"><name>asv_foo</name><depend>asv_core</depend>'
                           '<depend>roscpp</depend></package>',
    "asv_foo/src/n.cpp": '#include <ros/ros.h>\n#include <sys/socket.h>\n#include <nav_msgs/Odometry.h>\n'
                         '#include <asv_core/world/scenario.h>\n#include <asv_core/sim/simulation.h>\n',
    "asv_sim/package.xml": '<package format="2"><name>asv_sim</name><depend>asv_core</depend></package>',
    "asv_sim/src/s.cpp": '#include <asv_core/sim/simulation.h>\n#include <asv_sim/sim_node.h>\n',
}
EXPECTED = [
    "src/lib/common/a.cpp:2:", "src/lib/common/a.cpp:3:", "src/lib/common/a.cpp:4:", "src/lib/common/a.cpp:5:",
    "src/lib/world/w.cpp:3:", "asv_foo/src/n.cpp:3:", "asv_foo/src/n.cpp:5:",
]


def check(finding):
    with tempfile.TemporaryDirectory() as tmp:
        for rel, text in FILES.items():
            os.makedirs(os.path.dirname(os.path.join(tmp, rel)), exist_ok=True)
            with open(os.path.join(tmp, rel), "w") as f:
                f.write(text)
        p = subprocess.run([sys.executable, CHECKER, os.path.join(tmp, "src")], capture_output=True, text=True)
        lines = [os.path.relpath(l, tmp) if l.startswith(tmp) else l for l in p.stdout.splitlines()]
        got = sorted(l.split(" ", 1)[0] for l in lines)
        if got != sorted(EXPECTED):
            finding("findings on the made tree: %s\nexpected at: %s" % ("\n".join(lines), EXPECTED))
        if p.returncode != 1:
            finding("exit status %d on the made tree, expected 1" % p.returncode)
    p = subprocess.run([sys.executable, CHECKER, os.path.join(ROOT, "src")], capture_output=True, text=True)
    if p.returncode != 0 or p.stdout.strip():
        finding("the repository's own tree: exit %d\n%s" % (p.returncode, p.stdout))


if __name__ == "__main__":
    sys.exit(junit_case.run(__doc__, "layers", "allow_list", [check],
                            "the allow-list refuses each planted include, the tree is clean"))
