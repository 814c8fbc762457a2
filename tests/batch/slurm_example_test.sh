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
grep -q "^merge.sbatch: 1 of 3 shard summaries missing (tasks 2): rerun them" "$scratch/err" ||
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

# Submitted and rerun as documented, through a stand-in sbatch: submit records the sweep's
# environment in sweep.env; a lost shard makes the merge print one command, which reruns
# exactly that task with the same sweep and sgmp, and the merge after it.
mkdir -p "$scratch/fake" "$scratch/submitted"
ln -s "$source_dir/tests/batch/fake_sbatch" "$scratch/fake/sbatch"
cd "$scratch/submitted"
PATH="$scratch/fake:$PATH" SGMP="$sgmp" "$source_dir/scripts/slurm/submit" 3 "$scratch/sweep.toml" >/dev/null
[ -f summary.csv ] || { echo "slurm example: submit made no summary.csv" >&2; exit 1; }
rm summaries/shard-2.csv summary.csv
rm packs/large-dense/n80-s2.xyz.gz  # a pack of task 2, so the rerun has work to do
if env -u SGMP -u SGMP_SHARDS -u SGMP_SWEEP "$source_dir/scripts/slurm/merge.sbatch" \
        >/dev/null 2>"$scratch/err"; then
    echo "slurm example: the merge ran without shard 2" >&2
    exit 1
fi
command="$(sed -n 's/^merge.sbatch: 1 of 3 shard summaries missing (tasks 2): rerun them and this merge, in .*, with: //p' "$scratch/err")"
[ -n "$command" ] || { cat "$scratch/err" >&2; echo "slurm example: no rerun command" >&2; exit 1; }
[[ "$command" == *"--rerun 2" ]] || { echo "slurm example: rerun command '$command'" >&2; exit 1; }
env -u SGMP -u SGMP_SHARDS -u SGMP_SWEEP PATH="$scratch/fake:$PATH" \
    FAKE_SBATCH_LOG="$scratch/sbatch.log" bash -c "$command" >/dev/null
[ "$(cat "$scratch/sbatch.log")" == "sweep.sbatch 2"$'\n'"merge.sbatch single" ] ||
    { echo "slurm example: the rerun submitted: $(cat "$scratch/sbatch.log")" >&2; exit 1; }
if ! diff <(untimed "$scratch/serial/summary.csv") <(untimed summary.csv); then
    echo "slurm example: the rerun's merged summary differs from the serial run" >&2
    exit 1
fi
cmp "$scratch/serial/packs/large-dense/n80-s2.xyz.gz" packs/large-dense/n80-s2.xyz.gz
# Without submit's environment a task refuses to guess a sweep (it once ran ./sweep.toml).
mkdir -p "$scratch/bare" && cd "$scratch/bare"
if env -u SGMP_SWEEP -u SGMP_SHARDS SLURM_ARRAY_TASK_ID=3 SGMP="$sgmp" \
        "$source_dir/scripts/slurm/sweep.sbatch" >/dev/null 2>"$scratch/err"; then
    echo "slurm example: a task ran without a sweep" >&2
    exit 1
fi
grep -q "^sweep.sbatch: no sweep" "$scratch/err" || { cat "$scratch/err" >&2; exit 1; }
echo "slurm example: 3 tasks merged = serial run (16 packs byte-identical); a lost shard reruns with the merge's command"
