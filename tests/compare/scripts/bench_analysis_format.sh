#!/usr/bin/env bash
# The output format of `scripts/bench-analysis --quick`: a header, nine rows
# "caption  measured unit  target <=|>= value unit  PASS|FAIL" (measurement, five stages,
# the whole process, bytes per particle, pair-rate ratio) and the pair-rate line; it must finish in a minute.
#   tests/compare/scripts/bench_analysis_format.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build="$(realpath "$1")"
cd "$2"
start=$SECONDS
output="$(SGMP_BUILD_DIR="$build" timeout 60 scripts/bench-analysis --quick)"
echo "$output"
fail() { echo "bench_analysis_format: $*" >&2; exit 1; }
[ $((SECONDS - start)) -le 60 ] || fail "--quick took $((SECONDS - start)) s (more than 60)"
head -1 <<<"$output" | grep -q '^analysis benchmark: sgmp-compare measure, loose-random pack of 20000 particles' ||
    fail "no header line"
row='^  [A-Za-z].{33} +[0-9]+\.[0-9]{3} (s|B|x) +target (<=|>=) +[0-9]+\.[0-9]{3} (s|B|x) +(PASS|FAIL)$'
rows=$(grep -c -E "$row" <<<"$output" || true)
[ "$rows" -eq 9 ] || fail "$rows rows of the form 'caption measured target PASS|FAIL', expected 9"
for caption in 'measurement (all but reading)' overlaps 'Z(delta) + g(r) to 5 d + Q6' \
    'spatial ordering' phi 'phi(y)' 'whole process, wall clock' 'peak RSS per particle' 'fused pass / minimal scan rate'; do
    grep -q -F "  $caption " <<<"$output" || fail "no row '$caption'"
done
grep -q -E '^  pairs within 5 d of the [0-9]+ origins: [0-9]+; one core' <<<"$output" ||
    fail "no pair-rate line"
[ "$(wc -l <<<"$output")" -eq 11 ] || fail "expected 11 lines"
echo "bench_analysis_format: ok"
