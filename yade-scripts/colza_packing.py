# colza's packing file format, read without YADE: shared by the YADE scripts (through
# colza_yade.py) and tests/bench/compare_codes.py, which runs outside YADE.
#
# Format (src/io/packing_file.cpp): one sphere per line, exactly four numbers "x y z r" in m;
# blank lines and lines starting with '#' are skipped. A line that is not four numbers is an
# error here too, as in colza.


def read_packing(path):
    """The spheres of a colza packing file as (x, y, z, r) tuples, in file order."""
    spheres = []
    with open(path) as f:
        for line in f:
            s = line.strip()
            if not s or s.startswith("#"):
                continue
            fields = s.split()
            if len(fields) != 4:
                raise ValueError(f"{path}: expected four numbers 'x y z r' (m), got {line.rstrip()!r}")
            x, y, z, r = (float(v) for v in fields)
            spheres.append((x, y, z, r))
    return spheres
