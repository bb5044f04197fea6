#!/usr/bin/env python3
"""Markdown tables from hull_bench's JSON lines (one object per input and builder).

Usage: bench/hull_report.py build/bench/hull_bench.json
Prints two tables: median build times with each builder's throughput relative to Qhull's
(default options) measured in the same run, and accuracy (fraction of the true extreme points
kept, largest distance of an input point outside the result).
"""
import json
import sys

NAMES = {
    "mink": "mink",
    "qhull": "Qhull",
    "qhull_qt": "Qhull Qt",
    "cgal": "CGAL",
    "bullet": "Bullet",
}


def fmt_time(seconds):
    if seconds < 1e-3:
        return f"{seconds * 1e6:.0f} µs"
    if seconds < 1:
        return f"{seconds * 1e3:.3g} ms"
    return f"{seconds:.3g} s"


def fmt_n(n):
    exponent = len(str(n)) - 1
    return f"1e{exponent}" if n == 10**exponent else str(n)


def main(paths):
    rows = []
    for path in paths:
        with open(path) as f:
            rows += [json.loads(line) for line in f if line.strip()]
    if not rows:
        print("hull_report: no results", file=sys.stderr)
        return 1
    builders = []
    for r in rows:
        if r["builder"] not in builders:
            builders.append(r["builder"])
    cases = []
    for r in rows:
        key = (r["dist"], r["n"])
        if key not in cases:
            cases.append(key)
    by = {(r["dist"], r["n"], r["builder"]): r for r in rows}

    print("### Build time (median; in parentheses: throughput relative to Qhull in the same run)\n")
    print("| input | n | " + " | ".join(NAMES.get(b, b) for b in builders) + " |")
    print("|---|---|" + "---|" * len(builders))
    for dist, n in cases:
        qhull = by.get((dist, n, "qhull"))
        cells = []
        for b in builders:
            r = by.get((dist, n, b))
            if r is None:
                cells.append("–")
                continue
            cell = fmt_time(r["median_s"])
            if qhull is not None and b != "qhull":
                cell += f" ({qhull['median_s'] / r['median_s']:.2f}x)"
            if not r["ok"]:
                cell += " FAILED"
            cells.append(cell)
        print(f"| {dist} | {fmt_n(n)} | " + " | ".join(cells) + " |")

    print("\n### Accuracy: true extreme points kept; largest distance of an input point outside\n")
    print("| input | n | true vertices | " + " | ".join(NAMES.get(b, b) for b in builders) + " |")
    print("|---|---|---|" + "---|" * len(builders))
    for dist, n in cases:
        true_vertices = next(
            (by[(dist, n, b)]["true_vertices"] for b in builders if (dist, n, b) in by), 0)
        cells = []
        for b in builders:
            r = by.get((dist, n, b))
            if r is None:
                cells.append("–")
                continue
            kept = 100 * r["kept"]
            kept_text = "100 %" if r["kept"] == 1 else f"{kept:.2f} %"
            outside = r["max_outside"]
            outside_text = "0" if outside <= 0 else f"{outside:.1e}"
            if r["sampled"]:
                outside_text = "~" + outside_text
            cells.append(f"{kept_text}; {outside_text}")
        print(f"| {dist} | {fmt_n(n)} | {true_vertices} | " + " | ".join(cells) + " |")
    print("\n(~: distance over an evenly spaced sample of the true extreme points)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
