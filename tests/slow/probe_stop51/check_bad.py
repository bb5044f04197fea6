"""Runs bad_cases.jsonl through `mink query`: each line alone (timeout, exit code, one answer line),
then all in one stream with a valid sentinel after each (the tool must go on)."""
import json, os, subprocess, sys, time
TOOL = os.environ.get("MINK", "../../../build/release/tools/mink/mink")
SENT = '{"id":"sentinel","a":{"type":"sphere","radius":1},"b":{"type":"sphere","radius":1},"pb":{"t":[3,0,0]}}'
cases = [json.loads(l) for l in open("bad_cases.jsonl")]
out = []
bad = 0
for c in cases:
    t0 = time.time()
    try:
        p = subprocess.run(["timeout", "30", TOOL, "query"], input=(c["line"] + "\n").encode("utf-8", "surrogatepass"), capture_output=True)
        rc, so, se = p.returncode, p.stdout.decode("utf-8", "replace"), p.stderr.decode("utf-8", "replace")
    except Exception as e:
        rc, so, se = -999, "", str(e)
    dt = time.time() - t0
    lines = [l for l in so.split("\n") if l.strip()]
    r = {"what": c["what"], "expect": c["expect"], "rc": rc, "secs": round(dt, 3), "n_lines": len(lines), "stderr": se[:200]}
    probs = []
    if rc != 0: probs.append(f"exit code {rc}")
    if len(lines) != 1: probs.append(f"{len(lines)} answer lines")
    if lines:
        try:
            a = json.loads(lines[0])
            r["status"] = a.get("status"); r["error"] = a.get("error"); r["answer"] = lines[0][:300]
            def walk(x):
                if isinstance(x, float): return x != x or x in (float("inf"), float("-inf"))
                if isinstance(x, dict): return any(walk(v) for v in x.values())
                if isinstance(x, list): return any(walk(v) for v in x)
                return False
            if walk(a): probs.append("NaN/inf in answer")
            st = a.get("status")
            if c["expect"] == "error" and st != "error": probs.append(f"expected error, got {st}")
            if c["expect"] == "ok" and st != "ok": probs.append(f"expected ok, got {st}: {a.get('error')}")
        except Exception as e:
            probs.append(f"answer not JSON: {lines[0][:100]}")
    if dt > 10: probs.append(f"slow: {dt:.1f}s")
    r["problems"] = probs
    bad += bool(probs)
    out.append(r)
# one stream
stream = "".join(c["line"] + "\n" + SENT + "\n" for c in cases)
p = subprocess.run(["timeout", "300", TOOL, "query"], input=stream.encode("utf-8", "surrogatepass"), capture_output=True)
lines = [l for l in p.stdout.decode("utf-8", "replace").split("\n") if l.strip()]
sent = sum(1 for l in lines if '"id":"sentinel"' in l and '"status":"ok"' in l)
stream_res = {"rc": p.returncode, "answers": len(lines), "expected_answers": 2 * len(cases), "sentinels_ok": sent, "stderr": p.stderr.decode()[:300]}
with open("bad_results.jsonl", "w") as f:
    for r in out: f.write(json.dumps(r) + "\n")
    f.write(json.dumps({"stream": stream_res}) + "\n")
print(f"{len(cases)} lines, {bad} with problems; stream: {stream_res}")
for r in out:
    if r["problems"]: print(r["what"], r["problems"], (r.get("answer") or "")[:200], r["stderr"][:100])
