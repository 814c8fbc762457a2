#!/bin/sh
# Installs the build tree into a scratch prefix, builds a downstream project against it
# with find_package(sgmp), and checks that its pack is byte-identical to the installed
# `sgmp pack` of the same request.
#   install_test.sh BUILD_DIR SOURCE_DIR SCRATCH
set -eu
build=$1 source=$2 scratch=$3
rm -rf "$scratch" && mkdir -p "$scratch"
cmake --install "$build" --prefix "$scratch/prefix" >"$scratch/install.log"
test -x "$scratch/prefix/bin/sgmp" && test -x "$scratch/prefix/bin/sgmp-compare"
cmake -S "$source/tests/install/downstream" -B "$scratch/downstream" \
      -DCMAKE_PREFIX_PATH="$scratch/prefix" -DCMAKE_BUILD_TYPE=Release >"$scratch/configure.log"
cmake --build "$scratch/downstream" -j2 >"$scratch/build.log"
"$scratch/downstream/downstream" "$scratch/downstream.xyz"
"$scratch/prefix/bin/sgmp" pack --count 150 --arrangement loose-random --seed 3 \
    --out "$scratch/sgmp.xyz" >/dev/null
cmp "$scratch/downstream.xyz" "$scratch/sgmp.xyz"
echo "install_test: downstream pack identical to sgmp pack"
