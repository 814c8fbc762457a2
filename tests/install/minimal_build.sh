#!/bin/sh
# The build of a cluster node with Eigen, CLI11 and Boost only: every optional part off
# (SGMP_WITH_MPI, SGMP_WITH_CLP, SGMP_BUILD_REPORT, SGMP_BUILD_PYTHON, BUILD_TESTING), and
# CMake told not to find MPI, CGAL, Python, pybind11, nlohmann-json or pkg-config (so the
# build cannot use them even where they are installed). Then:
#   - `sgmp pack` gives the bytes of the full build's `sgmp pack`;
#   - `sgmp batch` writes its summary;
#   - what needs a missing part is refused in one line naming it: --relax (CLP, exit 2),
#     --measure (the metrics, exit 2), a batch started by an MPI launcher (exit 1).
#   minimal_build.sh SOURCE_DIR FULL_SGMP SCRATCH
set -eu
source=$1 full=$2 scratch=$3
rm -rf "$scratch" && mkdir -p "$scratch/run"
cmake -S "$source" -B "$scratch/build" -DCMAKE_BUILD_TYPE=Release -DSGMP_WERROR=ON \
      -DSGMP_WITH_MPI=OFF -DSGMP_WITH_CLP=OFF -DSGMP_BUILD_REPORT=OFF -DSGMP_BUILD_PYTHON=OFF \
      -DBUILD_TESTING=OFF -DCMAKE_DISABLE_FIND_PACKAGE_MPI=ON \
      -DCMAKE_DISABLE_FIND_PACKAGE_CGAL=ON -DCMAKE_DISABLE_FIND_PACKAGE_Python=ON \
      -DCMAKE_DISABLE_FIND_PACKAGE_pybind11=ON -DCMAKE_DISABLE_FIND_PACKAGE_nlohmann_json=ON \
      -DCMAKE_DISABLE_FIND_PACKAGE_PkgConfig=ON >"$scratch/configure.log" 2>&1
cmake --build "$scratch/build" -j2 --target sgmp sgmp-reference >"$scratch/build.log" 2>&1
sgmp=$scratch/build/sgmp/sgmp
cd "$scratch/run"
"$sgmp" pack --count 1002 --arrangement loose-random --seed 4 --out minimal.xyz >/dev/null
"$full" pack --count 1002 --arrangement loose-random --seed 4 --out full.xyz >/dev/null
cmp minimal.xyz full.xyz
"$sgmp" batch --seeds 1-3 --count 200 --arrangement loose-random,small-dense --no-packs \
    --summary summary.csv >/dev/null
test "$(grep -cv '^#' summary.csv)" -eq 7  # the header row and 6 jobs
refused() {  # refused STATUS TEXT COMMAND...: exit STATUS, one stderr line holding TEXT
    status=$1 text=$2
    shift 2
    if "$@" >/dev/null 2>err; then echo "minimal_build: accepted: $*" >&2; exit 1; else got=$?; fi
    test "$got" -eq "$status" || { echo "minimal_build: exit $got, not $status: $*" >&2; exit 1; }
    test "$(wc -l <err)" -eq 1 && grep -q "$text" err || { cat err >&2; exit 1; }
}
refused 2 "needs COIN-OR CLP" "$sgmp" pack --count 100 --arrangement loose-random \
    --relax frictionless --out r.xyz
refused 2 "built without the metrics" "$sgmp" batch --seeds 1 --count 100 \
    --arrangement loose-random --no-packs --summary m.csv --measure
OMPI_COMM_WORLD_SIZE=2 refused 1 "built without MPI" "$sgmp" batch --seeds 1 --count 100 \
    --arrangement loose-random --no-packs --summary w.csv
test ! -e r.xyz && test ! -e m.csv && test ! -e w.csv
echo "minimal_build: sgmp pack and batch build and run without MPI, CLP, CGAL and Python"
