#!/usr/bin/env python3
"""Turn Google Benchmark JSON from manifold_bench into a Markdown table.

Usage: manifold_report.py manifold_bench.json > manifold.md

Benchmark names are manifold/<set>/<method>: mink, and Bullet's manifold path for the set
(bullet64_boxbox or bullet64_sat_clip). Times are the median over repetitions of the CPU time per
manifold (ns). The ratio is Bullet / mink, so > 1 means mink is faster; issue 6 asks for >= 1.5.
"""
import json
import statistics
import sys

TARGET = 1.5


def load(path):
    with open(path) as f:
        data = json.load(f)
    times = {}  # (set, method) -> [cpu ns per repetition]
    for b in data["benchmarks"]:
        if b.get("run_type") == "aggregate" or b.get("error_occurred"):
            continue
        _, case, method = b.get("run_name", b["name"]).split("/")[:3]
        scale = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}[b.get("time_unit", "ns")]
        times.setdefault((case, method), []).append(b["cpu_time"] * scale)
    return data.get("context", {}), times


def main(path):
    context, times = load(path)
    cases = list(dict.fromkeys(case for case, _ in times))
    print(f"CPU: {context.get('num_cpus', '?')} x {context.get('mhz_per_cpu', '?')} MHz; "
          f"median of {max(len(v) for v in times.values())} repetitions, ns per manifold.\n")
    print("| pair | mink | Bullet | Bullet method | Bullet / mink | target 1.5x |")
    print("|---|---:|---:|---|---:|---|")
    for case in cases:
        mink = times.get((case, "mink"))
        peers = [(m, t) for (c, m), t in times.items() if c == case and m != "mink"]
        if not mink or not peers:
            continue
        method, bullet = peers[0]
        ours, theirs = statistics.median(mink), statistics.median(bullet)
        ratio = theirs / ours
        print(f"| {case} | {ours:,.0f} | {theirs:,.0f} | {method} | {ratio:.2f} | "
              f"{'met' if ratio >= TARGET else 'missed'} |")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
