#!/usr/bin/env bash
# Every CSV that sgmp-compare writes (measure's per-pack curves, report.csv, headline.csv)
# reads with one numpy.genfromtxt(path, comments='#', names=True, delimiter=',') call, with
# the header row's names and at least one row; every JSON carries schema_version.
#   outputs_read_by_numpy.sh BUILD_DIR SOURCE_DIR SCRATCH
set -euo pipefail
build=$1 source=$2 scratch=$3
rm -rf "$scratch" && mkdir -p "$scratch"
for seed in 1 2; do
    "$build/sgmp/sgmp" pack --count 150 --arrangement loose-random --seed "$seed" \
        --out "$scratch/sgmp-$seed.xyz" >/dev/null
done
{
    echo "role,group,count,seed,seconds,path"
    for seed in 1 2; do echo "candidate,loose-random,150,$seed,0.01,$scratch/sgmp-$seed.xyz"; done
    for mu in 0.5 0.01; do
        for seed in 1 2 3; do
            echo "reference,DEM mu=$mu,150,$seed,1,$source/data/reference/n0150-mu$mu-seed$seed.xyz.gz"
        done
    done
} >"$scratch/manifest.csv"
SGMP_GNUPLOT= "$build/compare/sgmp-compare" crossval --manifest "$scratch/manifest.csv" \
    --out "$scratch/report" >/dev/null
"$build/compare/sgmp-compare" measure "$scratch/sgmp-1.xyz" --out "$scratch/metrics"
/usr/bin/python3 - "$scratch" <<'PY'
import glob, json, sys
import numpy as np
root = sys.argv[1]
csvs = sorted(glob.glob(root + "/report/*.csv") + glob.glob(root + "/metrics/*.csv"))
assert len(csvs) == 6, csvs  # report.csv, headline.csv, g_r, phi_y, p_z, voronoi_phi
for path in csvs:
    header = open(path).readline().strip().split(",")
    data = np.genfromtxt(path, comments="#", names=True, delimiter=",", dtype=None,
                         encoding="utf-8")
    names = [n for n in data.dtype.names]
    assert len(names) == len(header), (path, names, header)
    assert data.size > 0, path
    print(f"{path}: {data.size} rows, columns {', '.join(header[:4])}, ...")
jsons = sorted(glob.glob(root + "/report/*.json") + glob.glob(root + "/metrics/*.json"))
for path in jsons:
    with open(path) as f:
        doc = json.load(f)
    assert "schema_version" in doc, path
print(f"{len(csvs)} CSV files read by numpy.genfromtxt, {len(jsons)} JSON files with schema_version")
PY
