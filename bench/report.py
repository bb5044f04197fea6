#!/usr/bin/env python3
"""Turn Google Benchmark JSON from gjk_bench (and gjk_bench_bullet_float) into Markdown tables.

Usage: report.py result.json [more.json ...] > results.md

Benchmark names are <query>/<family>/<set>/<method>, query being intersect, distance or contact.
Times are the median over repetitions of the CPU time per query (ns); CPU time rather than wall
time because the benchmark machine may be shared. The ratio is fastest peer / mink, so > 1 means
mink is faster.
"""
import json
import math
import sys
from collections import OrderedDict

PEERS = ["ccd_gjk", "ccd_mpr", "fcl_ccd", "fcl_indep", "bullet64_pd", "bullet64_epa2",
         "bullet32_pd", "bullet32_epa2"]
TARGET = {"intersect": 2.0, "distance": 1.5, "contact": 2.0}
MAX_REL_ERR = 1e-10
# Contact: the bar on the depth (distance) error and on the normal's optimality gap, both
# relative to the sum of the bounding radii.
CONTACT_MAX_REL_ERR = 1e-9
# Cells where FCL does not run GJK but dedicated primitive code (see bench/peers/fcl_adapter.cpp),
# keyed by family or by family/set.
NOT_GJK = {("intersect", "box-box", "fcl_ccd"), ("intersect", "box-box", "fcl_indep"),
           ("distance", "capsule-capsule", "fcl_ccd"),
           ("distance", "capsule-capsule", "fcl_indep"),
           ("contact", "box-box/overlap", "fcl_indep"),
           ("contact", "capsule-capsule", "fcl_indep"),
           ("intersect", "sphere-box", "fcl_ccd"), ("intersect", "sphere-box", "fcl_indep"),
           ("distance", "sphere-box", "fcl_ccd"), ("distance", "sphere-box", "fcl_indep"),
           ("contact", "sphere-box", "fcl_indep")}
COUNTERS = ("wrong", "max_rel_err", "normal_err", "point_err", "iterations", "threw")


def not_gjk(query, case, method):
    return ((query, case.split("/")[0], method) in NOT_GJK or (query, case, method) in NOT_GJK)


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
            # Registration order: with random interleaving the file lists runs in random order.
            entry["order"] = min(entry.get("order", math.inf), b.get("family_index", math.inf))
            if b.get("error_occurred"):
                entry["error"] = b.get("error_message", "error")
                continue
            scale = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}[b.get("time_unit", "ns")]
            if b.get("run_type") == "aggregate":
                if b.get("aggregate_name") == "median":
                    entry["median"] = b["cpu_time"] * scale
                continue
            entry["times"].append(b["cpu_time"] * scale)
            for c in COUNTERS:
                if c in b:
                    entry["counters"][c] = b[c]
    runs = dict(sorted(runs.items(), key=lambda item: item[1]["order"]))
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


def fmt_num(e):
    return "inf" if math.isinf(e) else ("0" if e == 0 else f"{e:.0e}")


def fmt_contact(counters, key="max_rel_err", with_wrong=True):
    """A contact error counter, with the wrong answers when asked."""
    if not counters or key not in counters:
        return "–"
    s = fmt_num(max(0.0, counters[key]))
    wrong = int(round(counters.get("wrong", 0)))
    return s + (f" ({wrong} wrong)" if with_wrong and wrong else "")


def accurate(query, case, counters):
    if not counters or counters.get("wrong", 0) > 0:
        return False
    if query == "contact":
        return (counters.get("max_rel_err", math.inf) <= CONTACT_MAX_REL_ERR and
                counters.get("normal_err", math.inf) <= CONTACT_MAX_REL_ERR)
    if query == "distance" and case.endswith("/separated"):
        return counters.get("max_rel_err", math.inf) <= MAX_REL_ERR
    return True


def table(query, runs):
    cases = list(OrderedDict.fromkeys(k[1] for k in runs if k[0] == query))
    methods = [m for m in PEERS if any(k[0] == query and k[2] == m for k in runs)]
    lines = []
    contact = query == "contact"
    head = ["case", "mink ns"] + [m for m in methods] + [
        "fastest peer", "ratio", "target", "fastest accurate peer", "ratio vs accurate",
        "mink iters"]
    head += (["mink depth err", "mink normal err", "mink points err", "fastest peer depth err",
              "fastest peer normal err"] if contact else ["mink error", "fastest peer error"])
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
            mark = "†" if not_gjk(query, case, m) else ""
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
                f"{mink.get('counters', {}).get('iterations', float('nan')):.2f}"]
        peer = runs.get((query, case, best[0]), {}).get("counters") if best else None
        if contact:
            mc = mink.get("counters")
            row += [fmt_contact(mc), fmt_contact(mc, "normal_err", False),
                    fmt_contact(mc, "point_err", False), fmt_contact(peer),
                    fmt_contact(peer, "normal_err", False)]
        else:
            row += [fmt_err(mink.get("counters"), case), fmt_err(peer, case)]
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


def contact_accuracy_table(runs, key):
    """Per library: the depth (distance) error and the normal's gap, or the points' error."""
    query = "contact"
    cases = list(OrderedDict.fromkeys(k[1] for k in runs if k[0] == query))
    methods = ["mink"] + [m for m in PEERS if any(k[0] == query and k[2] == m for k in runs)]
    lines = ["| case | " + " | ".join(methods) + " |",
             "|---|" + "|".join(["---:"] * len(methods)) + "|"]
    for case in cases:
        cells = []
        for m in methods:
            e = runs.get((query, case, m))
            if not e:
                cells.append("–")
            elif "error" in e:
                cells.append("err")
            elif key == "point_err":
                cells.append(fmt_contact(e["counters"], "point_err", False))
            else:
                c = e["counters"]
                cell = (fmt_contact(c, "max_rel_err", False) + " / " +
                        fmt_contact(c, "normal_err", False))
                wrong = int(round(c.get("wrong", 0)))
                threw = int(round(c.get("threw", 0)))
                if wrong:
                    cell += f" ({wrong} wrong" + (f", {threw} threw" if threw else "") + ")"
                cells.append(cell)
        lines.append(f"| {case} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def main():
    runs, context = load(sys.argv[1:])
    out = ["# mink vs peers: boolean intersection, distance and contact", ""]
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
    present = {k[0] for k in runs}  # the queries run (a --benchmark_filter may leave some out)
    all_misses = {}
    for query, title in (("intersect", "Boolean intersection"), ("distance", "Distance")):
        if query not in present:
            continue
        t, misses = table(query, runs)
        all_misses[query] = misses
        out += [f"## {title}", "", t, ""]
    if "contact" in present:
        t, misses = table("contact", runs)
        all_misses["contact"] = misses
        out += ["## Contact (penetration)", "",
                "The full answer: verdict, penetration depth (overlap rows) or distance "
                "(separated rows), unit normal and the two deepest (closest) points, each library "
                "converted to mink's conventions (normal from A to B: the direction B must move to "
                "separate). mink: mink::contact. libccd: ccdGJKPenetration (ccd_gjk) and "
                "ccdMPRPenetration (ccd_mpr), overlap rows only (no distance). FCL: signed "
                "distance (fcl_ccd: GJKSolver_libccd::shapeSignedDistance, GJK + EPA) and "
                "GJKSolver_indep's distance then, when overlapping, its intersection with a "
                "contact (fcl_indep). Bullet: btGjkEpaSolver2::Distance then Penetration "
                "(bullet64_epa2, bullet32_epa2). Peers at their default tolerances. Target: >= 2x "
                "the fastest peer with depth (distance) error and normal gap <= "
                f"{CONTACT_MAX_REL_ERR:.0e} and no wrong answer. Depth err: max |depth - "
                "reference| / size (distance error on separated rows), against an exact long "
                "double reference (bench/reference.cpp). Normal err: max (h_A(n) + h_B(-n) - "
                "reference depth) / size, h the support function: 0 for an optimal normal. Points "
                "err: max offset of a point from its shape's support plane along the normal, "
                "distance outside its shape, or mismatch |point_b - point_a + depth * normal|, "
                "over size (reported, not part of the bar). Wrong: verdict wrong, no answer, "
                "non-finite, or depth or normal error > 1e-6. libccd and FCL's GJKSolver_indep "
                "give one position, not two points: we take it as the midpoint.", "", t, ""]
    for query, title in (("intersect", "Boolean intersection"), ("distance", "Distance")):
        if query in present:
            out += [f"## Accuracy per library: {title.lower()}", "", accuracy_table(query, runs),
                    ""]
    if "contact" in present:
        out += ["## Accuracy per library: contact", "",
                "Depth (distance) error / normal gap, relative to size; wrong answers (and "
                "exceptions) in brackets. Errors are maxima over the answers given.", "",
                contact_accuracy_table(runs, "max_rel_err"), "",
                "## Points error per library: contact", "",
                contact_accuracy_table(runs, "point_err"), ""]
    out += ["## Targets missed", ""]
    for query, misses in all_misses.items():
        out.append(f"- {query}: " + (", ".join(misses) if misses else "none"))
    bad_points = [k[1] for k, e in runs.items()
                  if k[0] == "contact" and k[2] == "mink" and
                  e["counters"].get("point_err", 0) > CONTACT_MAX_REL_ERR]
    if bad_points:
        out.append("- contact, mink's points off by more than "
                   f"{CONTACT_MAX_REL_ERR:.0e} of size: " + ", ".join(bad_points))
    print("\n".join(out))


if __name__ == "__main__":
    main()
