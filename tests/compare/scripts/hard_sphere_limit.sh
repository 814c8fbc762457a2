#!/usr/bin/env bash
# scripts/hard-sphere-limit on the stored mu = 0 pours at N = 3000 (seeds 1-3 in both sets):
# every printed limit is stiff + 0.658 (stiff - main) of the printed means (to the printed
# 4 decimals: 1e-4 x 1.66 from rounding both), Z(1e-3) is the limit measured when this test
# was written (5.970 +- 0.005: a regression guard on the measurement), a pack held against
# the limit gets a P(Z) ratio line, and a bad count is a one-line usage error (status 2).
#   tests/compare/scripts/hard_sphere_limit.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build="$(realpath "$1")"
cd "$2"
fail() { echo "hard_sphere_limit: $*" >&2; exit 1; }
output="$(scripts/hard-sphere-limit --count 3000 --build-dir "$build" \
    --packs data/reference/stiff/n3000-mu0-seed1.xyz.gz)"
echo "$output"
grep -q '^N = 3000, mu = 0: 3 seeds, a = 0.658$' <<<"$output" || fail "no header line"
for metric in phi z_mean_tol_1e-3 z_mean_tol_1e-2; do
    read -r main stiff hard sgmp < <(awk -v m="$metric" '$1 == m {print $2, $3, $4, $5}' <<<"$output")
    awk -v m="$main" -v s="$stiff" -v h="$hard" 'BEGIN {
        e = s + 0.658 * (s - m); d = e - h; if (d < 0) d = -d; exit !(d <= 2e-4) }' ||
        fail "$metric: limit $hard is not stiff + 0.658 (stiff - main) of $main, $stiff"
    [ -n "$sgmp" ] && [ "$sgmp" != "-" ] || fail "$metric: no SGMP column"
done
z=$(awk '$1 == "z_mean_tol_1e-3" {print $4}' <<<"$output")
awk -v z="$z" 'BEGIN { exit !(z > 5.965 && z < 5.975) }' || fail "Z(1e-3) limit $z, expected 5.970 +- 0.005"
grep -q -E '^P\(Z\) 1e-3 distance [0-9.]+ over replicate distance [0-9.]+: ratio [0-9.]+$' <<<"$output" ||
    fail "no P(Z) ratio line"
set +e
message="$(scripts/hard-sphere-limit --count 0 --build-dir "$build" 2>&1 >/dev/null)"
status=$?
set -e
[ "$status" -eq 2 ] || fail "--count 0 exited with $status, expected 2"
[ "$(wc -l <<<"$message")" -eq 1 ] && grep -q '^hard-sphere-limit: --count 0' <<<"$message" ||
    fail "usage error is not one line naming the value: $message"
echo "hard_sphere_limit: ok"
