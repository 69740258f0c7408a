#!/usr/bin/python3
"""Compares two OUTBOX trees (ours and LMGC90's) state file by state file.

For every DOF.OUT.n (and DOF.LAST) present in both trees: the largest difference of body
positions X and velocities V, absolute and relative to the largest value of the reference
file; for every Vloc_Rloc.OUT.n present in both: the number of interactions per module and of
active ones (rn != 0). Prints one line per file and a summary; exits 1 when --tolerance is given
and a relative position difference exceeds it.

Usage: compare_outbox.py OURS/OUTBOX LMGC90/OUTBOX [--tolerance 1e-8] [--max-index N]
"""
import argparse
import gzip
import os
import re
import sys

import numpy as np

NUMBER = re.compile(r"[-+]?\d*\.\d+(?:[DE][-+]?\d+)?")
NORMAL_REACTION = re.compile(r"\brl?n/H\s*=?\s*([-+]?\d*\.\d+(?:[DE][-+]?\d+)?)")


def read_text(path):
    if os.path.exists(path):
        with open(path, "r", encoding="ascii", errors="replace") as f:
            return f.read()
    if os.path.exists(path + ".gz"):
        with gzip.open(path + ".gz", "rt", encoding="ascii", errors="replace") as f:
            return f.read()
    return None


def dof_state(text):
    """X and V of each node, as two arrays (one row per node, in file order)."""
    xs, vs = [], []
    for line in text.splitlines():
        if "X(1)=" in line:
            xs.append([float(v.replace("D", "E")) for v in NUMBER.findall(line)])
        elif "V(1)=" in line:
            vs.append([float(v.replace("D", "E")) for v in NUMBER.findall(line)])
    width = max((len(r) for r in xs + vs), default=0)
    pad = lambda rows: np.array([r + [0.0] * (width - len(r)) for r in rows])
    return pad(xs), pad(vs)


def vloc_rloc_counts(text):
    """Interactions per module and how many carry a non-zero normal reaction."""
    counts, active = {}, 0
    lines = text.splitlines()
    for i, line in enumerate(lines):
        if line.startswith("$icdan"):
            module = line.split()[1]
            counts[module] = counts.get(module, 0) + 1
            for follow in lines[i + 1 : i + 6]:
                match = NORMAL_REACTION.search(follow)
                if match:
                    active += float(match.group(1).replace("D", "E")) != 0.0
                    break
    return counts, active


def index_of(name):
    tail = name.rsplit(".", 1)[-1]
    return int(tail) if tail.isdigit() else None


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("ours")
    parser.add_argument("reference")
    parser.add_argument("--tolerance", type=float, default=None)
    parser.add_argument("--max-index", type=int, default=None, help="compare OUT.n with n <= this only")
    args = parser.parse_args()

    names = set()
    for folder in (args.ours, args.reference):
        for name in os.listdir(folder):
            names.add(name[:-3] if name.endswith(".gz") else name)
    dof_names = sorted((n for n in names if re.fullmatch(r"DOF\.OUT\.\d+", n)), key=index_of)
    if args.max_index is not None:
        dof_names = [n for n in dof_names if index_of(n) <= args.max_index]
    worst = 0.0
    compared = 0
    for name in dof_names:
        ours = read_text(os.path.join(args.ours, name))
        theirs = read_text(os.path.join(args.reference, name))
        if ours is None or theirs is None:
            continue
        x1, v1 = dof_state(ours)
        x2, v2 = dof_state(theirs)
        if x1.shape != x2.shape:
            print(f"{name}: {x1.shape[0]} nodes here, {x2.shape[0]} in the reference")
            worst = float("inf")
            continue
        scale = max(np.abs(x2).max(), 1e-300)
        dx = np.abs(x1 - x2).max()
        dv = np.abs(v1 - v2).max() if v1.shape == v2.shape and v1.size else 0.0
        rel = dx / scale
        worst = max(worst, rel)
        compared += 1
        line = f"{name}: bodies {x1.shape[0]}  max|dX| {dx:.3e} (relative {rel:.3e})  max|dV| {dv:.3e}"
        vloc = name.replace("DOF", "Vloc_Rloc")
        a, b = read_text(os.path.join(args.ours, vloc)), read_text(os.path.join(args.reference, vloc))
        if a is not None and b is not None:
            (ca, aa), (cb, ab) = vloc_rloc_counts(a), vloc_rloc_counts(b)
            line += f"  interactions {sum(ca.values())}/{sum(cb.values())}  active {aa}/{ab}"
        print(line)
    print(f"compared {compared} DOF files; worst relative position difference {worst:.3e}")
    if args.tolerance is not None and (compared == 0 or worst > args.tolerance):
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
