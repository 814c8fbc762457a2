#!/usr/bin/env bash
# Byte-for-byte comparison of two sgmp-compare builds' `measure` outputs over many packs:
# SGMP packs of every arrangement and several options, and DEM pours of data/reference
# (main and variant sets). Both builds run from directories laid out alike (same relative
# pack and output paths), so even the recorded command lines agree; every output file
# must be identical (cmp). Also checks --threads 1 against --threads 2 for the new build
# (all but the recorded command line). Extra pack files may follow the four arguments.
#   tests/compare/scripts/measure_identical.sh OLD_SGMP_COMPARE NEW_SGMP_COMPARE SGMP WORKDIR [PACK...]
set -euo pipefail
old="$(realpath "$1")" new="$(realpath "$2")" sgmp="$(realpath "$3")" work="$4"
repo="$(cd "$(dirname "$0")/../../.." && pwd)"
mkdir -p "$work/packs"
work="$(realpath "$work")"
make_pack() {  # make_pack NAME OPTIONS...
    local name="$1"
    shift
    [ -s "$work/packs/$name.xyz.gz" ] ||
        "$sgmp" pack --out "$work/packs/$name.xyz.gz" --force "$@" >/dev/null
}
make_pack loose-3000 --count 3000 --arrangement loose-random --seed 3
make_pack large-dense-3000 --count 3000 --arrangement large-dense --seed 4
make_pack small-dense-2000 --count 2000 --arrangement small-dense --seed 5
make_pack column-1500 --count 1500 --arrangement single-column --seed 6
make_pack bidisperse-3000 --count 3000 --arrangement loose-random --seed 7 --size-modes 1:0.7,0.5:0.3
make_pack roll-2000 --count 2000 --arrangement loose-random --seed 8 --contact roll --walls block
make_pack relaxed-2000 --count 2000 --arrangement loose-random --seed 9 --relax frictionless --keep-uncertified
for pour in n0750-mu0.5-seed1 n0300-mu0.01-seed2; do
    cp -n "$repo/data/reference/$pour.xyz.gz" "$work/packs/"
done
cp -n "$repo/data/reference/variant/n1002-mu0.01-seed1.xyz.gz" "$work/packs/variant-n1002.xyz.gz"
for extra in "${@:5}"; do cp -n "$extra" "$work/packs/"; done

status=0
run() {  # run BUILD LABEL OPTIONS...
    local binary="$1" label="$2"
    shift 2
    mkdir -p "$work/$label"
    ln -sfn "$work/packs" "$work/$label/packs"
    (cd "$work/$label" && "$binary" measure packs/*.xyz.gz --out out --force "$@" >/dev/null)
}
compare() {  # compare LABEL_A LABEL_B [--except-command]: the command line records --threads
    local files=0 f g
    for f in "$work/$1/out"/*; do
        files=$((files + 1))
        g="$work/$2/out/$(basename "$f")"
        if [ "${3:-}" = --except-command ]; then
            cmp <(grep -v -E '"command":|^# command:' "$f") <(grep -v -E '"command":|^# command:' "$g") ||
                { echo "differs: $f $g" >&2; status=1; }
        else
            cmp "$f" "$g" || status=1
        fi
    done
    echo "$1 vs $2: $files files compared${3:+ (all but the command line)}"
}
run "$old" old
run "$new" new
compare old new
run "$old" old-options --gr-thesis --gr-container-space --gr-density space --q6-cutoff 1.4
run "$new" new-options --gr-thesis --gr-container-space --gr-density space --q6-cutoff 1.4
compare old-options new-options
run "$new" threads-1 --threads 1
run "$new" threads-2 --threads 2
compare threads-1 threads-2 --except-command
echo "packs: $(ls "$work/packs" | wc -l)"
[ $status -eq 0 ] && echo "measure_identical: every output identical" || echo "measure_identical: DIFFERENCES" >&2
exit $status
