#!/usr/bin/env python3
"""Where the bound -0.5 on the measured correlation of c1 and c2 lies, in standard errors of
Fisher's z = atanh(r) (standard error 1 / sqrt(n - 3) for n realisations), from the
correlation the realisations gave when the tests were written (session 21):
  tests/integration/test_calibrate_dem.cpp            n = 7, r = -0.95
  tests/full/test_calibrate_compression_identity.cpp  n = 5, r = -0.99
Usage: python3 tests/integration/correlation_bound_reference.py"""
import math

BOUND = -0.5
for where, n, r in (("integration (small oedometer)", 7, -0.95), ("full (paper's oedometer)", 5, -0.99)):
    se = 1.0 / math.sqrt(n - 3)
    distance = (math.atanh(BOUND) - math.atanh(r)) / se
    print(f"{where}: n = {n}, r = {r}: z = {math.atanh(r):.4f}, se {se:.4f}; "
          f"r = {BOUND} lies {distance:.2f} standard errors above it")
