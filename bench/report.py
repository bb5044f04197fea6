#!/usr/bin/env python3
"""Turn Google Benchmark JSON from gjk_bench (and gjk_bench_bullet_float) into Markdown tables.

Usage: report.py result.json [more.json ...] > results.md

Benchmark names are <query>/<family>/<set>/<method>. Times are the median over repetitions of
the CPU time per query (ns); CPU time rather than wall time because the benchmark machine may be
shared. The ratio is fastest peer / mink, so > 1 means mink is faster.
"""
import json
import math
import sys
from collections import OrderedDict

PEERS = ["ccd_gjk", "ccd_mpr", "fcl_ccd", "fcl_indep", "bullet64_pd", "bullet64_epa2",
         "bullet32_pd", "bullet32_epa2"]
TARGET = {"intersect": 2.0, "distance": 1.5}
MAX_REL_ERR = 1e-10
# Cells where FCL does not run GJK but dedicated primitive code (see bench/peers/fcl_adapter.cpp).
NOT_GJK = {("intersect", "box-box", "fcl_ccd"), ("intersect", "box-box", "fcl_indep"),
           ("distance", "capsule-capsule", "fcl_ccd"),
           ("distance", "capsule-capsule", "fcl_indep")}


def load(paths):
    runs = {}  # (query, case, method) -> {"times": [...], "counters": {...}, "median": ...}
    context = None
    for path in paths:
        with open(path) as f:
            data = json.load(f)
        context = context or data.get("context", {})
        for b in data["benchmarks"]:
            name = b.get("run_name", b["name"])
            query, family, subset, method = name.split("/")[:4]
            key = (query, family + "/" + subset, method)
            entry = runs.setdefault(key, {"times": [], "counters": {}, "median": None})
            if b.get("error_occurred"):
                entry["error"] = b.get("error_message", "error")
                continue
            scale = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}[b.get("time_unit", "ns")]
            if b.get("run_type") == "aggregate":
                if b.get("aggregate_name") == "median":
                    entry["median"] = b["cpu_time"] * scale
                continue
            entry["times"].append(b["cpu_time"] * scale)
            for c in ("wrong", "max_rel_err", "iterations"):
                if c in b:
                    entry["counters"][c] = b[c]
    for entry in runs.values():
        if entry["median"] is None and entry["times"]:
            t = sorted(entry["times"])
            entry["median"] = t[len(t) // 2]
    return runs, context


def fmt_time(ns):
    if ns is None:
        return "–"
    return f"{ns:.0f}" if ns >= 100 else f"{ns:.1f}"


def fmt_err(counters, case):
    if not counters:
        return "–"
    wrong = int(round(counters.get("wrong", 0)))
    if "max_rel_err" in counters and case.endswith("/separated"):
        e = counters["max_rel_err"]
        s = "inf" if math.isinf(e) else ("0" if e == 0 else f"{e:.0e}")
        return s + (f" ({wrong} wrong)" if wrong else "")
    return f"{wrong} wrong"


def accurate(query, case, counters):
    if not counters or counters.get("wrong", 0) > 0:
        return False
    if query == "distance" and case.endswith("/separated"):
        return counters.get("max_rel_err", math.inf) <= MAX_REL_ERR
    return True


def table(query, runs):
    cases = list(OrderedDict.fromkeys(k[1] for k in runs if k[0] == query))
    methods = [m for m in PEERS if any(k[0] == query and k[2] == m for k in runs)]
    lines = []
    head = ["case", "mink ns"] + [m for m in methods] + [
        "fastest peer", "ratio", "target", "fastest accurate peer", "ratio vs accurate",
        "mink iters", "mink error", "fastest peer error"]
    lines.append("| " + " | ".join(head) + " |")
    lines.append("|" + "|".join(["---"] + ["---:"] * (len(head) - 1)) + "|")
    misses = []
    for case in cases:
        mink = runs.get((query, case, "mink"), {})
        mt = mink.get("median")
        row = [case, fmt_time(mt)]
        best = None
        best_accurate = None  # the fastest peer that itself meets the accuracy bar
        for m in methods:
            e = runs.get((query, case, m))
            t = e.get("median") if e else None
            mark = "†" if (query, case.split("/")[0], m) in NOT_GJK else ""
            row.append(fmt_time(t) + mark if e and "error" not in e else ("err" if e else "–"))
            if t is not None and (best is None or t < best[1]):
                best = (m, t)
            if (t is not None and accurate(query, case, e.get("counters")) and
                    (best_accurate is None or t < best_accurate[1])):
                best_accurate = (m, t)
        ratio_accurate = best_accurate[1] / mt if best_accurate and mt else None
        ratio = best[1] / mt if best and mt else None
        ok = ratio is not None and ratio >= TARGET[query] and accurate(query, case,
                                                                      mink.get("counters"))
        if not ok:
            misses.append(case)
        row += [best[0] if best else "–", f"{ratio:.2f}" if ratio else "–",
                "met" if ok else "**missed**",
                best_accurate[0] if best_accurate else "none",
                f"{ratio_accurate:.2f}" if ratio_accurate else "–",
                f"{mink.get('counters', {}).get('iterations', float('nan')):.2f}",
                fmt_err(mink.get("counters"), case),
                fmt_err(runs.get((query, case, best[0]), {}).get("counters") if best else None,
                        case)]
        lines.append("| " + " | ".join(row) + " |")
    return "\n".join(lines), misses


def accuracy_table(query, runs):
    cases = list(OrderedDict.fromkeys(k[1] for k in runs if k[0] == query))
    methods = ["mink"] + [m for m in PEERS if any(k[0] == query and k[2] == m for k in runs)]
    lines = ["| case | " + " | ".join(methods) + " |",
             "|---|" + "|".join(["---:"] * len(methods)) + "|"]
    for case in cases:
        cells = [fmt_err(runs.get((query, case, m), {}).get("counters"), case) for m in methods]
        lines.append(f"| {case} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def main():
    runs, context = load(sys.argv[1:])
    out = ["# mink vs peers: boolean intersection and distance", ""]
    if context:
        out.append(f"Host: {context.get('host_name', '?')}, {context.get('num_cpus', '?')} CPUs "
                   f"at {context.get('mhz_per_cpu', '?')} MHz, load average "
                   f"{', '.join(f'{x:.2f}' for x in context.get('load_avg', []))}; "
                   f"{context.get('date', '')}.")
    out += ["",
            "Median CPU time per query in ns over 256 pairs per case (fixed seeds; see "
            "bench/cases.hpp). Ratio = fastest peer / mink (> 1: mink faster). Target: "
            "intersect >= 2x, distance >= 1.5x the fastest peer, at max relative error "
            "<= 1e-10 and no wrong answers. † FCL runs dedicated primitive code there, not GJK. "
            "bullet32 = Bullet's float build, bullet64 = its double build. 'Fastest accurate peer' "
            "is the fastest peer that itself meets the accuracy bar on that row. Errors: max |d - "
            "reference| / (sum of bounding radii) on separated cases; 'wrong' counts answers "
            "with the wrong intersect/separated verdict.", ""]
    all_misses = {}
    for query, title in (("intersect", "Boolean intersection"), ("distance", "Distance")):
        t, misses = table(query, runs)
        all_misses[query] = misses
        out += [f"## {title}", "", t, ""]
    for query, title in (("intersect", "Boolean intersection"), ("distance", "Distance")):
        out += [f"## Accuracy per library: {title.lower()}", "", accuracy_table(query, runs), ""]
    out += ["## Targets missed", ""]
    for query, misses in all_misses.items():
        out.append(f"- {query}: " + (", ".join(misses) if misses else "none"))
    print("\n".join(out))


if __name__ == "__main__":
    main()
