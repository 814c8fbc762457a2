"""Pack, relax, measure and plot g(r) with the sgmp Python module.

    PYTHONPATH=build/sgmp/python /usr/bin/python3 sgmp/python/examples/pack_measure_plot.py [OUT_DIR] [COUNT]

Writes OUT_DIR/relaxed.xyz (a pack file) and OUT_DIR/g_r.png (g(r) of the deposited and the
relaxed pack), and prints phi, Z(1e-3) and the split ratio of each.
"""

import pathlib
import sys

import matplotlib

matplotlib.use("Agg")  # files only; drop this line to show the figure in a window
import matplotlib.pyplot as plt

import sgmp

out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
count = int(sys.argv[2]) if len(sys.argv) > 2 else 1002
out.mkdir(parents=True, exist_ok=True)

packs = {
    "deposited": sgmp.pack(count=count, arrangement="loose-random", seed=1),
    "relaxed": sgmp.pack(count=count, arrangement="loose-random", seed=1, relax="frictionless"),
}
sgmp.write(packs["relaxed"], out / "relaxed.xyz", force=True)

fig, ax = plt.subplots(figsize=(6, 4))
for label, pack in packs.items():
    m = sgmp.measure(pack)
    print(f"{label}: N = {len(pack)}, phi = {m['phi']:.4f}, "
          f"Z(1e-3) = {m['z_mean_tol_1e-3']:.3f}, split ratio = {m['split_ratio']:.3f}")
    r, g = m["g_r"][:, 0], m["g_r"][:, 1]
    ax.plot(r, g, label=f"{label} (phi = {m['phi']:.3f})")
ax.axhline(1.0, color="grey", linewidth=0.5)
ax.set_xlabel("r / d")
ax.set_ylabel("g(r)")
ax.set_title(f"SGMP, N = {count}, loose-random start, seed 1")
ax.legend()
fig.tight_layout()
fig.savefig(out / "g_r.png", dpi=120)
print(f"wrote {out / 'relaxed.xyz'} and {out / 'g_r.png'}")
