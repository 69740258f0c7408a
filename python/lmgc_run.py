#!/usr/bin/python3
"""lmgc-run: run a case's own command.py, unchanged, with lmgc's chipy.

Usage: lmgc-run CASE_DIR [--max-steps N] [--quiet] [-- script arguments]

The script runs in CASE_DIR with `from pylmgc90 import chipy` giving lmgc's chipy (a forwarding
package put first on sys.path for this run only); sys.argv is the script's path and the arguments
after `--` (scripts test --norand). --max-steps N ends the script after N steps: the .LAST files
are written and lmgc-run exits 0. Exit: 0 success, 1 the script raised (its traceback is shown),
2 usage, 7 a Newton loop did not converge at the smallest time step (DOF.LAST and GPV.LAST hold the
last converged step).
"""
import argparse
import os
import runpy
import sys

HERE = os.path.dirname(os.path.realpath(__file__))
PYTHON_DIR = os.path.normpath(os.path.join(HERE, "@LMGC_RUN_PYTHON_DIR@"))
FORWARD_DIR = os.path.normpath(os.path.join(HERE, "@LMGC_RUN_FORWARD_DIR@"))


def main(argv):
    script_args = []
    if "--" in argv:
        cut = argv.index("--")
        argv, script_args = argv[:cut], argv[cut + 1:]
    parser = argparse.ArgumentParser(prog="lmgc-run", description="run CASE_DIR/command.py with lmgc's chipy")
    parser.add_argument("case_dir", metavar="CASE_DIR")
    parser.add_argument("--max-steps", type=int, default=-1, metavar="N",
                        help="end the script after N steps (.LAST written, exit 0)")
    parser.add_argument("--script", default="command.py", help="the script to run (default command.py)")
    parser.add_argument("-q", "--quiet", action="store_true", help="no warnings, no summary line")
    args = parser.parse_args(argv)
    if args.max_steps < -1:
        parser.error("--max-steps must be at least 0")
    script = os.path.join(args.case_dir, args.script)
    if not os.path.isfile(script):
        parser.error("no %s in %s" % (args.script, args.case_dir))
    sys.path[:0] = [FORWARD_DIR, PYTHON_DIR]
    import lmgc.chipy
    lmgc.chipy._configure(max_steps=args.max_steps, quiet=args.quiet)
    os.chdir(args.case_dir)
    script = os.path.abspath(args.script)
    sys.path.insert(0, os.path.dirname(script))
    sys.argv = [script] + script_args
    try:
        runpy.run_path(script, run_name="__main__")
    except SystemExit as stop:
        if stop.code not in (None, 0):
            raise
    finally:
        # Files whole even when the script raised or stopped: POSTPRO flushed, run report closed.
        if lmgc.chipy._session is not None:
            lmgc.chipy._session.finalize()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
