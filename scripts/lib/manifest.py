#!/usr/bin/env python3
"""The manifests of scripts/run (role,group,count,seed,seconds,path) written and read as CSV
(packfiles.py), so the shell neither quotes nor splits a manifest line.

    manifest.py rows N              stdin: fields separated by NUL, N per row; one CSV line
                                    per row on stdout (a field with a comma or quote quoted)
    manifest.py paths FILE          the path of every row of FILE, each followed by a NUL
    manifest.py metrics FILE        stdin: NUL-separated pairs PACK METRICS; FILE with the
                                    header and each row's path replaced by its metrics file
    manifest.py select FILE --role R [--group G] [--count C]
                                    the lines of FILE's rows with that role, group and count,
                                    as they are
    manifest.py count FILE --role R [--timed]
                                    how many rows of FILE have that role (and a time)
    manifest.py verdicts HEADLINE   "A agree, D differ, I inconclusive" of headline.csv
    manifest.py budget FILE --group G --count C --add K --budget B
                                    whether K more candidate packs of that group and count
                                    keep its packing time within B seconds: its packs' CPU
                                    seconds (the .cpu file scripts/run wrote beside each
                                    pack: `times` of its shell; else the row's seconds, else
                                    the .seconds file beside the pack) plus K times their
                                    mean; prints the estimate, exit 0 within the budget, 1
                                    past it
"""
import argparse
import csv
import pathlib
import re
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import packfiles  # noqa: E402

HEADER = ["role", "group", "count", "seed", "seconds", "path"]


def nul_fields():
    data = sys.stdin.buffer.read().decode("utf-8", errors="surrogateescape")
    fields = data.split("\0")
    if fields and fields[-1] == "":
        fields.pop()
    return fields


def write(text):
    sys.stdout.buffer.write(text.encode("utf-8", errors="surrogateescape"))


def rows_of(path):
    """(line, fields) of each row of the manifest PATH, header and '#' lines left out."""
    with open(path, encoding="utf-8", errors="surrogateescape", newline="") as f:
        lines = f.read().split("\n")
    for line in lines[1:]:
        if line and not line.startswith("#"):
            yield line, next(csv.reader([line]))


def pack_seconds(fields):
    """The recorded packing time of a candidate row: its seconds field, else the .seconds
    file scripts/run wrote beside the pack (a reused pack's own time); None when neither."""
    if fields[4]:
        return float(fields[4])
    path = pathlib.Path(fields[5])
    timing = path.with_name(path.name.removesuffix(".xyz") + ".seconds")
    try:
        return float(timing.read_text().strip())
    except (OSError, ValueError):
        return None


def pack_cpu_seconds(fields):
    """The CPU seconds (user + system) of a candidate row's packing, from the .cpu file
    beside the pack (the `times` builtin's two lines; the second, its children's, counts),
    else its recorded wall seconds (pack_seconds)."""
    path = pathlib.Path(fields[5])
    cpu = path.with_name(path.name.removesuffix(".xyz") + ".cpu")
    try:
        lines = cpu.read_text().splitlines()
        found = re.findall(r"(\d+)m([0-9.]+)s", lines[1])
        if len(found) == 2:
            return sum(60 * float(minutes) + float(seconds) for minutes, seconds in found)
    except (OSError, ValueError, IndexError):
        pass
    return pack_seconds(fields)


def budget(args):
    """Exit status 0 when ADD more packs keep the group within BUDGET seconds (see above)."""
    times = [pack_cpu_seconds(fields) for _, fields in rows_of(args.file)
             if fields[0] == "candidate" and fields[1] == args.group and fields[2] == args.count]
    known = [t for t in times if t is not None]
    spent = sum(known) * len(times) / len(known) if known else 0.0
    mean = spent / len(times) if times else 0.0
    estimate = spent + args.add * mean
    write(f"{estimate:.0f}\n")
    return 0 if estimate <= args.budget else 1


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="command", required=True)
    sub.add_parser("rows").add_argument("n", type=int)
    sub.add_parser("paths").add_argument("file")
    sub.add_parser("metrics").add_argument("file")
    p = sub.add_parser("select")
    p.add_argument("file")
    p.add_argument("--role", required=True)
    p.add_argument("--group")
    p.add_argument("--count")
    p = sub.add_parser("count")
    p.add_argument("file")
    p.add_argument("--role", required=True)
    p.add_argument("--timed", action="store_true")
    sub.add_parser("verdicts").add_argument("file")
    p = sub.add_parser("budget")
    p.add_argument("file")
    p.add_argument("--group", required=True)
    p.add_argument("--count", required=True)
    p.add_argument("--add", type=int, required=True)
    p.add_argument("--budget", type=float, required=True)
    args = parser.parse_args(argv)

    if args.command == "rows":
        fields = nul_fields()
        for i in range(0, len(fields) - args.n + 1, args.n):
            write(packfiles.csv_line(fields[i:i + args.n]) + "\n")
    elif args.command == "paths":
        for _, fields in rows_of(args.file):
            write(fields[5] + "\0")
    elif args.command == "metrics":
        pairs = nul_fields()
        metrics = dict(zip(pairs[0::2], pairs[1::2]))
        write(packfiles.csv_line(HEADER) + "\n")
        for _, fields in rows_of(args.file):
            write(packfiles.csv_line(fields[:5] + [metrics.get(fields[5], "")]) + "\n")
    elif args.command == "select":
        for line, fields in rows_of(args.file):
            if fields[0] == args.role and (args.group is None or fields[1] == args.group) \
                    and (args.count is None or fields[2] == args.count):
                write(line + "\n")
    elif args.command == "count":
        write(str(sum(1 for _, fields in rows_of(args.file)
                      if fields[0] == args.role and (not args.timed or fields[4] != ""))) + "\n")
    elif args.command == "verdicts":
        _, rows = packfiles.read_csv(args.file)
        n = {v: sum(1 for r in rows if r.get("verdict") == v)
             for v in ("agree", "differ", "inconclusive")}
        write(f"{n['agree']} agree, {n['differ']} differ, {n['inconclusive']} inconclusive")
    elif args.command == "budget":
        return budget(args)
    return 0


if __name__ == "__main__":
    sys.exit(main())
