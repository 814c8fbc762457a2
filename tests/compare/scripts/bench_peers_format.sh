#!/usr/bin/env bash
# The output format of `scripts/bench-peers --quick` (SGMP against LIGGGHTS at N = 300,
# sgmp-compare against LAMMPS on 20,000 spheres): a header, then per peer either one
# "skipped: ..." line (the program is not installed) or its lines and rows
# "caption  measured unit  target <=|>= value unit  PASS|FAIL". The LAMMPS cross-check row
# must PASS: coord/atom's mean coordination equals sgmp-compare's Z(1e-3) over all spheres.
#   tests/compare/scripts/bench_peers_format.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build="$(realpath "$1")"
cd "$2"
start=$SECONDS
output="$(SGMP_BUILD_DIR="$build" timeout 120 scripts/bench-peers --quick)"
echo "$output"
fail() { echo "bench_peers_format: $*" >&2; exit 1; }
[ $((SECONDS - start)) -le 120 ] || fail "--quick took $((SECONDS - start)) s (more than 120)"
head -1 <<<"$output" | grep -q '^peer benchmark (quick): SGMP against LIGGGHTS, sgmp-compare against LAMMPS' ||
    fail "no header line"
row='^  [A-Za-z|].{33} +[0-9]+\.[0-9]{3} (s|B|x|Z) +target (<=|>=) +[0-9]+\.[0-9]{3} (s|B|x|Z) +(PASS|FAIL)$'
has() { grep -q -E "$1" <<<"$output"; }
lines=1
if has '^  skipped: SGMP against LIGGGHTS \(liggghts is not installed\)$'; then
    lines=$((lines + 1))
else
    has '^  N = 300, mu = 0\.5: LIGGGHTS [0-9.]+ s, SGMP [0-9.]+ s \(whole processes, wall clock\)$' ||
        fail "no LIGGGHTS timing line"
    grep -E "$row" <<<"$output" | grep -q -F '  LIGGGHTS / SGMP time, N = 300 ' || fail "no LIGGGHTS row"
    lines=$((lines + 2))
fi
if has '^  skipped: sgmp-compare against LAMMPS \(.* is not installed\)$'; then
    lines=$((lines + 1))
else
    has '^  20000 particles: LAMMPS [0-9.]+ s, [0-9]+ MB \(one run, all spheres as origins\); sgmp-compare measure --no-voronoi [0-9.]+ s, [0-9]+ MB \(min of 3\)$' ||
        fail "no LAMMPS timing line"
    for caption in 'LAMMPS / sgmp-compare wall time' 'sgmp-compare / LAMMPS peak RSS'; do
        grep -E "$row" <<<"$output" | grep -q -F "  $caption " || fail "no row '$caption'"
    done
    has '^  cross-check, mean coordination of all 20000 spheres within d\(1 \+ 1e-3\): LAMMPS coord/atom [0-9.]+, sgmp-compare Z\(1e-3\) [0-9.]+$' ||
        fail "no cross-check line"
    grep -E "$row" <<<"$output" | grep -F '  |Z LAMMPS - Z sgmp-compare| ' | grep -q 'PASS$' ||
        fail "the coordination cross-check does not pass"
    lines=$((lines + 5))
fi
[ "$(wc -l <<<"$output")" -eq "$lines" ] || fail "expected $lines lines"
echo "bench_peers_format: ok"
