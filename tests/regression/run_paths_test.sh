#!/usr/bin/env bash
# scripts/run into a directory whose name holds a space, a comma and quotes; a truncated
# pack is made anew, packs live under the engine's content identity, an option without
# its value is a usage error, --seed-budget stops adding seeds.
#   run_paths_test.sh BUILD_DIR
set -euo pipefail
cd "$(dirname "$0")/../.."
build=$1
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
out="$scratch/run dir, \"quoted\""
fail() { echo "run_paths_test: $*" >&2; exit 1; }
run() { scripts/run --counts 150 --seeds "1 2" --arrangements loose-random --frictions 0.5 \
            --out "$out" --build-dir "$build" >"$scratch/log" 2>&1 || { cat "$scratch/log" >&2; fail "scripts/run failed"; }; }

run
[[ -f "$out/report/report.md" ]] || fail "no report in '$out'"
[[ "$(ls -A "$scratch")" == "log"$'\n'"run dir, \"quoted\"" ]] || fail "files outside --out: $(ls -A "$scratch")"
grep -q '^candidate,loose-random,150,1,[0-9.]*,"'"$scratch"'/run dir, ""quoted""/packs/' "$out/manifest.csv" \
    || fail "the manifest does not quote the path: $(sed -n 2p "$out/manifest.csv")"
engine=$(sha256sum "$build/sgmp/sgmp" | cut -c1-12)
pack=$(ls "$out"/packs/sgmp-*-"$engine"/loose-random/n0150-seed1.xyz) || fail "no pack under the engine identity $engine"

# Seeds added until decided: the looks ran to the end, and every candidate row carries its look.
[[ $(wc -l <"$out/.looks/seeds-needed.csv") == 1 ]] || fail "groups left open after the loop"
head -1 "$out/report/report.csv" | grep -q ',look,looks,alpha_spent,nominal_alpha,limited_by,pours_to_decide$' \
    || fail "report.csv has no look columns"
grep -q '^run: look 1: ' "$scratch/log" || fail "no progress line for look 1"
grep -Eq '^run: done in [0-9.]+ s: [0-9]+ SGMP packs \(([0-9]+) packed and timed now, 0 reused\), [0-9]+ DEM pours, [0-9]+ looks; headline [0-9]+ agree, [0-9]+ differ, [0-9]+ inconclusive; report ' \
    "$scratch/log" || fail "no closing line: $(tail -n 1 "$scratch/log")"

# --seed-budget 0: no group is extended; each open one is named, and the report is written.
scripts/run --counts 150 --seeds "1 2" --arrangements loose-random --frictions 0.5 --out "$out" \
    --build-dir "$build" --seed-budget 0 >"$scratch/log0" 2>&1 || { cat "$scratch/log0" >&2; fail "--seed-budget 0 failed"; }
open=$(( $(wc -l <"$out/.looks/seeds-needed.csv") - 1 ))
if (( open > 0 )); then
    grep -q '^run: look 2: loose-random N=150 not extended: 5 more seeds would take its packing to about [0-9]* s, past --seed-budget 0 s; [0-9]* rows stay undecided$' \
        "$scratch/log0" || fail "an open group was not named: $(cat "$scratch/log0")"
fi
grep -q '^run: 1 looks, 0 SGMP seeds added' "$scratch/log0" || fail "--seed-budget 0 added seeds: $(cat "$scratch/log0")"

head -5 "$pack" >"$scratch/short" && cat "$scratch/short" >"$pack"  # header intact, lines lost
run
[[ "$(wc -l <"$pack")" == 152 ]] || fail "a truncated pack was reused ($(wc -l <"$pack") lines)"
# Only the pack made anew carries a time: a reused one was timed by another run.
grep -Eq '^candidate,loose-random,150,1,[0-9.]+,' "$out/manifest.csv" || fail "the remade pack has no time"
grep -q '^candidate,loose-random,150,2,,' "$out/manifest.csv" || fail "a reused pack carries its old time"
grep -Eq '^run: done in .* \(1 packed and timed now, [1-9][0-9]* reused\)' "$scratch/log" \
    || fail "the closing line does not count the reused packs: $(tail -n 1 "$scratch/log")"
grep -q 'of [0-9]* packs timed in this run' "$out/report/report.md" \
    || fail "the report does not say how many packs this run timed"

status=0
scripts/run --max-seeds 1 --build-dir "$build" 2>"$scratch/err" || status=$?
[[ $status == 2 && "$(cat "$scratch/err")" == "run: --max-seeds '1' must be an integer from 2 to 10000" ]] \
    || fail "--max-seeds 1: status $status, '$(cat "$scratch/err")'"
status=0
scripts/run --counts 2>"$scratch/err" || status=$?
[[ $status == 2 && "$(cat "$scratch/err")" == "run: --counts needs a value (see --help)" ]] \
    || fail "--counts without a value: status $status, '$(cat "$scratch/err")'"
# A newline in --out once sent packs to a stray file outside it: refused before any work.
status=0
scripts/run --counts 150 --out "$scratch/a"$'\n'"b" --build-dir "$build" 2>"$scratch/err" || status=$?
[[ $status == 2 && "$(cat "$scratch/err")" == *"holds a control character"* ]] \
    || fail "--out with a newline: status $status, '$(cat "$scratch/err")'"
[[ ! -e "$scratch/a" && ! -e "$scratch/a"$'\n'"b" ]] || fail "--out with a newline wrote something"
# The blend job: periodic SGMP packs of the bimodal blend against its stored pours, one
# report per blend; a name that is no blend is a usage error.
scripts/run --blends bimodal --counts 1002 --seeds 1 --modes "loose-random loose-random+relax" \
    --frictions 0.5 --out "$out" --build-dir "$build" --no-pictures >"$scratch/log" 2>&1 \
    || { cat "$scratch/log" >&2; fail "scripts/run --blends failed"; }
[[ -f "$out/blends/bimodal/report/report.md" ]] || fail "no blend report"
# Progress lines name their pack; none is left in the program's own unnamed form.
! grep -q '^sgmp: ' "$scratch/log" || fail "an unnamed progress line: $(grep -m1 '^sgmp: ' "$scratch/log")"
grep -q '^## Per-species verdict matrix' "$out/blends/bimodal/report/report.md" \
    || fail "no per-species verdict matrix in the blend report"
blend_manifest="$out/blends/bimodal/manifest.csv"
[[ $(grep -c '^candidate,loose-random,1002,1,' "$blend_manifest") == 1 ]] || fail "no blend candidate"
[[ $(grep -c '^candidate,loose-random+relax,1002,1,' "$blend_manifest") == 1 ]] || fail "no relaxed blend candidate"
[[ $(grep -c '^reference,DEM bimodal mu=0.5,1002,' "$blend_manifest") == 5 ]] || fail "not 5 DEM pours"
# Per-species rows (species_rows.hpp) with their declared margins; none for equal spheres.
blend_csv="$out/blends/bimodal/report/report.csv"
for row in 'species_1:z_mean_tol_1e-2,contacts/particle' 'species_2:voronoi_phi_mean,ratio' \
           'mixing_deviation_max,ratio'; do
    grep -q ",DEM bimodal mu=0.5,$row," "$blend_csv" || fail "no row $row in the blend report"
done
! grep -q 'species_' "$out/report/report.csv" || fail "species rows for equal spheres"
relaxed_blend=$(ls "$out"/packs/sgmp-*-"$engine"/blends/bimodal/loose-random+relax/n1002-seed1.xyz)
"$build/compare/sgmp-compare" header "$relaxed_blend" sides certified | tr '\n' ' ' \
    | grep -q '^periodic true $' || fail "the relaxed blend pack is not a certified periodic pack"
blend_pack=$(ls "$out"/packs/sgmp-*-"$engine"/blends/bimodal/loose-random/n1002-seed1.xyz)
"$build/compare/sgmp-compare" header "$blend_pack" sides size_modes | tr '\n' ' ' \
    | grep -q '^periodic 1:0.5,0.5:0.5 $' || fail "the blend pack is not periodic bimodal"
status=0
scripts/run --blends nonsense --build-dir "$build" 2>"$scratch/err" || status=$?
[[ $status == 2 ]] || fail "--blends nonsense: status $status"
echo "run_paths_test: passed"
