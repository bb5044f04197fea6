"""Bad and borderline input lines for `mink query`, each with what the protocol says must happen.
Writes bad_cases.jsonl: {"line": <raw text>, "expect": "error"|"ok"|"any", "what": ...}.
"any" = either an answer or an error line, but one line back, valid JSON, no NaN, no crash."""
import json, math

S = {"type": "sphere", "radius": 1}
B = {"type": "box", "half_extents": [1, 1, 1]}
P0 = {"t": [0.5, 0, 0]}
cases = []

def add(line, expect, what):
    cases.append({"line": line, "expect": expect, "what": what})

def q(a=S, b=S, pa=None, pb=P0, want=None, **extra):
    d = {"id": None, "a": a, "b": b}
    if pa is not None: d["pa"] = pa
    if pb is not None: d["pb"] = pb
    if want is not None: d["want"] = want
    d.update(extra)
    return d

def addq(d, expect, what):
    d = dict(d); d["id"] = what
    add(json.dumps(d), expect, what)

# --- malformed JSON ---
for i, raw in enumerate(['{', '{"a":', '[1,2]', '"str"', 'null', '42', 'true', '{}}', '{"id":1,"a":{"type":"sphere","radius":1}}}',
                         '{"id":"x", "a": {"type":"sphere","radius":1}, "b": {"type":"sphere","radius":1},}',
                         "{'id':1}", '{"id":1 "a":2}', '{"id":"\\ud800"}', '{"id":"\\u00"}', '\x00', '{"id":"tab\tinside"}',
                         '{"id":1,"a":{"type":"sphere","radius":NaN},"b":{"type":"sphere","radius":1}}',
                         '{"id":1,"a":{"type":"sphere","radius":Infinity},"b":{"type":"sphere","radius":1}}',
                         '{"id":1,"a":{"type":"sphere","radius":-Infinity},"b":{"type":"sphere","radius":1}}',
                         '{"id":1,"a":{"type":"sphere","radius":1e400},"b":{"type":"sphere","radius":1}}',
                         '{"id":1,"a":{"type":"sphere","radius":123456789012345678901234567890},"b":{"type":"sphere","radius":1}}',
                         '{"id":1,"a":{"type":"sphere","radius":01},"b":{"type":"sphere","radius":1}}',
                         '{"id":1,"a":{"type":"sphere","radius":.5},"b":{"type":"sphere","radius":1}}',
                         '{"id":1,"a":{"type":"sphere","radius":1.},"b":{"type":"sphere","radius":1}}',
                         '{"id":1,"a":{"type":"sphere","radius":+1},"b":{"type":"sphere","radius":1}}',
                         '{"id":1,"a":{"type":"sphere","radius":0x10},"b":{"type":"sphere","radius":1}}',
                         '{"id":1,"a":{"type":"sphere","radius":1e},"b":{"type":"sphere","radius":1}}',
                         '{"id":1,"a":{"type":"sphere","radius":-},"b":{"type":"sphere","radius":1}}',
                         '{"id":1,"a":{"type":"sphere","radius":1}', '\ufeff{"id":"bom","a":{"type":"sphere","radius":1},"b":{"type":"sphere","radius":1}}',
                         ]):
    add(raw, "any" if ("ud800" in raw or "\t" in raw or "\ufeff" in raw) else "error", f"malformed-{i}")
# deep nesting: parser recursion
for depth in (100, 1000, 10000, 100000, 1000000):
    add('{"id":"deep-array-%d","a":%s1%s}' % (depth, "[" * depth, "]" * depth), "error", f"deep-array-{depth}")
    add('{"id":"deep-object-%d","a":%s1%s}' % (depth, '{"x":' * depth, "}" * depth), "error", f"deep-object-{depth}")
# deeply nested valid shapes: rounded and sums
for depth in (10, 100, 1000, 10000, 100000):
    s = {"type": "sphere", "radius": 0.001}
    txt = json.dumps(s)
    for _ in range(depth):
        txt = '{"type":"rounded","radius":0.001,"shape":' + txt + '}'
    add('{"id":"deep-rounded-%d","a":%s,"b":{"type":"sphere","radius":1},"pb":{"t":[50,0,0]}}' % (depth, txt), "any", f"deep-rounded-{depth}")
    txt = json.dumps(s)
    for _ in range(depth):
        txt = '{"type":"sum","shapes":[' + txt + ',{"type":"point","points":[[0.001,0,0]]}]}'
    add('{"id":"deep-sum-%d","a":%s,"b":{"type":"sphere","radius":1},"pb":{"t":[50,0,0]}}' % (depth, txt), "any", f"deep-sum-{depth}")

# --- wrong types / shapes ---
W = [
    (q(a={"type": "sphere", "radius": "1"}), "error", "radius-string"),
    (q(a={"type": "sphere", "radius": "NaN"}), "error", "radius-NaN-string"),
    (q(a={"type": "sphere", "radius": "Infinity"}), "error", "radius-Infinity-string"),
    (q(a={"type": "sphere", "radius": [1]}), "error", "radius-array"),
    (q(a={"type": "sphere", "radius": None}), "error", "radius-null"),
    (q(a={"type": "sphere", "radius": True}), "error", "radius-bool"),
    (q(a={"type": "sphere"}), "error", "radius-missing"),
    (q(a={"type": "sphere", "radius": 1, "extra": 2}), "error", "shape-unknown-field"),
    (q(a={"type": "Sphere", "radius": 1}), "error", "type-case"),
    (q(a={"type": "torus", "radius": 1}), "error", "type-unknown"),
    (q(a={"radius": 1}), "error", "type-missing"),
    (q(a={"type": 3, "radius": 1}), "error", "type-number"),
    (q(a=[1, 2]), "error", "shape-array"),
    (q(a="sphere"), "error", "shape-string"),
    (q(a={"type": "box", "half_extents": [1, 1]}), "error", "box-2-extents"),
    (q(a={"type": "box", "half_extents": [1, 1, 1, 1]}), "error", "box-4-extents"),
    (q(a={"type": "box", "half_extents": [1, "1", 1]}), "error", "box-string-extent"),
    (q(a={"type": "box", "half_extents": 1}), "error", "box-scalar-extent"),
    (q(a={"type": "box", "half_extents": [1, -1, 1]}), "error", "box-negative-extent"),
    (q(a={"type": "box", "half_extents": [1, -0.0, 1]}), "any", "box-minus-zero-extent"),
    (q(a={"type": "capsule", "radius": -1, "half_height": 1}), "error", "capsule-negative-radius"),
    (q(a={"type": "capsule", "radius": 1, "half_height": -1}), "error", "capsule-negative-half-height"),
    (q(a={"type": "cylinder", "radius": -1e-300, "half_height": 1}), "error", "cylinder-tiny-negative-radius"),
    (q(a={"type": "cone", "radius": 1, "half_height": -1}), "error", "cone-negative-half-height"),
    (q(a={"type": "ellipsoid", "radii": [1, -1, 1]}), "error", "ellipsoid-negative"),
    (q(a={"type": "ellipsoid", "radii": [1, 1]}), "error", "ellipsoid-2"),
    (q(a={"type": "sphere", "radius": -1}), "error", "sphere-negative"),
    (q(a={"type": "sphere", "radius": -0.0}), "any", "sphere-minus-zero"),
    (q(a={"type": "rounded", "shape": B, "radius": -0.1}), "error", "rounded-negative"),
    (q(a={"type": "rounded", "shape": B}), "error", "rounded-no-radius"),
    (q(a={"type": "rounded", "radius": 0.1}), "error", "rounded-no-shape"),
    (q(a={"type": "sum", "shapes": [B]}), "error", "sum-1"),
    (q(a={"type": "sum", "shapes": [B, S, S]}), "error", "sum-3"),
    (q(a={"type": "sum", "shapes": []}), "error", "sum-0"),
    (q(a={"type": "sum", "shapes": B}), "error", "sum-object"),
    (q(a={"type": "polytope", "points": []}), "error", "polytope-empty"),
    (q(a={"type": "polytope", "points": [[1, 2]]}), "error", "polytope-2d-point"),
    (q(a={"type": "polytope", "points": [[1, 2, 3, 4]]}), "error", "polytope-4d-point"),
    (q(a={"type": "polytope", "points": [1, 2, 3]}), "error", "polytope-flat-list"),
    (q(a={"type": "polytope", "points": [[0, 0, 0]]}), "any", "polytope-1-point"),
    (q(a={"type": "polytope", "points": [[0, 0, 0], [0, 0, 0]]}), "any", "polytope-2-equal-points"),
    (q(a={"type": "polytope", "points": [[0, 0, 0], [1, 0, 0]]}), "any", "polytope-2-points"),
    (q(a={"type": "polytope", "points": [[0, 0, 0], [1, 0, 0], [2, 0, 0]]}), "any", "polytope-collinear"),
    (q(a={"type": "point", "points": [[0, 0, 0], [1, 0, 0]]}), "error", "point-2-points"),
    (q(a={"type": "point", "points": []}), "error", "point-0-points"),
    (q(a={"type": "segment", "points": [[0, 0, 0]]}), "error", "segment-1-point"),
    (q(a={"type": "segment", "points": [[0, 0, 0], [0, 0, 0]]}), "ok", "segment-zero-length"),
    (q(a={"type": "triangle", "points": [[0, 0, 0], [1, 0, 0]]}), "error", "triangle-2-points"),
    (q(a={"type": "triangle", "points": [[0, 0, 0], [1, 0, 0], [2, 0, 0]]}), "ok", "triangle-collinear"),
    (q(a={"type": "triangle", "points": [[0, 0, 0], [0, 0, 0], [0, 0, 0]]}), "ok", "triangle-all-equal"),
    (q(a={"type": "sphere", "radius": 0}), "ok", "sphere-zero"),
    (q(a={"type": "capsule", "radius": 0, "half_height": 0}), "ok", "capsule-zero"),
    (q(a={"type": "cylinder", "radius": 0, "half_height": 0}), "ok", "cylinder-zero"),
    (q(a={"type": "cylinder", "radius": 1, "half_height": 0}), "ok", "cylinder-disc"),
    (q(a={"type": "cylinder", "radius": 0, "half_height": 1}), "ok", "cylinder-needle"),
    (q(a={"type": "cone", "radius": 0, "half_height": 1}), "ok", "cone-needle"),
    (q(a={"type": "cone", "radius": 1, "half_height": 0}), "ok", "cone-disc"),
    (q(a={"type": "cone", "radius": 0, "half_height": 0}), "ok", "cone-zero"),
    (q(a={"type": "ellipsoid", "radii": [0, 0, 0]}), "ok", "ellipsoid-zero"),
    (q(a={"type": "ellipsoid", "radii": [1, 0, 0]}), "ok", "ellipsoid-needle"),
    (q(a={"type": "ellipsoid", "radii": [1, 1, 0]}), "ok", "ellipsoid-disc"),
    (q(a={"type": "box", "half_extents": [0, 0, 0]}), "ok", "box-zero"),
    (q(a={"type": "box", "half_extents": [0, 0, 0]}, b={"type": "box", "half_extents": [0, 0, 0]}, pb=None), "ok", "box-zero-vs-box-zero-coincident"),
    (q(a={"type": "sphere", "radius": 0}, b={"type": "sphere", "radius": 0}, pb=None), "ok", "sphere0-vs-sphere0-coincident"),
    (q(a={"type": "point", "points": [[0, 0, 0]]}, b={"type": "point", "points": [[0, 0, 0]]}, pb=None), "ok", "point-vs-point-coincident"),
    (q(a={"type": "point", "points": [[0, 0, 0]]}, b={"type": "point", "points": [[0, 0, 0]]}, pb=None, want="manifold"), "ok", "point-vs-point-coincident-manifold"),
    (q(a={"type": "ellipsoid", "radii": [0, 0, 0]}, b={"type": "ellipsoid", "radii": [0, 0, 0]}, pb=None, want="manifold"), "ok", "ell0-vs-ell0-coincident-manifold"),
    (q(a={"type": "cone", "radius": 0, "half_height": 0}, b={"type": "cylinder", "radius": 0, "half_height": 0}, pb={"t": [1e-300, 0, 0]}), "ok", "zero-shapes-1e-300-apart"),
    (q(a={"type": "sphere", "radius": 1e-300}, b={"type": "sphere", "radius": 1e-300}, pb={"t": [1e-300, 0, 0]}), "ok", "spheres-1e-300"),
    (q(a={"type": "sphere", "radius": 5e-324}, b={"type": "box", "half_extents": [5e-324, 5e-324, 5e-324]}, pb={"t": [1e-323, 0, 0]}), "any", "denormal-shapes"),
    (q(a={"type": "polytope", "points": [[0, 0, 0], [5e-324, 0, 0], [0, 5e-324, 0], [0, 0, 5e-324]]}, b={"type": "polytope", "points": [[0, 0, 0], [5e-324, 0, 0], [0, 5e-324, 0], [0, 0, 5e-324]]}, pb={"t": [1e-324, 0, 0]}, want="manifold"), "any", "denormal-polytopes"),
    # huge numbers
    (q(a={"type": "sphere", "radius": 1e308}), "error", "radius-1e308"),
    (q(a={"type": "sphere", "radius": 1e50}), "ok", "radius-1e50"),
    (q(a={"type": "sphere", "radius": 1.0000001e50}), "error", "radius-above-1e50"),
    (q(pb={"t": [1e308, 0, 0]}), "error", "t-1e308"),
    (q(pb={"t": [-1e308, 0, 0]}), "error", "t-minus-1e308"),
    (q(pb={"t": [1e50, 1e50, 1e50]}), "ok", "t-1e50"),
    (q(a={"type": "box", "half_extents": [1e50, 1e50, 1e50]}, b={"type": "box", "half_extents": [1e50, 1e50, 1e50]}, pb={"t": [1e50, 1e50, 1e50]}, want="manifold"), "ok", "boxes-1e50-manifold"),
    (q(a={"type": "cone", "radius": 1e50, "half_height": 1e50}, b={"type": "ellipsoid", "radii": [1e50, 1e-50, 1e50]}, pb={"t": [1e50, -1e50, 1e50], "q": [0.5, 0.5, 0.5, 0.5]}), "ok", "cone-ellipsoid-1e50"),
    (q(a={"type": "polytope", "points": [[1e50, 0, 0], [0, 1e50, 0], [0, 0, 1e50], [-1e50, -1e50, -1e50]]}, b={"type": "sphere", "radius": 1e-50}, pb={"t": [1e-50, 0, 0]}, want="manifold"), "ok", "poly-1e50-vs-sphere-1e-50"),
    (q(a={"type": "sphere", "radius": 1e-50}, b={"type": "sphere", "radius": 1e50}, pb={"t": [1e50, 0, 0]}, want="manifold"), "ok", "sphere-ratio-1e100"),
    (q(a={"type": "cylinder", "radius": 1e50, "half_height": 1e-50}, b={"type": "capsule", "radius": 1e-50, "half_height": 1e50}, pb={"t": [0, 0, 1e-50], "q": [0.7071067811865476, 0.7071067811865476, 0, 0]}, want="manifold"), "ok", "flat-cylinder-vs-long-capsule-1e100"),
    # poses
    (q(pb={"t": [1, 0]}), "error", "t-2"),
    (q(pb={"t": [1, 0, 0, 0]}), "error", "t-4"),
    (q(pb={"t": "1,0,0"}), "error", "t-string"),
    (q(pb={"q": [1, 0, 0]}), "error", "q-3"),
    (q(pb={"q": [0, 0, 0, 0]}), "error", "q-zero"),
    (q(pb={"q": [1 + 1e-7, 0, 0, 0]}), "ok", "q-norm-plus-1e-7"),
    (q(pb={"q": [1 - 1e-7, 0, 0, 0]}), "ok", "q-norm-minus-1e-7"),
    (q(pb={"q": [1 + 1e-5, 0, 0, 0]}), "error", "q-norm-plus-1e-5"),
    (q(pb={"q": [1 - 1e-5, 0, 0, 0]}), "error", "q-norm-minus-1e-5"),
    (q(pb={"q": [0.5 * (1 + 1e-7), 0.5, 0.5, 0.5]}), "ok", "q-off-1e-7-mixed"),
    (q(pb={"q": [0.5 * (1 + 2e-5), 0.5, 0.5, 0.5]}), "error", "q-off-1e-5-mixed"),
    (q(pb={"q": [-1, 0, 0, 0]}), "ok", "q-minus-identity"),
    (q(pb={"q": [1, 0, 0, 0], "s": 2}), "error", "pose-unknown-field"),
    (q(pb=[0, 0, 0]), "error", "pose-array"),
    (q(pb={}), "ok", "pose-empty"),
    (q(pb=None, pa={"t": [0, 0, 0]}), "ok", "pose-omitted"),
    # want and margin
    (q(want="Contact"), "error", "want-case"),
    (q(want="closest"), "error", "want-unknown"),
    (q(want=1), "error", "want-number"),
    (q(want="contact", margin=0.1), "error", "margin-with-contact"),
    (q(want="distance", margin=0), "error", "margin-zero-with-distance"),
    (q(want="manifold", margin=-0.1), "error", "margin-negative"),
    (q(want="manifold", margin=-0.0), "any", "margin-minus-zero"),
    (q(want="manifold", margin="0.1"), "error", "margin-string"),
    (q(want="manifold", margin="NaN"), "error", "margin-NaN-string"),
    (q(want="manifold", margin=1e50), "ok", "margin-1e50"),
    (q(want="manifold", margin=2e50), "error", "margin-2e50"),
    (q(want="manifold", margin=1e49, pb={"t": [1e49, 0, 0]}), "ok", "margin-1e49-far"),
    (q(want="manifold", margin=None), "error", "margin-null"),
    # top-level
    (q(extra_field=1), "error", "top-unknown-field"),
    ({"id": None, "a": S}, "error", "missing-b"),
    ({"id": None, "b": S}, "error", "missing-a"),
]
for d, e, w in W: addq(d, e, w)
# ids
for idv, e in ((1.50, "ok"), (-3, "ok"), (1e300, "any"), (0, "ok"), ([1], "error"), ({"x": 1}, "error"), (True, "error"), (None, "any"), ("", "ok"), ("x" * 100000, "ok"), ("é\u2028\"\\", "ok")):
    d = q(); d["id"] = idv
    add(json.dumps(d), e, f"id-{json.dumps(idv)[:20]}")
add('{"a":{"type":"sphere","radius":1},"b":{"type":"sphere","radius":1}}', "ok", "no-id")
add('{"id":"crlf","a":{"type":"sphere","radius":1},"b":{"type":"sphere","radius":1}}\r', "ok", "crlf")
add('{"id":"dupkey","a":{"type":"sphere","radius":1},"a":{"type":"sphere","radius":2},"b":{"type":"sphere","radius":1}}', "any", "duplicate-key")
add('{"id":"esc","a":{"type":"sph\\u0065re","radius":1},"b":{"type":"sphere","radius":1}}', "ok", "escaped-type")
add('   {"id":"ws","a":{"type":"sphere","radius":1},"b":{"type":"sphere","radius":1}}   ', "ok", "surrounding-whitespace")
add('{"id":"exp","a":{"type":"sphere","radius":1E0},"b":{"type":"sphere","radius":1e-0}}', "ok", "exponent-forms")
add('{"id":"under","a":{"type":"sphere","radius":1e-400},"b":{"type":"sphere","radius":1}}', "any", "underflow-literal")
# a big polytope on one line
import random
random.seed(51)
pts = [[random.gauss(0, 1) for _ in range(3)] for _ in range(200000)]
add(json.dumps({"id": "poly-200k", "a": {"type": "polytope", "points": pts}, "b": S, "pb": {"t": [3, 0, 0]}, "want": "manifold", "margin": 5}), "ok", "poly-200k")
pts = [[0.0, 0.0, 0.0]] * 100000 + [[1, 0, 0], [0, 1, 0], [0, 0, 1]]
add(json.dumps({"id": "poly-100k-dups", "a": {"type": "polytope", "points": pts}, "b": S, "pb": {"t": [0.3, 0.3, 0.3]}, "want": "manifold"}), "ok", "poly-100k-dups")

with open("bad_cases.jsonl", "w") as f:
    for c in cases: f.write(json.dumps(c) + "\n")
print(len(cases))
