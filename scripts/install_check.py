#!/usr/bin/python3
"""The install space works on its own, as one JUnit test case (make test counts it).

Usage: install_check.py OUT.xml
1. `catkin_make install` into install/ (the build space's CMAKE_INSTALL_PREFIX).
2. A third-party planner plugin compiles against the installed headers alone (asv_core's planner
   interface and what it includes).
3. With only install/setup.bash sourced (a fresh environment: no devel space, no source folders on the
   package path), every package is found in install/, and scenario.launch runs head_on end to end
   (lockstep, 120 simulated seconds, the installed scenario, rviz config and vessel presets) and writes
   its result.
Exit status 1 when a step fails (its output in the case's failure).
"""
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile

import junit_case

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
INSTALL = os.path.join(ROOT, "install")
PLUGIN = """#include <asv_core/planning/planning.h>
// A third party's planner, built against the installed headers only.
class Straight : public asv::PlannerAlgorithm {
public:
  void configure(const asv::ParamMap&) override {}
  asv::Plan plan(const asv::PlanningProblem&) override { return {}; }
  std::string name() const override { return "straight"; }
};
int main() { return 0; }
"""


def step(name, cmd, env=None, timeout=1200):
    """Runs `cmd` in a process group of its own: on a timeout the whole group (a launch's nodes and
    master too) is killed."""
    print("install_check: " + name, flush=True)
    p = subprocess.Popen(cmd, cwd=ROOT, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                         start_new_session=True)
    try:
        out = p.communicate(timeout=timeout)[0]
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, signal.SIGKILL)
        p.communicate()
        raise RuntimeError("%s did not finish within %d s" % (name, timeout))
    if p.returncode != 0:
        raise RuntimeError("%s failed (exit %d):\n%s" % (name, p.returncode, out[-3000:]))
    return out


def fresh_env():
    """The environment of a new shell that sourced install/setup.bash only."""
    base = {"PATH": "/usr/bin:/bin", "HOME": os.environ.get("HOME", "/root"), "LANG": "C.UTF-8",
            "ROS_MASTER_URI": "http://localhost:11395", "ROS_HOSTNAME": "localhost",
            "ROS_LOG_DIR": os.path.join(ROOT, "build", "ros_log_install")}
    out = subprocess.run(["bash", "-c", "source '%s/setup.bash' && env -0" % INSTALL], env=base,
                         stdout=subprocess.PIPE, check=True).stdout.decode()
    env = dict(kv.split("=", 1) for kv in out.split("\0") if "=" in kv)
    # A build configured from a shell that had sourced devel/ chains it under install/ (catkin's
    # overlays): drop it and the source space, so that only what is installed is found.
    for key in ("CMAKE_PREFIX_PATH", "LD_LIBRARY_PATH", "PATH", "PKG_CONFIG_PATH", "PYTHONPATH", "ROS_PACKAGE_PATH"):
        parts = [p for p in env.get(key, "").split(":")
                 if p and not p.startswith(os.path.join(ROOT, "devel")) and p.rstrip("/") != ROOT]
        env[key] = ":".join(parts)
    return env


def check():
    jobs = os.environ.get("JOBS", "2")
    # install/ lies in the source space: without this (first, so that a failed install leaves it too),
    # catkin and rostest would find every package twice.
    os.makedirs(INSTALL, exist_ok=True)
    open(os.path.join(INSTALL, "CATKIN_IGNORE"), "w").close()
    step("catkin_make install", ["catkin_make", "--source", ROOT, "--build", os.path.join(ROOT, "build"),
                                 "-j" + jobs, "install"])
    tmp = tempfile.mkdtemp(prefix="asv_install_")
    with open(os.path.join(tmp, "plugin.cpp"), "w") as f:
        f.write(PLUGIN)
    step("a plugin against the installed headers",
         ["g++", "-std=c++17", "-fsyntax-only", "-I" + os.path.join(INSTALL, "include"), "-I/usr/include/eigen3",
          os.path.join(tmp, "plugin.cpp")])
    env = fresh_env()
    where = step("rospack find", ["rospack", "find", "asv_bringup"], env=env).strip()
    if not where.startswith(INSTALL):
        raise RuntimeError("asv_bringup found at %s, not in %s" % (where, INSTALL))
    step("scenario.launch from the install space",
         ["roslaunch", "asv_bringup", "scenario.launch", "scenario:=head_on", "planner:=ga", "lockstep:=true",
          "max_sim_time:=120", "out:=" + tmp], env=env, timeout=600)
    with open(os.path.join(tmp, "result.json")) as f:
        result = json.load(f)
    if result.get("scenario") != "head_on" or result.get("collision"):
        raise RuntimeError("unexpected result: %s" % json.dumps(result)[:500])
    shutil.rmtree(tmp, ignore_errors=True)


def main():
    out = junit_case.out_path(__doc__)
    try:
        check()
        failure = ""
    except (RuntimeError, OSError, subprocess.SubprocessError, ValueError) as e:
        failure = str(e)
    junit_case.write(out, "install_space", "install_and_run", failure.splitlines()[0] if failure else None, failure)
    print("install_check: " + ("the install space builds a plugin and runs head_on" if not failure
                               else failure.splitlines()[0]))
    return 1 if failure else 0


if __name__ == "__main__":
    sys.exit(main())
