#!/usr/bin/python3
"""The layering rule of asv_core, run by the build (src/CMakeLists.txt): every source and header belongs
to a stage (the first folder under lib/ or include/asv_core/), and includes only headers of its own or
earlier stages, in pipeline order; papers may include every stage. asv_core is ROS-free: no ROS header.
Usage: check_layers.py SRC_DIR   (exit status 1 and one line per violation, file:line: reason)"""
import os
import re
import sys

STAGES = ["common", "charts", "codec", "tracking", "risk", "planning", "sim", "eval", "papers"]
INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]')
ROS = re.compile(r"^(ros|roscpp|tf2|tf2_ros|std_msgs|geometry_msgs|nav_msgs|asv_msgs|asv_ros)/")


def stage_of(rel):
    """The stage of a path relative to lib/ or include/asv_core/, or None."""
    first = rel.split("/", 1)[0]
    return first if "/" in rel and first in STAGES else None


def check_file(path, stage):
    errors = []
    with open(path, encoding="utf-8") as f:
        for n, line in enumerate(f, 1):
            m = INCLUDE.match(line)
            if not m:
                continue
            inc = m.group(1)
            if ROS.match(inc):
                errors.append("%s:%d: asv_core is ROS-free, includes <%s>" % (path, n, inc))
            elif inc.startswith("asv_core/"):
                other = stage_of(inc[len("asv_core/"):])
                if other is None:
                    errors.append("%s:%d: %s is in no stage" % (path, n, inc))
                elif STAGES.index(other) > STAGES.index(stage):
                    errors.append("%s:%d: stage '%s' includes '%s' of the later stage '%s'"
                                  % (path, n, stage, inc, other))
    return errors


def main(src):
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
                else:
                    errors += check_file(path, stage)
    for e in errors:
        print(e)
    return 1 if errors else 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1]))
