#!/bin/bash
# make eval: every scenario of asv_bringup/scenarios/*.yaml through asv_batch with every planner that
# applies, several seeds; results in out/eval/results.jsonl, a report in out/eval/report.md and one
# trajectory plot per run in out/eval/plots/.
#
# Which planners run a scenario: the scenario's own_ship.planner when it names one; all five (aco,
# dssa, dssa_plus, mopso, ga) when the own ship has none (the textbook single encounters).
#
# usage: scripts/eval.sh [SEEDS]   (default 3; env EVAL_SCENARIOS="a b" restricts the scenarios)
set -u
SEEDS=${1:-3}
ROOT=$(cd "$(dirname "$0")/.." && pwd)
OUT=$ROOT/out/eval
BATCH=${ASV_BATCH:-$ROOT/devel/lib/asv_sim/asv_batch}
CHART=$ROOT/devel/lib/asv_core/asv_chart
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
if [ ${#scenarios[@]} -eq 0 ]; then echo "eval: no scenarios in asv_bringup/scenarios/"; exit 1; fi
# Plan: one line per (scenario, planner).
jobs=()
for f in "${scenarios[@]}"; do
  own=$($PY -c "import yaml,sys; print((yaml.safe_load(open(sys.argv[1])).get('own_ship') or {}).get('planner') or '')" "$f" 2>/dev/null)
  if [ -n "$own" ]; then jobs+=("$f|$own"); else for p in $ALL_PLANNERS; do jobs+=("$f|$p"); done; fi
done
total=$(( ${#jobs[@]} * SEEDS ))
echo "eval: ${#scenarios[@]} scenarios, ${#jobs[@]} scenario/planner pairs x $SEEDS seeds = $total runs"
start=$(date +%s)
n=0; failed=0
plots=()
for job in "${jobs[@]}"; do
  f=${job%%|*}; p=${job##*|}; name=$(basename "$f" .yaml)
  # The scenario's land (static obstacles and chart land) for the plots, once per scenario.
  [ -e "$OUT/traj/$name.land.txt" ] || "$CHART" --scenario "$f" --local "$OUT/traj/$name.land.txt" >/dev/null
  for seed in $(seq 1 "$SEEDS"); do
    n=$((n + 1))
    traj="$OUT/traj/${name}__${p}__s${seed}.csv"
    line=$("$BATCH" --scenario "$f" --planner "$p" --seed "$seed" --trajectory "$traj" --json "$OUT/results.jsonl" 2>&1 >/dev/null | tail -1)
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
       "%d runs, %s seeds per scenario/planner (scripts/eval.sh; format and scores: docs/evaluation.md)." % (len(rows), sys.argv[3]), "",
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
