#!/usr/bin/python3
"""Frictional dense-bed throughput against LAMMPS, side by side in one run (issue 27 §4).

The anchor bed of tools/bench_dense.py (N balls, settled frictionless by silodem), then STEPS steps
with Coulomb friction mu = 0.5 and a linear history spring k_t = 2/7 k_n (no tangential dashpot):
silodem `contact.tangential: "linear_history"` on 1 and 2 threads, and LAMMPS `pair granular`
`tangential linear_history` (1 rank and 2 MPI ranks split along x). The LAMMPS input is the harness
adapter's translation of the frictionless bed with its pair_coeff lines given the same friction
(the adapter itself does not translate friction yet: issue 28), and LAMMPS's older, leaner
`pair_style gran/hooke/history` (the issue's anchor; one global coefficient set: Kn = k_ij,
Kt = 2/7 Kn, gamma_n = c_ij / m_eff of two 5 mm grains — the wall pairs' dashpot then differs by
2x, immaterial for throughput on a settled bed); and LIGGGHTS 3.8 `hooke/stiffness tangential history`,
its input the LIGGGHTS adapter's translation with kt and coefficientFriction set the same way (1 and 2
ranks). Median of REPEATS; loop time only.

Usage (after tools/build.sh): tools/bench_friction.py [N] [STEPS] [REPEATS]  (defaults 20000 2000 3)
Prints a Markdown table; record it in reports/.
"""
import json
import os
import re
import statistics
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bench_dense  # noqa: E402

WORK = "/tmp/silodem_bench_friction"
MU, SHEAR = 0.5, 2.0 / 7.0


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 20000
    steps = int(sys.argv[2]) if len(sys.argv) > 2 else 2000
    repeats = int(sys.argv[3]) if len(sys.argv) > 3 else 3
    os.makedirs(WORK, exist_ok=True)
    dense = bench_dense.settled_case(n, WORK, bench_dense.SETTLE, "friction_bed_%d" % n)
    dense["time"] = {"dt": bench_dense.DT, "duration": bench_dense.DT * steps}
    dense["output"] = {"series_interval": 1.0, "dump_interval_steps": steps}
    dense["compare"] = {"codes": ["silodem", "lammps", "liggghts"], "checks": [{"type": "energy_terms"}],
                        "time_limit_s": 7200}
    plain_path = os.path.join(WORK, "plain.json")
    json.dump(dense, open(plain_path, "w"))
    lmp_dir = bench_dense.lammps_translation(plain_path, dense["name"], os.path.join(WORK, "lammps"))
    if lmp_dir is None:
        sys.exit("bench_friction: no LAMMPS translation (is lmp installed?)")
    friction = json.loads(json.dumps(dense))
    del friction["compare"]
    friction["contact"]["tangential"] = "linear_history"
    for m in friction["materials"].values():
        m["friction"], m["shear_stiffness_ratio"] = MU, SHEAR
    path = os.path.join(WORK, "friction.json")
    json.dump(friction, open(path, "w"))
    text = bench_dense.lammps_timing_input(open(os.path.join(lmp_dir, "in.lammps")).read(), 1)

    def with_history(m):  # hooke k c ... -> the same with k_t = 2/7 k, no tangential damping, mu
        k = float(m.group(2))
        return "%s hooke %s %s tangential linear_history %.17g 0 %g" % (m.group(1), m.group(2), m.group(3), SHEAR * k, MU)
    text = re.sub(r"^(pair_coeff \d+ \d+) hooke (\S+) (\S+) tangential linear_nohistory 0 0", with_history, text, flags=re.M)
    assert "linear_history" in text
    open(os.path.join(lmp_dir, "in1.lammps"), "w").write(text)
    open(os.path.join(lmp_dir, "in2.lammps"), "w").write(bench_dense.lammps_timing_input(text, 2))
    first = re.search(r"^pair_coeff \d+ \d+ hooke (\S+) (\S+) ", text, flags=re.M)
    k_ij, c_ij = float(first.group(1)), float(first.group(2))
    m_eff = 0.5 * 2500 * 4.0 / 3.0 * 3.141592653589793 * 0.005 ** 3
    old = re.sub(r"^pair_style granular\n", "pair_style gran/hooke/history %.17g %.17g %.17g 0 %g 0\npair_coeff * *\n" %
                 (k_ij, SHEAR * k_ij, c_ij / m_eff, MU), text, flags=re.M)
    old = re.sub(r"^pair_coeff \d+ \d+ hooke .*\n", "", old, flags=re.M)
    assert "gran/hooke/history" in old
    open(os.path.join(lmp_dir, "in1h.lammps"), "w").write(old)
    open(os.path.join(lmp_dir, "in2h.lammps"), "w").write(bench_dense.lammps_timing_input(old, 2))
    lig_dir = liggghts_history_inputs(plain_path, dense["name"])
    times = {k: [] for k in ("silodem_1", "silodem_2", "lammps_1", "lammps_2", "hooke_history_1", "hooke_history_2",
                             "liggghts_history_1", "liggghts_history_2")}
    for _ in range(repeats):
        for t in (1, 2):
            out = os.path.join(WORK, "silodem_%d" % t)
            bench_dense.run([bench_dense.SILODEM, "run", path, "--out", out, "--threads", str(t), "--quiet"])
            s = json.load(open(os.path.join(out, "summary.json")))
            times["silodem_%d" % t].append(s["run"]["loop_seconds"])
        bench_dense.run(["lmp", "-in", "in1.lammps", "-log", "log1.txt", "-echo", "none", "-screen", "none"], cwd=lmp_dir)
        times["lammps_1"].append(bench_dense.loop_time(os.path.join(lmp_dir, "log1.txt")))
        bench_dense.run(["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", "2", "lmp", "-in", "in2.lammps", "-log",
                         "log2.txt", "-echo", "none", "-screen", "none"], cwd=lmp_dir)
        times["lammps_2"].append(bench_dense.loop_time(os.path.join(lmp_dir, "log2.txt")))
        bench_dense.run(["lmp", "-in", "in1h.lammps", "-log", "log1h.txt", "-echo", "none", "-screen", "none"], cwd=lmp_dir)
        times["hooke_history_1"].append(bench_dense.loop_time(os.path.join(lmp_dir, "log1h.txt")))
        bench_dense.run(["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", "2", "lmp", "-in", "in2h.lammps", "-log",
                         "log2h.txt", "-echo", "none", "-screen", "none"], cwd=lmp_dir)
        times["hooke_history_2"].append(bench_dense.loop_time(os.path.join(lmp_dir, "log2h.txt")))
        for r in (1, 2):
            mpi = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", "2"] if r == 2 else []
            bench_dense.run(mpi + ["liggghts", "-in", "in%d.liggghts" % r, "-log", "log%d.txt" % r, "-echo", "none",
                                   "-screen", "none"], cwd=lig_dir)
            times["liggghts_history_%d" % r].append(bench_dense.loop_time(os.path.join(lig_dir, "log%d.txt" % r)))
    med = {k: statistics.median(v) for k, v in times.items()}
    sliding = s["energy"].get("friction_dissipated")
    print("| run | loop s (median of %d) | Mps/s | all |" % repeats)
    print("|---|---|---|---|")
    for k, v in med.items():
        print("| %s | %.3f | %.2f | %s |" % (k, v, n * steps / v / 1e6, [round(x, 3) for x in times[k]]))
    print("\nsilodem / LAMMPS pair granular linear_history: 1 core %.2f x, 2 threads / 2 ranks %.2f x; "
          "silodem / LAMMPS pair gran/hooke/history: 1 core %.2f x, 2 threads / 2 ranks %.2f x; %d mobile balls, %d steps, mu = %g, "
          "k_t = 2/7 k_n; silodem's friction dissipation over the run %.3g J" %
          (med["lammps_1"] / med["silodem_1"], med["lammps_2"] / med["silodem_2"],
           med["hooke_history_1"] / med["silodem_1"], med["hooke_history_2"] / med["silodem_2"], n, steps, MU, sliding))
    print("silodem / LIGGGHTS hooke/stiffness tangential history: 1 core %.2f x, 2 threads / 2 ranks %.2f x" %
          (med["liggghts_history_1"] / med["silodem_1"], med["liggghts_history_2"] / med["silodem_2"]))


def liggghts_history_inputs(plain_path, name):
    """The LIGGGHTS adapter's translation of the frictionless bed with the same friction: kt = 2/7 kn
    per type pair, coefficientFriction mu, `tangential history` (gammat_abs stays 0); in1.liggghts
    for 1 rank and in2.liggghts for 2 ranks split along x. Returns the directory."""
    lig_dir = bench_dense.lammps_translation(plain_path, name, os.path.join(WORK, "liggghts"), "liggghts")
    if lig_dir is None:
        sys.exit("bench_friction: no LIGGGHTS translation (is liggghts installed?)")
    text = open(os.path.join(lig_dir, "in.liggghts")).read()
    kn = re.search(r"^fix m_kn all property/global kn peratomtypepair (\d+) (.*)$", text, flags=re.M)
    kt = " ".join("%.17g" % (SHEAR * float(v)) for v in kn.group(2).split())
    text = re.sub(r"^(fix m_kt all property/global kt peratomtypepair \d+) .*$", lambda m: m.group(1) + " " + kt, text, flags=re.M)
    mu = " ".join("%g" % MU for _ in kn.group(2).split())
    text = re.sub(r"^(fix m_coefficientFriction all property/global coefficientFriction peratomtypepair \d+) .*$",
                  lambda m: m.group(1) + " " + mu, text, flags=re.M)
    assert "tangential no_history" in text
    text = text.replace("tangential no_history", "tangential history")
    for r in (1, 2):
        open(os.path.join(lig_dir, "in%d.liggghts" % r), "w").write(bench_dense.lammps_timing_input(text, r))
    return lig_dir


if __name__ == "__main__":
    main()
