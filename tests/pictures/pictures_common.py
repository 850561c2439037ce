"""What the pictures tests share: running colza, skipping when a reader is missing.

CTest passes the colza executable and the source tree as arguments; a test that cannot run
for want of a Python module exits SKIP (77, CTest's SKIP_RETURN_CODE) with the reason."""
import os
import shutil
import subprocess
import sys
import tempfile

SKIP = 77


def skip(reason):
    print(f"SKIPPED: {reason}")
    sys.exit(SKIP)


def args():
    if len(sys.argv) < 3:
        sys.exit(f"usage: {sys.argv[0]} COLZA_EXECUTABLE SOURCE_DIR")
    return sys.argv[1], sys.argv[2]


def run_colza(colza, *arguments, env=None, check=True):
    full_env = dict(os.environ, OMP_NUM_THREADS="1")
    full_env.update(env or {})
    r = subprocess.run([colza, *arguments], capture_output=True, text=True, env=full_env)
    if check and r.returncode != 0:
        raise AssertionError(f"colza {' '.join(arguments)} exited {r.returncode}:\n{r.stderr}")
    return r


class Scratch:
    """A fresh temporary folder, removed at exit unless the test failed."""

    def __enter__(self):
        self.path = tempfile.mkdtemp(prefix="colza-pictures-")
        return self.path

    def __exit__(self, kind, value, tb):
        if kind is None:
            shutil.rmtree(self.path, ignore_errors=True)
        else:
            print(f"(kept {self.path})")
        return False


def png_size(path):
    """(width, height) from a PNG's IHDR chunk; AssertionError if the file is not a PNG."""
    with open(path, "rb") as f:
        head = f.read(24)
    assert head[:8] == b"\x89PNG\r\n\x1a\n", f"{path} is not a PNG"
    assert head[12:16] == b"IHDR", f"{path}: no IHDR chunk first"
    return int.from_bytes(head[16:20], "big"), int.from_bytes(head[20:24], "big")
