#!/usr/bin/python3
"""One command from result files to a report folder (issue 7):

    /usr/bin/python3 tools/report.py [--results results] [--out reports] [--bench reports/benchmarks.json]

reads <results>/verify and <results>/compare (written by `silodem verify` / `silodem compare`,
tools/suite.sh runs both) and the benchmark JSON, and writes <out>/figures/*.png, <out>/tables/*.csv
(header line with units), <out>/index.html (self-contained but for the PNGs beside it) and
<out>/report.md. A figure whose case was not run is listed as skipped with the reason; a missing or
malformed result file is named in one line on stderr and the exit status is 1 (no traceback).
Uses Debian's matplotlib: run it with /usr/bin/python3."""
import argparse
import csv
import datetime
import html
import os
import platform
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from reporting import (bench_figures, code_figures, dosta_figures, frictional_codes, frictional_figures, hopper_figures,  # noqa: E402
                       sections, silo_figures, verdicts)  # noqa: E402
from reporting.files import ResultFileError, Results, Skip, read_csv, wall_bands  # noqa: E402

VERIFY_CMD = "build/silodem verify cases/*.json --out results/verify --report reports/verification.md"
COMPARE_CMD = "build/silodem compare cases/*.json --out results/compare --report reports/comparison.md"
REPORT_CMD = "/usr/bin/python3 tools/report.py --results results --out reports"

# (section, function, the command that made its results). One section per silo: the paper's silo of
# frictionless grains, then the frictional silos predicted from their material tests.
PAPER_SILO = "Silo 1: the paper's silo, frictionless grains"
FRICTIONAL_SILO = "Silo 2: frictional grains, predicted from virtual material tests"
DOSTA_SILO = "Silo 3: the multi-code benchmark of Dosta et al. (2024)"
FIGURES = [
    (PAPER_SILO, code_figures.janssen, COMPARE_CMD),
    (PAPER_SILO, silo_figures.wall_maps, VERIFY_CMD + "; " + COMPARE_CMD),
    (PAPER_SILO, silo_figures.silo_fill, VERIFY_CMD),
    (PAPER_SILO, sections.section, COMPARE_CMD),
    (PAPER_SILO, silo_figures.discharge, VERIFY_CMD),
    (PAPER_SILO, silo_figures.closure, COMPARE_CMD),
    (FRICTIONAL_SILO, frictional_figures.material_tests, VERIFY_CMD),
    (FRICTIONAL_SILO, frictional_figures.shear_and_heap, VERIFY_CMD),
    (FRICTIONAL_SILO, frictional_figures.janssen_column, VERIFY_CMD),
    (FRICTIONAL_SILO, frictional_codes.column, COMPARE_CMD),
    (FRICTIONAL_SILO, frictional_figures.wall_maps, VERIFY_CMD),
    (FRICTIONAL_SILO, frictional_figures.discharge, VERIFY_CMD),
    (FRICTIONAL_SILO, frictional_codes.discharge, COMPARE_CMD),
    (FRICTIONAL_SILO, hopper_figures.flow_pattern, VERIFY_CMD),
    (FRICTIONAL_SILO, silo_figures.closure_frictional, COMPARE_CMD),
    (DOSTA_SILO, dosta_figures.reduced, COMPARE_CMD),
    (DOSTA_SILO, dosta_figures.full, "tools/dosta_full.sh"),
    ("Collision cases", code_figures.collisions, COMPARE_CMD + "; " + VERIFY_CMD),
    ("Energy", code_figures.energy, COMPARE_CMD),
    ("Benchmarks", bench_figures.work_precision, VERIFY_CMD),
    ("Benchmarks", bench_figures.throughput, "/usr/bin/python3 tools/bench_throughput.py"),
    ("Benchmarks", bench_figures.scaling, "/usr/bin/python3 tools/bench_scaling.py"),
    ("Benchmarks", bench_figures.stability, "build/bench/bench_stability reports"),
    ("Benchmarks", bench_figures.dense_stability, "build/bench/bench_dense_stability reports"),
    ("Benchmarks", bench_figures.feature_cost, "build/bench/bench_feature_cost reports"),
]


def machine():
    model = "?"
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                model = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return "%d cores, %s, %s" % (os.cpu_count() or 0, model, platform.platform())


def version(top):
    try:
        return subprocess.run(["git", "-C", top, "describe", "--always", "--dirty"], capture_output=True, text=True,
                              check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def tables(res, out):
    """CSV tables with units in the header; returns their names."""
    made = []
    for job in ("verify", "compare"):
        rows = res.verdicts(job)
        if not rows:
            continue
        # One line per (case, variant, code, quantity) and class (judged, report, skip) with its
        # worst row, as the Markdown reports; every row is in <results>/<job>/verdicts.json.
        name = "checks_%s.csv" % job
        with open(os.path.join(out, "tables", name), "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["case", "variant", "code", "quantity", "kind", "rows", "failed rows", "worst subject",
                        "measured [unit of the quantity]", "expected [same unit]",
                        "error [relative unless the note says otherwise; bound rows: measured - bound]",
                        "tolerance [same as error]", "bound [same unit as measured]", "verdict",
                        "tolerance source or reason not judged", "note"])
            for (case, variant, code, q, cls), rs in verdicts.quantity_lines(rows):
                r = verdicts.worst(rs)
                fails = sum(x["verdict"] == "fail" for x in rs)
                why = r.get("tolerance_source", "") if cls == "judged" else r.get("reason", r.get("note", ""))
                w.writerow([case, variant, code, q, r.get("kind", ""), len(rs), fails, r["subject"], r["measured"],
                            r["expected"], r.get("error", ""), r.get("tolerance", ""), r.get("bound", ""), r["verdict"],
                            why, r["note"]])
        made.append(name)
    runs = res.run_dirs("compare", "janssen_column", "base")
    if runs:
        with open(os.path.join(out, "tables", "janssen_profile.csv"), "w", newline="") as f:
            w = csv.writer(f)
            cols = {c: wall_bands(r, "mantle", "pressure_final") for c, r in runs.items()}
            w.writerow(["band centre height [m]"] + ["%s p_h [Pa]" % c for c in cols])
            z = next(iter(cols.values()))[0]
            for i, zi in enumerate(z):
                w.writerow([zi] + [cols[c][1][i] for c in cols])
        made.append("janssen_profile.csv")
    dis = os.path.join(res.verify, "silo_discharge")
    if os.path.isdir(dis):
        with open(os.path.join(out, "tables", "discharge_flow.csv"), "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["variant", "balls out", "discharged mass [kg]", "from [s]", "to [s]",
                        "mean mass flow over the second half [kg/s]"])
            for v in sorted(os.listdir(dis)):
                if os.path.isdir(os.path.join(dis, v)):
                    rows = read_csv(os.path.join(dis, v, "probes", "outflow.csv"), need=("t", "cumulative_mass"))
                    a, b = rows[len(rows) // 2], rows[-1]
                    flow = (b["cumulative_mass"] - a["cumulative_mass"]) / (b["t"] - a["t"]) if b["t"] > a["t"] else 0.0
                    w.writerow([v, len(rows), b["cumulative_mass"], a["t"], b["t"], flow])
        made.append("discharge_flow.csv")
    return made


def counts(rows):
    """The headline of one job: judged quantities and their sub-rows, report rows apart."""
    return verdicts.headline(rows)


CHECK_COLUMNS = ["job", "judged quantities passed", "failed", "judged sub-rows passed", "reported quantities (rows)",
                 "skipped rows"]


def check_cells(c):
    return ["%d / %d" % (c["judged_passed"], c["judged"]), "%d" % (c["judged"] - c["judged_passed"]),
            "%d / %d" % (c["rows_passed"], c["rows"]), "%d (%d)" % (c["reported"], c["report_rows"]), "%d" % c["skipped"]]


# A table at the head of a section: (section, file in <out>/tables, caption).
SECTION_TABLES = [(FRICTIONAL_SILO, "material_tests.csv",
                   "Virtual material tests (EN 1991-4 Annex C), mean and scatter over 3 packings; K_EN = 1.1 (1 - sin phi_i)")]


def section_table(out, sec):
    """(caption, header, rows) of the section's table, or None when the figure that writes it did not run."""
    for s, name, caption in SECTION_TABLES:
        path = os.path.join(out, "tables", name)
        if s == sec and os.path.exists(path):
            with open(path, newline="") as f:
                rows = list(csv.reader(f))
            fmt = lambda x: x if not x.replace(".", "", 1).replace("-", "", 1).isdigit() else "%.4g" % float(x)
            return caption + " ([tables/%s](tables/%s))" % (name, name), rows[0], [[fmt(x) for x in r] for r in rows[1:]]
    return None


def table_markdown(caption, header, rows):
    return [caption + ":", "", "| " + " | ".join(header) + " |", "|" + "---|" * len(header)] + \
           ["| " + " | ".join(r) + " |" for r in rows] + [""]


def table_html(caption, header, rows):
    return ["<p>%s</p><table><tr>%s</tr>" % (html.escape(caption.split(" ([")[0]), "".join("<th>%s</th>" % html.escape(x) for x in header))] + \
           ["<tr>%s</tr>" % "".join("<td>%s</td>" % html.escape(x) for x in r) for r in rows] + ["</table>"]


def anchor(title):
    """The anchor a Markdown renderer (GitHub's rule) gives a heading; index.html uses the same ids."""
    return "".join(c for c in title.lower() if c.isalnum() or c in " -").replace(" ", "-")


def write_pages(out, res, figures, skipped, errors, made_tables, top):
    now = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    head = [("Date", now), ("Version", version(top)), ("Machine", machine()),
            ("Commands", "tools/suite.sh, which runs: %s; %s; %s" % (VERIFY_CMD, COMPARE_CMD, REPORT_CMD))]
    job_counts = [(job, counts(res.verdicts(job))) for job in ("verify", "compare") if res.verdicts(job)]
    md = ["# silodem report", "", "Regenerate with `%s` (after the verify and compare runs; `tools/suite.sh` does all)." % REPORT_CMD, ""]
    md += ["| | |", "|---|---|"] + ["| %s | %s |" % (k, v.replace("|", "\\|")) for k, v in head] + [""]
    md += ["## Checks", "", "| " + " | ".join(CHECK_COLUMNS) + " |", "|" + "---|" * len(CHECK_COLUMNS)]
    md += ["| %s | %s |" % (j, " | ".join(check_cells(c))) for j, c in job_counts] + [""]
    md += ["A judged quantity is one (case, variant, code, quantity) of match or bound rows whose tolerance "
           "states its source; report rows give figures without a verdict (docs/case-format.md).", ""]
    md += ["Every check row: " + ", ".join("[tables/%s](tables/%s)" % (t, t) for t in made_tables) + ".", ""]
    h = ["<!DOCTYPE html><html><head><meta charset='utf-8'><title>silodem report</title>",
         "<style>body{font-family:sans-serif;max-width:1200px;margin:auto;padding:1em}img{max-width:100%;border:1px solid #ddd}"
         "td,th{border:1px solid #ccc;padding:3px 8px}table{border-collapse:collapse}.cap{color:#444;font-size:90%}</style>",
         "</head><body><h1>silodem report</h1><table>"]
    h += ["<tr><th>%s</th><td>%s</td></tr>" % (html.escape(k), html.escape(v)) for k, v in head] + ["</table>"]
    h += ["<h2>Checks</h2><table><tr>" + "".join("<th>%s</th>" % html.escape(t) for t in CHECK_COLUMNS) + "</tr>"]
    h += ["<tr><td>%s</td>%s</tr>" % (html.escape(j), "".join("<td>%s</td>" % x for x in check_cells(c)))
          for j, c in job_counts]
    h += ["</table><p>Tables: " + ", ".join("<a href='tables/%s'>%s</a>" % (t, t) for t in made_tables) + "</p>"]
    sections_drawn = list(dict.fromkeys(sec for sec, *_ in figures))
    if sections_drawn:  # one part per silo, then the collision cases, the energy and the benchmarks
        md += ["Contents: " + " · ".join("[%s](#%s)" % (sec, anchor(sec)) for sec in sections_drawn), ""]
        h += ["<p>Contents: " + " · ".join("<a href='#%s'>%s</a>" % (anchor(sec), html.escape(sec))
                                          for sec in sections_drawn) + "</p>"]
    section = None
    for sec, name, title, case, cmd in figures:
        if sec != section:
            md += ["## " + sec, ""]
            h += ["<h2 id='%s'>%s</h2>" % (anchor(sec), html.escape(sec))]
            section = sec
            table = section_table(out, sec)
            if table:
                md += table_markdown(*table)
                h += table_html(*table)
        cap = "Case: %s. Results: `%s`; figure: `%s`." % (case, cmd, REPORT_CMD)
        md += ["### " + title, "", "![%s](figures/%s)" % (title, name), "", cap, ""]
        h += ["<h3>%s</h3><img src='figures/%s' alt='%s'><p class='cap'>%s</p>" % (
            html.escape(title), name, html.escape(title), html.escape(cap).replace("`", ""))]
    if skipped or errors:
        md += ["## Not drawn", ""] + ["- %s (skipped: %s)" % s for s in skipped] + ["- %s (**error**: %s)" % e for e in errors] + [""]
        h += ["<h2>Not drawn</h2><ul>"] + ["<li>%s (skipped: %s)</li>" % tuple(map(html.escape, s)) for s in skipped]
        h += ["<li>%s (<b>error</b>: %s)</li>" % tuple(map(html.escape, e)) for e in errors] + ["</ul>"]
    h += ["</body></html>"]
    for name, text in (("report.md", "\n".join(md) + "\n"), ("index.html", "\n".join(h) + "\n")):
        tmp = os.path.join(out, name + ".tmp")
        with open(tmp, "w") as f:
            f.write(text)
        os.replace(tmp, os.path.join(out, name))


def main():
    top = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--results", default=os.path.join(top, "results"))
    ap.add_argument("--out", default=os.path.join(top, "reports"))
    ap.add_argument("--bench", default=os.path.join(top, "reports", "benchmarks.json"))
    a = ap.parse_args()
    if not os.path.isdir(a.results):
        print("report: %s: no such results directory" % a.results, file=sys.stderr)
        return 1
    for d in ("figures", "tables"):
        os.makedirs(os.path.join(a.out, d), exist_ok=True)
    res = Results(a.results, a.bench)
    figures, skipped, errors = [], [], []
    for sec, fn, cmd in FIGURES:
        label = "%s: %s" % (sec, fn.__name__)
        try:
            for name, title, case in fn(res, a.out):
                figures.append((sec, name, title, case, cmd))
        except Skip as e:
            skipped.append((label, str(e)))
        except ResultFileError as e:
            errors.append((label, str(e)))
        except Exception as e:  # a bug in a figure must not hide the others
            errors.append((label, "internal error: %s: %s" % (type(e).__name__, e)))
    try:
        made_tables = tables(res, a.out)
    except ResultFileError as e:
        errors.append(("tables", str(e)))
        made_tables = []
    write_pages(a.out, res, figures, skipped, errors, made_tables, top)
    print("report: %d figures, %d tables, %d skipped, %d errors -> %s" % (len(figures), len(made_tables), len(skipped),
                                                                        len(errors), os.path.join(a.out, "index.html")))
    for label, why in errors:
        print("report: %s: %s" % (label, why), file=sys.stderr)
    return 1 if errors else 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except ResultFileError as e:
        print("report: %s" % e, file=sys.stderr)
        sys.exit(1)
