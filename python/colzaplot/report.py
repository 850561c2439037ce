"""Embeds a calibration's or a diagnosis's plots in its report.md: a "Plots" section at the end, replaced
when the plots are drawn again."""
import os

MARKER = "<!-- colza plot: the plots below are written by colza_plot.py -->"


def embed_plots(report_file, names):
    if not os.path.isfile(report_file):
        return
    with open(report_file, encoding="utf-8") as f:
        text = f.read()
    text = text.split("\n" + MARKER)[0].rstrip("\n") + "\n"
    section = ["", MARKER, "## Plots", ""]
    for name in names:
        section += [f"![{os.path.splitext(name)[0]}](plots/{name})", ""]
    tmp = f"{report_file}.tmp.{os.getpid()}"
    with open(tmp, "w", encoding="utf-8") as f:
        f.write(text + "\n".join(section))
    os.replace(tmp, report_file)
