#!/usr/bin/python3
"""Peak memory and time per step of lmgc and LMGC90 on the same disk boxes of 10^4, 10^5, 10^6 bodies.

The scene (bench/datbox_writer.py, one DATBOX/ and one command.py for both codes): N disks of
radius 1 on a square lattice of spacing 2, each touching its neighbours and the walls (about 2N
contacts, most of them loaded, as in a dense 2D packing), in a box of three fixed JONCx walls,
under gravity, one IQS_CLB law. `lmgc-solve CASE` reads the script, LMGC90 runs it.

For each size and code, in its own process: the peak resident memory (getrusage of the finished
child: the whole run, reading included) and the median wall time of a step (lmgc: run_report.csv's
step_seconds; LMGC90: the script times each step). lmgc-check's peak is measured too. The runs of
the two codes alternate (lmgc, LMGC90, lmgc, ...) so that both see the same machine load.

Writes bench/results/<machine>/memory.csv and the table of docs/memory.md.

Usage: bench/memory.py [--sizes 10000 100000 1000000] [--steps 5] [--rounds 1]
                       [--lmgc90 ../lmgc90/build] [--build build/product] [--work /tmp/lmgc_memory]
"""
import argparse
import csv
import datetime
import math
import os
import resource
import statistics
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import datbox_writer as w  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MACHINE = os.environ.get("LMGC_MACHINE", "debian12-2core")


def write_case(folder, n, steps):
    """The disk box of n disks (see above)."""
    side = math.ceil(math.sqrt(n))
    width = 2.0 * side
    # JONCx walls: the ground under the lattice, two sides turned a quarter turn.
    bodies = [w.rbdy2(1, "TDURx", width / 2, -0.5, 0.0, w.joncx(width / 2 + 1, 0.5)),
              w.rbdy2(2, "TDURx", -0.5, width / 2, math.pi / 2, w.joncx(width / 2 + 1, 0.5)),
              w.rbdy2(3, "TDURx", width + 0.5, width / 2, math.pi / 2, w.joncx(width / 2 + 1, 0.5))]
    for k in range(n):
        i, j = k % side, k // side
        bodies.append(w.rbdy2(4 + k, "PLEXx", 1.0 + 2.0 * i, 1.0 + 2.0 * j, 0.0, w.disk(1.0)))
    files = {
        "BODIES.DAT": "".join(bodies),
        "BULK_BEHAV.DAT": w.bulk_behav([("PLEXx", 1000.0), ("TDURx", 1000.0)]),
        "TACT_BEHAV.DAT": w.tact_behav("iqsc0", 0.3, [("DISKx", "BLEUx", "DISKx", "BLEUx", 0.05),
                                                     ("DISKx", "BLEUx", "JONCx", "WALLx", 0.05)]),
        "DRV_DOF.DAT": w.fixed([1, 2, 3]),
    }
    w.write_case(folder, files, w.rigid_2d_script(1e-3, steps, 1.666e-4, 50, 10, timed=True))


def measured(command, cwd=None, env=None):
    """Runs `command` in a child of a fresh interpreter; returns (peak RSS in bytes, wall seconds)."""
    probe = ("import resource, subprocess, sys, time\n"
             "start = time.perf_counter()\n"
             f"r = subprocess.run({command!r}, cwd={cwd!r}, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)\n"
             "wall = time.perf_counter() - start\n"
             "if r.returncode: sys.stderr.write(r.stderr.decode()[-2000:]); sys.exit(r.returncode)\n"
             "print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss * 1024, wall)\n")
    out = subprocess.run([sys.executable, "-c", probe], env=env, capture_output=True, text=True)
    if out.returncode:
        raise RuntimeError(f"{command}: exit {out.returncode}: {out.stderr[-1000:]}")
    peak, wall = out.stdout.split()
    return int(peak), float(wall)


def lmgc_steps(case):
    with open(os.path.join(case, "OUTBOX", "run_report.csv")) as f:
        return [float(row["step_seconds"]) for row in csv.DictReader(f)]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sizes", type=int, nargs="+", default=[10000, 100000, 1000000])
    parser.add_argument("--steps", type=int, default=5)
    parser.add_argument("--rounds", type=int, default=1)
    parser.add_argument("--lmgc90", default=os.path.join(os.path.dirname(ROOT), "lmgc90", "build"))
    parser.add_argument("--build", default=os.path.join(ROOT, "build", "product"))
    parser.add_argument("--work", default="/tmp/lmgc_memory")
    parser.add_argument("--doc", default=os.path.join(ROOT, "docs", "memory.md"))
    args = parser.parse_args()
    tools = os.path.join(args.build, "tools")
    have_lmgc90 = os.path.isdir(os.path.join(args.lmgc90, "pylmgc90"))
    env90 = dict(os.environ, OMP_NUM_THREADS="1", OPENBLAS_NUM_THREADS="1", PYTHONPATH=args.lmgc90)
    rows = []
    for n in args.sizes:
        cases = {code: os.path.join(args.work, f"{code}_{n}") for code in ("lmgc", "lmgc90")}
        for case in cases.values():
            if not os.path.exists(os.path.join(case, "DATBOX", "BODIES.DAT")):
                write_case(case, n, args.steps)
        row = dict(bodies=n, steps=args.steps)
        check, lmgc, lmgc90, lmgc_step, lmgc90_step = [], [], [], [], []
        for _ in range(args.rounds):
            check.append(measured([os.path.join(tools, "lmgc-check"), "--quiet", cases["lmgc"]])[0])
            lmgc.append(measured([os.path.join(tools, "lmgc-solve"), "--quiet", cases["lmgc"]])[0])
            lmgc_step.append(statistics.median(lmgc_steps(cases["lmgc"])))
            if have_lmgc90:
                lmgc90.append(measured([sys.executable, "command.py"], cwd=cases["lmgc90"], env=env90)[0])
                with open(os.path.join(cases["lmgc90"], "step_seconds.txt")) as f:
                    lmgc90_step.append(statistics.median(float(t) for t in f.read().split()))
        row.update(lmgc_check_peak_mb=round(min(check) / 2**20), lmgc_solve_peak_mb=round(min(lmgc) / 2**20),
                   lmgc_seconds_per_step=f"{min(lmgc_step):.4g}",
                   lmgc90_peak_mb=round(min(lmgc90) / 2**20) if lmgc90 else "",
                   lmgc90_seconds_per_step=f"{min(lmgc90_step):.4g}" if lmgc90_step else "")
        print(row, flush=True)
        rows.append(row)
    out_dir = os.path.join(ROOT, "bench", "results", MACHINE)
    os.makedirs(out_dir, exist_ok=True)
    with open(os.path.join(out_dir, "memory.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    cpu = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")), "")
    with open(args.doc, "w") as f:
        f.write(f"""# Memory

`bench/memory.py --steps {args.steps} --rounds {args.rounds}`, {datetime.date.today()}, on {MACHINE} ({cpu}),
lmgc's product build and LMGC90 built by `../shared/tools/build-lmgc90.sh`. The scene: N disks on a
square lattice in a box of three JONCx walls, every disk touching its neighbours (about 2N contacts,
most of them loaded), both codes running the same `command.py` (dt 1e-3, NLGS Quad 1.666e-4,
50 × 10 sweeps). Peak resident memory of the whole run (reading included); time per step the
median of {args.steps} steps (the smallest of the rounds), with the same NLGS settings but not the same
achieved residual: speed at equal residual is compared in `docs/performance.md`. Raw data:
`bench/results/{MACHINE}/memory.csv`.

| bodies | lmgc-check peak (MB) | lmgc-solve peak (MB) | LMGC90 peak (MB) | lmgc s/step | LMGC90 s/step |
| --- | --- | --- | --- | --- | --- |
""")
        for r in rows:
            f.write(f"| {r['bodies']} | {r['lmgc_check_peak_mb']} | {r['lmgc_solve_peak_mb']} | {r['lmgc90_peak_mb']} | "
                    f"{r['lmgc_seconds_per_step']} | {r['lmgc90_seconds_per_step']} |\n")


if __name__ == "__main__":
    main()
