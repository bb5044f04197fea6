import json, sys, collections
cases = {}
args = sys.argv[1:]
by = "cls"
if args[0] == "--by": by = args[1]; args = args[2:]
for cf in args[0::2]:
    for l in open(cf):
        c = json.loads(l); cases[c["id"]] = c
rows = collections.OrderedDict()
def key(c):
    if by == "cls": return c["cls"]
    if by == "mode": return c["mode"]
    if by == "clsmode": return c["cls"] + " " + c["mode"]
    if by == "regime": return c["cat"].split("|")[2]
    if by == "scale": return c["cat"].split("|")[3]
    if by == "feat":
        a, b = c["cat"].split("|")[:2]
        return " / ".join(sorted([a.split(":")[1], b.split(":")[1]]))
WIT = ("witness", "struct_witness", "support_plane", "surface", "relation", "swap_points")
for rf in args[1::2]:
    for l in open(rf):
        r = json.loads(l); c = cases[r["id"]]
        g = rows.setdefault(key(c), {"n": 0, "fail": 0, "failexact": 0, "value": 0, "normal": 0, "wit": 0, "st": 0})
        g["n"] += 1
        if r["issues"]:
            g["fail"] += 1
        g["st"] += len(r.get("status", []))
        e = r["errs"]
        g["value"] = max(g["value"], e.get("value", 0)); g["normal"] = max(g["normal"], e.get("normal", 0))
        g["wit"] = max([g["wit"]] + [e.get(k, 0) for k in WIT])
print(f"| {by} | cases | failing | bad status | worst value | worst normal subopt. | worst witness |")
print("|---|---|---|---|---|---|---|")
T = {"n": 0, "fail": 0, "st": 0, "value": 0, "normal": 0, "wit": 0}
for k in sorted(rows):
    g = rows[k]
    print(f"| {k} | {g['n']} | {g['fail']} | {g['st']} | {g['value']:.1e} | {g['normal']:.1e} | {g['wit']:.1e} |")
    for x in ("n", "fail", "st"): T[x] += g[x]
    for x in ("value", "normal", "wit"): T[x] = max(T[x], g[x])
print(f"| all | {T['n']} | {T['fail']} | {T['st']} | {T['value']:.1e} | {T['normal']:.1e} | {T['wit']:.1e} |")
