"""Writes an experiment's case file, never over an existing one (the experiments' shared writer)."""
import json
import sys


def write_new(out, name, case):
    target = out / name
    if target.exists():
        sys.exit(f"{target} exists: not overwritten (choose another folder)")
    out.mkdir(parents=True, exist_ok=True)
    with open(target, "x") as f:  # "x": never over a file that appeared meanwhile
        f.write(json.dumps(case))
    print(target)
