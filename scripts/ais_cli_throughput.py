#!/usr/bin/env python3
"""asv_ais_decode against gpsd's gpsdecode on the same input, side by side in one run.

The input is gpsd 3.22's whole regression file (sample.aivdm, all 27 message types) repeated until it
holds about --sentences sentences. Each decoder runs --repeats times in both JSON forms (-u and
scaled), alternating, and the best time of each counts. Prints sentences per second and the ratio, and
writes out/bench/ais_cli_vs_gpsdecode.json. Exit status 0 also when gpsdecode or the shared data is
missing (it says so): this is a measurement, not a test.

usage: scripts/ais_cli_throughput.py [--sentences N] [--repeats R] [--cli PATH]
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SAMPLE = os.path.join(ROOT, "..", "shared", "data", "ais", "gpsd-3.22", "sample.aivdm")


def timed(cmd, path):
    with open(path, "rb") as f:
        start = time.perf_counter()
        subprocess.run(cmd, stdin=f, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
        return time.perf_counter() - start


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--sentences", type=int, default=300000, help="sentences in the input (default 300000)")
    ap.add_argument("--repeats", type=int, default=3, help="runs of each decoder per form (default 3)")
    ap.add_argument("--cli", default=os.path.join(ROOT, "devel", "lib", "asv_core", "asv_ais_decode"))
    a = ap.parse_args()
    gpsdecode = shutil.which("gpsdecode")
    if not os.path.exists(SAMPLE) or not gpsdecode or not os.access(a.cli, os.X_OK):
        print("ais_cli_throughput: skipped (needs %s, gpsdecode and %s)" % (SAMPLE, a.cli))
        return 0
    with open(SAMPLE) as f:
        text = f.read()
    per_copy = sum(1 for line in text.splitlines() if line.startswith("!"))
    copies = max(1, a.sentences // per_copy)
    with tempfile.NamedTemporaryFile("w", suffix=".aivdm", delete=False) as tmp:
        for _ in range(copies):
            tmp.write(text)
        path = tmp.name
    sentences = copies * per_copy
    best = {}
    try:
        for form, flags in (("unscaled", ["-u"]), ("scaled", [])):
            for k in range(a.repeats):
                print("ais_cli_throughput: %s run %d/%d" % (form, k + 1, a.repeats), file=sys.stderr)
                for name, cmd in (("asv_ais_decode", [a.cli] + flags), ("gpsdecode", [gpsdecode, "-j"] + flags)):
                    t = timed(cmd, path)
                    best[(name, form)] = min(best.get((name, form), t), t)
    finally:
        os.unlink(path)
    result = {"cores": os.cpu_count(), "sentences": sentences, "input": "sample.aivdm x %d" % copies}
    for form in ("unscaled", "scaled"):
        ours, theirs = best[("asv_ais_decode", form)], best[("gpsdecode", form)]
        result[form] = {"asv_ais_decode_s": ours, "gpsdecode_s": theirs,
                        "asv_ais_decode_sentences_per_s": sentences / ours,
                        "gpsdecode_sentences_per_s": sentences / theirs, "ratio": theirs / ours}
        print("%-8s asv_ais_decode %.3f s (%.0f sentences/s), gpsdecode %.3f s (%.0f sentences/s): %.1fx"
              % (form, ours, sentences / ours, theirs, sentences / theirs, theirs / ours))
    os.makedirs(os.path.join(ROOT, "out", "bench"), exist_ok=True)
    with open(os.path.join(ROOT, "out", "bench", "ais_cli_vs_gpsdecode.json"), "w") as f:
        json.dump(result, f, indent=2)
    return 0


if __name__ == "__main__":
    sys.exit(main())
