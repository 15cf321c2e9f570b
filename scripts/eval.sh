#!/bin/bash
# make eval: every scenario of asv_bringup/scenarios/*.yaml through asv_batch with every planner that
# applies, several seeds; results in out/eval/results.jsonl, a report in out/eval/report.md and one
# trajectory plot per run in out/eval/plots/.
#
# Which planners run a scenario: the scenario's own_ship.planner when it names one; all five (aco,
# dssa, dssa_plus, mopso, ga) when the own ship has none (the textbook single encounters).
#
# Real traffic: when the New York AIS hour is present (env ASV_AIS_LOG, default
# ../shared/data/ais/real/NYHarbor_2020_06_30_first_hour.csv), two scenarios are made from it with
# asv_scenario_from_ais into out/eval/real/ (never committed: the recorded data stays outside the
# repository) and run with all five planners, seed 1 only (recorded traffic has no randomness; a run
# through 90 real ships takes minutes). Without the file a line says they are skipped.
#
# Mode: every planner runs in sea mode (the stack at sea), also on the papers' scenarios whose files
# default to paper mode; EVAL_MODE=paper runs the methods as published (make papers compares those).
#
# usage: scripts/eval.sh [SEEDS]   (default 3; env EVAL_SCENARIOS="a b" restricts the scenarios)
set -u
SEEDS=${1:-3}
MODE=${EVAL_MODE:-sea}
ROOT=$(cd "$(dirname "$0")/.." && pwd)
OUT=$ROOT/out/eval
BATCH=${ASV_BATCH:-$ROOT/devel/lib/asv_sim/asv_batch}
CHART=$ROOT/devel/lib/asv_core/asv_chart
FROM_AIS=$ROOT/devel/lib/asv_core/asv_scenario_from_ais
AIS_LOG=${ASV_AIS_LOG:-$ROOT/../shared/data/ais/real/NYHarbor_2020_06_30_first_hour.csv}
PY=/usr/bin/python3
ALL_PLANNERS="aco dssa dssa_plus mopso ga"
if [ ! -x "$BATCH" ]; then echo "eval: $BATCH not built (make build)"; exit 1; fi
rm -rf "$OUT" && mkdir -p "$OUT/traj" "$OUT/plots"
: > "$OUT/results.jsonl"
scenarios=()
for f in "$ROOT"/asv_bringup/scenarios/*.yaml; do
  [ -e "$f" ] || continue
  name=$(basename "$f" .yaml)
  if [ -n "${EVAL_SCENARIOS:-}" ] && ! [[ " $EVAL_SCENARIOS " == *" $name "* ]]; then continue; fi
  scenarios+=("$f")
done
# The two real-traffic scenarios (asv_bringup/scenarios/README.md, "Real traffic"): an inbound ship
# through the Narrows to the Hudson, and the Staten Island ferry John F. Kennedy's own crossing to
# Whitehall (her logged start, course and speed; the goal off the slip, afloat on GSHHG).
real=()
if [ -r "$AIS_LOG" ]; then
  mkdir -p "$OUT/real"
  "$FROM_AIS" "$AIS_LOG" --quiet --start 2020-06-30T00:05:00 --duration 3000 --own-speed 12 \
    --own-start 40.600,-74.043 --own-goal 40.715,-74.025 --out "$OUT/real/ny_real_upper_bay.yaml" \
    && real+=("$OUT/real/ny_real_upper_bay.yaml")
  "$FROM_AIS" "$AIS_LOG" --quiet --start 2020-06-30T00:04:00 --duration 1500 --own-mmsi 367000190 \
    --own-goal 40.6975,-74.0165 --out "$OUT/real/ny_real_ferry.yaml" && real+=("$OUT/real/ny_real_ferry.yaml")
  [ ${#real[@]} -eq 2 ] || { echo "eval: asv_scenario_from_ais failed on $AIS_LOG"; exit 1; }
  for f in "${real[@]}"; do
    name=$(basename "$f" .yaml)
    if [ -z "${EVAL_SCENARIOS:-}" ] || [[ " $EVAL_SCENARIOS " == *" $name "* ]]; then scenarios+=("$f"); fi
  done
else
  echo "eval: real-traffic scenarios SKIPPED: no AIS log at $AIS_LOG (set ASV_AIS_LOG)"
fi
if [ ${#scenarios[@]} -eq 0 ]; then echo "eval: no scenarios in asv_bringup/scenarios/"; exit 1; fi
# Plan: one line per (scenario, planner).
jobs=()
for f in "${scenarios[@]}"; do
  own=$($PY -c "import yaml,sys; print((yaml.safe_load(open(sys.argv[1])).get('own_ship') or {}).get('planner') or '')" "$f" 2>/dev/null)
  if [ -n "$own" ]; then jobs+=("$f|$own"); else for p in $ALL_PLANNERS; do jobs+=("$f|$p"); done; fi
done
total=0
for job in "${jobs[@]}"; do if [[ "$job" == "$OUT/real/"* ]]; then total=$((total + 1)); else total=$((total + SEEDS)); fi; done
echo "eval: ${#scenarios[@]} scenarios, ${#jobs[@]} scenario/planner pairs, $total runs ($SEEDS seeds; real traffic 1)"
start=$(date +%s)
n=0; failed=0
plots=()
for job in "${jobs[@]}"; do
  f=${job%%|*}; p=${job##*|}; name=$(basename "$f" .yaml)
  # The scenario's land (static obstacles and chart land) for the plots, once per scenario.
  [ -e "$OUT/traj/$name.land.txt" ] || "$CHART" --scenario "$f" --local "$OUT/traj/$name.land.txt" >/dev/null
  seeds=$SEEDS; [[ "$f" == "$OUT/real/"* ]] && seeds=1
  for seed in $(seq 1 "$seeds"); do
    n=$((n + 1))
    traj="$OUT/traj/${name}__${p}__s${seed}.csv"
    line=$("$BATCH" --scenario "$f" --planner "$p" --set "$p.mode=$MODE" --seed "$seed" --trajectory "$traj" --json "$OUT/results.jsonl" 2>&1 >/dev/null | tail -1)
    rc=${PIPESTATUS[0]}
    if [ "$rc" -ne 0 ] || [ ! -s "$traj" ]; then failed=$((failed + 1)); echo "[$n/$total] FAILED $name / $p / seed $seed: $line";
    else echo "[$n/$total] $line"; plots+=("$traj" "$OUT/plots/${name}__${p}__s${seed}.png"); fi
  done
done
echo "eval: plotting ${#plots[@]} files"
[ ${#plots[@]} -gt 0 ] && $PY "$ROOT/scripts/plot_trajectory.py" --pairs "${plots[@]}" || true
$PY - "$OUT/results.jsonl" "$OUT/report.md" "$SEEDS" <<'PYEOF'
import json, sys, statistics
from collections import OrderedDict
rows = [json.loads(l) for l in open(sys.argv[1]) if l.strip()]
groups = OrderedDict()
for r in rows:
    groups.setdefault((r["scenario"], r["planner"]), []).append(r)
def fmt(v, f="%.0f"):
    return "-" if v is None else f % v
out = ["# asv_batch evaluation", "",
       "%d runs, %s seeds per scenario/planner, seed 1 for the real-traffic scenarios ny_real_* (scripts/eval.sh; format and scores: docs/evaluation.md)." % (len(rows), sys.argv[3]), "",
       "| scenario | planner | runs | collisions | groundings | safety violations | arrived | min separation m (worst / mean) | COLREGs score (mean / worst) | path ratio (mean) | plan time ms (median / max) |",
       "|---|---|---|---|---|---|---|---|---|---|---|"]
for (s, p), rs in groups.items():
    seps = [r["min_separation_m"] for r in rs if r["min_separation_m"] is not None]
    sc = [r["colregs_score"] for r in rs]
    pr = [r["path_ratio"] for r in rs if r["path_ratio"] is not None]
    med = [r["plan_time_ms"]["median"] for r in rs if r["plan_time_ms"]["median"] is not None]
    mx = [r["plan_time_ms"]["max"] for r in rs if r["plan_time_ms"]["max"] is not None]
    out.append("| %s | %s | %d | %d | %d | %d | %d | %s / %s | %.2f / %.2f | %s | %s / %s |" % (
        s, p, len(rs), sum(r["collision"] for r in rs), sum(r["grounding"] for r in rs), sum(r["safety_violation"] for r in rs),
        sum(r["arrived"] for r in rs), fmt(min(seps) if seps else None), fmt(statistics.mean(seps) if seps else None),
        statistics.mean(sc), min(sc), fmt(statistics.mean(pr) if pr else None, "%.3f"),
        fmt(statistics.median(med) if med else None, "%.1f"), fmt(max(mx) if mx else None, "%.1f")))
out += ["", "## Totals", ""]
out.append("- runs: %d, collisions: %d, groundings: %d, safety violations: %d, arrived: %d" % (
    len(rows), sum(r["collision"] for r in rows), sum(r["grounding"] for r in rows),
    sum(r["safety_violation"] for r in rows), sum(r["arrived"] for r in rows)))
if rows:
    out.append("- mean COLREGs score: %.3f" % statistics.mean(r["colregs_score"] for r in rows))
out += ["", "## COLREGs notes (first seed of each pair)", ""]
for (s, p), rs in groups.items():
    notes = ["%s: %s" % (t["name"], "; ".join(t["colregs_notes"])) for t in rs[0]["targets"] if t["colregs_notes"] and not t["colregs_ok"]]
    if notes:
        out.append("- %s / %s: %s" % (s, p, " | ".join(notes)))
out += ["", "Trajectory plots: `plots/<scenario>__<planner>__s<seed>.png`."]
open(sys.argv[2], "w").write("\n".join(out) + "\n")
print("\n".join(out[:len(groups) + 6]))
PYEOF
echo "eval: $n runs ($failed failed) in $(( $(date +%s) - start )) s; results out/eval/results.jsonl, report out/eval/report.md, plots out/eval/plots/"
[ "$failed" -eq 0 ]
