#!/usr/bin/env bash
# scripts/slurm without Slurm: three array tasks of a small sweep (SLURM_ARRAY_TASK_ID set
# by hand), the merge, and the serial run of the same sweep. The merged summary must equal
# the serial one apart from the timing columns, and the packs must be byte-identical.
# Usage: slurm_example_test.sh SOURCE_DIR SGMP_EXECUTABLE
set -euo pipefail
source_dir="$1"
sgmp="$2"
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
cat >"$scratch/sweep.toml" <<'TOML'
seeds = "1-4"
count = [50, 80]
arrangement = ["loose-random", "large-dense"]
out-pattern = "packs/{arrangement}/n{count}-s{seed}.xyz.gz"
progress-seconds = 0
TOML
mkdir -p "$scratch/array" "$scratch/serial"
cd "$scratch/array"
for task in 1 2 3; do
    SLURM_ARRAY_TASK_ID=$task SGMP_SHARDS=3 SGMP_SWEEP="$scratch/sweep.toml" SGMP="$sgmp" \
        "$source_dir/scripts/slurm/sweep.sbatch" >/dev/null
done
# A missing shard summary fails the merge in one line naming the task.
mv summaries/shard-2.csv "$scratch/shard-2.csv"
if SGMP_SHARDS=3 SGMP="$sgmp" "$source_dir/scripts/slurm/merge.sbatch" >/dev/null 2>"$scratch/err"; then
    echo "slurm example: the merge ran without shard 2" >&2
    exit 1
fi
grep -q "^merge.sbatch: 1 of 3 shard summaries missing (tasks 2): resubmit" "$scratch/err" ||
    { cat "$scratch/err" >&2; exit 1; }
[ "$(wc -l <"$scratch/err")" -eq 1 ] || { echo "more than one line" >&2; exit 1; }
mv "$scratch/shard-2.csv" summaries/shard-2.csv
SGMP_SHARDS=3 SGMP="$sgmp" "$source_dir/scripts/slurm/merge.sbatch" >/dev/null
cd "$scratch/serial"
"$sgmp" batch --config "$scratch/sweep.toml" >/dev/null
# Every column but the timings (seconds, measure_seconds), found by name in the header.
untimed() {
    awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "seconds" || $i == "measure_seconds") t[i] = 1 }
             { line = ""; for (i = 1; i <= NF; i++) if (!(i in t)) line = line $i ","; print line }' "$1"
}
if ! diff <(untimed "$scratch/serial/summary.csv") <(untimed "$scratch/array/summary.csv"); then
    echo "slurm example: merged summary differs from the serial run" >&2
    exit 1
fi
[ "$(grep -vc '^#' "$scratch/array/summary.csv")" -eq 17 ] || { echo "wrong row count" >&2; exit 1; }
(cd "$scratch/serial" && find packs -type f | sort) >"$scratch/list"
while read -r pack; do
    cmp "$scratch/serial/$pack" "$scratch/array/$pack"
done <"$scratch/list"
[ "$(wc -l <"$scratch/list")" -eq 16 ] || { echo "wrong pack count" >&2; exit 1; }
echo "slurm example: 3 tasks merged = serial run (16 packs byte-identical)"
