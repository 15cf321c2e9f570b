#!/usr/bin/python3
"""Start-up parameter errors rostest: a node given a parameter of the wrong type, an unknown key (a
typo) or an invalid global lockstep parameter stops at once with exit status 1 and a message naming the
parameter, instead of running on a default. Before, sim_node, evaluator_node, risk_node and the DSSA
exchange read with `param()`, which silently kept the default (a list of lockstep participants given
as a number made the simulation wait for nobody).

Run by rostest (test/param_errors.test), which provides the master.
"""
import subprocess
import sys
import time
import unittest

import rospy
import rosunit
from rosgraph_msgs.msg import Log

START_LIMIT = 30.0  # [s, wall] a node that has not exited by then is running on a default: a failure
EXECUTABLES = {}  # (pkg, node) -> path, found once: rosrun would search the workspace at every start


def executable(pkg, node):
    """The path of `pkg node` as rosrun finds it (devel or install space)."""
    if (pkg, node) not in EXECUTABLES:
        found = subprocess.run(["catkin_find", "--first-only", "--libexec", pkg, node], stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, universal_newlines=True)
        if found.returncode != 0 or not found.stdout.strip():
            raise AssertionError("%s %s: no such executable (catkin_find: %s)" % (pkg, node, found.stdout.strip()))
        found = found.stdout.strip()
        EXECUTABLES[(pkg, node)] = found
    return EXECUTABLES[(pkg, node)]


def run_node(pkg, node, name, *args):
    """Runs `pkg node` as /name with private parameters args (_key:=value); returns (status, stderr)."""
    cmd = [executable(pkg, node), "__name:=" + name] + list(args)
    try:
        done = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=START_LIMIT,
                              universal_newlines=True)
    except subprocess.TimeoutExpired:
        return None, "still running after %.0f s" % START_LIMIT
    return done.returncode, done.stderr


class ParamErrors(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("param_error_tests", anonymous=True, disable_signals=True)

    def expect_refused(self, needle, pkg, node, name, *args):
        status, err = run_node(pkg, node, name, *args)
        self.assertEqual(status, 1, "%s %s: exit %s, stderr: %s" % (node, " ".join(args), status, err[-400:]))
        self.assertIn(needle, err, "%s %s: stderr: %s" % (node, " ".join(args), err[-400:]))

    def test_wrong_type_names_the_parameter(self):
        self.expect_refused("'/pe_sim/rate' has the wrong type", "asv_sim", "sim_node", "pe_sim", "_rate:=fast")
        # A number where the list of lockstep participants belongs.
        self.expect_refused("'/pe_sim2/lockstep_participants' has the wrong type", "asv_sim", "sim_node",
                            "pe_sim2", "_lockstep_participants:=5")
        self.expect_refused("'/pe_eval/pretty' has the wrong type", "asv_sim", "evaluator_node", "pe_eval",
                            "_own_ship:=own", "_pretty:=1")
        self.expect_refused("'/pe_risk/stale_after' has the wrong type", "asv_risk", "risk_node", "pe_risk",
                            "_stale_after:=later")
        self.expect_refused("'/pe_plan/replan_period' has the wrong type", "asv_planning", "planner_node",
                            "pe_plan", "_replan_period:=soon")
        self.expect_refused("'/pe_arpa/max_targets' has the wrong type", "asv_risk", "arpa_node", "pe_arpa",
                            "_origin_lat_deg:=54.6", "_origin_lon_deg:=18.8", "_max_targets:=many")

    def test_unknown_key_is_a_typo(self):
        self.expect_refused("unknown parameter '/pe_sim3/rat'", "asv_sim", "sim_node", "pe_sim3", "_rat:=30")
        self.expect_refused("unknown parameter '/pe_eval2/prety'", "asv_sim", "evaluator_node", "pe_eval2",
                            "_own_ship:=own", "_prety:=true")
        self.expect_refused("unknown parameter '/pe_track/forget_afte'", "asv_risk", "tracker", "pe_track",
                            "_forget_afte:=5")
        # A typo of a required key is named as a typo, not as the missing key.
        self.expect_refused("unknown parameter '/pe_ais/origin_lat_dg'", "asv_risk", "ais_node", "pe_ais",
                            "_origin_lat_dg:=54.6", "_origin_lon_deg:=18.8")
        # The input's subtree is checked too.
        self.expect_refused("unknown parameter '/pe_ais2/input/typ'", "asv_risk", "ais_node", "pe_ais2",
                            "_origin_lat_deg:=54.6", "_origin_lon_deg:=18.8", "_input/typ:=udp")
        self.expect_refused("unknown parameter '/pe_plan2/replan_perod'", "asv_planning", "planner_node",
                            "pe_plan2", "_planner:=none", "_replan_perod:=5")

    def test_missing_scenario_is_named_on_screen_and_on_rosout(self):
        fatal = []
        sub = rospy.Subscriber("/rosout", Log, lambda m: m.level == Log.FATAL and fatal.append(m), queue_size=100)
        try:
            self.expect_refused("/nonexistent/dir/head_on.yaml", "asv_sim", "sim_node", "pe_sim4",
                                "_scenario:=/nonexistent/dir/head_on.yaml")
            deadline = time.time() + 5.0
            while time.time() < deadline and not any("head_on.yaml" in m.msg for m in fatal):
                time.sleep(0.1)
            self.assertTrue(any(m.name == "/pe_sim4" and "head_on.yaml" in m.msg for m in fatal),
                            "no FATAL from /pe_sim4 naming the file on /rosout: %s" % [m.msg for m in fatal])
        finally:
            sub.unregister()

    def test_unreadable_chart_names_the_file(self):
        # A chart source that cannot be read stops every node that loads the scenario's land, naming the
        # scenario, the key and the chart file (island.yaml has no charts key: the parameter adds one).
        import rospkg
        scenarios = rospkg.RosPack().get_path("asv_bringup") + "/scenarios/"
        for pkg, node, name, extra in [("asv_sim", "sim_node", "pe_chart_sim", []),
                                       ("asv_sim", "evaluator_node", "pe_chart_eval", ["_own_ship:=own"]),
                                       ("asv_planning", "planner_node", "pe_chart_plan", ["_planner:=none"])]:
            self.expect_refused("'charts': /nonexistent/land.geojson: cannot open as a vector chart", pkg, node, name,
                                "_scenario:=" + scenarios + "island.yaml", "_charts:=/nonexistent/land.geojson",
                                *extra)

    def test_spawn_agents_refuses_malformed_planner_params(self):
        # A list where the mapping of planner name to parameters belongs: refused before any node starts,
        # naming the key, not a Python traceback.
        import rospkg
        import tempfile
        import yaml
        with open(rospkg.RosPack().get_path("asv_bringup") + "/scenarios/dssa_two_ships.yaml") as f:
            scenario = yaml.safe_load(f)
        for bad, needle in [(["dssa_plus"], "planner_params must be a mapping"),
                            ({"dssa_plus": 5}, "planner_params.dssa_plus must be a mapping")]:
            scenario["planner_params"] = bad
            with tempfile.NamedTemporaryFile("w", suffix=".yaml") as f:
                yaml.safe_dump(scenario, f)
                f.flush()
                self.expect_refused(needle, "asv_bringup", "spawn_agents.py", "pe_spawn", "--scenario", f.name)

    def test_invalid_global_lockstep_parameters(self):
        try:
            rospy.set_param("/lockstep", True)
            rospy.set_param("/lockstep_timeout", -1.0)
            self.expect_refused("'/lockstep_timeout' must be a finite number of seconds > 0", "asv_risk",
                                "tracker", "pe_track2")
            rospy.set_param("/lockstep", "yes")
            self.expect_refused("'/lockstep' has the wrong type", "asv_risk", "tracker", "pe_track3")
        finally:
            rospy.delete_param("/lockstep")
            rospy.delete_param("/lockstep_timeout")


if __name__ == "__main__":
    rosunit.unitrun("asv_bringup", "param_errors", ParamErrors, sys.argv)
