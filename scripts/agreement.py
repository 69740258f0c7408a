#!/usr/bin/python3
"""Step-by-step agreement of lmgc-solve with LMGC90 on LMGC90's rigid example cases.

For each case: a scratch copy of its DATBOX/ and command.py is run by LMGC90 (built by
../shared/tools/build-lmgc90.sh) and by lmgc-solve for N steps, both writing DOF.OUT.k and
Vloc_Rloc.OUT.k at every step. The script given to both is the case's own, with four edits that
change what is written or how often, not the problem: nb_steps = N, freq_write = 1, WriteOutDof
becomes WriteOut (so Vloc_Rloc is written too), and the quick scramble (random sweep order, which
differs from run to run) is left out; DISPLAY files are not written. Then, step by step:

- the interactions of each code (count per module), how many of them the other code has too
  (same bodies, contactors and vertex, counted with multiplicity) and how many sit at the same place
  of Vloc_Rloc.OUT.k;
- the largest position and velocity differences over the bodies;
- the bodies that part: a coordinate differing by more than one unit of the files' last (7th)
  digit, and the first step and body where that happens.

Writes bench/results/<machine>/agreement/<case>.csv (one row per step) and the table of
docs/agreement.md (its hand-kept "## Why they part" section stays).

Usage: scripts/agreement.py [--steps 100] [--lmgc90 ../lmgc90/build] [--build build/release]
                            [--work /tmp/lmgc_agreement] [CASE ...]
CASE: a folder of ../shared/lmgc90-examples (RIGID_2D/BridgePL_GroundJC) or a path; default every
RIGID_2D and RIGID_3D example.
"""
import argparse
import collections
import csv
import datetime
import os
import platform
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SHARED = os.environ.get("LMGC_SHARED_DIR", os.path.join(os.path.dirname(ROOT), "shared"))
EXAMPLES = os.path.join(SHARED, "lmgc90-examples")
sys.path.insert(0, os.path.join(ROOT, "bench"))
from lmgc90_examples import prepare_case  # noqa: E402
MACHINE = os.environ.get("LMGC_MACHINE", "debian12-2core")

# A number as LMGC90 writes it: 0.1234567D+01 (mantissa and exponent kept apart for the last digit).
NUMBER = re.compile(r"([-+ ]?)(\d*)\.(\d+)D([-+]\d+)")


def number_and_ulp(text):
    """The value and one unit of its last written digit."""
    sign, whole, fraction, exponent = NUMBER.fullmatch(text.strip()).groups()
    value = float(f"{sign.strip()}{whole or '0'}.{fraction}E{exponent}")
    return value, 10.0 ** (int(exponent) - len(fraction))


def read_dof(path):
    """{body number: [(value, ulp) of X(1..), V(1..)]}, in file order."""
    bodies = collections.OrderedDict()
    body = None
    with open(path, encoding="ascii", errors="replace") as f:
        lines = f.read().splitlines()
    for i, line in enumerate(lines):
        if line.startswith("$bdyty") and i + 1 < len(lines):
            body = int(lines[i + 1].split()[1])
            bodies[body] = []
        elif body is not None and ("X(1)=" in line or "V(1)=" in line):
            bodies[body] += [number_and_ulp(m.group(0)) for m in NUMBER.finditer(line)]
    return bodies


def read_interactions(path):
    """[(module, cd body, cd contactor, its number, vertex number, an body, an contactor, its number)]."""
    out = []
    with open(path, encoding="ascii", errors="replace") as f:
        lines = f.read().splitlines()
    for i, line in enumerate(lines):
        if not line.startswith("$icdan"):
            continue
        module = line.split()[1]
        header, row = lines[i + 1], lines[i + 2]
        # The header names the columns above their values (a 'numbr' column is the number of the
        # column before it; a value may be blank, as 3D's CDVER): each value is read under its name.
        names = []
        for m in re.finditer(r"\S+", header):
            name = m.group(0)
            name = names[-1][0] + "#" if name == "numbr" and names else name
            names.append((name, m.start(), m.end()))
        fields = {}
        for k, (name, start, end) in enumerate(names):
            stop = names[k + 1][1] if k + 1 < len(names) else len(row)
            fields[name] = row[max(0, start - 2):stop].strip() if k else row[:stop].strip()
        out.append((module, fields.get("cdbdy#"), fields.get("cdtac"), fields.get("cdtac#"),
                    fields.get("vertx#", fields.get("CDVER", "")), fields.get("anbdy#"), fields.get("antac"),
                    fields.get("antac#")))
    return out


def edit_script(text, steps):
    """The case's command.py with the writing edits described above."""
    text = re.sub(r"^nb_steps\s*=.*$", f"nb_steps = {steps}", text, flags=re.M)
    text = re.sub(r"^freq_write\s*=.*$", "freq_write = 1", text, flags=re.M)
    text = re.sub(r"^freq_display\s*=.*$", "freq_display = 1000000000", text, flags=re.M)
    text = text.replace("chipy.WriteOutDof(", "chipy.WriteOut(")
    text = re.sub(r"chipy\.nlgs(_3D)?_SetWithQuickScramble\(\)", "pass", text)
    return text


def prepare(case, work, steps):
    prepare_case(case, work, lambda text: edit_script(text, steps))


def run_lmgc90(work, lmgc90_build, timeout):
    env = dict(os.environ, OMP_NUM_THREADS="1", OPENBLAS_NUM_THREADS="1", PYTHONPATH=lmgc90_build)
    with open(os.path.join(work, "lmgc90.log"), "w") as log:
        return subprocess.run(["/usr/bin/python3", "command.py", "--norand"], cwd=work, env=env,
                              timeout=timeout, stdout=log, stderr=subprocess.PIPE, text=True)


def lmgc90_check_norms(work):
    """{step: (QuadDV/QuadWR, QuadDVR/MeanWRR, MeanDVoR/SumWRR) of its last check, number of checks}
    from LMGC90's log (display_check_nlgs prints each check, normalised by the tolerance)."""
    norms, step = {}, 0
    number = r"([-+]?\d*\.\d+D[-+]\d+)"
    value = lambda m: float(m.group(1).replace("D", "E"))
    with open(os.path.join(work, "lmgc90.log"), errors="replace") as f:
        for line in f:
            m = re.search(r"@ step =\s+(\d+)", line)
            if m:
                step = int(m.group(1))
                norms[step] = [None, None, None, 0]
                continue
            if step not in norms:
                continue
            for k, label in enumerate(("QuadDV  /QuadWR", "QuadDVR /MeanWRR", "MeanDVoR/SumWRR")):
                m = re.search(re.escape(label) + r"\s*=\s*" + number, line)
                if m:
                    norms[step][k] = value(m)
                    norms[step][3] += k == 0
    return norms


def lmgc_report(work):
    """{step: row of OUTBOX/run_report.csv}."""
    path = os.path.join(work, "OUTBOX", "run_report.csv")
    if not os.path.exists(path):
        return {}
    with open(path) as f:
        return {int(row["step"]): row for row in csv.DictReader(f)}


def run_lmgc(work, build, timeout):
    solve = os.path.join(build, "tools", "lmgc-solve")
    return subprocess.run([solve, work, "--quiet"], timeout=timeout, stdout=subprocess.DEVNULL,
                          stderr=subprocess.PIPE, text=True)


def compare_step(reference_dir, ours_dir, k):
    """One row of the per-step table, or None when a file is missing."""
    paths = [os.path.join(d, "OUTBOX", f"{name}.OUT.{k}") for d in (reference_dir, ours_dir)
             for name in ("DOF", "Vloc_Rloc")]
    if not all(os.path.exists(p) for p in paths):
        return None
    ref_dof, ref_vloc, our_dof, our_vloc = read_dof(paths[0]), read_interactions(paths[1]), \
        read_dof(paths[2]), read_interactions(paths[3])
    common = sum((collections.Counter(ref_vloc) & collections.Counter(our_vloc)).values())
    same_place = sum(a == b for a, b in zip(ref_vloc, our_vloc))
    max_dx = max_dv = 0.0
    parted = []
    for body, ref in ref_dof.items():
        ours = our_dof.get(body)
        if ours is None or len(ours) != len(ref):
            parted.append(body)
            continue
        half = len(ref) // 2
        apart = False
        for j, ((a, ulp_a), (b, ulp_b)) in enumerate(zip(ref, ours)):
            difference = abs(a - b)
            if j < half:
                max_dx = max(max_dx, difference)
            else:
                max_dv = max(max_dv, difference)
            apart |= difference > max(ulp_a, ulp_b) * 1.000001
        if apart:
            parted.append(body)
    modules = lambda rows: " ".join(f"{m}:{n}" for m, n in sorted(collections.Counter(r[0] for r in rows).items()))
    return dict(step=k, lmgc90_interactions=len(ref_vloc), lmgc_interactions=len(our_vloc),
                lmgc90_modules=modules(ref_vloc), lmgc_modules=modules(our_vloc), common=common,
                same_place=same_place, max_position_difference=f"{max_dx:.3e}",
                max_velocity_difference=f"{max_dv:.3e}", bodies_parted=len(parted),
                first_body_parted=parted[0] if parted else "")


def agreement(case, args):
    name = os.path.relpath(case, EXAMPLES) if case.startswith(EXAMPLES) else os.path.basename(case)
    work = os.path.join(args.work, name.replace("/", "_"))
    reference_dir, ours_dir = work + "/lmgc90", work + "/lmgc"
    prepare(case, reference_dir, args.steps)
    prepare(case, ours_dir, args.steps)
    result = dict(case=name, steps=args.steps, note="")
    ours = run_lmgc(ours_dir, args.build, args.timeout)
    if ours.returncode != 0:
        codes = sorted(set(re.findall(r"\[(L\d{4})\]", ours.stderr)))
        result["note"] = f"lmgc-solve exit {ours.returncode} ({', '.join(codes) or ours.stderr.strip()[-200:]})"
        return result, []
    reference = run_lmgc90(reference_dir, args.lmgc90, args.timeout)
    if reference.returncode != 0:
        result["note"] = f"LMGC90 exit {reference.returncode}: {reference.stderr.strip()[-200:]}"
        return result, []
    rows = []
    norms, report = lmgc90_check_norms(reference_dir), lmgc_report(ours_dir)
    for k in range(1, args.steps + 1):
        row = compare_step(reference_dir, ours_dir, k)
        if row is None:
            break
        # The achieved NLGS check norms of both codes (LMGC90's measure, normalised by the tolerance).
        theirs, mine = norms.get(k, [None] * 4), report.get(k, {})
        row.update(lmgc90_quad_dv=theirs[0] if theirs[0] is not None else "",
                   lmgc_quad_dv=mine.get("quad_dv", ""),
                   lmgc90_checks=theirs[3], lmgc_iterations=mine.get("iterations", ""),
                   lmgc_natural_map_residual=mine.get("residual_natural_map_over_q", ""))
        rows.append(row)
    return result, rows


def summarise(result, rows):
    """One line of docs/agreement.md."""
    if not rows:
        return f"| {result['case']} | — | — | — | — | — | — | {result['note'] or 'no step written'} |"
    first_interactions = next((r["step"] for r in rows if r["common"] != r["lmgc90_interactions"]
                               or r["lmgc_interactions"] != r["lmgc90_interactions"]), None)
    first_parted = next((r for r in rows if r["bodies_parted"]), None)
    last = rows[-1]
    parted = (f"step {first_parted['step']}, body {first_parted['first_body_parted']} "
              f"({first_parted['bodies_parted']} bodies)" if first_parted else "none")
    same = f"through step {first_interactions - 1}" if first_interactions else f"all {len(rows)} steps"
    order = f"{last['same_place']}/{last['lmgc90_interactions']}"
    # Achieved check norm QuadDV/(tol QuadWR), median over the steps with contacts, both codes.
    def median(key):
        values = sorted(float(r[key]) for r in rows if r[key] not in ("", None) and r["lmgc90_interactions"])
        return f"{values[len(values) // 2]:.2g}" if values else "—"
    return (f"| {result['case']} | {len(rows)} | {same} | {order} | {parted} | "
            f"{last['max_position_difference']} / {last['max_velocity_difference']} | "
            f"{last['lmgc90_interactions']} / {last['lmgc_interactions']} | "
            f"{median('lmgc90_quad_dv')} / {median('lmgc_quad_dv')} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("cases", nargs="*")
    parser.add_argument("--steps", type=int, default=100)
    parser.add_argument("--lmgc90", default=os.path.join(os.path.dirname(ROOT), "lmgc90", "build"))
    parser.add_argument("--build", default=os.path.join(ROOT, "build", "release"))
    parser.add_argument("--work", default="/tmp/lmgc_agreement")
    parser.add_argument("--timeout", type=float, default=3600)
    parser.add_argument("--doc", default=os.path.join(ROOT, "docs", "agreement.md"))
    args = parser.parse_args()
    if not os.path.isdir(os.path.join(args.lmgc90, "pylmgc90")):
        sys.exit(f"agreement: no LMGC90 build at {args.lmgc90} (../shared/tools/build-lmgc90.sh)")
    cases = [c if os.path.isdir(c) else os.path.join(EXAMPLES, c) for c in args.cases] or sorted(
        os.path.join(EXAMPLES, d, c) for d in ("RIGID_2D", "RIGID_3D")
        for c in os.listdir(os.path.join(EXAMPLES, d)))
    out_dir = os.path.join(ROOT, "bench", "results", MACHINE, "agreement")
    os.makedirs(out_dir, exist_ok=True)
    lines = []
    for case in cases:
        result, rows = agreement(os.path.abspath(case), args)
        line = summarise(result, rows)
        print(line, flush=True)
        lines.append(line)
        if rows:
            with open(os.path.join(out_dir, result["case"].replace("/", "_") + ".csv"), "w", newline="") as f:
                writer = csv.DictWriter(f, fieldnames=list(rows[0]))
                writer.writeheader()
                writer.writerows(rows)
    kept = ""
    if os.path.exists(args.doc):
        with open(args.doc) as f:
            text = f.read()
        if "## Why they part" in text:
            kept = text[text.index("## Why they part"):]
    cpu = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")), "")
    with open(args.doc, "w") as f:
        f.write(f"""# Agreement with LMGC90, step by step

`scripts/agreement.py --steps {args.steps}`, {datetime.date.today()}, on {MACHINE} ({cpu}): each rigid
example run by LMGC90 and by lmgc-solve from the same script (the case's `command.py`, edited only in
what it writes: every step, Vloc_Rloc too, no DISPLAY; and without the quick scramble, whose random
sweep order differs from run to run), compared step by step. Per-step data:
`bench/results/{MACHINE}/agreement/<case>.csv`.

Columns: steps compared; the steps through which both codes have the same interactions (the same
bodies, contactors and vertices); at the last step, how many interactions sit at the same place of
`Vloc_Rloc.OUT` (LMGC90's order); the first step and body where a position or velocity differs by
more than one unit of the files' 7th digit; the largest position / velocity difference at the last
step; the interactions of LMGC90 / lmgc at the last step; the achieved NLGS check norm of LMGC90 / lmgc
(QuadDV over tol·QuadWR, as LMGC90 prints it at a step's last check: 1 is the tolerance), median over the
steps with contacts.

| case | steps | same interactions | same place (last) | first parting | max Δx / Δv (last) | interactions (last) | check norm |
| --- | --- | --- | --- | --- | --- | --- | --- |
""")
        f.write("\n".join(lines) + "\n\n")
        f.write(kept or "## Why they part\n")


if __name__ == "__main__":
    main()
