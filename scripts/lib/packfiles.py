"""What the scripts share about pack files, reference sets, CSV tables and numbers.

- Header values: `header_values(path)` reads the `key=value` header of a pack file, plain or
  gzip-compressed: an extended XYZ's comment line (`key=value` and `key="quoted value"`
  pairs), or the `# key=value` comment lines after a LAMMPS data file's title (a dump has
  none).
  `header_value(path, key, default="")` gives one value. Every helper takes the file first,
  then the key.
- Reference file names: the pours of a reference set are named `nNNNN-muMU-seedS.xyz.gz`
  (count zero-padded to 4 digits, the friction as written, the seed).
  `reference_name(count, mu, seed)` spells one, `parse_reference_name(name)` reads one back
  (None when it is not such a name), `reference_pattern(count, mu)` is the glob pattern of
  a class's pours, `reference_files(directory, count, mu)` lists the
  pours stored for a class, by seed, and `reference_seeds(directory, count, mu)` their
  seeds.
- CSV: the testbed's tables have their header row first, then `#` lines, then the rows.
  `read_csv(path)` returns the columns and the rows as dicts, skipping `#` lines;
  `csv_field(text)` quotes a field that holds a comma or a quote (quotes doubled), as every
  table the testbed writes does; `csv_line(fields)` joins fields into one line;
  `write_csv(file, columns, rows, comments=())` writes a whole table.
- Numbers: `fixed(value, places)` is C's `%.Nf` of a value given as a number or as text
  (empty text counts as 0, as the shell's printf takes it); `awk_number(value)` prints a
  number as awk's `print` does (`%.6g`, whole numbers in full).
"""
import csv
import gzip
import io
import pathlib
import re

_PAIR = re.compile(r'([^\s=]+)=("([^"]*)"|(\S*))')
_REFERENCE = re.compile(r"^n(\d{4,})-mu([^-/]+)-seed(\d+)(\.[A-Za-z0-9.]+)$")


# --- Header values -------------------------------------------------------------------------
def _open_text(path):
    path = pathlib.Path(path)
    if path.suffix == ".gz":
        return gzip.open(path, "rt", encoding="utf-8", errors="replace")
    return open(path, encoding="utf-8", errors="replace")


def parse_pairs(line):
    """The key=value pairs of one header line, in order; a quoted value loses its quotes."""
    values = {}
    for match in _PAIR.finditer(line):
        key = match.group(1)
        values[key] = match.group(3) if match.group(3) is not None else match.group(4)
    return values


def header_values(path):
    """Every header key of the pack file PATH and its value (text), in the file's order."""
    with _open_text(path) as f:
        first = f.readline()
        if first.startswith("ITEM:"):
            return {}  # a LAMMPS dump: no comment lines
        if first.strip().isdigit():
            return parse_pairs(f.readline())  # extended XYZ: count line, then the header
        values = {}  # LAMMPS data file: title line, then '# key=value' comments
        for line in f:
            if not line.startswith("#"):
                break
            key, sep, value = line[1:].strip().partition("=")
            if sep and key and " " not in key:
                values[key] = value
        return values


def header_value(path, key, default=""):
    """The value of KEY in the header of the pack file PATH, DEFAULT when it has none."""
    return header_values(path).get(key, default)


# --- Reference file names -----------------------------------------------------------------
class ReferenceName:
    """A reference pour's name read back: count, friction (as written), seed, suffix."""

    def __init__(self, count, mu, seed, suffix):
        self.count, self.mu, self.seed, self.suffix = count, mu, seed, suffix

    def __eq__(self, other):
        return (self.count, self.mu, self.seed, self.suffix) == \
            (other.count, other.mu, other.seed, other.suffix)

    def __repr__(self):
        return f"ReferenceName({self.count}, {self.mu!r}, {self.seed}, {self.suffix!r})"


def reference_name(count, mu, seed, suffix=".xyz.gz"):
    """nNNNN-muMU-seedS plus SUFFIX; MU is written as given (text), or with %g (a number)."""
    mu_text = mu if isinstance(mu, str) else f"{mu:g}"
    return f"n{int(count):04d}-mu{mu_text}-seed{int(seed)}{suffix}"


def reference_pattern(count, mu="*"):
    """The glob pattern of the pours of class (COUNT, MU), any seed and suffix; MU "*" any."""
    return reference_name(count, mu, 0, "")[:-1] + "*"


def parse_reference_name(name):
    """A ReferenceName from a file name (a path's last part), None when it is not one."""
    match = _REFERENCE.match(pathlib.PurePath(str(name)).name)
    if not match:
        return None
    return ReferenceName(int(match.group(1)), match.group(2), int(match.group(3)),
                         match.group(4))


def reference_files(directory, count, mu, suffix=".xyz.gz"):
    """The pours of class (COUNT, MU) stored in DIRECTORY, by increasing seed."""
    found = []
    for path in pathlib.Path(directory).glob(reference_pattern(count, mu) + suffix):
        parsed = parse_reference_name(path.name)
        if parsed and parsed.suffix == suffix and path.is_file():
            found.append((parsed.seed, path))
    return [path for _, path in sorted(found)]


def reference_seeds(directory, count, mu, suffix=".xyz.gz"):
    """The seeds of the pours of class (COUNT, MU) stored in DIRECTORY, increasing."""
    return [parse_reference_name(p.name).seed for p in reference_files(directory, count, mu, suffix)]


# --- CSV ----------------------------------------------------------------------------------
def read_csv(path):
    """(columns, rows) of a table: header first, '#' lines skipped, rows as dicts."""
    with open(path, newline="", encoding="utf-8") as f:
        lines = [line for line in f if not line.startswith("#")]
    reader = csv.DictReader(lines)
    rows = list(reader)
    return list(reader.fieldnames or []), rows


def csv_field(text):
    """TEXT as one CSV field: quoted, its quotes doubled, when it holds a comma or a quote."""
    text = str(text)
    if "," in text or '"' in text:
        return '"' + text.replace('"', '""') + '"'
    return text


def csv_line(fields):
    """One CSV line (no line end) of FIELDS."""
    return ",".join(csv_field(field) for field in fields)


def write_csv(file, columns, rows, comments=()):
    """Writes the header, '# ' comment lines and ROWS (dicts or sequences) to FILE, a path
    or an open text file; '\\n' line ends."""
    out = io.StringIO()
    out.write(csv_line(columns) + "\n")
    for comment in comments:
        out.write(f"# {comment}\n")
    for row in rows:
        values = [row.get(c, "") for c in columns] if isinstance(row, dict) else row
        out.write(csv_line(values) + "\n")
    if hasattr(file, "write"):
        file.write(out.getvalue())
    else:
        pathlib.Path(file).write_text(out.getvalue(), encoding="utf-8")


# --- Numbers ------------------------------------------------------------------------------
def number(text):
    """A number from text as C's strtod reads a shell printf argument: empty is 0."""
    text = str(text).strip()
    return float(text) if text else 0.0


def fixed(value, places):
    """VALUE (a number or its text) with PLACES decimals, C's %.Nf."""
    return f"{number(value):.{places}f}"


def awk_number(value):
    """VALUE as awk's print writes it: a whole number in full, else %.6g."""
    value = float(value)
    if value == int(value) and abs(value) < 1e16:
        return str(int(value))
    return f"{value:.6g}"
