#!/usr/bin/python3
"""Soak test: a long scenario through the whole ROS pipeline (scenario.launch) as fast as the pipeline
sustains it (sim_node rate 0: it keeps pace with the risk node), watching every node.

Pass criteria (docs/reliability.md): no node dies; each node's resident memory at the end is within
--max-growth (10 %) of its value once warmed up (after --warmup simulated seconds); every rate that a node
checks in its diagnostics stays within its bounds (no frequency WARN/ERROR after the warm-up).
Writes OUT/summary.json and OUT/rss.csv; exit status 0 when every criterion holds, 1 otherwise.

Default: asv_bringup/test/soak_50_ships.yaml (the own ship and 49 ships, 2 hours), MOPSO.
Run from the repository root after `make build` (`make soak` does both).
"""
import argparse
import csv
import json
import os
import re
import signal
import subprocess
import sys
import threading
import time
import xmlrpc.client

import rosgraph
import rospy
from diagnostic_msgs.msg import DiagnosticArray, DiagnosticStatus
from rosgraph_msgs.msg import Clock

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EPOCH = 1.0e9  # sim_node's ROS time of simulation time 0
RATE_WORDS = re.compile(r"frequency|rate", re.IGNORECASE)


def node_pids(master):
    """{node name: pid} of every node registered with the master."""
    pids = {}
    try:
        state = master.getSystemState()
        names = sorted({n for group in state for _, nodes in group for n in nodes})
    except Exception:
        return pids
    for n in names:
        try:
            uri = master.lookupNode(n)
            code, _, pid = xmlrpc.client.ServerProxy(uri).getPid("/soak")
            if code == 1:
                pids[n] = int(pid)
        except Exception:
            pass
    return pids


def rss_mib(pid):
    try:
        with open("/proc/%d/status" % pid) as f:
            for line in f:
                if line.startswith("VmRSS:"):
                    return int(line.split()[1]) / 1024.0
    except OSError:
        return None
    return None


def sample_loop(a, launch, wall0, sim_t, samples, pids, master):
    """Every a.sample wall seconds until the launch ends: each node's RSS into samples and OUT/rss.csv."""
    with open(os.path.join(a.out, "rss.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["wall_s", "sim_s", "node", "rss_mib"])
        while launch.poll() is None:
            time.sleep(a.sample)
            fresh = node_pids(master)
            pids.update(fresh)
            row = {n: rss_mib(p) for n, p in pids.items()}
            row = {n: r for n, r in row.items() if r is not None and n in fresh}
            now = time.time() - wall0
            samples.append((now, sim_t[0], row))
            for n, r in sorted(row.items()):
                w.writerow(["%.1f" % now, "%.1f" % sim_t[0], n, "%.2f" % r])
            f.flush()
            print("soak: wall %5.0f s, sim %6.0f s (%.1fx), %d nodes, RSS %.0f MiB in all" %
                  (now, sim_t[0], sim_t[0] / max(now, 1e-3), len(row), sum(row.values())), flush=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--scenario", default=os.path.join(ROOT, "asv_bringup", "test", "soak_50_ships.yaml"))
    ap.add_argument("--planner", default="mopso", help="own ship's planner (default mopso)")
    ap.add_argument("--sim-time", type=float, default=7200.0, help="simulated seconds (default 7200)")
    ap.add_argument("--warmup", type=float, default=600.0,
                    help="simulated seconds before the memory baseline and the rate checks (default 600)")
    ap.add_argument("--max-growth", type=float, default=10.0, help="largest RSS growth allowed [%%] (default 10)")
    ap.add_argument("--sample", type=float, default=10.0, help="wall seconds between samples (default 10)")
    ap.add_argument("--out", default=os.path.join(ROOT, "out", "soak"), help="output folder (default out/soak)")
    ap.add_argument("--exempt", default="/evaluator,/rosout",
                    help="nodes whose memory grows with the run by design, reported but not judged: the "
                         "evaluator records every ship's track for the result (default /evaluator,/rosout)")
    a = ap.parse_args()
    a.out = os.path.abspath(a.out)  # the nodes run in ROS_HOME: a relative result path would land there
    a.scenario = os.path.abspath(a.scenario)
    if "ROS_PACKAGE_PATH" not in os.environ:
        sys.exit("soak: source devel/setup.bash first")
    os.makedirs(a.out, exist_ok=True)
    name = os.path.splitext(os.path.basename(a.scenario))[0]
    launch_log = open(os.path.join(a.out, "launch.log"), "w")
    cmd = ["roslaunch", "asv_bringup", "scenario.launch", "scenario:=" + name, "scenario_file:=" + a.scenario,
           "planner:=" + a.planner, "rate:=0", "max_sim_time:=%g" % a.sim_time, "start_delay:=1.0",
           "out:=" + a.out, "result:=" + os.path.join(a.out, "result.json"), "output:=log"]
    print("soak: %s" % " ".join(cmd), flush=True)
    wall0 = time.time()
    launch = subprocess.Popen(cmd, stdout=launch_log, stderr=subprocess.STDOUT, start_new_session=True)

    master = None
    for _ in range(100):
        try:
            master = xmlrpc.client.ServerProxy(rosgraph.get_master_uri())
            master.getSystemState("/soak")
            break
        except Exception:
            master = None
            time.sleep(0.2)
    if master is None:
        launch.kill()
        sys.exit("soak: no ROS master came up (see %s/launch.log)" % a.out)

    class Master:  # xmlrpc wants the caller id first
        def getSystemState(self):
            return master.getSystemState("/soak")[2]

        def lookupNode(self, n):
            return master.lookupNode("/soak", n)[2]

    rospy.init_node("soak", anonymous=True, disable_signals=True)
    sim_t = [0.0]
    lock = threading.Lock()
    bad_rates = {}  # (status name, message) -> count, after the warm-up
    levels = {}     # status name -> (worst level, its message) after the warm-up

    def on_clock(m):
        sim_t[0] = m.clock.to_sec() - EPOCH

    def on_diag(m):
        if sim_t[0] < a.warmup:
            return
        with lock:
            for st in m.status:
                if st.level > levels.get(st.name, (-1, ""))[0]:
                    levels[st.name] = (int(st.level), st.message)
                if st.level >= DiagnosticStatus.WARN and RATE_WORDS.search(st.message):
                    key = (st.name, st.message)
                    bad_rates[key] = bad_rates.get(key, 0) + 1

    rospy.Subscriber("/clock", Clock, on_clock, queue_size=10)
    rospy.Subscriber("/diagnostics", DiagnosticArray, on_diag, queue_size=100)

    samples = []  # (wall, sim, {node: rss})
    pids = {}
    try:
        sample_loop(a, launch, wall0, sim_t, samples, pids, Master())
    except KeyboardInterrupt:
        os.killpg(launch.pid, signal.SIGINT)
        launch.wait(timeout=60)
        raise
    wall = time.time() - wall0
    launch_log.close()
    with open(os.path.join(a.out, "launch.log")) as f:
        log = f.read()
    died = sorted(set(re.findall(r"\[([^\]]+)\] process has died", log)))
    died = [d for d in died if not d.startswith("sim_node")]  # sim_node ends the run (required)

    # Memory: each node's RSS at its first sample after the warm-up against its last one but the very last
    # (which may catch it shutting down). A node that did not answer at some sample has none there.
    per_node = {}
    for _, t, row in samples:
        for n, r in row.items():
            per_node.setdefault(n, []).append((t, r))
    growth = {}
    for n, series in per_node.items():
        warm = [r for t, r in series if t >= a.warmup]
        if len(warm) < 3 or warm[0] <= 0:
            continue
        growth[n] = {"rss_warm_mib": round(warm[0], 1), "rss_end_mib": round(warm[-2], 1),
                     "rss_max_mib": round(max(r for _, r in series), 1),
                     "growth_pct": round(100.0 * (warm[-2] - warm[0]) / warm[0], 2)}
    result = {}
    try:
        with open(os.path.join(a.out, "result.json")) as f:
            result = json.load(f)
    except (OSError, ValueError):
        pass
    reached = samples[-1][1] if samples else 0.0
    exempt = {n for n in a.exempt.split(",") if n}
    summary = {
        "scenario": a.scenario, "planner": a.planner, "cores": os.cpu_count(),
        "sim_time_s": a.sim_time, "sim_time_reached_s": round(reached, 1),
        "wall_time_s": round(wall, 1), "real_time_factor": round(a.sim_time / wall, 2) if wall > 0 else None,
        "nodes_died": died, "rss": growth, "rss_exempt": sorted(exempt),
        "rate_warnings_after_warmup": [{"status": k[0], "message": k[1], "count": v} for k, v in sorted(bad_rates.items())],
        "worst_diagnostic_after_warmup": {n: {"level": lv, "message": m} for n, (lv, m) in sorted(levels.items())},
        "result": {k: result.get(k) for k in ("collision", "min_separation_m", "safety_violation", "arrived")},
    }
    too_big = {n: g for n, g in growth.items()
               if g["growth_pct"] > a.max_growth and n not in exempt and not n.startswith("/soak")}
    ok = not died and not too_big and not bad_rates and bool(growth) and launch.returncode == 0
    summary["pass"] = ok
    with open(os.path.join(a.out, "summary.json"), "w") as f:
        json.dump(summary, f, indent=2)
    print(json.dumps(summary, indent=2))
    if died:
        print("soak: FAIL: nodes died: %s" % died)
    if too_big:
        print("soak: FAIL: resident memory grew more than %.0f %%: %s" % (a.max_growth, too_big))
    if bad_rates:
        print("soak: FAIL: rate warnings after the warm-up: %s" % bad_rates)
    print("soak: %s (%s/summary.json)" % ("PASS" if ok else "FAIL", a.out))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
