"""Writes every failing answer line as a query (the line mink was given) plus a "why" field, and
prints a summary by fault class.
usage: python3 collect_failures.py cases1.jsonl results1.jsonl [cases2 results2 ...] > failures.jsonl
Classes (from the witness checks; values and F(normal) never failed):
  W-face  the normal is exact (the structured minimum is a plane's normal: a face, a cap or base,
          or two crossing edges, and the tool's normal is that direction to < 1e-12 rad) but
          the witness pair lies displaced along the flat support set;
  W-kink  the normal is off the exact minimum by 1e-9..1e-4 rad (on a kink circle: a cone's
          slant, a cylinder's rim or side, an edge; or a smooth minimum next to a rim) and the
          witness points with it;
  ill     struct-only failures where the construction's exact pair passed: the structured
          minimum there is ill-conditioned (near-touching corner to rim, or a face tilted by
          1e-9..1e-4: the search accepts a direction within 1e-12 of the size in F): not
          reported as faults, listed on stderr only.
A "witness" issue compares with the construction's exact pair; "struct_witness" with the pair
from the structured minimum near the tool's normal (common.structured_min)."""
import json, sys, collections
from check import qline
args = sys.argv[1:]
summary = collections.defaultdict(lambda: {"lines": 0, "cases": set(), "worst": 0.0, "worst_id": "", "one_order": 0})
ill = []
for cf, rf in zip(args[0::2], args[1::2]):
    cases = {json.loads(l)["id"]: json.loads(l) for l in open(cf)}
    for l in open(rf):
        r = json.loads(l)
        by_line = collections.defaultdict(list)
        for i in r["issues"]:
            by_line[i["line"]].append(i)
        c = cases[r["id"]]
        exact_ok = r["ref"] == "exact" and c["exp"]["unique"] and not any(i["kind"] == "witness" for i in r["issues"])
        failing_orders = collections.defaultdict(set)
        for lid, iss in by_line.items():
            parts = lid.split(":")
            if len(parts) < 3: continue   # swap issues: reported with their lines
            kinds = {i["kind"] for i in iss}
            sw = [i for i in iss if i["kind"] == "struct_witness"]
            ang = max((i.get("angle", 0.0) for i in sw), default=None)
            if kinds == {"struct_witness"} and exact_ok:
                ill.append((lid, r["cat"], ang)); continue
            structure = sw[0].get("structure") if sw else None
            cls = "W-face" if (structure == "plane" and ang is not None and ang < 1e-12) else "W-kink"
            if not sw:
                f = r["cat"].split("|")[0].split(":")[1]
                cls = "W-face" if f in ("face", "cap", "base") else "W-kink"
            if not kinds & {"witness", "struct_witness"}: cls = "other:" + "+".join(sorted(kinds))
            worst = max(i["rel"] for i in iss)
            why = (f"{cls}: [{r['cat']}, size {r['size']:.3g}, gap/size {r['gap'] / r['size']:.2g}, reference {r['ref']}] " +
                   "; ".join(f"{i['kind']} {i['rel']:.2e} of size" + "".join(
                       f", {k}={v:.3g}" if isinstance(v, float) else f", {k}={v}"
                       for k, v in i.items() if k not in ("kind", "line", "rel")) for i in iss) +
                   f"; value and F(normal) within {max(r['errs'].get('value', 0), r['errs'].get('normal', 0)):.1e} of size")
            q = qline(c, parts[1], parts[2]); q["why"] = why
            print(json.dumps(q))
            s = summary[cls]; s["lines"] += 1; s["cases"].add(r["id"])
            if worst > s["worst"]: s["worst"], s["worst_id"] = worst, lid
            failing_orders[(cls, parts[1])].add(parts[2])
        for (cls, w), o in failing_orders.items():
            if len(o) == 1: summary[cls]["one_order"] += 1
for cls, s in sorted(summary.items()):
    print(f"{cls}: {s['lines']} lines in {len(s['cases'])} cases, worst {s['worst']:.2e} of size ({s['worst_id']}), "
          f"{s['one_order']} (case, want) pairs failing in one argument order only", file=sys.stderr)
for x in ill:
    print("struct only, exact pair passed (not reported): %s %s angle %.2g" % x, file=sys.stderr)
