#!/usr/bin/python3
"""Large scenes (issue 32): how fast a case of N balls loads and validates, the peak memory of its
run per mobile ball, and the size per ball of every file a run writes.

The scene: N grains of r = 2 mm on a simple cubic lattice of spacing 2r (each touching its six
neighbours: three listed pairs a ball, about what a settled bed lists) over a smooth floor, with
Coulomb friction and a linear history spring (so the contact history and the spins are stored).
Every run uses one thread.

1. load: `silodem check` (read, validate, estimate) of the scene given three ways — `generate`
   (the lattice described in the case), `balls.state_file` (a compact state.sds) and the balls
   listed in JSON (the way before issue 32) — wall time and peak RSS (wait4 of the child).
2. run: STEPS steps from the state file; peak RSS per mobile ball and the solver's own count
   (summary.json `memory`); the state files' sizes and the time to write state.json.
3. checkpoint: the same run checkpointing every STEPS/2 steps, killed (SIGKILL) once the first
   checkpoint is on disk and continued with --restart: its state.sds must equal the uninterrupted
   run's byte for byte. The checkpoint's size per ball.
4. output: dump.txt and VTK frames per ball per frame, from a run of 2 frames.

Usage (after tools/build.sh): tools/bench_large.py [N]   (default 1000000)
Writes reports/large_scenes.json and reports/large_scenes.md. Run on a quiet machine.
"""
import json
import math
import os
import shutil
import signal
import subprocess
import sys
import time

TOP = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SILODEM = os.path.join(TOP, "build", "silodem")
WORK = "/tmp/silodem_bench_large"
R = 0.002
STEPS = 20


def case(n, balls=None, **output):
    side = round(n ** (1 / 3))
    if side ** 3 != n:
        raise SystemExit("bench_large: N must be a cube (1000000 = 100^3)")
    edge = side * 2 * R
    c = {"format": "silodem-case/1", "name": "large_scene", "seed": 1,
         "contact": {"tangential": "linear_history"},
         "materials": {"grain": {"density": 2500, "stiffness": 2e5, "restitution": 0.5, "reference_radius": R,
                                 "friction": 0.5}},
         "surfaces": [{"name": "floor", "material": "grain", "axis": [edge / 2, edge / 2],
                       "profile": [[0, 0], [edge, 0]]}],
         "time": {"dt": 1e-5, "duration": STEPS * 1e-5},
         "output": dict({"series_interval": 0.0, "state_json": False}, **output)}
    if balls is None:
        c["generate"] = [{"name": "g", "type": "lattice", "material": "grain", "radius": R, "spacing": 2 * R,
                          "region": {"shape": "box", "min": [0, 0, 0], "max": [edge, edge, edge]}}]
    else:
        c["balls"] = balls
    return c


def write(c, name):
    path = os.path.join(WORK, name)
    with open(path, "w") as f:
        json.dump(c, f, separators=(",", ":"))
    return path


def timed(args):
    """(wall seconds, peak RSS in bytes) of one silodem command; exits on failure. The peak is
    /usr/bin/time's: a child forked from this process would inherit its peak RSS as a start."""
    t0 = time.monotonic()
    p = subprocess.run(["/usr/bin/time", "-f", "%M", SILODEM] + args, stdout=subprocess.DEVNULL,
                       stderr=subprocess.PIPE, text=True)
    wall = time.monotonic() - t0
    if p.returncode != 0:
        raise SystemExit("bench_large: silodem %s failed:\n%s" % (" ".join(args), p.stderr))
    return wall, int(p.stderr.strip().splitlines()[-1]) * 1024


def best_of(k, args):
    runs = [timed(args) for _ in range(k)]
    return min(r[0] for r in runs), max(r[1] for r in runs)


def listed_json(state_json_path):
    with open(state_json_path) as f:
        return json.load(f)["balls"]


def checkpoint_run(n, state_file, uninterrupted):
    c = case(n, {"state_file": state_file})
    c["checkpoint"] = {"interval_steps": STEPS // 2, "keep": 1}
    path = write(c, "checkpointed.json")
    out = os.path.join(WORK, "checkpointed")
    ckpt = out + ".checkpoint"
    p = subprocess.Popen([SILODEM, "run", path, "--out", out, "--threads", "1", "--quiet"],
                         stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    while p.poll() is None and not (os.path.isdir(ckpt) and any(f.endswith(".ckpt") for f in os.listdir(ckpt))):
        time.sleep(0.02)
    # A checkpoint is renamed into place only when complete: kill at once, before the run ends.
    p.send_signal(signal.SIGKILL)
    if p.wait() == 0:
        raise SystemExit("bench_large: the checkpointed run ended before it could be killed (N too small)")
    files = [f for f in os.listdir(ckpt) if f.endswith(".ckpt")]
    size = os.path.getsize(os.path.join(ckpt, sorted(files)[-1]))
    wall, rss = timed(["run", path, "--out", out, "--threads", "1", "--quiet", "--restart"])
    same = open(os.path.join(out, "state.sds"), "rb").read() == open(uninterrupted, "rb").read()
    return {"checkpoint_bytes": size, "checkpoint_bytes_per_ball": size / n, "restart_wall_seconds": wall,
            "restart_peak_rss_bytes": rss, "bitwise_equal_to_uninterrupted": same}


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 1000000
    if not os.access(SILODEM, os.X_OK):
        raise SystemExit("bench_large: build silodem first (tools/build.sh)")
    shutil.rmtree(WORK, ignore_errors=True)
    os.makedirs(WORK)
    res = {"n": n, "steps": STEPS, "threads": 1, "machine_cores": os.cpu_count()}

    # The lattice, generated, run once to make the state files the other forms load.
    gen = write(case(n), "generated.json")
    seed_dir = os.path.join(WORK, "seed")
    c = case(n)
    c["output"]["state_json"] = True
    timed(["run", write(c, "seed.json"), "--out", seed_dir, "--threads", "1", "--quiet"])
    state_sds = os.path.join(seed_dir, "state.sds")
    from_state = write(case(n, {"state_file": state_sds}), "from_state.json")
    listed = write(case(n, listed_json(os.path.join(seed_dir, "state.json"))), "listed.json")

    load = {}
    for name, path in (("generate", gen), ("state_file", from_state), ("listed_json", listed)):
        wall, rss = best_of(3 if name != "listed_json" else 1, ["check", path])
        load[name] = {"wall_seconds": wall, "peak_rss_bytes": rss, "case_file_bytes": os.path.getsize(path)}
        print("load %-11s %6.2f s  peak %7.1f MB  case file %9.0f B" % (name, wall, rss / 1e6, os.path.getsize(path)))
    res["load"] = load

    # The run from the state file: peak memory and the solver's own count.
    run_dir = os.path.join(WORK, "run")
    wall, rss = timed(["run", from_state, "--out", run_dir, "--threads", "1", "--quiet"])
    with open(os.path.join(run_dir, "summary.json")) as f:
        summary = json.load(f)
    mem = summary["memory"]
    res["run"] = {"wall_seconds": wall, "loop_seconds": summary["run"]["loop_seconds"], "peak_rss_bytes": rss,
                  "peak_rss_per_mobile_ball": rss / n, "solver_memory": mem,
                  "solver_bytes_per_mobile_ball": mem["total_bytes"] / n}
    print("run  %6.2f s  peak %7.1f MB = %.0f B per ball (solver's arrays %.0f B)" %
          (wall, rss / 1e6, rss / n, mem["total_bytes"] / n))

    # State files: sizes, and what state.json costs to write (the seed run wrote both).
    sizes = {"state_sds": os.path.getsize(state_sds), "state_json": os.path.getsize(os.path.join(seed_dir, "state.json"))}
    res["files"] = {k + "_bytes_per_ball": v / n for k, v in sizes.items()}

    res["checkpoint"] = checkpoint_run(n, state_sds, os.path.join(run_dir, "state.sds"))
    print("checkpoint %.0f B per ball; restart bitwise: %s" % (res["checkpoint"]["checkpoint_bytes_per_ball"],
                                                              res["checkpoint"]["bitwise_equal_to_uninterrupted"]))

    # Dump and VTK: two frames each (step 0 and the last), per ball per frame.
    out_dir = os.path.join(WORK, "frames")
    timed(["run", write(case(n, {"state_file": state_sds}, dump_interval_steps=STEPS, vtk_interval_steps=STEPS),
                        "frames.json"), "--out", out_dir, "--threads", "1", "--quiet"])
    vtk = os.path.join(out_dir, "vtk")
    vtk_bytes = sum(os.path.getsize(os.path.join(vtk, f)) for f in os.listdir(vtk) if f.startswith("balls_"))
    res["files"]["dump_bytes_per_ball_frame"] = os.path.getsize(os.path.join(out_dir, "dump.txt")) / (2 * n)
    res["files"]["vtk_bytes_per_ball_frame"] = vtk_bytes / (2 * n)
    print("files per ball: " + ", ".join("%s %.0f" % kv for kv in res["files"].items()))

    with open(os.path.join(TOP, "reports", "large_scenes.json"), "w") as f:
        json.dump(res, f, indent=1)
    write_report(res)


def write_report(res):
    n, load, run, files, ck = res["n"], res["load"], res["run"], res["files"], res["checkpoint"]
    mem = run["solver_memory"]
    lines = [
        "# Large scenes: load time, memory per ball, output sizes",
        "",
        "`tools/bench_large.py %d` (one thread; %d cores on the machine). %d grains on a touching lattice "
        "with friction (three listed pairs a ball). Figures: reports/large_scenes.json." % (n, res["machine_cores"], n),
        "",
        "## Load and validate (`silodem check`)",
        "",
        "| the balls given as | case file | wall time | peak RSS |",
        "|---|---|---|---|",
    ]
    for name, what in (("generate", "`generate` (a lattice in the case)"), ("state_file", "`balls.state_file` (state.sds)"),
                       ("listed_json", "listed in JSON (before issue 32)")):
        x = load[name]
        lines.append("| %s | %.3g MB | %.2f s | %.0f MB |" % (what, x["case_file_bytes"] / 1e6, x["wall_seconds"],
                                                             x["peak_rss_bytes"] / 1e6))
    lines += [
        "",
        "Target: < 10 s for 10^6 balls.",
        "",
        "## Peak memory of a run (%d steps from the state file)" % res["steps"],
        "",
        "Peak RSS %.0f MB = **%.0f bytes per mobile ball** (target ≤ 1024). The solver's own count "
        "(summary.json `memory`), per ball:" % (run["peak_rss_bytes"] / 1e6, run["peak_rss_per_mobile_ball"]),
        "",
        "| part | bytes per ball |",
        "|---|---|",
    ]
    for key in ("particles_bytes", "neighbour_list_bytes", "force_buffers_bytes", "integrator_bytes"):
        lines.append("| %s | %.0f |" % (key.replace("_bytes", ""), mem[key] / n))
    lines += [
        "| all the solver's arrays | %.0f |" % (mem["total_bytes"] / n),
        "| the rest of the peak (the case's ball list, the allocator, the executable) | %.0f |"
        % (run["peak_rss_per_mobile_ball"] - mem["total_bytes"] / n),
        "",
        "Listed pairs: %.2f per ball." % (mem["list_pairs"] / n),
        "",
        "## Files per ball",
        "",
        "| file | bytes per ball |",
        "|---|---|",
        "| state.sds (compact state) | %.0f |" % files["state_sds_bytes_per_ball"],
        "| state.json | %.0f |" % files["state_json_bytes_per_ball"],
        "| checkpoint (whole run state, contact history included) | %.0f |" % ck["checkpoint_bytes_per_ball"],
        "| dump.txt, per frame | %.0f |" % files["dump_bytes_per_ball_frame"],
        "| VTK (vtk/balls_<step>.vtp), per frame | %.0f |" % files["vtk_bytes_per_ball_frame"],
        "",
        "## Checkpoint read back",
        "",
        "A run checkpointing every %d steps, killed with SIGKILL after its first checkpoint and continued "
        "with `--restart` (%.1f s, peak %.0f MB): its state.sds is %s the uninterrupted run's."
        % (res["steps"] // 2, ck["restart_wall_seconds"], ck["restart_peak_rss_bytes"] / 1e6,
           "byte for byte" if ck["bitwise_equal_to_uninterrupted"] else "**not** byte for byte"),
        "",
    ]
    with open(os.path.join(TOP, "reports", "large_scenes.md"), "w") as f:
        f.write("\n".join(lines))


if __name__ == "__main__":
    main()
