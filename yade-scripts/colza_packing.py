# colza's packing file format, read without YADE: shared by the YADE scripts (through
# colza_yade.py) and tests/bench/compare_codes.py, which runs outside YADE.
#
# Format (src/io/packing_file.cpp): one sphere per line, "x y z r" in m (further columns
# ignored); blank lines and lines starting with '#' are skipped.


def read_packing(path):
    """The spheres of a colza packing file as (x, y, z, r) tuples, in file order."""
    spheres = []
    with open(path) as f:
        for line in f:
            s = line.strip()
            if not s or s.startswith("#"):
                continue
            x, y, z, r = (float(v) for v in s.split()[:4])
            spheres.append((x, y, z, r))
    return spheres
