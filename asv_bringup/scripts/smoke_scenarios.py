#!/usr/bin/python3
"""Launch-file smoke test: every scenario of asv_bringup/scenarios starts through scenario.launch,
runs SMOKE_SIM_TIME simulated seconds as fast as it can, shuts down cleanly and leaves a result JSON
with the keys of docs/evaluation.md.

Run by rostest (test/smoke.test), which provides the master; each scenario is one test case.
Environment: ASV_SMOKE_SIM_TIME (default 20 s), ASV_SMOKE_ONLY (comma-separated scenario names).
"""
import glob
import json
import os
import subprocess
import sys
import tempfile
import unittest

import rospkg
import rosunit

SIM_TIME = float(os.environ.get("ASV_SMOKE_SIM_TIME", "20"))
KEYS = ["scenario", "planner", "seed", "collision", "collisions_between_targets", "grounding",
        "min_obstacle_distance_m", "min_separation_m", "safety_violation", "arrived",
        "path_length_m", "targets", "colregs_score", "plan_time_ms", "wall_time_s"]


class ScenarioSmoke(unittest.TestCase):
    pass


def make_test(name, path):
    def test(self):
        out = tempfile.mkdtemp(prefix="asv_smoke_")
        result = os.path.join(out, "result.json")
        cmd = ["roslaunch", "asv_bringup", "scenario.launch", "scenario:=" + name, "scenario_file:=" + path,
               "lockstep:=true", "max_sim_time:=%g" % SIM_TIME, "out:=" + out,
               "result:=" + result, "output:=log"]
        proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=120)
        log = proc.stdout.decode(errors="replace")
        self.assertEqual(proc.returncode, 0, "roslaunch failed:\n" + log[-3000:])
        self.assertNotIn("process has died", log.replace("[sim_node-", "[ok-").replace("[rosbag", "[ok"),
                         "a node died:\n" + log[-3000:])
        self.assertTrue(os.path.exists(result), "no result JSON:\n" + log[-3000:])
        with open(result) as f:
            data = json.load(f)
        for k in KEYS:
            self.assertIn(k, data)
        self.assertEqual(data["scenario"], name)
    return test


def main():
    root = rospkg.RosPack().get_path("asv_bringup")
    only = [s for s in os.environ.get("ASV_SMOKE_ONLY", "").split(",") if s]
    for path in sorted(glob.glob(os.path.join(root, "scenarios", "*.yaml"))):
        name = os.path.splitext(os.path.basename(path))[0]
        if only and name not in only:
            continue
        setattr(ScenarioSmoke, "test_" + name, make_test(name, path))
    rosunit.unitrun("asv_bringup", "scenario_smoke", ScenarioSmoke, sysargs=sys.argv)


if __name__ == "__main__":
    main()
