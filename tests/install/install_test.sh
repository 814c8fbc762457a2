#!/bin/sh
# Installs the build tree into a scratch prefix, builds a downstream project against it
# with find_package(sgmp) linking every exported library, and checks that its pack is
# byte-identical to the installed `sgmp pack` of the same request and its φ the installed
# `sgmp-compare measure`'s.
#   install_test.sh BUILD_DIR SOURCE_DIR SCRATCH
set -eu
build=$1 source=$2 scratch=$3
rm -rf "$scratch" && mkdir -p "$scratch"
cmake --install "$build" --prefix "$scratch/prefix" >"$scratch/install.log"
test -x "$scratch/prefix/bin/sgmp" && test -x "$scratch/prefix/bin/sgmp-compare"
cmake -S "$source/tests/install/downstream" -B "$scratch/downstream" \
      -DCMAKE_PREFIX_PATH="$scratch/prefix" -DCMAKE_BUILD_TYPE=Release >"$scratch/configure.log"
cmake --build "$scratch/downstream" -j2 >"$scratch/build.log"
"$scratch/downstream/downstream" "$scratch/downstream.xyz" >"$scratch/downstream.out"
"$scratch/prefix/bin/sgmp" pack --count 150 --arrangement loose-random --seed 3 \
    --out "$scratch/sgmp.xyz" >/dev/null
cmp "$scratch/downstream.xyz" "$scratch/sgmp.xyz"
echo "install_test: downstream pack identical to sgmp pack"
# φ of the linked metrics library, as the installed sgmp-compare measures it (the same text).
"$scratch/prefix/bin/sgmp-compare" measure "$scratch/sgmp.xyz" --out "$scratch/measured" >/dev/null
phi=$(grep -o '"phi": [^,]*' "$scratch/measured/sgmp.metrics.json" | head -n 1)
grep -qxF "$phi" "$scratch/downstream.out"
grep -qxF "mean 2.3333333333333335" "$scratch/downstream.out"
echo "install_test: sgmp::metrics and sgmp::report link and measure as sgmp-compare does ($phi)"
