#!/usr/bin/python3
"""One scenario through asv_batch, for the rostests that compare a ROS run with the in-process one."""
import json
import subprocess
import tempfile


def batch_result(scenario_file, *options, timeout=300):
    """The result (JSON) of asv_batch's first run of `scenario_file` with `options` (asv_batch's own, e.g.
    "--planner", "ga"). Raises AssertionError with the tail of its output when asv_batch fails."""
    with tempfile.NamedTemporaryFile(suffix=".jsonl") as js:
        proc = subprocess.run(["rosrun", "asv_sim", "asv_batch", "--scenario", scenario_file, "--quiet", "--json",
                               js.name] + list(options), stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                              timeout=timeout)
        if proc.returncode != 0:
            raise AssertionError("asv_batch failed:\n" + proc.stdout.decode(errors="replace")[-3000:])
        with open(js.name) as f:
            return json.loads(f.readline())
