#!/usr/bin/env bash
# The output format of `scripts/bench-engine --quick`: a header, a rule, nine time rows
# "label | N | seconds | B/particle | moves/particle | ns/move | travel/d | target |
# PASS|FAIL|-" (three arrangements at 10^3 and 10^4, the single column at 10^3 and 10^4, the
# step fall at 9000) and four scaling rows "scaling ARRANGEMENT 1000->10000 | - | ratio | - |
# - | - | - | target | PASS|FAIL (N^x)"; exit status 0 (every target met) or 3 (a target
# missed); it must finish in a minute. The moves per particle are the packs' own (`moves`
# header key over N), ns/move is the row's seconds over those moves, and the travel is never
# more than the path the moves make (each goes d/50 sideways).
#   tests/engine/scripts/bench_engine_format.sh SGMP_EXECUTABLE SOURCE_DIR
set -euo pipefail
binary="$(realpath "$1")"
cd "$2"
fail() { echo "bench_engine_format: $*" >&2; exit 1; }
start=$SECONDS
status=0
output="$(SGMP_BENCH_BINARY="$binary" timeout 60 scripts/bench-engine --quick)" || status=$?
echo "$output"
[ "$status" -eq 0 ] || [ "$status" -eq 3 ] || fail "exit status $status (expected 0 or 3)"
[ $((SECONDS - start)) -le 60 ] || fail "--quick took $((SECONDS - start)) s (more than 60)"
head -1 <<<"$output" |
    grep -q -E '^row +\| +N \| +seconds \| B/particle \| moves/particle \| ns/move \| travel/d \| target +\| verdict$' ||
    fail "no header line"
time_row='^[a-z][a-z ,-]+ \| +[0-9]+ \| +[0-9]+\.[0-9]{4} \| +[0-9]+ \| +[0-9]+\.[0-9] \| +[0-9]+ \| +[0-9]+\.[0-9]{3} \| [^|]+ \| (PASS|FAIL|-)$'
scaling_row='^scaling [a-z-]+ 1000->10000 +\| +- \| +[0-9]+\.[0-9]{2} \| +- \| +- \| +- \| +- \| [^|]+ \| (PASS|FAIL) \(N\^[0-9.]+\)$'
rows=$(grep -c -E "$time_row" <<<"$output" || true)
[ "$rows" -eq 9 ] || fail "$rows time rows, expected 9"
rows=$(grep -c -E "$scaling_row" <<<"$output" || true)
[ "$rows" -eq 4 ] || fail "$rows scaling rows, expected 4"
grep -q -E '^loose-random, --fall step +\| +9000 \| .*\| <= 0\.05 s +\| (PASS|FAIL)$' <<<"$output" ||
    fail "no step-fall row with its target"
# The moves per particle are the pack's: the single column slides furthest, every row moves.
moves_of() { grep -E "^$1 +\| +$2 \|" <<<"$output" | awk -F'|' '{ print $5 + 0 }'; }
[ "$(awk -v a="$(moves_of single-column 10000)" -v b="$(moves_of loose-random 10000)" \
    'BEGIN { print (a > b && b > 0) }')" = 1 ] ||
    fail "moves per particle: single column $(moves_of single-column 10000), loose random $(moves_of loose-random 10000)"
# ns/move is the row's seconds over its moves (to the rounding of the printed columns, 2 %).
grep -E "$time_row" <<<"$output" | awk -F'|' '{
        expected = $3 * 1e9 / ($5 * $2); printed = $6 + 0
        if (printed < 0.98 * expected - 1 || printed > 1.02 * expected + 1) {
            print "bench_engine_format: ns/move " printed ", seconds over moves " expected ": " $0
            bad = 1 } }
    END { exit bad }' >&2 || fail "ns/move is not the seconds over the moves"
# Every particle's path is made of moves of d/50 sideways (F = 50, the thesis'), so the mean
# travel from its starting place is at most moves/particle / 50; every row travels (the
# arrangements' particles all start away from their final places), and the single column,
# whose particles slide down a cone, furthest. The bound is exact arithmetic with no slack
# but the printed rounding (travel to 0.001 d, moves to 0.1: 0.002 d). With the exact fall
# the paths are nearly straight: 1.21-1.32 times the travel for every arrangement from 10^3
# to 10^6 (seed 1), so a path more than twice the travel means a travel in the wrong unit.
grep -E "$time_row" <<<"$output" | awk -F'|' '{
        travel = $7 + 0; path = $5 / 50; straight = ($1 !~ /fall step/)
        if (travel <= 0 || travel > path + 0.002 || (straight && path > 2 * travel)) {
            print "bench_engine_format: travel " travel " d against a path of " path " d: " $0
            bad = 1 } }
    END { exit bad }' >&2 || fail "the travel is not within the moves' path"
travel_of() { grep -E "^$1 +\| +$2 \|" <<<"$output" | awk -F'|' '{ print $7 + 0 }'; }
[ "$(awk -v a="$(travel_of single-column 10000)" -v b="$(travel_of loose-random 10000)" \
    'BEGIN { print (a > b) }')" = 1 ] ||
    fail "travel: single column $(travel_of single-column 10000), loose random $(travel_of loose-random 10000)"
[ "$(wc -l <<<"$output")" -eq 15 ] || fail "expected 15 lines"
# A missed target is reported as status 3, never hidden.
if grep -q -E '\| FAIL' <<<"$output"; then
    [ "$status" -eq 3 ] || fail "a FAIL row with exit status $status"
fi
echo "bench_engine_format: ok"
