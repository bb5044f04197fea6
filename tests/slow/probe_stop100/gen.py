"""Pairs of small polytopes placed at a known gap, for the boolean test (stop 100).

usage: gen.py SEED PAIRS > lines.jsonl   (two lines a pair: A-B and B-A, want: intersect)

B's point farthest along -u is put on A's point farthest along u, then B moves by gap * size
along u: a gap > 0 puts a plane between them (the pair is apart by at least the gap), a gap <= 0
makes them touch or, mostly, overlap. Gaps from -1e-3 to 0.1 of the size, half of them within
the first support values' slack (4e-6 of B's bounding radius, query/polytope_pair.hpp); 4 to 39
points, sizes 1e-2 to 1e2, a quarter of the pairs 1e6 from the origin.
"""
import json, sys, numpy as np
rng = np.random.default_rng(int(sys.argv[1])); n = int(sys.argv[2])
def quat():
    q = rng.normal(size=4); q /= np.linalg.norm(q); return q  # w x y z
def rot(q):
    w,x,y,z = q
    return np.array([[1-2*(y*y+z*z),2*(x*y-w*z),2*(x*z+w*y)],[2*(x*y+w*z),1-2*(x*x+z*z),2*(y*z-w*x)],[2*(x*z-w*y),2*(y*z+w*x),1-2*(x*x+y*y)]])
GAPS = [-1e-3,-1e-6,-1e-9,0,1e-9,1e-7,5e-7,1e-6,3e-6,1e-5,1e-3,0.1]
for i in range(n):
    pts = []
    for _ in range(2):
        k = int(rng.integers(4, 40)); ax = rng.uniform(0.2, 1, 3)
        p = rng.normal(size=(k,3)); p /= np.linalg.norm(p, axis=1)[:,None]
        if rng.random() < 0.5: p *= rng.uniform(0,1,(k,1))
        pts.append(p * ax * (10 ** rng.uniform(-2, 2)))
    qa, qb = quat(), quat(); Ra, Rb = rot(qa), rot(qb)
    far = rng.random() < 0.25
    ta = np.array([3e5, -1e6, 2e6]) if far else rng.uniform(-5, 5, 3)
    u = rng.normal(size=3); u /= np.linalg.norm(u)
    wa = pts[0] @ Ra.T + ta; wb0 = pts[1] @ Rb.T
    size = np.max(np.linalg.norm(pts[0],axis=1)) + np.max(np.linalg.norm(pts[1],axis=1))
    g = GAPS[i % len(GAPS)] * size
    tb = wa[np.argmax(wa @ u)] - wb0[np.argmin(wb0 @ u)] + u * g
    for o in (0, 1):
        A, B = (0, 1) if o == 0 else (1, 0)
        P = [(qa, ta), (qb, tb)]
        line = {"id": f"{i}:{o}:{GAPS[i % len(GAPS)]!r}", "want": "intersect",
                "a": {"type": "polytope", "points": pts[A].tolist()}, "pa": {"t": P[A][1].tolist(), "q": P[A][0].tolist()},
                "b": {"type": "polytope", "points": pts[B].tolist()}, "pb": {"t": P[B][1].tolist(), "q": P[B][0].tolist()}}
        print(json.dumps(line))
