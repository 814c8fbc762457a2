#!/usr/bin/env bash
# `pip install --no-build-isolation .` into a clean virtual environment (Debian's setuptools
# through --system-site-packages; no package index), then the installed sgmp packs,
# pickles and refuses writes into its arrays. SGMP_CMAKE_BUILD_DIR = the test's build tree,
# so the extension is the one already built (a fresh install builds its own tree).
#   pip_install.sh PYTHON SOURCE_DIR BUILD_DIR SCRATCH
set -euo pipefail
python="$1" source="$2" build="$3" scratch="$4"
rm -rf "$scratch"
mkdir -p "$scratch"
"$python" -m venv --system-site-packages "$scratch/venv"
# A copy of the sources, so that pip's build leaves no build/ or egg-info in the checkout.
tar -C "$source" --exclude=./build --exclude=./.git --exclude=./out -cf - . | tar -C "$scratch" -xf - --one-top-level=src
SGMP_CMAKE_BUILD_DIR="$build" "$scratch/venv/bin/pip" install --quiet --no-build-isolation \
    --no-deps --no-index "$scratch/src" >"$scratch/pip.log" 2>&1 || {
    tail -20 "$scratch/pip.log" >&2
    exit 1
}
cd "$scratch"
env -u PYTHONPATH "$scratch/venv/bin/python" - <<'PY'
import pathlib, pickle, sys
import numpy as np
import sgmp
where = pathlib.Path(sgmp.__file__).resolve()
assert "venv" in where.parts, f"imported from {where}, not the virtual environment"
p = sgmp.pack(200, "loose-random", seed=3)
assert isinstance(p.header["count"], int) and p.header["count"] == 200
assert p.header["container"].lengths[0] == 1.25
q = pickle.loads(pickle.dumps(p))
assert np.array_equal(q.positions, p.positions)
try:
    p.positions[0, 0] = 1.0
    sys.exit("an array write was accepted")
except ValueError:
    pass
print(f"sgmp {sgmp.__version__} installed at {where.parent}")
PY
