#!/usr/bin/env python3
"""Regenerates the reference spheres of test_generation.cpp (GenerationReference.*).

An independent implementation of what physics.md section 4 fixes for generation: Boost's
mt19937_64 (the standard's 64-bit Mersenne twister, seeded with one integer) and Boost's
uniform_real_distribution<double>(0, 1) (engine output as a double, divided by 2^64 as a
double, redrawn when the quotient rounds to 1), drawn in this order: the diameter
d_min + (d_max - d_min) u, then the centre's z, y and x (in this order), each lo + span u,
redrawing the centre until the sphere lies inside the region and overlaps no sphere placed before.
Python floats are IEEE doubles and every operation here is one rounded IEEE operation, as in
colza's build (-ffp-contract=off), so the printed numbers are the bits colza must give.

Usage: python3 tests/unit/generation_reference.py   (prints C++ initialisers)
"""

MASK64 = (1 << 64) - 1


class MersenneTwister64:
    """std::mt19937_64 / boost::random::mt19937_64 (Matsumoto and Nishimura 2004)."""

    def __init__(self, seed):
        self.state = [seed & MASK64]
        for i in range(1, 312):
            prev = self.state[-1]
            self.state.append((6364136223846793005 * (prev ^ (prev >> 62)) + i) & MASK64)
        self.index = 312

    def _twist(self):
        upper, lower = 0xFFFFFFFF80000000, 0x7FFFFFFF
        for i in range(312):
            x = (self.state[i] & upper) | (self.state[(i + 1) % 312] & lower)
            x_a = x >> 1
            if x & 1:
                x_a ^= 0xB5026F5AA96619E9
            self.state[i] = self.state[(i + 156) % 312] ^ x_a
        self.index = 0

    def __call__(self):
        if self.index >= 312:
            self._twist()
        y = self.state[self.index]
        self.index += 1
        y ^= (y >> 29) & 0x5555555555555555
        y ^= (y << 17) & 0x71D67FFFEDA60000
        y ^= (y << 37) & 0xFFF7EEE000000000
        y ^= y >> 43
        return y & MASK64


def unit(engine):
    """boost::random::uniform_real_distribution<double>(0, 1)."""
    while True:
        u = float(engine()) / (float(MASK64) + 1.0)
        if u < 1.0:
            return u


def box_spheres(seed, lo, hi, d_min, d_max, count):
    engine = MersenneTwister64(seed)
    span = [hi[k] - lo[k] for k in range(3)]
    placed = []
    while len(placed) < count:
        d = d_min + (d_max - d_min) * unit(engine)
        r = 0.5 * d
        while True:
            u_z = unit(engine)
            u_y = unit(engine)
            u_x = unit(engine)
            x = [lo[0] + span[0] * u_x, lo[1] + span[1] * u_y, lo[2] + span[2] * u_z]
            inside = all(x[k] - r >= lo[k] and x[k] + r <= hi[k] for k in range(3))
            free = all(sum((p[k] - x[k]) ** 2 for k in range(3)) >= (r + pr) ** 2 for p, pr in placed)
            if inside and free:
                break
        placed.append((x, r))
    return placed


if __name__ == "__main__":
    # box_request(7) of test_generation.cpp: a 50 mm cube, 6-7 mm; the first three spheres.
    for x, r in box_spheres(7, (0.0, 0.0, 0.0), (0.05, 0.05, 0.05), 6e-3, 7e-3, 3):
        print("{{{!r}, {!r}, {!r}, {!r}}},".format(x[0], x[1], x[2], r))
