#!/usr/bin/python3
"""The discharge rate of a Dosta silo run from its series.csv (n_mobile every 0.01 s), usable while
the run goes on: the folder may be the finished discharge or its DIR.partial-<pid>.

  tools/dosta_flow.py DIR [--grain-mass KG] [--from S] [--block S]

Prints the mass flow per 0.1 s window and, from --from (default 0.1 s, when the flow is steady)
to the last row, the mean over blocks of --block s (default 0.05) with the blocks' standard
deviation. A grain of d = 4 mm and 2500 kg/m³ (material M1) is 8.378e-5 kg."""
import argparse
import csv
import math
import os
import statistics

parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
parser.add_argument("dir")
parser.add_argument("--grain-mass", type=float, default=2500.0 * math.pi / 6 * 0.004 ** 3)
parser.add_argument("--from", dest="start", type=float, default=0.1)
parser.add_argument("--block", type=float, default=0.05)
args = parser.parse_args()

with open(os.path.join(args.dir, "series.csv")) as f:
    rows = [(float(r["t"]), int(r["n_mobile"])) for r in csv.DictReader(f)]
if len(rows) < 3:
    raise SystemExit("dosta_flow: %s/series.csv has fewer than 3 rows" % args.dir)


def mobile_at(t):
    """n_mobile at the row nearest t."""
    return min(rows, key=lambda r: abs(r[0] - t))[1]


def rate(a, b):
    return (mobile_at(a) - mobile_at(b)) * args.grain_mass / (b - a)


end = rows[-1][0]
print("| window [s] | mass flow [kg/s] |\n|---|---|")
t = 0.0
while t + 0.1 <= end + 1e-9:
    print("| %.1f–%.1f | %.3f |" % (t, t + 0.1, rate(t, t + 0.1)))
    t += 0.1
blocks, t = [], args.start
while t + args.block <= end + 1e-9:
    blocks.append(rate(t, t + args.block))
    t += args.block
if len(blocks) >= 2:
    print("| %.2f–%.2f, %d blocks of %g s | **%.3f ± %.3f** (block sd) |" % (
        args.start, args.start + len(blocks) * args.block, len(blocks), args.block, statistics.mean(blocks),
        statistics.stdev(blocks)))
print("\nlast row t = %.4f s, %d grains left, %.2f kg discharged" % (end, rows[-1][1], (rows[0][1] - rows[-1][1]) * args.grain_mass))
