#!/usr/bin/env python3
"""Checks (and can regenerate) the two-load input of MohrCoulomb.TwoLoadsGiveAnR2OfExactlyOne.

r^2 = Sxy^2 / (Sxx Syy) is exactly 1 for any two points, but evaluated in IEEE doubles it can
round above 1. The test needs an input for which it does, so that the fit's cap
(std::min(1.0, ...) in src/analysis/mohr_coulomb.cpp) is exercised. This script evaluates the
sums in the order fit_mohr_coulomb does (means, then the three centred sums, each operation one
rounded IEEE double operation, as in colza's build with -ffp-contract=off; Python floats are
IEEE doubles) and prints the uncapped r^2 of the test's input. With --search it draws shear
stresses at the loads 25750 and 78750 Pa (seeded, so the search repeats) until one pair rounds
above 1, and prints it.

Usage: python3 tests/unit/mohr_coulomb_r2_reference.py [--search]
"""
import random
import sys

SIGMA = (25750.0, 78750.0)
TEST_TAU = (32913.238569298424, 30202.761029576868)  # the test's input


def uncapped_r2(sigma, tau):
    n = float(len(sigma))
    ms = 0.0
    mt = 0.0
    for s, t in zip(sigma, tau):
        ms += s
        mt += t
    ms /= n
    mt /= n
    sxx = sxy = syy = 0.0
    for s, t in zip(sigma, tau):
        sxx += (s - ms) * (s - ms)
        sxy += (s - ms) * (t - mt)
        syy += (t - mt) * (t - mt)
    return sxy * sxy / (sxx * syy)


def main():
    r2 = uncapped_r2(SIGMA, TEST_TAU)
    print(f"test input {TEST_TAU!r}: uncapped r^2 = {r2!r} ({'above 1' if r2 > 1.0 else 'NOT above 1'})")
    if "--search" in sys.argv[1:]:
        rng = random.Random(2024)
        for _ in range(1_000_000):
            tau = (rng.uniform(20e3, 50e3), rng.uniform(20e3, 50e3))
            if uncapped_r2(SIGMA, tau) > 1.0:
                print(f"found {tau[0]!r}, {tau[1]!r}: uncapped r^2 = {uncapped_r2(SIGMA, tau)!r}")
                break
    return 0 if r2 > 1.0 else 1


if __name__ == "__main__":
    sys.exit(main())
