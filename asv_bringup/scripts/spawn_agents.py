#!/usr/bin/python3
"""Starts one planner_node per planning ship of a scenario, each in its own namespace.

A planning ship is the own ship when it has a planner and every target with `behaviour: planner`
(asv::Scenario::planningShips()). Ship S gets the node /S/planner (respawned when it dies): it reads
/S/odom, writes /S/cmd, /S/plan, /S/path, and - for dssa and dssa_plus in distributed mode - exchanges
intentions with the other ships on /intentions. The agents do not share a process or anything else:
run this script on several machines with --ships to place ships on different computers (README,
"Distributed DSSA").

Parameters of each node: asv_planning/config/planner_node.yaml, then planner, ship, scenario, seed,
distributed; for dssa/dssa_plus asv_planning/config/dssa.yaml under ~<planner>/, less the keys the
scenario's planner_params set for that planner (the node reads those from the scenario: a paper scenario
runs with the paper's values and mode); then --param-file (under every node's private namespace) and
--set SHIP:KEY=VALUE (one node's private key, YAML value).

    spawn_agents.py --scenario FILE [--planner NAME] [--ships a,b] [--seed N] [--output screen|log]
                    [--distributed true|false] [--param-file FILE] [--set SHIP:KEY=VALUE ...]
"""
import argparse
import sys

import rosparam
import rospkg
import rospy
import yaml

import roslaunch.core
import roslaunch.scriptapi

PLANNERS = ("aco", "dssa", "dssa_plus", "mopso", "ga")


def planning_ships(scenario):
    """[(name, planner)] of the scenario's planning ships, own ship first."""
    out = []
    own = scenario.get("own_ship") or {}
    if own.get("planner") and own.get("planner") != "none":
        out.append((str(own["name"]), str(own["planner"])))
    for t in scenario.get("targets") or []:
        if t.get("behaviour") == "planner":
            if not t.get("planner"):
                raise ValueError("target '%s' has behaviour planner but no planner" % t.get("name"))
            out.append((str(t["name"]), str(t["planner"])))
    return out


def planner_params(scenario, planner):
    """The scenario's planner_params for `planner` (a mapping, empty when it sets none); ValueError when
    planner_params or its entry for `planner` is not a mapping."""
    params = scenario.get("planner_params") or {}
    if not isinstance(params, dict):
        raise ValueError("planner_params must be a mapping of planner name to parameters, not %r" % (params,))
    own = params.get(planner) or {}
    if not isinstance(own, dict):
        raise ValueError("planner_params.%s must be a mapping of parameter to value, not %r" % (planner, own))
    return own


def package_defaults(defaults, scenario, planner):
    """The package's parameter file for `planner` without the keys the scenario's planner_params set:
    the node puts its private parameters over the scenario's, so a package default would override them."""
    own = planner_params(scenario, planner)
    return {k: v for k, v in defaults.items() if k not in own}


def parse_bool(text):
    if text.lower() in ("true", "1", "yes"):
        return True
    if text.lower() in ("false", "0", "no"):
        return False
    raise argparse.ArgumentTypeError("expected true or false, got '%s'" % text)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--scenario", required=True, help="scenario file (format 1)")
    ap.add_argument("--planner", default="", help="planner for every agent (default: each ship's own)")
    ap.add_argument("--ships", default="", help="comma-separated subset of the planning ships to start here")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--output", default="log", choices=("log", "screen"))
    ap.add_argument("--distributed", type=parse_bool, default=True, help="dssa/dssa_plus exchange intentions")
    ap.add_argument("--param-file", default="", help="YAML loaded under every node's private namespace")
    ap.add_argument("--set", action="append", default=[], metavar="SHIP:KEY=VALUE",
                    help="private parameter of one ship's node (VALUE parsed as YAML)")
    args = ap.parse_args(rospy.myargv(sys.argv)[1:])

    rospy.init_node("spawn_agents")
    with open(args.scenario) as f:
        scenario = yaml.safe_load(f)
    try:
        if not isinstance(scenario, dict):
            raise ValueError("not a scenario (a YAML mapping)")
        ships = planning_ships(scenario)
        for _, planner in ships:
            planner_params(scenario, args.planner or planner)  # its shape, before any node starts
    except ValueError as e:
        rospy.logfatal("spawn_agents: %s: %s", args.scenario, e)
        return 1
    if args.ships:
        wanted = [s.strip() for s in args.ships.split(",") if s.strip()]
        unknown = [s for s in wanted if s not in [n for n, _ in ships]]
        if unknown:
            rospy.logfatal("spawn_agents: %s not planning ships of %s (planning: %s)", ", ".join(unknown),
                           args.scenario, ", ".join(n for n, _ in ships))
            return 1
        ships = [(n, p) for n, p in ships if n in wanted]
    if not ships:
        rospy.logwarn("spawn_agents: no planning ship to start in %s", args.scenario)

    per_ship = {}
    for s in args.set:
        try:
            ship, kv = s.split(":", 1)
            key, value = kv.split("=", 1)
        except ValueError:
            rospy.logfatal("spawn_agents: --set '%s' is not SHIP:KEY=VALUE", s)
            return 1
        per_ship.setdefault(ship, []).append((key, yaml.safe_load(value)))
    for ship in per_ship:
        if ship not in [n for n, _ in ships]:
            rospy.logfatal("spawn_agents: --set for '%s', which is not started here", ship)
            return 1

    planning = rospkg.RosPack().get_path("asv_planning")
    node_yaml = rosparam.load_file(planning + "/config/planner_node.yaml")[0][0]
    dssa_yaml = rosparam.load_file(planning + "/config/dssa.yaml")[0][0]
    extra = rosparam.load_file(args.param_file)[0][0] if args.param_file else {}

    launch = roslaunch.scriptapi.ROSLaunch()
    launch.start()
    rospy.on_shutdown(launch.stop)
    for ship, planner in ships:
        planner = args.planner or planner
        if planner not in PLANNERS:
            rospy.logfatal("spawn_agents: ship '%s': unknown planner '%s' (known: %s)", ship, planner,
                           ", ".join(PLANNERS))
            return 1
        ns = "/%s/planner" % ship
        if rospy.has_param(ns):
            rospy.delete_param(ns)  # a previous run's keys would be unknown-key errors or stale values
        rosparam.upload_params(ns, node_yaml)
        rosparam.upload_params(ns, {"planner": planner, "ship": ship, "scenario": args.scenario,
                                    "seed": args.seed, "distributed": args.distributed})
        if planner in ("dssa", "dssa_plus"):
            rosparam.upload_params(ns + "/" + planner, package_defaults(dssa_yaml, scenario, planner))
        if extra:
            rosparam.upload_params(ns, extra)
        for key, value in per_ship.get(ship, []):
            rospy.set_param(ns + "/" + key, value)
        node = roslaunch.core.Node("asv_planning", "planner_node", name="planner", namespace="/" + ship,
                                   respawn=True, respawn_delay=1.0, output=args.output)
        launch.launch(node)
        rospy.loginfo("spawn_agents: started %s (%s)", ns, planner)
    rospy.spin()
    return 0


if __name__ == "__main__":
    sys.exit(main())
