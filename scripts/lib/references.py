#!/usr/bin/env python3
"""The reference pours as scripts/run and scripts/make-references need them (packfiles.py).

    references.py list DIR --counts "C..." --frictions "MU..." [--seeds all|"S..."]
                  [--by count|friction] [--stored]
        one line "COUNT MU SEED PATH" per pour of DIR, PATH = DIR/nNNNN-muMU-seedS.xyz.gz:
        counts then frictions (--by count, the default) or frictions then counts; seeds
        as given, or 'all' (the default): the seeds stored for that class, increasing, or
        seed 1 when none is, so a missing pour is named like any other. --stored leaves
        out the pours that are not there.
    references.py table DIR --counts "C..." --frictions "MU..." --seeds "S..."
        the Markdown table of the stored pours' headers (make-references --table).
    references.py speedup COUNT SERIAL MPI2
        the wall time, steps and time per step of two pours of COUNT spheres (1 and 2 MPI
        ranks) and the 2-rank speed-up per time step (make-references --speedup).
"""
import argparse
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import packfiles  # noqa: E402


def pours(directory, counts, frictions, seeds, by):
    pairs = ([(c, mu) for c in counts for mu in frictions] if by == "count"
             else [(c, mu) for mu in frictions for c in counts])
    for count, mu in pairs:
        if seeds == ["all"]:
            chosen = packfiles.reference_seeds(directory, count, mu) or [1]
        else:
            chosen = seeds
        for seed in chosen:
            yield count, mu, seed, f"{directory}/{packfiles.reference_name(count, mu, seed)}"


def list_pours(args):
    for count, mu, seed, path in pours(args.dir, args.counts.split(), args.frictions.split(),
                                       args.seeds.split(), args.by):
        if args.stored and not pathlib.Path(path).is_file():
            continue
        print(f"{count} {mu} {seed} {path}")


def table(args):
    print("| count | mu | seed | wall s | steps | settling measure | max overlap / d | "
          "phi (control volume) |")
    print("| ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |")
    for count, mu, seed, path in pours(args.dir, args.counts.split(), args.frictions.split(),
                                       args.seeds.split(), "count"):
        if not pathlib.Path(path).is_file():
            continue
        h = packfiles.header_values(path)
        print(f"| {count} | {mu} | {seed} | {h.get('wall_seconds', '')} | {h.get('steps', '')} | "
              f"{h.get('settling_measure', '')} | "
              f"{packfiles.fixed(h.get('max_overlap_over_d', ''), 4)} | "
              f"{packfiles.fixed(h.get('phi_control_volume', ''), 4)} |")


def speedup(args):
    # Round-off differs between the two runs, so they settle after different numbers of
    # steps: the speed-up is compared per time step.
    per_step = {}
    for run, path in (("serial", args.serial), ("mpi2", args.mpi2)):
        wall = packfiles.header_value(path, "wall_seconds")
        steps = packfiles.header_value(path, "steps")
        w, s = packfiles.number(wall), packfiles.number(steps)
        ms = float(packfiles.awk_number(1000 * w / s))
        print(f"{run:<6} {wall:>8} s {steps:>7} steps {ms:8.3f} ms/step")
        per_step[run] = float(packfiles.awk_number(w / s))
    print(f"count {args.count}: 2-rank speed-up per time step "
          f"{per_step['serial'] / per_step['mpi2']:.2f} (processors 2 1 1)")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="command", required=True)
    for name in ("list", "table"):
        p = sub.add_parser(name)
        p.add_argument("dir")
        p.add_argument("--counts", required=True)
        p.add_argument("--frictions", required=True)
        p.add_argument("--seeds", default="all")
        if name == "list":
            p.add_argument("--by", choices=("count", "friction"), default="count")
            p.add_argument("--stored", action="store_true")
    p = sub.add_parser("speedup")
    p.add_argument("count")
    p.add_argument("serial")
    p.add_argument("mpi2")
    args = parser.parse_args(argv)
    {"list": list_pours, "table": table, "speedup": speedup}[args.command](args)
    return 0


if __name__ == "__main__":
    sys.exit(main())
