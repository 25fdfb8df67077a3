#!/usr/bin/python3
"""tools/report.py on small results (issue 7): the compare test's results (collision restitution,
cohesion, free fall in every code) and a verify run of three small cases made here. Checks that
every figure and table these results allow is written and non-empty, that the pages link them and
list the figures without results as skipped, and that a malformed or missing result file gives
one line naming it and exit status 1, never a Python traceback.
Usage: report_test.py SILODEM_BINARY TEST_RESULTS_DIR (the compare test writes TEST_RESULTS_DIR/compare)."""
import os
import shutil
import subprocess
import sys
import tempfile

binary, test_results = sys.argv[1], sys.argv[2]
top = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
report = os.path.join(top, "tools", "report.py")
failures = []


def check(cond, what):
    if not cond:
        failures.append(what)
        print("FAIL: " + what)


def run_report(results, out, bench="/nonexistent.json"):
    p = subprocess.run(["/usr/bin/python3", report, "--results", results, "--out", out, "--bench", bench],
                       capture_output=True, text=True)
    return p.returncode, p.stdout, p.stderr


work = tempfile.mkdtemp(prefix="silodem_report_test_")
results = os.path.join(work, "results")
os.makedirs(results)
compare_src = os.path.join(test_results, "compare")
if not os.path.exists(os.path.join(compare_src, "verdicts.json")):
    print("FAIL: the compare test's results are missing: " + compare_src)
    sys.exit(1)
shutil.copytree(compare_src, os.path.join(results, "compare"), symlinks=True)
cases = [os.path.join(top, "cases", c + ".json") for c in ("collision_restitution", "free_fall_contact", "cohesion_cutoff")]
v = subprocess.run([binary, "verify"] + cases + ["--out", os.path.join(results, "verify"), "--quiet"],
                   capture_output=True, text=True)
check(v.returncode == 0, "verify of the three small cases: exit %d\n%s" % (v.returncode, v.stderr[-2000:]))

# 1. Everything these results allow.
out = os.path.join(work, "out")
code, so, se = run_report(results, out)
check(code == 0, "report on good results: exit %d\n%s%s" % (code, so, se))
check("Traceback" not in se, "report on good results printed a traceback")
expected_figures = ["collisions.png", "work_precision.png", "energy_collision_restitution.png"]
expected_tables = ["checks_verify.csv", "checks_compare.csv"]
for f in expected_figures:
    p = os.path.join(out, "figures", f)
    check(os.path.exists(p) and os.path.getsize(p) > 10000, "figure %s written and non-empty" % f)
for t in expected_tables:
    p = os.path.join(out, "tables", t)
    ok = os.path.exists(p) and os.path.getsize(p) > 0
    check(ok, "table %s written" % t)
    if ok:
        lines = open(p).read().splitlines()
        check(len(lines) > 1 and "[" in lines[0], "table %s has a header with units and rows" % t)
for page in ("index.html", "report.md"):
    p = os.path.join(out, page)
    text = open(p).read() if os.path.exists(p) else ""
    check(len(text) > 500, "%s written" % page)
    for f in expected_figures:
        check("figures/" + f in text, "%s links %s" % (page, f))
    # The silo figures have no results here: listed as skipped with the reason, not silently absent.
    check("frictionless grains: janssen (skipped: " in text,
          "%s lists the Janssen figure as skipped" % page)
    check("Machine" in text and "cores" in text and "Commands" in text, "%s states the machine and the commands" % page)
    # A contents line links each part drawn to its heading (index.html: the same id as Markdown's anchor).
    check("Contents: " in text and "#collision-cases" in text, "%s has a contents line linking its parts" % page)
    check(("<h2 id='collision-cases'>" if page == "index.html" else "\n## Collision cases\n") in text,
          "%s's contents link lands on the heading" % page)

# 2. A malformed summary and a missing probe file: named, exit 1, no traceback.
bad = os.path.join(work, "bad")
shutil.copytree(results, bad, symlinks=True)
variant = sorted(d for d in os.listdir(os.path.join(bad, "verify", "collision_restitution")))[0]
summary = os.path.join(bad, "verify", "collision_restitution", variant, "summary.json")
os.remove(summary)  # a copy, not the compare test's file
with open(summary, "w") as f:
    f.write('{"run": {"wall_sec')
series = os.path.join(bad, "compare", "collision_restitution", "contact_end=clamped", "lammps", "series.csv")
os.remove(series)
code, so, se = run_report(bad, os.path.join(work, "bad_out"))
check(code == 1, "report on a malformed summary: exit %d (expected 1)" % code)
check("Traceback" not in se and "Traceback" not in so, "no traceback on malformed input:\n" + se)
check(summary in se and "not valid JSON" in se, "the malformed file is named with the reason:\n" + se)
check(series in se and "missing" in se, "the missing file is named:\n" + se)

# 3. No results at all.
code, so, se = run_report(os.path.join(work, "nowhere"), os.path.join(work, "none_out"))
check(code == 1 and "no such results directory" in se and "Traceback" not in se, "missing results directory:\n" + se)

shutil.rmtree(work)
print("report test: %d failures" % len(failures))
sys.exit(1 if failures else 0)
