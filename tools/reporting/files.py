"""Reading result files (docs/case-format.md, "Result files") with errors that name the file:
a missing or malformed file is a ResultFileError, which the driver reports as one line, never as
a Python traceback."""
import csv
import json
import os

CODES = ("silodem", "lammps", "liggghts", "yade")
CODE_STYLE = {"silodem": ("C0", "o"), "lammps": ("C1", "s"), "liggghts": ("C2", "^"), "yade": ("C3", "D")}


class ResultFileError(Exception):
    """A result file that is missing or cannot be read; str() names it and says why."""


class Skip(Exception):
    """A figure whose results are not in this run (the case was not run): listed, not an error."""


def read_json(path):
    try:
        with open(path) as f:
            return json.load(f)
    except FileNotFoundError:
        raise ResultFileError("%s: missing" % path)
    except (json.JSONDecodeError, UnicodeDecodeError) as e:
        raise ResultFileError("%s: not valid JSON (%s)" % (path, e))


def read_csv(path, need=(), text=()):
    """Rows as dicts of floats where the text is a number; `need`: numeric columns that must be
    there, `text`: other columns that must be there."""
    try:
        with open(path, newline="") as f:
            rows = list(csv.DictReader(f))
    except FileNotFoundError:
        raise ResultFileError("%s: missing" % path)
    except (csv.Error, UnicodeDecodeError) as e:
        raise ResultFileError("%s: not a CSV table (%s)" % (path, e))
    if not rows:
        raise ResultFileError("%s: no rows" % path)
    missing = [c for c in tuple(need) + tuple(text) if c not in rows[0]]
    if missing:
        raise ResultFileError("%s: no column %s" % (path, ", ".join(missing)))
    out = []
    for i, r in enumerate(rows):
        d = {}
        for k, v in r.items():
            if k is None or v is None:
                raise ResultFileError("%s: row %d has %s fields than the header" % (path, i + 2, "more" if k is None else "fewer"))
            try:
                d[k] = float(v)
            except ValueError:
                d[k] = v
        for c in need:
            if not isinstance(d[c], float):
                raise ResultFileError("%s: row %d, column %s is not a number (%r)" % (path, i + 2, c, d[c]))
        out.append(d)
    return out


def field(obj, path, keys):
    """obj[k0][k1]... or a ResultFileError naming `path` and the missing key."""
    for k in keys:
        try:
            obj = obj[k]
        except (KeyError, IndexError, TypeError):
            raise ResultFileError("%s: no %s" % (path, "/".join(str(x) for x in keys)))
    return obj


def need_dir(path, what):
    if not os.path.isdir(path):
        raise Skip("%s not in these results (%s)" % (what, path))
    return path


class Results:
    """Where the result files are: <root>/verify, <root>/compare, and the benchmark JSON."""

    def __init__(self, root, bench):
        self.verify = os.path.join(root, "verify")
        self.compare = os.path.join(root, "compare")
        self.bench = bench
        self._verdicts = {}

    def verdicts(self, which):
        """Rows of <root>/<which>/verdicts.json ([] if that job was not run)."""
        if which not in self._verdicts:
            path = os.path.join(getattr(self, which), "verdicts.json")
            self._verdicts[which] = field(read_json(path), path, ["rows"]) if os.path.exists(path) else []
        return self._verdicts[which]

    def run_dirs(self, which, case, variant):
        """{code: run directory} of one compare variant (codes that ran to completion: a failed
        or killed run leaves a summary with its error, which is in the verdicts, not drawn)."""
        return complete_runs(os.path.join(getattr(self, which), case, variant))


def complete_runs(base):
    """{code: run directory} of the codes under one compare variant's folder that ran to completion."""
    out = {}
    for c in CODES:
        path = os.path.join(base, c, "summary.json")
        if os.path.exists(path) and read_json(path).get("status") == "complete":
            out[c] = os.path.join(base, c)
    return out


def wall_bands(run, probe, column):
    """(band centre heights, area-weighted angle averages of `column`) of a wall-pressure probe,
    band 0 first (the bottom of a cylinder, the outlet end of a cone), and the probe geometry."""
    spath = os.path.join(run, "summary.json")
    geo = field(read_json(spath), spath, ["probes", probe, "geometry"])
    path = os.path.join(run, "probes", probe + ".csv")
    rows = read_csv(path, need=("height_bin", "area", column))
    nh = 1 + int(max(r["height_bin"] for r in rows))
    force, area = [0.0] * nh, [0.0] * nh
    for r in rows:
        h = int(r["height_bin"])
        force[h] += r[column] * r["area"]
        area[h] += r["area"]
    z = [geo["centre"][2] + geo["height"] * (h + 0.5) / nh for h in range(nh)]
    return z, [f / a if a > 0 else 0.0 for f, a in zip(force, area)], geo


def wall_grid(run, probe, column):
    """(grid [height bin][angle bin] of `column`, geometry) of a wall-pressure probe."""
    spath = os.path.join(run, "summary.json")
    geo = field(read_json(spath), spath, ["probes", probe, "geometry"])
    path = os.path.join(run, "probes", probe + ".csv")
    rows = read_csv(path, need=("angle_bin", "height_bin", column))
    na = 1 + int(max(r["angle_bin"] for r in rows))
    nh = 1 + int(max(r["height_bin"] for r in rows))
    grid = [[0.0] * na for _ in range(nh)]
    for r in rows:
        grid[int(r["height_bin"])][int(r["angle_bin"])] = r[column]
    return grid, geo
