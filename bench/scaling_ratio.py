#!/usr/bin/python3
"""Scaling ratio of the rigid benches: (64k s/step ÷ 1k s/step) ÷ (64k contacts ÷ 1k contacts).

Runs each given bench binary (build/release/bench/rigid_2d_bench or rigid_3d_bench) in full, or the
benchmarks --filter takes, N rounds, the binaries alternated within each round so that they share the
machine's slow and quick spells.
Prints, per binary and scene, every run's ratio, their median, and the ratio from the fastest run at
each size (on a shared machine other load only adds time, so the fastest run is the least disturbed);
then, from the fastest run at each size, the time per contact and step of every size and its growth
over the 1k one's.

  bench/scaling_ratio.py [--runs N] [--keep DIR] [--filter REGEX] BENCH [BENCH...]
"""
import argparse
import os
import re
import statistics
import subprocess
import sys

UNITS = {'': 1.0, 'k': 1e3, 'm': 1e-3, 'u': 1e-6, 'n': 1e-9}


def counter(line, name):
    match = re.search(r' ' + name + r'=([0-9.e+-]+)([kmun]?)', line)
    if not match:
        raise ValueError(f'no counter {name} in: {line}')
    return float(match.group(1)) * UNITS[match.group(2)]


def run_once(bench, benchmark_filter=None):
    """{(scene, size): (s_per_step, contacts)} of one run (all of the bench, or the benchmarks the filter takes)."""
    command = [bench] + ([f'--benchmark_filter={benchmark_filter}'] if benchmark_filter else [])
    out = subprocess.run(command, capture_output=True, text=True, check=True).stdout
    sizes = {}
    for line in out.splitlines():
        match = re.match(r'BM_Step(\w+)/(\d+)/', line)
        if match:
            sizes[(match.group(1), int(match.group(2)))] = (counter(line, 's_per_step'), counter(line, 'contacts'))
    return out, sizes


def ratio(small, large):
    (t_small, c_small), (t_large, c_large) = small, large
    return (t_large / t_small) / (c_large / c_small)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('benches', nargs='+', metavar='BENCH')
    parser.add_argument('--runs', type=int, default=4)
    parser.add_argument('--keep', metavar='DIR', help='write each run\'s output there')
    parser.add_argument('--filter', metavar='REGEX',
                        help='only the benchmarks this Google Benchmark filter takes; it must keep the 1k and 64k '
                             'sizes of a scene, e.g. \'StepDiskLayer/(1000|64000)/\' (more runs in the same time)')
    args = parser.parse_args()
    runs = {bench: [] for bench in args.benches}
    for round_index in range(args.runs):
        for bench in args.benches:
            out, sizes = run_once(bench, args.filter)
            scenes = sorted({scene for scene, _ in sizes})
            if not scenes or any((scene, size) not in sizes for scene in scenes for size in (1000, 64000)):
                sys.exit(f'{bench}: every scene run needs its 1k and 64k sizes (filter: {args.filter})')
            runs[bench].append(sizes)
            if args.keep:
                os.makedirs(args.keep, exist_ok=True)
                name = f'{os.path.basename(bench)}.{args.benches.index(bench)}.run{round_index}.txt'
                with open(os.path.join(args.keep, name), 'w') as f:
                    f.write(out)
            line = ', '.join(f'{s} {ratio(sizes[(s, 1000)], sizes[(s, 64000)]):.3f}' for s in scenes)
            print(f'round {round_index + 1}: {bench}: {line}', file=sys.stderr, flush=True)
    for bench, results in runs.items():
        for scene in sorted({scene for scene, _ in results[0]}):
            ratios = [ratio(r[(scene, 1000)], r[(scene, 64000)]) for r in results]
            fastest_small = min(r[(scene, 1000)][0] for r in results)
            fastest_large = min(r[(scene, 64000)][0] for r in results)
            contacts = results[0][(scene, 1000)][1], results[0][(scene, 64000)][1]
            fastest = ratio((fastest_small, contacts[0]), (fastest_large, contacts[1]))
            print(f'{bench} {scene}: contacts {contacts[0]:.0f} -> {contacts[1]:.0f}; runs '
                  f'{" ".join(f"{x:.3f}" for x in ratios)}; median {statistics.median(ratios):.3f}; '
                  f'fastest at each size (1k {fastest_small * 1e3:.3f} ms, 64k {fastest_large:.4f} s): {fastest:.3f}')
            # Every size, from its fastest run: time per contact and step, and its growth over 1k's.
            per_contact = {}
            for size in sorted({size for (s, size) in results[0] if s == scene}):
                seconds = min(r[(scene, size)][0] for r in results)
                per_contact[size] = seconds / results[0][(scene, size)][1]
            print('  per contact and step, fastest run at each size: ' + ', '.join(
                f'{size // 1000}k {t * 1e9:.0f} ns ({t / per_contact[1000]:.3f})' for size, t in per_contact.items()))


if __name__ == '__main__':
    main()
