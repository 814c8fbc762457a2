#!/usr/bin/env python3
"""The libraries' include graph points one way (ARCHITECTURE.md, "Libraries").

Every `#include "sgmp/..."` in a library's sources and headers is resolved to the library
whose include/ folder holds it, and must be the library itself or one it may depend on.
Each library's headers sit under its own prefix, include/sgmp/<library>/, and its code in
the namespace sgmp::<library>.
Front ends (sgmp/app, compare/app, reference/app, sgmp/python) put parts together and are
not checked. Exit 0 when the graph holds, 1 listing every upward include otherwise.

    check_include_graph.py SOURCE_DIR
    check_include_graph.py --self-test   (a made-up tree with one upward include fails)
"""
import pathlib
import re
import sys
import tempfile

# Each library, its folder and the libraries it may include (the layering, lowest first).
LIBRARIES = {
    "pack": ("sgmp/pack", set()),
    "cli": ("sgmp/cli", {"pack"}),
    "engine": ("sgmp/engine", {"pack"}),
    "render": ("sgmp/render", {"pack"}),
    "batch": ("sgmp/batch", {"pack", "engine"}),
    "reference": ("reference", {"pack"}),
    "metrics": ("compare/metrics", {"pack"}),
    "report": ("compare/report", {"pack", "render", "metrics", "reference"}),
}
NAMESPACE = re.compile(r"^namespace\s+(sgmp(?:::\w+)*)\s*\{", re.MULTILINE)
INCLUDE = re.compile(r'^\s*#\s*include\s+"(sgmp/[^"]+)"', re.MULTILINE)


def owner_of(root, header):
    """The library whose include/ folder holds `header`, or None."""
    owners = [name for name, (folder, _) in LIBRARIES.items()
              if (root / folder / "include" / header).is_file()]
    return owners[0] if len(owners) == 1 else None


def sources_of(root, folder):
    for sub in ("include", "src"):
        base = root / folder / sub
        if base.is_dir():
            yield from sorted(p for p in base.rglob("*") if p.suffix in (".hpp", ".cpp", ".h"))


def main(argv):
    root = pathlib.Path(argv[1]).resolve()
    problems = []
    checked = 0
    for name, (folder, allowed) in LIBRARIES.items():
        for path in sources_of(root, folder):
            for header in INCLUDE.findall(path.read_text(encoding="utf-8")):
                checked += 1
                owner = owner_of(root, header)
                if owner is None:
                    problems.append(f"{path.relative_to(root)}: \"{header}\" is in no library's "
                                    "include/ (or in more than one)")
                elif owner != name and owner not in allowed:
                    problems.append(f"{path.relative_to(root)}: includes \"{header}\" of "
                                    f"{owner}, which {name} may not depend on")
    for name, (folder, _) in LIBRARIES.items():
        include = root / folder / "include"
        for path in sorted(include.rglob("*.hpp")) if include.is_dir() else []:
            relative = path.relative_to(include).as_posix()
            if not relative.startswith(f"sgmp/{name}/"):
                problems.append(f"{path.relative_to(root)}: a header of {name} outside its "
                                f"prefix sgmp/{name}/")
            for space in NAMESPACE.findall(path.read_text(encoding="utf-8")):
                if space != f"sgmp::{name}" and not space.startswith(f"sgmp::{name}::") \
                        and space != "sgmp":
                    problems.append(f"{path.relative_to(root)}: namespace {space} in a header "
                                    f"of {name} (expected sgmp::{name})")
    if checked == 0:
        problems.append("no include was found: is SOURCE_DIR the project root?")
    for p in problems:
        print("check_include_graph: " + p, file=sys.stderr)
    return 1 if problems else 0


def self_test():
    """The check finds an engine header including a metrics header, and passes without it."""
    with tempfile.TemporaryDirectory() as tmp:
        root = pathlib.Path(tmp)
        for folder, header in (("sgmp/pack", "sgmp/pack/a.hpp"),
                               ("sgmp/engine", "sgmp/engine/b.hpp"),
                               ("compare/metrics", "sgmp/metrics/c.hpp")):
            path = root / folder / "include" / header
            path.parent.mkdir(parents=True)
            path.write_text('#include "sgmp/pack/a.hpp"\n' if "pack" not in folder else "\n")
        if main(["", str(root)]) != 0:
            return 1
        engine = root / "sgmp/engine/include/sgmp/engine/b.hpp"
        engine.write_text('#include "sgmp/metrics/c.hpp"\n')
        return 0 if main(["", str(root)]) == 1 else 1


if __name__ == "__main__":
    sys.exit(self_test() if sys.argv[1:] == ["--self-test"] else main(sys.argv))
