"""Grades `mink query` answers to gen.py's lines: a pair placed apart by gap > 0 must be
Separated, unless the gap is within the rounding of its placement (8 ulp of its largest
coordinate, as for pairs 1e6 from the origin at a gap of 1e-9 of the size).

usage: check.py lines.jsonl answers.jsonl
"""
import json, math, sys

lines = [json.loads(l) for l in open(sys.argv[1])]
answers = [json.loads(l) for l in open(sys.argv[2])]
assert len(lines) == len(answers)
graded = failing = skipped = 0
for q, a in zip(lines, answers):
    assert q["id"] == a["id"]
    if a.get("status") != "ok":
        print("error", a); failing += 1; continue
    gap_factor = float(q["id"].split(":")[2])
    if gap_factor <= 0: continue
    size = sum(max(math.sqrt(sum(c * c for c in p)) for p in s["points"]) for s in (q["a"], q["b"]))
    largest = max(abs(c) for pose in (q["pa"], q["pb"]) for c in pose["t"]) + size
    if gap_factor * size <= 8 * math.ulp(largest):
        skipped += 1; continue
    graded += 1
    if a["intersect"]:
        failing += 1; print("claims an overlap:", q["id"], "gap", gap_factor * size)
print(f"graded {graded} apart, skipped {skipped} within the placement's rounding, failing {failing}")
sys.exit(1 if failing else 0)
