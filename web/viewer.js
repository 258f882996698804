// The kvd view page: reads the kvd-view/1 data that `kvd view` inlines
// (src/view/page_data.hpp), draws the decomposition with three.js (global
// THREE, with THREE.OrbitControls), and lists the run's batches. Exact
// numbers stay strings; coordinates are for drawing only.
(function () {
  'use strict';
  const data = JSON.parse(document.getElementById('kvd-data').textContent);
  const palette = [0x8dd3c7, 0xffffb3, 0xbebada, 0xfb8072, 0x80b1d3, 0xfdb462, 0xb3de69, 0xfccde5, 0xd9d9d9,
                   0xbc80bd, 0xccebc5, 0xffed6f];
  const wallColour = { P: 0xd62728, E: 0x2ca02c, T: 0x1f4fd8 };
  const el = (id) => document.getElementById(id);
  const kindOf = (entry) => data.entries[entry][0][0];  // "P(3)" -> "P"
  const nodeLabel = (entry) => data.entries[entry][0] + ' ' + data.entries[entry][1];

  // Coordinates are integers on a grid; the view works in grid units.
  const points = (flat) => {
    const out = [];
    for (let i = 0; i + 2 < flat.length; i += 3) out.push(new THREE.Vector3(flat[i], flat[i + 1], flat[i + 2]));
    return out;
  };

  // --- three.js scene
  const holder = el('canvas-holder');
  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  renderer.setClearColor(0xffffff);
  holder.appendChild(renderer.domElement);
  const scene3 = new THREE.Scene();
  scene3.add(new THREE.AmbientLight(0xffffff, 0.75));
  const sun = new THREE.DirectionalLight(0xffffff, 0.35);
  sun.position.set(1, 2, 3);
  scene3.add(sun);
  const camera = new THREE.PerspectiveCamera(40, 1, 1, 1e7);
  camera.up.set(0, 0, 1);
  const controls = new THREE.OrbitControls(camera, renderer.domElement);
  const layers = { fragments: new THREE.Group(), P: new THREE.Group(), E: new THREE.Group(), T: new THREE.Group(),
                   highlight: new THREE.Group() };
  Object.values(layers).forEach((g) => scene3.add(g));

  function clear(group) {
    while (group.children.length) {
      const c = group.children.pop();
      if (c.geometry) c.geometry.dispose();
      if (c.material) c.material.dispose();
    }
  }
  // Shapes gathered into one mesh and one set of line segments per group,
  // coloured per vertex, so that a frame is a few draw calls rather than one
  // per node.
  class Gathered {
    constructor() { this.tri = []; this.triColour = []; this.line = []; this.lineColour = []; }
    polygon(ps, colour) {
      const c = new THREE.Color(colour);
      for (let i = 1; i + 1 < ps.length; ++i)
        for (const p of [ps[0], ps[i], ps[i + 1]]) { this.tri.push(p.x, p.y, p.z); this.triColour.push(c.r, c.g, c.b); }
    }
    outline(ps, colour, closed) {
      const c = new THREE.Color(colour);
      for (let i = 0; i + (closed ? 0 : 1) < ps.length; ++i) {
        const a = ps[i], b = ps[(i + 1) % ps.length];
        this.line.push(a.x, a.y, a.z, b.x, b.y, b.z);
        this.lineColour.push(c.r, c.g, c.b, c.r, c.g, c.b);
      }
    }
    addTo(group, opacity) {
      const geometry = (positions, colours) => {
        const g = new THREE.BufferGeometry();
        g.setAttribute('position', new THREE.Float32BufferAttribute(positions, 3));
        g.setAttribute('color', new THREE.Float32BufferAttribute(colours, 3));
        return g;
      };
      if (this.tri.length) {
        const g = geometry(this.tri, this.triColour);
        g.computeVertexNormals();
        group.add(new THREE.Mesh(g, new THREE.MeshLambertMaterial({ vertexColors: THREE.VertexColors, side: THREE.DoubleSide,
                                                                    transparent: opacity < 1, opacity: opacity,
                                                                    depthWrite: opacity >= 1 })));
      }
      if (this.line.length)
        group.add(new THREE.LineSegments(geometry(this.line, this.lineColour),
                                         new THREE.LineBasicMaterial({ vertexColors: THREE.VertexColors })));
    }
  }
  function lineLoop(ps, colour, closed) {
    const g = new THREE.Geometry();
    g.vertices = ps;
    const m = new THREE.LineBasicMaterial({ color: colour });
    return closed ? new THREE.LineLoop(g, m) : new THREE.Line(g, m);
  }
  function marker(p, colour, size) {
    const m = new THREE.Mesh(new THREE.SphereGeometry(size, 12, 8), new THREE.MeshBasicMaterial({ color: colour }));
    m.position.copy(p);
    return m;
  }

  // The scene's size on the grid, for markers and the default camera.
  const first = points(data.frames[0].vertices);
  const box = new THREE.Box3().setFromPoints(first.length ? first : [new THREE.Vector3()]);
  const centre = box.getCenter(new THREE.Vector3());
  const radius = Math.max(box.getSize(new THREE.Vector3()).length() / 2, 1);
  if (data.view) {
    const v = data.view.map((x, j) => (x - data.origin[j]) / data.unit);
    camera.position.set(v[0], v[1], v[2]);
  } else {
    camera.position.set(centre.x - 1.0 * radius, centre.y - 1.6 * radius, centre.z + 1.0 * radius);
  }
  controls.target.copy(centre);
  controls.update();

  // Drawn on demand (a move of the camera, a new frame, a layer toggled),
  // not in a loop: software WebGL would keep a core busy for nothing.
  let pending = false;
  function render() {
    if (pending) return;
    pending = true;
    requestAnimationFrame(() => { pending = false; renderer.render(scene3, camera); });
  }
  controls.addEventListener('change', render);
  function resize() {
    const w = holder.clientWidth || 400, h = holder.clientHeight || 400;
    renderer.setSize(w, h);
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
    render();
  }
  window.addEventListener('resize', resize);

  // --- state: the frame shown and the batch selected
  const state = { frame: 0, batch: null };

  // --- the cells: each cut clipped to its node's cell (the box and the
  // half-spaces of the ancestors, the negative side to the left), each
  // fragment to the same cell. A point within `slack` grid units of a plane
  // counts as on both sides: fragments lie on their ancestors' planes where
  // they share a vertex, and rounding must not drop them.
  const slack = 1e-3;
  const valueAt = (h, p) => h[4] * (h[0] * p.x + h[1] * p.y + h[2] * p.z + h[3]);
  function clipPolygon(poly, h) {
    const out = [];
    for (let i = 0; i < poly.length; ++i) {
      const a = poly[i], b = poly[(i + 1) % poly.length];
      const va = valueAt(h, a), vb = valueAt(h, b);
      if (va >= -slack) out.push(a);
      if ((va >= -slack) !== (vb >= -slack) && poly.length > 1) out.push(a.clone().lerp(b, (va + slack) / (va - vb)));
    }
    return out;
  }
  function clipSegment(seg, h) {
    const [a, b] = seg;
    const va = valueAt(h, a), vb = valueAt(h, b);
    if (va < -slack && vb < -slack) return [];
    if (va >= -slack && vb >= -slack) return seg;
    const m = a.clone().lerp(b, (va + slack) / (va - vb));
    return va >= -slack ? [a, m] : [m, b];
  }
  // The polygon where a plane meets the box, in order around it.
  function planeInBox(p, lo, hi) {
    const n = new THREE.Vector3(p[0], p[1], p[2]);
    const ps = [];
    for (let axis = 0; axis < 3; ++axis) {
      for (let k = 0; k < 4; ++k) {
        const u = (axis + 1) % 3, w = (axis + 2) % 3;
        const a = [0, 0, 0], b = [0, 0, 0];
        a[axis] = lo[axis]; b[axis] = hi[axis];
        a[u] = b[u] = (k & 1) ? hi[u] : lo[u];
        a[w] = b[w] = (k & 2) ? hi[w] : lo[w];
        const va = p[0] * a[0] + p[1] * a[1] + p[2] * a[2] + p[3], vb = p[0] * b[0] + p[1] * b[1] + p[2] * b[2] + p[3];
        if ((va <= 0) !== (vb <= 0)) {
          const s = va / (va - vb);
          ps.push(new THREE.Vector3(a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1]), a[2] + s * (b[2] - a[2])));
        }
      }
    }
    if (ps.length < 3) return [];
    const c = ps.reduce((acc, q) => acc.add(q), new THREE.Vector3()).divideScalar(ps.length);
    const e1 = new THREE.Vector3().crossVectors(n, Math.abs(n.x) < Math.abs(n.y) ? new THREE.Vector3(1, 0, 0) : new THREE.Vector3(0, 1, 0));
    const e2 = new THREE.Vector3().crossVectors(n, e1);
    const angle = (q) => { const d = q.clone().sub(c); return Math.atan2(d.dot(e2), d.dot(e1)); };
    return ps.sort((q, r) => angle(q) - angle(r));
  }
  // Every node of the frame's tree with its wall and fragment, in pre-order.
  function shapes(frame) {
    const V = points(frame.vertices);
    const lo = frame.box.slice(0, 3), hi = frame.box.slice(3, 6);
    const out = [];
    const path = [];
    const visit = (entry) => {
      if (entry < 0) return;
      const [cut, , left, right] = data.entries[entry];
      const kind = cut[0], id = Number(cut.slice(2, -1));
      const p = frame.planes[kind][id];
      let wall = p ? planeInBox(p, lo, hi) : [];
      let fragment;
      if (kind === 'T') fragment = data.triangles[id].map((v) => V[v]);
      else if (kind === 'E') fragment = data.edges[id].map((v) => V[v]);
      else fragment = [V[id]];
      for (const h of path) {
        if (wall.length) wall = clipPolygon(wall, h);
        if (kind === 'T') fragment = clipPolygon(fragment, h);
        else if (kind === 'E' && fragment.length) fragment = clipSegment(fragment, h);
      }
      out.push({ entry: entry, kind: kind, id: id, wall: wall.length >= 3 ? wall : [], fragment: fragment });
      if (p) path.push([p[0], p[1], p[2], p[3], -1]);
      visit(left);
      if (p) path[path.length - 1][4] = 1;
      visit(right);
      if (p) path.pop();
    };
    visit(frame.root);
    return out;
  }

  function drawFrame(f, batch) {
    Object.values(layers).forEach(clear);
    const frame = data.frames[f];
    const changed = new Set(frame.changed);
    state.shapes = shapes(frame);
    const fragments = new Gathered();
    const walls = { P: [new Gathered(), new Gathered()], E: [new Gathered(), new Gathered()], T: [new Gathered(), new Gathered()] };
    state.shapes.forEach((s) => {
      const hot = changed.has(s.entry);
      if (s.wall.length) walls[s.kind][hot ? 1 : 0].polygon(s.wall, wallColour[s.kind]);
      if (s.kind === 'T' && s.fragment.length >= 3) {
        fragments.polygon(s.fragment, palette[data.objects[s.id] % palette.length]);
        fragments.outline(s.fragment, hot ? 0xff8c00 : 0x555555, true);
      } else if (s.kind === 'E' && s.fragment.length === 2) {
        fragments.outline(s.fragment, hot ? 0xff8c00 : wallColour.E, false);
      }
    });
    fragments.addTo(layers.fragments, 1);
    ['P', 'E', 'T'].forEach((k) => { walls[k][0].addTo(layers[k], 0.12); walls[k][1].addTo(layers[k], 0.35); });
    if (batch !== null) {
      const r = radius / 60;
      data.batches[batch].failing.forEach((c) => {
        c.points.forEach((p) => layers.highlight.add(marker(points(p)[0], 0xd62728, r)));
        c.segments.forEach((s) => layers.highlight.add(lineLoop(points(s), 0xd62728, false)));
        c.triangles.forEach((t) => layers.highlight.add(lineLoop(points(t), 0xd62728, true)));
      });
    }
    applyLayers();
  }
  function applyLayers() {
    layers.fragments.visible = el('show-fragments').checked;
    ['P', 'E', 'T'].forEach((k) => { layers[k].visible = el('show-' + k).checked; });
    render();
  }
  ['fragments', 'P', 'E', 'T'].forEach((k) => el('show-' + k).addEventListener('change', applyLayers));

  // --- the tree as a collapsible outline
  function treeOutline(f, featurePlanes) {
    const frame = data.frames[f];
    const changed = new Set(frame.changed);
    const holderTree = el('tree');
    holderTree.textContent = '';
    if (frame.root < 0) { holderTree.textContent = '(empty)'; return; }
    const build = (entry, side, depth) => {
      const [cut, fragment, left, right] = data.entries[entry];
      const text = (side ? side + ' ' : '') + cut + ' ' + fragment;
      const classes = [];
      if (changed.has(entry)) classes.push('changed');
      if (featurePlanes.has(cut)) classes.push('feature');
      if (left < 0 && right < 0) {
        const d = document.createElement('div');
        d.className = 'node ' + classes.join(' ');
        d.textContent = text;
        d.dataset.entry = entry;
        return d;
      }
      const det = document.createElement('details');
      det.className = classes.join(' ');
      det.dataset.entry = entry;
      const sum = document.createElement('summary');
      sum.className = 'node';
      sum.textContent = text;
      det.appendChild(sum);
      let open = depth < 2;
      if (left >= 0) { const c = build(left, '-', depth + 1); det.appendChild(c); open = open || c.dataset.hot === '1'; }
      if (right >= 0) { const c = build(right, '+', depth + 1); det.appendChild(c); open = open || c.dataset.hot === '1'; }
      det.open = open;
      if (classes.length || open && depth >= 2) det.dataset.hot = '1';
      return det;
    };
    holderTree.appendChild(build(frame.root, '', 0));
  }

  // --- the timeline: the start, every batch, every motion change
  const items = [];
  function show(f, batch) {
    state.frame = f;
    state.batch = batch;
    items.forEach((li) => li.classList.toggle('selected', Number(li.dataset.frame) === f &&
                                                (li.dataset.batch === undefined ? batch === null : Number(li.dataset.batch) === batch)));
    const info = el('event-info');
    info.textContent = '';
    const frame = data.frames[f];
    const add = (tag, text, cls) => { const e = document.createElement(tag); e.textContent = text; if (cls) e.className = cls; info.appendChild(e); return e; };
    const planes = new Set();
    if (batch === null) {
      add('div', 'The start: the tree just after t = ' + data.start + '.');
    } else {
      const b = data.batches[batch];
      add('div', 'Batch ' + (batch + 1) + ' of ' + data.batches.length, 'batch-title');
      add('div', 't = ' + b.time, 'time-exact');
      add('div', '≈ ' + b.approx.toPrecision(12), 'time-approx');
      const ul = add('ul', '', 'failing');
      b.failing.forEach((c) => {
        const li = document.createElement('li');
        li.textContent = c.type + ' ' + c.features;
        ul.appendChild(li);
        c.planes.forEach((p) => planes.add(p));
      });
      add('div', (b.tree_changed ? frame.changed.length + ' tree entries changed' : 'the tree did not change') +
                 '; shown at t = ' + frame.sample + '.', 'changed-count');
    }
    drawFrame(f, batch);
    treeOutline(f, planes);
  }
  function addItem(text, frame, batch, cls, time) {
    const li = document.createElement('li');
    if (time !== undefined) li.dataset.time = time;
    li.textContent = text;
    li.dataset.frame = frame;
    if (batch !== null) li.dataset.batch = batch;
    if (cls) li.className = cls;
    li.addEventListener('click', () => show(frame, batch));
    el('timeline').appendChild(li);
    items.push(li);
    return li;
  }
  addItem('start, t = ' + data.start, 0, null, 'start');
  let change = 0;
  data.batches.forEach((b, k) => {
    for (; change < data.motion_changes.length && data.motion_changes[change].batches_before <= k; ++change) {
      const c = data.motion_changes[change];
      addItem('motion change at t ≈ ' + c.approx.toPrecision(8) + ': objects ' + c.objects.join(', ') + ' reversed',
              b.frame - 1, null, 'change');
    }
    addItem('t ≈ ' + b.approx.toPrecision(8) + ': ' + b.failing.map((c) => c.type + ' ' + c.features).join('; '),
            b.frame, k, 'batch', b.time);
  });
  el('title').textContent = data.title;
  document.title = 'kvd view: ' + data.title;
  el('summary').textContent = data.batches.length + ' batches, ' + data.events + ' events, ' +
                              data.motion_changes.length + ' motion changes; structure hash ' +
                              data.structure_hash.slice(0, 16) + '…';

  // --- a kvd diff report: the exact and the inexact events side by side
  if (data.diff) {
    const d = data.diff;
    el('diff').hidden = false;
    el('diff-kernel').textContent = d.kernel;
    el('diff-summary').textContent = d.missed_events + ' missed, ' + d.spurious_events + ' spurious, ' +
      d.order_mismatches + ' out of order, ' + d.structure_mismatches + ' followed by another tree; first divergence: ' +
      (d.first_divergence_event === null ? 'none' : 'event ' + d.first_divergence_event) +
      (d.inexact_stopped === 'stuck' ? '; the ' + d.kernel + ' run got stuck and missed every event after that' : '');
    // Exact event i lies in the batch holding the i-th failure.
    const batchOf = [];
    data.batches.forEach((b, k) => b.failing.forEach(() => batchOf.push(k)));
    const body = el('diff-table').querySelector('tbody');
    d.events.forEach((e) => {
      const tr = document.createElement('tr');
      const status = e.inexact_event === null ? 'missed' : [e.in_order ? '' : 'out of order', e.structure_equal ? '' : 'other tree'].filter((x) => x).join(', ') || 'matched';
      [e.event, e.certificate + ' ' + e.nodes, e.exact_approx, e.inexact_time === null ? '—' : e.inexact_time, status]
        .forEach((v) => { const td = document.createElement('td'); td.textContent = v; tr.appendChild(td); });
      if (e.inexact_event === null) tr.classList.add('missed');
      if (e.event === d.first_divergence_event) {
        tr.classList.add('divergence');
        const k = batchOf[e.event];
        if (k !== undefined) items.filter((li) => Number(li.dataset.batch) === k).forEach((li) => li.classList.add('divergence'));
      }
      tr.addEventListener('click', () => { const k = batchOf[e.event]; if (k !== undefined) show(data.batches[k].frame, k); });
      body.appendChild(tr);
    });
    d.spurious.forEach((s) => {
      const li = document.createElement('li');
      li.textContent = s.certificate + ' ' + s.nodes + ' at ' + s.inexact_time;
      el('diff-spurious').appendChild(li);
    });
  }

  resize();
  show(0, null);
  // For scripts and tests: select the k-th batch (from 0) as a click would.
  window.kvdViewer = { data: data, state: state, selectBatch: (k) => show(data.batches[k].frame, k) };
})();
