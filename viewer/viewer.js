// The page `mink view` writes: draws each query's shapes at their poses, the witness points, the
// normal and the manifold, and lists the answers beside the picture. Everything it needs is inside
// the page (three.js comes in through the import map as data: URLs), so it opens from a file
// without a network. The data is the JSON in <script id="mink-data">: for each query line its raw
// text and the raw answer line `mink query` gave for it (so the page shows exactly that answer).
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { ConvexGeometry } from 'three/addons/geometries/ConvexGeometry.js';

const COLOR_A = 0xd8402f;
const COLOR_B = 0x2f6fd8;
const COLOR_POINT_A = 0x7a1208;
const COLOR_POINT_B = 0x0b2f73;
const COLOR_NORMAL = 0x13a33a;
const COLOR_MANIFOLD = 0xff9a00;
const SHAPE_OPACITY = 0.72;
// Directions sampled to approximate shapes without a closed-form mesh (sum, rounded): their
// surface is drawn as the hull of their support points in these directions.
const SUPPORT_DIRECTIONS = 642;

const data = JSON.parse(document.getElementById('mink-data').textContent);

function tryParse(text) {
  try {
    return JSON.parse(text);
  } catch (e) {
    return undefined;
  }
}

const vec = (a) => new THREE.Vector3(a[0], a[1], a[2]);
const isVec3 = (a) => Array.isArray(a) && a.length === 3 && a.every((x) => typeof x === 'number');

// ---------------------------------------------------------------------------------------------
// Shapes: support functions (for sum, rounded and bounds) and meshes, in the shape's local frame.

function support(shape, d) {
  switch (shape.type) {
    case 'sphere':
      return d.clone().multiplyScalar(shape.radius);
    case 'box': {
      const h = shape.half_extents;
      return new THREE.Vector3(d.x >= 0 ? h[0] : -h[0], d.y >= 0 ? h[1] : -h[1],
                               d.z >= 0 ? h[2] : -h[2]);
    }
    case 'capsule':
      return d.clone().multiplyScalar(shape.radius)
          .add(new THREE.Vector3(0, 0, d.z >= 0 ? shape.half_height : -shape.half_height));
    case 'cylinder': {
      const r = Math.hypot(d.x, d.y);
      const s = r > 0 ? shape.radius / r : 0;
      return new THREE.Vector3(d.x * s, d.y * s, d.z >= 0 ? shape.half_height : -shape.half_height);
    }
    case 'cone': {
      const r = Math.hypot(d.x, d.y);
      const s = r > 0 ? shape.radius / r : 0;
      const rim = new THREE.Vector3(d.x * s, d.y * s, -shape.half_height);
      const apex = new THREE.Vector3(0, 0, shape.half_height);
      return apex.dot(d) >= rim.dot(d) ? apex : rim;
    }
    case 'ellipsoid': {
      const r = shape.radii;
      const rd = new THREE.Vector3(r[0] * d.x, r[1] * d.y, r[2] * d.z);
      const n = rd.length();
      if (n === 0) return new THREE.Vector3();
      return new THREE.Vector3(r[0] * rd.x / n, r[1] * rd.y / n, r[2] * rd.z / n);
    }
    case 'polytope':
    case 'point':
    case 'segment':
    case 'triangle': {
      let best = null;
      let bestDot = -Infinity;
      for (const p of shape.points) {
        const v = vec(p);
        const dot = v.dot(d);
        if (dot > bestDot) {
          bestDot = dot;
          best = v;
        }
      }
      return best;
    }
    case 'sum':
      return support(shape.shapes[0], d).add(support(shape.shapes[1], d));
    case 'rounded':
      return support(shape.shape, d).add(d.clone().multiplyScalar(shape.radius));
    default:
      throw new Error('unknown shape type ' + shape.type);
  }
}

// Radius of a ball about the local origin that holds the shape.
function boundRadius(shape) {
  switch (shape.type) {
    case 'sphere':
      return shape.radius;
    case 'box':
      return vec(shape.half_extents).length();
    case 'capsule':
      return shape.radius + shape.half_height;
    case 'cylinder':
    case 'cone':
      return Math.hypot(shape.radius, shape.half_height);
    case 'ellipsoid':
      return Math.max(...shape.radii);
    case 'polytope':
    case 'point':
    case 'segment':
    case 'triangle':
      return Math.max(...shape.points.map((p) => vec(p).length()));
    case 'sum':
      return boundRadius(shape.shapes[0]) + boundRadius(shape.shapes[1]);
    case 'rounded':
      return boundRadius(shape.shape) + shape.radius;
    default:
      return 0;
  }
}

function fibonacciDirections(n) {
  const out = [];
  const golden = Math.PI * (3 - Math.sqrt(5));
  for (let i = 0; i < n; ++i) {
    const z = 1 - (2 * i + 1) / n;
    const r = Math.sqrt(1 - z * z);
    out.push(new THREE.Vector3(r * Math.cos(golden * i), r * Math.sin(golden * i), z));
  }
  // The axes themselves, so that flat faces normal to them come out flat.
  for (const a of [[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]])
    out.push(vec(a));
  return out;
}

// The mesh of the convex hull of `points`, whatever their dimension: a 3D hull, a planar polygon,
// a segment or a single point. `marker` is the radius used to draw points and segments.
function hullMesh(points, marker, material) {
  const extent = points.reduce((m, p) => Math.max(m, p.length()), 0);
  const tol = 1e-9 * Math.max(extent, 1e-300);
  // Farthest pair from the first point, then farthest from their line, then from their plane.
  const p0 = points[0];
  let p1 = p0;
  for (const p of points) if (p.distanceTo(p0) > p1.distanceTo(p0)) p1 = p;
  if (p1.distanceTo(p0) <= tol) return markerMesh(p0, marker, material);
  const axis = p1.clone().sub(p0).normalize();
  const offLine = (p) => p.clone().sub(p0).sub(axis.clone().multiplyScalar(p.clone().sub(p0).dot(axis)));
  let p2 = p0;
  for (const p of points) if (offLine(p).length() > offLine(p2).length()) p2 = p;
  if (offLine(p2).length() <= tol) {
    let lo = p0, hi = p0;
    for (const p of points) {
      if (p.clone().sub(p0).dot(axis) < lo.clone().sub(p0).dot(axis)) lo = p;
      if (p.clone().sub(p0).dot(axis) > hi.clone().sub(p0).dot(axis)) hi = p;
    }
    return segmentMesh(lo, hi, marker, material);
  }
  const normal = axis.clone().cross(offLine(p2)).normalize();
  const offPlane = points.reduce((m, p) => Math.max(m, Math.abs(p.clone().sub(p0).dot(normal))), 0);
  if (offPlane > tol && points.length >= 4) return new THREE.Mesh(new ConvexGeometry(points), material);
  // Planar: a 2D hull (monotone chain) in the plane's coordinates, drawn as a fan.
  const v = normal.clone().cross(axis);
  const uv = points.map((p) => {
    const q = p.clone().sub(p0);
    return { u: q.dot(axis), v: q.dot(v), p };
  });
  uv.sort((a, b) => a.u - b.u || a.v - b.v);
  const cross = (o, a, b) => (a.u - o.u) * (b.v - o.v) - (a.v - o.v) * (b.u - o.u);
  const lower = [], upper = [];
  for (const q of uv) {
    while (lower.length >= 2 && cross(lower[lower.length - 2], lower[lower.length - 1], q) <= 0) lower.pop();
    lower.push(q);
  }
  for (let i = uv.length - 1; i >= 0; --i) {
    const q = uv[i];
    while (upper.length >= 2 && cross(upper[upper.length - 2], upper[upper.length - 1], q) <= 0) upper.pop();
    upper.push(q);
  }
  const ring = lower.slice(0, -1).concat(upper.slice(0, -1)).map((q) => q.p);
  const positions = [];
  for (let i = 1; i + 1 < ring.length; ++i)
    for (const p of [ring[0], ring[i], ring[i + 1]]) positions.push(p.x, p.y, p.z);
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.Float32BufferAttribute(positions, 3));
  geometry.computeVertexNormals();
  const flat = material.clone();
  flat.side = THREE.DoubleSide;
  return new THREE.Mesh(geometry, flat);
}

function markerMesh(p, radius, material) {
  const mesh = new THREE.Mesh(new THREE.SphereGeometry(radius, 16, 8), material);
  mesh.position.copy(p);
  return mesh;
}

function segmentMesh(a, b, radius, material) {
  const length = a.distanceTo(b);
  const geometry = new THREE.CylinderGeometry(radius, radius, length, 12);
  const mesh = new THREE.Mesh(geometry, material);
  mesh.position.copy(a).add(b).multiplyScalar(0.5);
  mesh.quaternion.setFromUnitVectors(new THREE.Vector3(0, 1, 0), b.clone().sub(a).normalize());
  return mesh;
}

// three's capsule, cylinder and cone stand along y; mink's along z.
function alongZ(geometry) {
  geometry.rotateX(Math.PI / 2);
  return geometry;
}

// The shape's mesh in its local frame. Returns { object, approximate }.
function shapeMesh(shape, marker, material) {
  switch (shape.type) {
    case 'sphere':
      return { object: new THREE.Mesh(new THREE.SphereGeometry(shape.radius, 48, 24), material) };
    case 'box': {
      const h = shape.half_extents;
      return { object: new THREE.Mesh(new THREE.BoxGeometry(2 * h[0], 2 * h[1], 2 * h[2]), material) };
    }
    case 'capsule':
      return { object: new THREE.Mesh(alongZ(new THREE.CapsuleGeometry(shape.radius, 2 * shape.half_height, 12, 32)), material) };
    case 'cylinder':
      return { object: new THREE.Mesh(alongZ(new THREE.CylinderGeometry(shape.radius, shape.radius, 2 * shape.half_height, 48)), material) };
    case 'cone':
      return { object: new THREE.Mesh(alongZ(new THREE.ConeGeometry(shape.radius, 2 * shape.half_height, 48)), material) };
    case 'ellipsoid': {
      const geometry = new THREE.SphereGeometry(1, 48, 24);
      geometry.scale(shape.radii[0], shape.radii[1], shape.radii[2]);
      return { object: new THREE.Mesh(geometry, material) };
    }
    case 'point':
    case 'segment':
    case 'triangle':
    case 'polytope':
      return { object: hullMesh(shape.points.map(vec), marker, material) };
    case 'sum':
    case 'rounded': {
      const points = fibonacciDirections(SUPPORT_DIRECTIONS).map((d) => support(shape, d));
      return { object: hullMesh(points, marker, material), approximate: true };
    }
    default:
      throw new Error('unknown shape type ' + shape.type);
  }
}

function shapeMaterial(color) {
  return new THREE.MeshLambertMaterial({
    color, transparent: true, opacity: SHAPE_OPACITY, depthWrite: false, side: THREE.FrontSide,
  });
}

function pose(p) {
  const t = p && isVec3(p.t) ? vec(p.t) : new THREE.Vector3();
  const q = p && Array.isArray(p.q) && p.q.length === 4
    ? new THREE.Quaternion(p.q[1], p.q[2], p.q[3], p.q[0])  // mink: [w, x, y, z]
    : new THREE.Quaternion();
  return { t, q };
}

// ---------------------------------------------------------------------------------------------
// The items: one per query line.

const items = data.items.map((raw, index) => {
  const query = tryParse(raw.query);
  const answer = tryParse(raw.answer);
  const item = { index, raw, query, answer, group: null, error: null, approximate: false };
  if (!answer) item.error = 'no answer';
  else if (answer.status === 'error') item.error = answer.error;
  else if (!query || typeof query !== 'object') item.error = 'the query line is not a JSON object';
  return item;
});

// Where both shapes of an item sit in the world, as bounding balls (for framing and for deciding
// whether the queries form one scene or must be shown one at a time).
function worldBall(shape, p) {
  return { centre: pose(p).t, radius: boundRadius(shape) };
}

const scene = new THREE.Scene();
scene.background = new THREE.Color(0xf4f4f2);
const shapeKeys = new Map();  // "shape+pose" JSON -> the first item that drew it

for (const item of items) {
  if (item.error) continue;
  const q = item.query;
  try {
    const balls = [worldBall(q.a, q.pa), worldBall(q.b, q.pb)];
    let scale = 0;
    for (const b of balls) scale = Math.max(scale, b.radius);
    scale = Math.max(scale, balls[0].centre.distanceTo(balls[1].centre) / 2);
    if (!(scale > 0)) scale = 1;
    item.scale = scale;
    const marker = 0.025 * scale;
    const group = new THREE.Group();
    for (const [shape, p, color, key] of [[q.a, q.pa, COLOR_A, 'a'], [q.b, q.pb, COLOR_B, 'b']]) {
      const built = shapeMesh(shape, marker, shapeMaterial(color));
      if (built.approximate) item.approximate = true;
      const { t, q: rotation } = pose(p);
      const holder = new THREE.Group();
      holder.add(built.object);
      if (built.object.geometry && built.object.geometry.index !== undefined && shape.type !== 'sphere' &&
          shape.type !== 'ellipsoid') {
        const edges = new THREE.LineSegments(new THREE.EdgesGeometry(built.object.geometry, 25),
                                             new THREE.LineBasicMaterial({ color: 0x333333, transparent: true, opacity: 0.5 }));
        edges.position.copy(built.object.position);
        edges.quaternion.copy(built.object.quaternion);
        holder.add(edges);
      }
      holder.position.copy(t);
      holder.quaternion.copy(rotation);
      holder.userData.role = 'shape';
      holder.userData.which = key;
      // The same shape at the same pose in several queries (a scene): drawn once when all are shown.
      const shapeKey = JSON.stringify([shape, p || null]);
      if (shapeKeys.has(shapeKey)) holder.userData.duplicate = true;
      else shapeKeys.set(shapeKey, item.index);
      group.add(holder);
    }
    addAnswer(group, item.answer, marker, scale);
    item.group = group;
    item.balls = balls;
    scene.add(group);
  } catch (e) {
    item.error = 'cannot draw: ' + e.message;
  }
}

function addAnswer(group, answer, marker, scale) {
  const pa = isVec3(answer.point_a) ? vec(answer.point_a) : null;
  const pb = isVec3(answer.point_b) ? vec(answer.point_b) : null;
  const overlay = (color) => new THREE.MeshBasicMaterial({ color, depthTest: false, transparent: true });
  if (pa) group.add(markerMesh(pa, marker, overlay(COLOR_POINT_A)));
  if (pb) group.add(markerMesh(pb, marker, overlay(COLOR_POINT_B)));
  if (pa && pb && pa.distanceTo(pb) > 0) {
    const geometry = new THREE.BufferGeometry().setFromPoints([pa, pb]);
    group.add(new THREE.Line(geometry, new THREE.LineBasicMaterial({ color: 0x111111, depthTest: false, transparent: true })));
  }
  if (isVec3(answer.normal) && pa) {
    const arrow = new THREE.ArrowHelper(vec(answer.normal).normalize(), pa, 0.45 * scale, COLOR_NORMAL,
                                        0.12 * scale, 0.06 * scale);
    arrow.traverse((o) => {
      if (o.material) {
        o.material.depthTest = false;
        o.material.transparent = true;
      }
    });
    group.add(arrow);
  }
  const m = answer.manifold;
  if (m && Array.isArray(m.points)) {
    const positions = m.points.filter((p) => p && isVec3(p.position)).map((p) => vec(p.position));
    for (const p of positions) group.add(markerMesh(p, 1.3 * marker, overlay(COLOR_MANIFOLD)));
    if (positions.length >= 2) {
      // The patch's outline, its points taken in angle order about their centre.
      const centre = positions.reduce((s, p) => s.add(p), new THREE.Vector3()).multiplyScalar(1 / positions.length);
      const n = isVec3(m.normal) ? vec(m.normal).normalize() : new THREE.Vector3(0, 0, 1);
      const u = positions[0].clone().sub(centre);
      u.sub(n.clone().multiplyScalar(u.dot(n)));
      if (u.lengthSq() > 0) {
        u.normalize();
        const v = n.clone().cross(u);
        const sorted = positions.slice().sort((a, b) =>
          Math.atan2(a.clone().sub(centre).dot(v), a.clone().sub(centre).dot(u)) -
          Math.atan2(b.clone().sub(centre).dot(v), b.clone().sub(centre).dot(u)));
        const loop = new THREE.LineLoop(new THREE.BufferGeometry().setFromPoints(sorted),
                                        new THREE.LineBasicMaterial({ color: COLOR_MANIFOLD, depthTest: false, transparent: true }));
        group.add(loop);
      }
      if (isVec3(m.normal)) {
        const arrow = new THREE.ArrowHelper(n, centre, 0.3 * scale, COLOR_MANIFOLD, 0.09 * scale, 0.05 * scale);
        arrow.traverse((o) => {
          if (o.material) {
            o.material.depthTest = false;
            o.material.transparent = true;
          }
        });
        group.add(arrow);
      }
    }
  }
  // Overlays are drawn after the translucent shapes so that they stay visible inside them.
  group.traverse((o) => {
    if (o.material && o.material.depthTest === false) o.renderOrder = 10;
  });
}

// The queries form one scene (shown all together by default) unless shapes of different queries
// overlap without being the same shape: then they are separate tests and are shown one at a time.
function looksLikeScene() {
  const drawn = items.filter((it) => it.group);
  if (drawn.length <= 1) return true;
  const balls = [];
  for (const it of drawn) {
    it.query && [['a', it.query.a, it.query.pa], ['b', it.query.b, it.query.pb]].forEach(([, s, p]) => {
      const key = JSON.stringify([s, p || null]);
      if (!balls.some((b) => b.key === key)) balls.push({ key, item: it.index, ...worldBall(s, p) });
    });
  }
  if (balls.length > 400) return false;
  const together = (k1, k2) => drawn.some((it) => {
    const ka = JSON.stringify([it.query.a, it.query.pa || null]);
    const kb = JSON.stringify([it.query.b, it.query.pb || null]);
    return (ka === k1 && kb === k2) || (ka === k2 && kb === k1);
  });
  for (let i = 0; i < balls.length; ++i)
    for (let j = i + 1; j < balls.length; ++j) {
      const a = balls[i], b = balls[j];
      if (a.centre.distanceTo(b.centre) < 0.9 * (a.radius + b.radius) && !together(a.key, b.key)) return false;
    }
  return true;
}

// ---------------------------------------------------------------------------------------------
// Rendering, camera and the panel.

const view = document.getElementById('view');
const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(window.devicePixelRatio || 1);
view.appendChild(renderer.domElement);
const camera = new THREE.PerspectiveCamera(40, 1, 0.01, 1000);
camera.up.set(0, 0, 1);  // mink's shapes stand along z
const controls = new OrbitControls(camera, renderer.domElement);
scene.add(new THREE.AmbientLight(0xffffff, 1.6));
const light = new THREE.DirectionalLight(0xffffff, 2.2);
light.position.set(0.4, 0.6, 1);
camera.add(light);
scene.add(camera);

const state = { mode: 'all', index: 0 };
const drawnItems = items.filter((it) => it.group);

function visible(item) {
  return state.mode === 'all' || state.index === item.index;
}

function applyVisibility() {
  for (const item of items) {
    if (!item.group) continue;
    item.group.visible = visible(item);
    for (const child of item.group.children)
      if (child.userData.role === 'shape') child.visible = state.mode === 'one' || !child.userData.duplicate;
  }
  for (const li of document.querySelectorAll('#answers li'))
    li.classList.toggle('current', state.mode === 'one' && Number(li.dataset.index) === state.index);
  document.getElementById('mode').textContent = state.mode === 'all'
    ? `all ${drawnItems.length} queries`
    : `query ${state.index + 1} of ${items.length}`;
}

// Frames what is shown: the camera looks at the centre of the visible shapes from the front right,
// a little above, far enough for their bounding ball to fit the view.
function frame() {
  const box = new THREE.Box3();
  for (const item of items)
    if (item.group && visible(item))
      for (const b of item.balls) {
        box.expandByPoint(b.centre.clone().addScalar(b.radius));
        box.expandByPoint(b.centre.clone().addScalar(-b.radius));
      }
  if (box.isEmpty()) box.set(new THREE.Vector3(-1, -1, -1), new THREE.Vector3(1, 1, 1));
  const sphere = box.getBoundingSphere(new THREE.Sphere());
  const radius = Math.max(sphere.radius, 1e-6);
  const aspect = camera.aspect;
  const halfFov = THREE.MathUtils.degToRad(camera.fov / 2);
  const fit = Math.min(Math.tan(halfFov), Math.tan(halfFov) * aspect);
  const distance = 1.15 * radius / Math.sin(Math.atan(fit));
  const direction = new THREE.Vector3(1.0, -1.6, 0.9).normalize();
  camera.position.copy(sphere.center).addScaledVector(direction, distance);
  camera.near = distance / 100;
  camera.far = distance * 100;
  camera.updateProjectionMatrix();
  controls.target.copy(sphere.center);
  controls.update();
}

function resize() {
  const w = Math.max(1, view.clientWidth);
  const h = Math.max(1, view.clientHeight);
  renderer.setSize(w, h);
  camera.aspect = w / h;
  camera.updateProjectionMatrix();
}

function render() {
  renderer.render(scene, camera);
}

function show(mode, index) {
  state.mode = mode;
  if (index !== undefined) state.index = Math.min(Math.max(index, 0), items.length - 1);
  applyVisibility();
  frame();
  render();
  const hash = mode === 'all' ? '#all' : '#' + (state.index + 1);
  if (location.hash !== hash) history.replaceState(null, '', hash);
}

function fromHash() {
  const h = location.hash.slice(1);
  if (h === 'all') return show('all');
  const n = Number(h);
  if (Number.isInteger(n) && n >= 1 && n <= items.length) return show('one', n - 1);
  show(looksLikeScene() ? 'all' : 'one', 0);
}

// ----- the panel
const fmt = (x) => (typeof x === 'number' ? String(Number(x.toPrecision(6))) : String(x));
const fmtVec = (v) => (isVec3(v) ? '(' + v.map(fmt).join(', ') + ')' : '');

function describeShape(s) {
  if (!s || typeof s !== 'object') return '?';
  if (s.type === 'sum') return 'sum(' + (s.shapes || []).map(describeShape).join(' + ') + ')';
  if (s.type === 'rounded') return 'rounded(' + describeShape(s.shape) + ', ' + fmt(s.radius) + ')';
  return String(s.type);
}

function el(tag, cls, text) {
  const e = document.createElement(tag);
  if (cls) e.className = cls;
  if (text !== undefined) e.textContent = text;
  return e;
}

function fillPanel() {
  const list = document.getElementById('answers');
  for (const item of items) {
    const li = el('li', item.error ? 'error' : '');
    li.dataset.index = String(item.index);
    const a = item.answer || {};
    const title = el('div', 'title');
    title.append(el('span', 'number', String(item.index + 1)),
                 el('span', 'id', a.id !== undefined ? JSON.stringify(a.id) : '(line ' + item.raw.line + ')'));
    li.append(title);
    const q = item.query && typeof item.query === 'object' ? item.query : null;
    if (q) li.append(el('div', 'shapes', describeShape(q.a) + ' vs ' + describeShape(q.b) + ' · ' + (q.want || 'contact')));
    li.append(el('div', 'where', item.raw.file + ':' + item.raw.line));
    if (item.error) {
      li.append(el('div', 'message', 'error: ' + item.error));
    } else {
      const rows = [];
      for (const key of ['status', 'intersect', 'distance', 'depth', 'error_bound', 'iterations'])
        if (a[key] !== undefined) rows.push([key, fmt(a[key])]);
      for (const key of ['normal', 'point_a', 'point_b'])
        if (a[key] !== undefined) rows.push([key, fmtVec(a[key])]);
      if (a.normal_chosen) rows.push(['normal_chosen', 'true']);
      if (a.manifold) {
        rows.push(['manifold', (a.manifold.points || []).length + ' points, normal ' + fmtVec(a.manifold.normal)]);
        (a.manifold.points || []).forEach((p, k) =>
          rows.push(['  ' + (k + 1), fmtVec(p.position) + '  depth ' + fmt(p.depth)]));
      }
      if (item.approximate) rows.push(['drawn', 'approximately (hull of support points)']);
      const table = el('table');
      for (const [k, v] of rows) {
        const tr = el('tr');
        tr.append(el('th', '', k), el('td', '', v));
        table.append(tr);
      }
      li.append(table);
    }
    li.addEventListener('click', () => show('one', item.index));
    list.append(li);
  }
  const errors = items.filter((it) => it.error).length;
  document.getElementById('summary').textContent =
    `${items.length} queries from ${data.sources.join(', ') || 'stdin'}` + (errors ? `, ${errors} with errors` : '');
}

document.getElementById('all').addEventListener('click', () => show('all'));
document.getElementById('prev').addEventListener('click', () => show('one', state.mode === 'all' ? 0 : state.index - 1));
document.getElementById('next').addEventListener('click', () => show('one', state.mode === 'all' ? 0 : state.index + 1));
window.addEventListener('keydown', (e) => {
  if (e.key === 'ArrowRight' || e.key === 'j') show('one', state.mode === 'all' ? 0 : state.index + 1);
  else if (e.key === 'ArrowLeft' || e.key === 'k') show('one', state.mode === 'all' ? 0 : state.index - 1);
  else if (e.key === 'a') show('all');
});
window.addEventListener('hashchange', fromHash);
window.addEventListener('resize', () => {
  resize();
  render();
});
controls.addEventListener('change', render);

fillPanel();
resize();
fromHash();

// For tests and scripts (tests/viewer): set once the first picture is drawn. project() tells where
// a world point lands on the page, in CSS pixels; scale(i) is the length the markers and arrows of
// query i are sized by (a marker's radius is 0.025 of it, the normal's arrow 0.45).
window.minkView = {
  ready: true,
  items: items.length,
  errors: items.filter((it) => it.error).length,
  background: '#' + scene.background.getHexString(),
  mode: () => state.mode,
  current: () => state.index,
  scale: (i) => (items[i] && items[i].scale) || null,
  project(p) {
    const v = vec(p).project(camera);
    const rect = renderer.domElement.getBoundingClientRect();
    return [rect.left + (v.x + 1) / 2 * rect.width, rect.top + (1 - v.y) / 2 * rect.height];
  },
};
document.body.dataset.ready = 'true';
