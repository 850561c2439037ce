#!/usr/bin/env python3
"""The constant of the Hertz head-on contact time used by test_mechanisms.cpp.

Energy conservation during the contact: m* v^2 / 2 = m* d'^2 / 2 + 8/15 E* sqrt(R*) d^(5/2),
so with x = d / d_max and d_max = (15 m* v^2 / (16 E* sqrt(R*)))^(2/5),
  t_c = 2 (d_max / v) I,  I = int_0^1 dx / sqrt(1 - x^(5/2)),
  t_c = 2 I (15/16)^(2/5) (m*^2 / (R* E*^2 v))^(1/5).
Prints I (1.47164) and the constant (2.86827). Midpoint rule after x = 1 - u^2, which
removes the end-point singularity.
"""
import math

N = 2_000_000
integral = sum(2.0 * u / math.sqrt(1.0 - (1.0 - u * u) ** 2.5) / N for u in ((i + 0.5) / N for i in range(N)))
print(f"I = {integral:.6f}")
print(f"constant = {2.0 * integral * (15.0 / 16.0) ** 0.4:.6f}")
