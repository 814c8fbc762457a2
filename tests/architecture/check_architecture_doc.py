#!/usr/bin/env python3
"""ARCHITECTURE.md names every script and every library the tree has.

A script is an executable file directly in scripts/, or a folder of scripts/ (slurm/, lib/)
named with its slash; a library is an `add_library(NAME` of a CMakeLists.txt outside tests/ (imported targets and
the INTERFACE target of the compile flags excepted). Exit 0 when ARCHITECTURE.md names
every one in backquotes, 1 listing the missing ones otherwise.

    check_architecture_doc.py SOURCE_DIR
"""
import os
import pathlib
import re
import sys


def main(argv):
    root = pathlib.Path(argv[1]).resolve()
    doc = (root / "ARCHITECTURE.md").read_text(encoding="utf-8")
    doc = re.sub(r"^```.*?^```", "", doc, flags=re.MULTILINE | re.DOTALL)  # drawings
    named = set(re.findall(r"`([^`\n]+)`", doc))
    missing = []
    scripts = [p.name for p in sorted((root / "scripts").iterdir())
               if p.is_file() and os.access(p, os.X_OK)]
    scripts += [folder.name + "/" for folder in sorted((root / "scripts").iterdir())
                if folder.is_dir() and not folder.name.startswith((".", "__"))]
    for name in scripts:
        if name not in named:
            missing.append(f"script scripts/{name}")
    for cmake in sorted(root.rglob("CMakeLists.txt")):
        rel = cmake.relative_to(root)
        if rel.parts[0] in ("tests", "build") or rel.parts[0].startswith("."):
            continue
        for lib in re.findall(r"add_library\(\s*([A-Za-z0-9_:]+)(\s+\w+)?", cmake.read_text()):
            name, kind = lib[0], lib[1].strip()
            if "::" in name or kind in ("INTERFACE", "UNKNOWN", "IMPORTED"):
                continue
            if name not in named:
                missing.append(f"library {name} ({rel})")
    if not scripts:
        missing.append("no script found: is SOURCE_DIR the project root?")
    for m in missing:
        print(f"check_architecture_doc: ARCHITECTURE.md does not name the {m}", file=sys.stderr)
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
