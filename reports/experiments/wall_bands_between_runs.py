#!/usr/bin/env python3
"""Rms difference, band by band, between the wall pressure profiles of several runs of one case
(reports/frictional_silo.md, the Janssen column between codes). A band's pressure is the
area-weighted mean over its angle bins of `pressure_final` in PROBE.csv; the difference of two runs
is the rms over the bands, as a fraction of the larger run's largest band.

    /usr/bin/python3 reports/experiments/wall_bands_between_runs.py mantle \\
        results/compare/janssen_frictional/base/silodem \\
        results/compare/janssen_frictional/base/silodem/reconstructed \\
        results/compare/janssen_frictional/base/{lammps,liggghts,yade}

Each folder holds probes/PROBE.csv (a result folder of any code, or silodem's rebuild from its
own dumps, `reconstructed/`). Prints the table of every pair.
"""
import csv
import math
import pathlib
import sys


def band_pressures(folder, probe):
    weighted, area = {}, {}
    with open(pathlib.Path(folder) / "probes" / f"{probe}.csv") as f:
        for row in csv.DictReader(f):
            band, a = int(row["height_bin"]), float(row["area"])
            weighted[band] = weighted.get(band, 0.0) + a * float(row["pressure_final"])
            area[band] = area.get(band, 0.0) + a
    return [weighted[b] / area[b] for b in sorted(weighted)]


def rms_of_largest(p, q):
    if len(p) != len(q):
        sys.exit(f"the runs have {len(p)} and {len(q)} bands: not the same probe")
    scale = max(max(abs(x) for x in p), max(abs(x) for x in q))
    return math.sqrt(sum((x - y) ** 2 for x, y in zip(p, q)) / len(p)) / scale


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    probe, folders = sys.argv[1], sys.argv[2:]
    profiles = {f: band_pressures(f, probe) for f in folders}
    names = [pathlib.Path(f).name if pathlib.Path(f).name != "reconstructed"
             else pathlib.Path(f).parent.name + "/reconstructed" for f in folders]
    print("| | " + " | ".join(names) + " |")
    print("|---" * (len(names) + 1) + "|")
    for f, name in zip(folders, names):
        cells = ["" if g == f else f"{100 * rms_of_largest(profiles[f], profiles[g]):.2f} %" for g in folders]
        print(f"| {name} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
