"""Worst errors per category over result files (relative to the size = sum of bounding radii)."""
import json, sys, collections
res = [json.loads(l) for f in sys.argv[1:] for l in open(f)]
by = collections.defaultdict(list)
for r in res: by[r["cat"]].append(r)
groups = {"value": ("value_", "normal_value_"), "witness": ("witness_outside",), "first depth": ("manifold_first_depth",),
          "first at support": ("manifold_first_support",), "off surface": ("manifold_point_off_surface",),
          "pair relation": ("manifold_pair_relation",), "swap": ("variant_points_swap", "variant_normal_value_swap"),
          "motion": ("variant_points_move", "variant_normal_value_move")}
print("| category | cases | issues | " + " | ".join(groups) + " |")
print("|---|---|---|" + "---|" * len(groups))
for cat, rs in sorted(by.items()):
    row = []
    for g, pre in groups.items():
        v = max([x for r in rs for k, x in r["errs"].items() if k.startswith(pre)] or [0])
        row.append(f"{v:.1e}")
    print(f"| {cat} | {len(rs)} | {sum(1 for r in rs if r['issues'])} | " + " | ".join(row) + " |")
