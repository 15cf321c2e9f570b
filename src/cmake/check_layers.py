#!/usr/bin/python3
"""The layering rules, run by asv_core's build (src/CMakeLists.txt). An allow-list: an include that no
rule allows is a violation.

asv_core (SRC_DIR): every source and header belongs to a stage (the first folder under lib/ or
include/asv_core/) and includes only
  - the C++ standard library (<vector>, <cmath>: a name with no folder and no extension),
  - headers of its own stage or an earlier one, in pipeline order (papers may include every stage),
  - a header beside it in the same folder ("ogr_land.h"),
  - the outside libraries named for its stage in LIBRARIES (no ROS: asv_core is ROS-free).
The ROS packages (asv_* beside SRC_DIR, when present): a C++ file includes only the standard library,
POSIX (<sys/...>, <netinet/...>, <arpa/...>, <unistd.h>), its own package, the packages its
package.xml depends on (asv_core among them, gtest in tests), and of asv_core only the stages its
package may use (ROS_CORE_STAGES: the nodes meant for a real boat never include the simulator).
No relative include reaches out of its folder ("../").
Usage: check_layers.py SRC_DIR   (exit status 1 and one line per violation, file:line: reason)"""
import os
import re
import sys
import xml.etree.ElementTree as ET

STAGES = ["common", "charts", "codec", "tracking", "risk", "world", "planning", "sim", "eval", "papers"]
# Outside libraries by the include paths they bring, and the stages allowed each.
LIBRARIES = {
    "Eigen": (re.compile(r"^Eigen/"), STAGES),
    "GeographicLib": (re.compile(r"^GeographicLib/"), ["common"]),
    "Boost.Geometry": (re.compile(r"^boost/geometry"), ["common"]),
    "GDAL": (re.compile(r"^(gdal|ogr|cpl)[a-z_]*\.h$"), ["charts"]),
    "yaml-cpp": (re.compile(r"^yaml-cpp/"), ["world", "sim"]),
    "tinyxml2": (re.compile(r"^tinyxml2\.h$"), ["world"]),
}
STD = re.compile(r"^[a-z_]+$")
POSIX = re.compile(r"^(sys|netinet|arpa)/[a-z_]+\.h$|^(unistd|fcntl|termios|poll|netdb)\.h$")
# The asv_core stages each ROS package may include. Only the simulator's package sees sim and eval; any
# other package (a third party's planner) gets the real boat's.
REAL_BOAT = ["common", "charts", "codec", "tracking", "risk", "world", "planning"]
ROS_CORE_STAGES = {
    "asv_ros": REAL_BOAT,
    "asv_risk": REAL_BOAT,
    "asv_planning": REAL_BOAT,
    "asv_sim": STAGES,
}
# Header folders that belong to a package of another name (roscpp installs ros/ and its xmlrpcpp).
HEADER_PACKAGE = {"ros": "roscpp", "xmlrpcpp": "roscpp"}
INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]')


def stage_of(rel):
    """The stage of a path relative to lib/ or include/asv_core/, or None."""
    first = rel.split("/", 1)[0]
    return first if "/" in rel and first in STAGES else None


def includes(path):
    """(line number, included path) of every #include of a file."""
    with open(path, encoding="utf-8") as f:
        for n, line in enumerate(f, 1):
            m = INCLUDE.match(line)
            if m:
                yield n, m.group(1)


def core_reason(inc, stage, here):
    """Why `inc` may not be included by a file of `stage` in folder `here`; None when it may."""
    if ".." in inc.split("/"):
        return "a relative include out of its folder"
    if STD.match(inc) or os.path.isfile(os.path.join(here, inc)):
        return None
    if inc.startswith("asv_core/"):
        other = stage_of(inc[len("asv_core/"):])
        if other is None:
            return "%s is in no stage" % inc
        if stage != "papers" and STAGES.index(other) > STAGES.index(stage):
            return "stage '%s' includes '%s' of the later stage '%s'" % (stage, inc, other)
        return None
    for lib, (pattern, stages) in LIBRARIES.items():
        if pattern.match(inc):
            return None if stage in stages else "%s is not a library of stage '%s'" % (lib, stage)
    return "<%s> is on no allow-list of asv_core (ROS-free: only its libraries)" % inc


def check_core(src):
    errors = []
    for base in (os.path.join(src, "lib"), os.path.join(src, "include", "asv_core")):
        for dirpath, _, names in os.walk(base):
            for name in sorted(names):
                if not name.endswith((".h", ".cpp")):
                    continue
                path = os.path.join(dirpath, name)
                stage = stage_of(os.path.relpath(path, base))
                if stage is None:
                    errors.append("%s: not in a stage folder (%s)" % (path, ", ".join(STAGES)))
                    continue
                for n, inc in includes(path):
                    why = core_reason(inc, stage, dirpath)
                    if why:
                        errors.append("%s:%d: %s" % (path, n, why))
    return errors


def manifest_depends(pkg_dir):
    """The packages a package.xml names in any depend tag."""
    root = ET.parse(os.path.join(pkg_dir, "package.xml")).getroot()
    return {e.text.strip() for e in root if e.tag.endswith("depend") and e.text}


def ros_reason(inc, pkg, deps, here):
    if ".." in inc.split("/"):
        return "a relative include out of its folder"
    if STD.match(inc) or POSIX.match(inc) or os.path.isfile(os.path.join(here, inc)):
        return None
    first = inc.split("/", 1)[0]
    first = HEADER_PACKAGE.get(first, first)
    if first == "asv_core":
        stage = stage_of(inc[len("asv_core/"):])
        if "asv_core" not in deps:
            return "asv_core is not in %s's package.xml" % pkg
        if stage not in ROS_CORE_STAGES.get(pkg, REAL_BOAT):
            return "%s may not include asv_core's stage '%s' (%s)" % (pkg, stage, inc)
        return None
    if first == pkg or first in deps or (first == "gtest" and os.sep + "test" in here):
        return None
    return "<%s>: %s is not in %s's package.xml" % (inc, first, pkg)


def check_ros(root):
    errors = []
    for pkg in sorted(os.listdir(root)):
        pkg_dir = os.path.join(root, pkg)
        if not (pkg.startswith("asv_") and os.path.isfile(os.path.join(pkg_dir, "package.xml"))):
            continue
        deps = manifest_depends(pkg_dir)
        for dirpath, _, names in os.walk(pkg_dir):
            for name in sorted(names):
                if name.endswith((".h", ".cpp")):
                    path = os.path.join(dirpath, name)
                    for n, inc in includes(path):
                        why = ros_reason(inc, pkg, deps, dirpath)
                        if why:
                            errors.append("%s:%d: %s" % (path, n, why))
    return errors


def main(src):
    errors = check_core(src) + check_ros(os.path.normpath(os.path.join(src, "..")))
    for e in errors:
        print(e)
    return 1 if errors else 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1]))
