"""Rows of verdicts.json grouped as the harness groups them (harness/src/harness/verdict_counts.hpp):
one line per (case, variant, code, quantity) and class — judged (match and bound rows), report
(a figure without a verdict) or skip. A judged quantity passes when all its sub-rows pass; report
rows are counted apart and never as passes."""


def row_class(r):
    v = r.get("verdict")
    return "skip" if v == "skip" else "report" if v == "report" else "judged"


def quantity_lines(rows):
    """[(key, [rows])] in the order the first row of each line appears; key = (case, variant, code,
    quantity, class)."""
    lines, index = [], {}
    for r in rows:
        key = (r["case"], r["variant"], r["code"], r["quantity"], row_class(r))
        if key not in index:
            index[key] = len(lines)
            lines.append((key, []))
        lines[index[key]][1].append(r)
    return lines


def headline(rows):
    """Counts of the whole table: judged quantities (passed), their sub-rows (passed), report
    quantities and rows, skipped rows."""
    c = {"judged": 0, "judged_passed": 0, "rows": 0, "rows_passed": 0, "reported": 0, "report_rows": 0, "skipped": 0}
    for (_, _, _, _, cls), rs in quantity_lines(rows):
        if cls == "judged":
            passed = sum(r["verdict"] == "pass" for r in rs)
            c["judged"] += 1
            c["judged_passed"] += passed == len(rs)
            c["rows"] += len(rs)
            c["rows_passed"] += passed
        elif cls == "report":
            c["reported"] += 1
            c["report_rows"] += len(rs)
        else:
            c["skipped"] += len(rs)
    return c


def worst(rs):
    """The line's worst row: a failing one with the largest |error|, else the largest |error|."""
    return max(rs, key=lambda r: (r["verdict"] == "fail", abs(r.get("error") or 0.0)))
