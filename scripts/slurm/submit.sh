#!/bin/bash
# Runs the Monte-Carlo benchmark as a Slurm job array: generates the situations and the job list here,
# submits CHUNKS array tasks (scripts/slurm/benchmark.sbatch) and a report job that runs after all of them.
# Usage: scripts/slurm/submit.sh [CHUNKS] [benchmark.py options for generation, e.g. --situations 1000]
# The checkout (built: make build) must be on a file system every node sees, at the same path.
set -euo pipefail
cd "$(dirname "$0")/../.."
chunks=${1:-8}
shift || true
export PATH=/usr/bin:/bin:$PATH
set +u; source devel/setup.bash; set -u  # ROS setup scripts read unset variables
out=${BENCHMARK_OUT:-out/benchmark}
scripts/benchmark.py --out "$out" --prepare-only "$@"
mkdir -p "$out"
array=$(sbatch --parsable --export=ALL,BENCHMARK_OUT="$out" --array=0-$((chunks - 1)) \
        --output="$out/slurm-%A_%a.log" scripts/slurm/benchmark.sbatch)
report=$(sbatch --parsable --dependency=afterany:"$array" --job-name=asv-benchmark-report \
         --output="$out/slurm-report-%j.log" --wrap="bash -c 'cd $PWD && export PATH=/usr/bin:/bin:\$PATH && source devel/setup.bash && scripts/benchmark.py --out $out --report-only'")
echo "submit: array job $array ($chunks tasks), report job $report; results in $out/report.md"
