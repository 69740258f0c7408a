#!/usr/bin/python3
"""A masonry wall for comparisons with LMGC90: ROWS courses of rectangular POLYG blocks in running
bond (every other course starts and ends with a half block), standing on a fixed JONCx ground,
blocks and ground touching exactly, under gravity; one IQS_CLB law; LMGC90's NLGS settings of such
walls (Quad 1.666e-4, 100 sweeps per check, up to 300 checks). Writes DATBOX/ and command.py.

Usage: bench/masonry_wall.py OUT_DIR [--rows 10] [--blocks 10] [--steps 100] [--dt 1e-3]
Then: lmgc-solve OUT_DIR, or LMGC90 (command.py), or scripts/agreement.py OUT_DIR.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import datbox_writer as w  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("out")
    parser.add_argument("--rows", type=int, default=10)
    parser.add_argument("--blocks", type=int, default=10)
    parser.add_argument("--steps", type=int, default=100)
    parser.add_argument("--dt", type=float, default=1e-3)
    args = parser.parse_args()
    length, height = 0.4, 0.2
    width = args.blocks * length
    bodies, number = [], 0
    for row in range(args.rows):
        y = (row + 0.5) * height
        # Course edges: full blocks, or a half block at each end of every other course.
        edges = [k * length for k in range(args.blocks + 1)]
        if row % 2:
            edges = [0.0] + [(k + 0.5) * length for k in range(args.blocks)] + [width]
        for left, right in zip(edges, edges[1:]):
            number += 1
            half = 0.5 * (right - left)
            vertices = [(-half, -0.5 * height), (half, -0.5 * height), (half, 0.5 * height), (-half, 0.5 * height)]
            bodies.append(w.rbdy2(number, "PLEXx", 0.5 * (left + right), y, 0.0, w.polygon(vertices)))
    ground = number + 1
    bodies.append(w.rbdy2(ground, "TDURx", 0.5 * width, -0.05, 0.0, w.joncx(0.5 * width + 0.5, 0.05)))
    files = {
        "BODIES.DAT": "".join(bodies),
        "BULK_BEHAV.DAT": w.bulk_behav([("PLEXx", 2000.0), ("TDURx", 2000.0)]),
        "TACT_BEHAV.DAT": w.tact_behav("iqsc0", 0.5, [("POLYG", "BLEUx", "POLYG", "BLEUx", 1e-3),
                                                     ("POLYG", "BLEUx", "JONCx", "WALLx", 1e-3)]),
        "DRV_DOF.DAT": w.fixed([ground]),
    }
    w.write_case(args.out, files, w.rigid_2d_script(args.dt, args.steps, 1.666e-4, 100, 300, write_every=10))
    print(f"{args.out}: {number} blocks on a JONCx ground")


if __name__ == "__main__":
    main()
