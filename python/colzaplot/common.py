"""What every plot shares: the figure size, reading a result's files, saving a PNG."""
import csv
import json
import os

import matplotlib

matplotlib.use("Agg")  # files only, no display
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

# Every PNG is FIGSIZE x DPI pixels exactly (no tight bounding box): 1000 x 625.
FIGSIZE = (8.0, 5.0)
DPI = 125
PIXELS = (int(FIGSIZE[0] * DPI), int(FIGSIZE[1] * DPI))


def read_json(path):
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def read_csv(path):
    """A CSV of colza's (a header of names, then rows of numbers; '#' lines skipped) as a
    dict name -> numpy array."""
    with open(path, encoding="utf-8") as f:
        rows = [r for r in csv.reader(line for line in f if line.strip() and not line.startswith("#"))]
    names = [n.strip() for n in rows[0]]
    values = np.array([[float(v) for v in r] for r in rows[1:]], dtype=float).reshape(-1, len(names))
    return {n: values[:, k] for k, n in enumerate(names)}


def figure(rows=1, cols=1, **kwargs):
    fig, axes = plt.subplots(rows, cols, figsize=FIGSIZE, dpi=DPI, **kwargs)
    return fig, axes


def save(fig, out_dir, name):
    """Writes out_dir/name (a PNG of PIXELS) and returns its path."""
    path = os.path.join(out_dir, name)
    fig.savefig(path, dpi=DPI)
    plt.close(fig)
    return path


def title_of(summary, what):
    """"what - <config> (seed N)": the run a plot comes from."""
    config = os.path.basename(str(summary.get("config", "")))
    seed = summary.get("seed")
    tail = f" - {config}" if config else ""
    return f"{what}{tail}" + (f" (seed {seed})" if seed is not None else "")


def finite(x):
    return x is not None and isinstance(x, (int, float)) and np.isfinite(x)
