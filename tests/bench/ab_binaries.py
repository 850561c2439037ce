#!/usr/bin/env python3
"""Two colza binaries on the same oedometer loading, interleaved: is B faster than A, and
does it give the same result?

Runs the loading stage from the settled oedometer packing (the one compare_codes.py
prepares) with a fixed dt and number of steps, alternating A and B for --rounds rounds,
and prints each binary's minimum and median stage time (the stage clock in summary.json)
and B/A. The minimum is the least disturbed run: this class of machine (2 shared cores, no
hardware counters in the VM) slows down by up to 2x for minutes, so single runs and
non-interleaved series mislead. Then compares the two runs' curve.csv and packing.txt
byte for byte: a change meant to keep the bits must print "identical".

    python3 tests/bench/ab_binaries.py OLD/colza build/src/colza --threads 2 --rounds 8
"""
import argparse
import filecmp
import os
import statistics
import sys

from compare_codes import prepare_packing, run_colza


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("a", help="colza binary A (the reference)")
    ap.add_argument("b", help="colza binary B (the candidate)")
    ap.add_argument("--packing", help="settled packing (x y z r); default: prepared once with A in --work")
    ap.add_argument("--work", default="/tmp/colza-compare")
    ap.add_argument("--dt", type=float, default=1e-5, help="fixed time step (s)")
    ap.add_argument("--steps", type=int, default=10000)
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--rounds", type=int, default=6)
    a = ap.parse_args()
    binaries = {"A": os.path.abspath(a.a), "B": os.path.abspath(a.b)}
    os.makedirs(a.work, exist_ok=True)
    packing = os.path.abspath(a.packing) if a.packing else prepare_packing(binaries["A"], a.work)

    seconds = {"A": [], "B": []}
    for k in range(a.rounds):
        for tag, binary in binaries.items():
            work = os.path.join(a.work, f"ab-{tag}")
            os.makedirs(work, exist_ok=True)
            seconds[tag].append(run_colza(binary, packing, a.dt, a.steps, work, a.threads)["seconds"])
        print(f"round {k + 1}/{a.rounds}: A {seconds['A'][-1]:.3f} s, B {seconds['B'][-1]:.3f} s",
              file=sys.stderr, flush=True)

    low = {t: min(s) for t, s in seconds.items()}
    mid = {t: statistics.median(s) for t, s in seconds.items()}
    print(f"\nloading, {a.steps} steps, dt {a.dt:g} s, {a.threads} thread(s), {a.rounds} interleaved rounds")
    print(f"A  min {low['A']:.3f} s  median {mid['A']:.3f} s   {binaries['A']}")
    print(f"B  min {low['B']:.3f} s  median {mid['B']:.3f} s   {binaries['B']}")
    print(f"B/A  min {low['B'] / low['A']:.3f}  median {mid['B'] / mid['A']:.3f}")
    same = all(filecmp.cmp(os.path.join(a.work, "ab-A", "colza", f), os.path.join(a.work, "ab-B", "colza", f),
                           shallow=False) for f in ("curve.csv", "packing.txt"))
    print("curve.csv and packing.txt: " + ("identical" if same else "DIFFERENT"))


if __name__ == "__main__":
    main()
