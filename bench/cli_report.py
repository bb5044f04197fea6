#!/usr/bin/env python3
"""`mink query --timing` on the benchmark's own pairs, beside gjk_bench's table.

Usage: cli_report.py REFERENCES.jsonl ANSWERS.jsonl [gjk_bench.json ...] > table.md

REFERENCES and the query lines come from bench_queries (bench/export_queries.cpp); ANSWERS is
`mink query --timing` on those lines. For each query and case, over its 256 lines:
- mink query ns: the mean of the lines' "us" (each the median time of that query repeated; mean
  over the pairs, as gjk_bench's time per query is, which cycles through them);
- gjk_bench's mink and fastest peer (median over repetitions, as in report.py), and the ratio of
  that peer to each of mink's two times;
- the answers' accuracy: wrong verdicts, and the largest |distance or depth - reference| / size.
The two mink columns differ in what they time: the command line answers through the run-time
Shape (a type switch per call) and repeats one line at a time, so its branches are warm; gjk_bench
calls the templates directly and cycles through the pairs.
"""
import json
import math
import os
import sys
from collections import OrderedDict

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from report import PEERS, TARGET, load, fmt_time  # noqa: E402

WRONG_REL_ERR = 1e-6  # as gjk_bench: a value off by more than this is a wrong answer


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    refs = {}
    with open(sys.argv[1]) as f:
        for line in f:
            r = json.loads(line)
            refs[r["id"]] = r
    rows = OrderedDict()  # (want, case) -> {"us": [...], "err": max, "wrong": n, "lines": n}
    with open(sys.argv[2]) as f:
        for line in f:
            a = json.loads(line)
            want, family, subset, index = a["id"].split("/")
            case = family + "/" + subset
            ref = refs[case + "/" + index]
            row = rows.setdefault((want, case), {"us": [], "err": 0.0, "wrong": 0, "errors": 0})
            if a.get("status") == "error":
                row["errors"] += 1
                continue
            row["us"].append(a["us"])
            wrong = a["intersect"] != ref["intersecting"]
            value = None
            if want == "distance" and not ref["intersecting"]:
                value = a["distance"]
            elif want == "contact":
                value = a["depth"] if ref["intersecting"] else a["distance"]
            if value is not None:
                err = abs(value - ref["reference"]) / ref["size"]
                row["err"] = max(row["err"], err)
                wrong = wrong or err > WRONG_REL_ERR
            row["wrong"] += int(wrong)
    runs = load(sys.argv[3:])[0] if len(sys.argv) > 3 else {}

    out = ["`mink query --timing` on gjk_bench's pairs (bench_queries, 256 lines per case and "
           "query): the mean over the lines of each line's median time, in ns; gjk_bench's mink "
           "and fastest peer from the same run; ratio = fastest peer / mink. Accuracy of the "
           "command line's answers: wrong verdicts (or values off by more than 1e-6 of the size) "
           "and the largest distance or depth error over the size.", ""]
    for want in ("intersect", "distance", "contact"):
        cases = [c for (w, c) in rows if w == want]
        if not cases:
            continue
        out += [f"### {want}", "",
                "| case | mink query ns | gjk_bench mink ns | fastest peer | peer ns | "
                "ratio (mink query) | ratio (gjk_bench) | target | wrong | max error |",
                "|---|---:|---:|---|---:|---:|---:|---:|---:|---:|"]
        for case in cases:
            row = rows[(want, case)]
            cli = 1000.0 * sum(row["us"]) / len(row["us"]) if row["us"] else None
            bench = runs.get((want, case, "mink"), {}).get("median")
            best = None
            for m in PEERS:
                t = runs.get((want, case, m), {}).get("median")
                if t is not None and (best is None or t < best[1]):
                    best = (m, t)
            ratio_cli = f"{best[1] / cli:.2f}" if best and cli else "–"
            ratio_bench = f"{best[1] / bench:.2f}" if best and bench else "–"
            err = "–" if want == "intersect" else (
                "0" if row["err"] == 0 else f"{row['err']:.0e}")
            wrong = str(row["wrong"]) + (f" ({row['errors']} error lines)" if row["errors"] else "")
            out.append(f"| {case} | {fmt_time(cli)} | {fmt_time(bench)} | "
                       f"{best[0] if best else '–'} | {fmt_time(best[1] if best else None)} | "
                       f"{ratio_cli} | {ratio_bench} | {TARGET[want]:g} | {wrong} | {err} |")
        out.append("")
    print("\n".join(out))


if __name__ == "__main__":
    main()
