#!/usr/bin/env python3
"""Writes vectors/uwb/tdoa_closed_form.csv: exact range differences r_i1 = |p - BS_i| - |p - BS_1|
for tag positions p, from plain geometry (no solver), so the C++ closed-form TDOA solver is judged
against the truth. Anchor layout: see README.md (assumed; the paper prints no anchor coordinates)."""
import math
import sys

ANCHORS = [(-10.0, -10.0), (10.0, -10.0), (10.0, 10.0), (-10.0, 10.0)]  # BS1..BS4


def r(p, a):
    return math.hypot(p[0] - a[0], p[1] - a[1])


def rows():
    # 15 m x 15 m test field, 2.5 m grid (the paper's field is 1 m; 2.5 m keeps the file short).
    for i in range(7):
        for j in range(7):
            yield f"grid_{i}_{j}", (-7.5 + 2.5 * i, -7.5 + 2.5 * j), "ok"
    # Table 2 "actual" positions of paper 003.
    table2 = [(1.5, 3.5), (1.5, -5.5), (3.5, 1.5), (3.5, -5.5), (6.5, 1.5), (-3.5, 3.5),
              (-3.5, -5.5), (-4.5, -5.5), (-5.5, -1.5), (-5.5, 5.0), (6.13, 1.58), (2.47, 5.39),
              (1.22, -3.66), (5.78, -2.32), (-4.65, 5.81), (-0.95, 1.43), (-2.61, -6.49),
              (-5.33, -4.53), (-5.2, -1.3), (-1.4, 2.7)]
    for k, p in enumerate(table2, 1):
        yield f"table2_{k}", p, "ok"
    # On a baseline segment (between two anchors): solvable; on an anchor itself: degenerate.
    yield "on_bs1", (-10.0, -10.0), "on_baseline"  # r_i1 = every baseline
    yield "on_segment_bs1_bs2", (0.0, -10.0), "ok"
    yield "outside_field", (14.0, 3.0), "ok"
    # On a baseline's extension beyond an anchor: the hyperbola collapses to a ray.
    yield "beyond_bs2_on_bs1_bs2", (15.0, -10.0), "on_baseline"
    yield "beyond_bs1_on_bs1_bs4", (-10.0, -14.0), "on_baseline"
    yield "beyond_bs1_on_diagonal", (-12.0, -12.0), "on_baseline"
    yield "beyond_bs3_on_diagonal", (12.0, 12.0), "on_baseline"


def main(path):
    with open(path, "w", encoding="ascii") as f:
        f.write("# Paper 003 closed-form TDOA (eqs. 1-6): exact range differences, metres.\n")
        f.write("# Generator: vectors/uwb/make_tdoa_vectors.py (independent of the C++ solver)\n")
        f.write("# anchors_m: " + " ".join(f"BS{i+1}=({a[0]:g},{a[1]:g})" for i, a in
                                        enumerate(ANCHORS)) + "\n")
        f.write("name,x_m,y_m,r21_m,r31_m,r41_m,expected_status\n")
        for name, p, status in rows():
            r1 = r(p, ANCHORS[0])
            d = [r(p, a) - r1 for a in ANCHORS[1:]]
            f.write(f"{name},{p[0]:.6f},{p[1]:.6f},{d[0]:.9f},{d[1]:.9f},{d[2]:.9f},{status}\n")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "vectors/uwb/tdoa_closed_form.csv")
