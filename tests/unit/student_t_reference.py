#!/usr/bin/env python3
"""Regenerates the p-values of test_crosscheck_ensemble_stats.cpp, independently of Boost.

The two-sided p-value of Student's t statistic t with df degrees of freedom is
p = 1 - 2 * integral_0^t f(x) dx, with the density
f(x) = Gamma((df+1)/2) / (sqrt(df pi) Gamma(df/2)) (1 + x^2/df)^(-(df+1)/2).
The integral over the finite interval [0, t] is taken with composite Simpson's rule
(200000 intervals: its error, ~h^4 max|f''''|, is far below the 1e-5 the tests ask for).
For an even df the closed form p = 1 - sin(a) * sum_{k=0}^{df/2-1} c_k cos(a)^(2k),
a = atan(t / sqrt(df)), c_0 = 1, c_k = c_{k-1} (2k-1) / (2k) (Abramowitz and Stegun 26.7.3)
is printed beside it as a check. The large-df limit is the normal 2 (1 - Phi(t)).

Usage: python3 tests/unit/student_t_reference.py
"""
import math


def density(x, df):
    log_norm = math.lgamma((df + 1) / 2) - math.lgamma(df / 2) - 0.5 * math.log(df * math.pi)
    return math.exp(log_norm - (df + 1) / 2 * math.log1p(x * x / df))


def two_sided_p(t, df, intervals=200000):
    h = t / intervals
    s = density(0.0, df) + density(t, df)
    for i in range(1, intervals):
        s += (4 if i % 2 else 2) * density(i * h, df)
    return 1.0 - 2.0 * s * h / 3.0


def two_sided_p_even_df(t, df):
    a = math.atan(t / math.sqrt(df))
    c, total = 1.0, 0.0
    for k in range(df // 2):
        if k > 0:
            c *= (2 * k - 1) / (2 * k)
        total += c * math.cos(a) ** (2 * k)
    return 1.0 - math.sin(a) * total


def main():
    df = 1875 / 337  # Welch-Satterthwaite: 25^2 / (9^2/3 + 16^2/3)
    print(f"WelchStatisticOfTwoMeans: t 0.6, df {df:.6f}: p = {two_sided_p(0.6, df):.6f}")
    print(f"  large df: normal 2 (1 - Phi(0.6)) = {math.erfc(0.6 / math.sqrt(2)):.6f}")
    print(f"TwoSidedPValueOfStudentsT: t 2, df 10: p = {two_sided_p(2.0, 10):.6f} "
          f"(closed form {two_sided_p_even_df(2.0, 10):.6f})")


if __name__ == "__main__":
    main()
