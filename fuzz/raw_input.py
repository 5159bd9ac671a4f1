#!/usr/bin/env python3
"""Writes a literal fuzz input (the form of fuzz/regressions/): b"raw:" and little-endian values.

Usage: python3 fuzz/raw_input.py TARGET OUT VALUE...
  pair   ax ay avx avy afriction  bx by bvx bvy bfriction  radius t_max  k m
  batch  N  then N times the pair's first 12 values  then 4 flags (1: shared) for
         friction_a, friction_b, radius, t_max
  scene  N  then N times (x y vx vy friction radius)  then t_max k
  poly   N  then N coefficients (highest degree first)  then k m
  geometry  3D (0 or 1)  P  then P paths, each K and K times (start, pos xyz, vel xyz,
         acc xyz)  then S and S times (px py qx qy side)  then C and C times (cx cy cz rho)
         then T and T targets likewise  then Q and Q times (point xyz, normal xyz)
         then radius t_max k j
k and m are the exponents of the invariants' power-of-two scalings (lengths or coefficients
by 2^k; time by 2^m, or the variable by 2^m); j that of geometry's translation (by 2^j). Floats as Python reads them ("inf" included);
a Rust Debug print of a case gives them exactly.
"""

import struct
import sys


def encode(target, values):
    out = bytearray(b"raw:")
    it = iter(values)

    def f(n=1):
        for _ in range(n):
            out.extend(struct.pack("<d", float(next(it))))

    def i(n=1):
        for _ in range(n):
            out.extend(struct.pack("<i", int(next(it))))

    def count():
        n = int(next(it))
        out.extend(struct.pack("<I", n))
        return n

    if target == "pair":
        f(12)
        i(2)
    elif target == "batch":
        f(12 * count())
        out.extend(bytes(int(next(it)) != 0 for _ in range(4)))
    elif target == "scene":
        f(6 * count() + 1)
        i()
    elif target == "poly":
        f(count())
        i(2)
    elif target == "geometry":
        out.extend(bytes([int(next(it)) != 0]) * 4)
        for _ in range(count()):
            f(10 * count())
        for _ in range(count()):
            f(4)
            i()
        f(4 * count())
        f(4 * count())
        f(6 * count())
        f(2)
        i(2)
    else:
        sys.exit(f"unknown target {target!r}")
    if next(it, None) is not None:
        sys.exit("too many values")
    return bytes(out)


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    target, path = sys.argv[1], sys.argv[2]
    data = encode(target, sys.argv[3:])
    with open(path, "wb") as fh:
        fh.write(data)


if __name__ == "__main__":
    main()
