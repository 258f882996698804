// The kvd view page of a scene of moving segments: reads the
// kvd-segment-view/3 data that `kvd view` inlines (src/view/segment_page.hpp):
// the trees of the run as one table of distinct subtrees; for each interval
// of the run (before the first batch, then after each) its tree's root
// there, which the page draws, and the pixel positions it is drawn with (of
// the endpoints, only those that move: the others are given once); and the
// batches. Exact numbers stay strings.
(function () {
  'use strict';
  const data = JSON.parse(document.getElementById('kvd-data').textContent);
  const el = (id) => document.getElementById(id);
  const text = (tag, content, cls) => {
    const e = document.createElement(tag);
    e.textContent = content;
    if (cls) e.className = cls;
    return e;
  };
  const picture = el('picture');
  picture.setAttribute('viewBox', '0 0 ' + data.width + ' ' + data.height);
  picture.setAttribute('width', data.width);
  picture.setAttribute('height', data.height);

  el('title').textContent = data.title;
  el('summary').textContent = data.segments + ' segments, ' + data.batches.length + ' batches (' + data.failures +
      ' failures) from t = ' + data.start + ' to t ≈ ' + data.time_reached_approx + ', stopped: ' + data.stopped +
      '. Every tree shown equals a fresh build at its instant.';

  // Every endpoint's pixel position in each interval, [x0, y0, x1, y1, ...]:
  // the first interval's (data.endpoints), with the endpoints that move
  // (data.moving) at their places in the interval (v.moving_at).
  const endpoints = data.intervals.map((v) => {
    const e = data.endpoints.slice();
    data.moving.forEach((p, k) => [e[2 * p], e[2 * p + 1]] = [v.moving_at[2 * k], v.moving_at[2 * k + 1]]);
    return e;
  });

  // Subtree k of the table (data.subtrees: [cut, left, right], null for a
  // leaf) -> {label: 'V s3.0', kind: 'V', name: 's3.0', children: [L, R]};
  // a leaf -> null. A subtree the intervals share is one object.
  const subtrees = [];
  function subtree(k) {
    if (subtrees[k] !== undefined) return subtrees[k];
    const e = data.subtrees[k];
    let n = null;
    if (e) {
      const [kind, name] = e[0].split(' ');
      n = { label: e[0], kind, name, children: [subtree(e[1]), subtree(e[2])] };
    }
    return (subtrees[k] = n);
  }

  // The picture of interval v, as draw_segment_bsp draws it
  // (src/segments/segment_svg.cpp): the leaves' cells, the segments, the
  // cuts clipped to their cells (vertex, intersection, then edge cuts),
  // the endpoints, the marked segments, the crossings, the caption and the
  // legend. The data give the pixel positions of the endpoints and of the
  // crossings cut through; each cell's walls, floor and roof come from the
  // cuts above it, as the tree's child_cell makes them.
  const pad = 8, lineHeight = 18, legendHeight = 28, charWidth = 8.4;
  const [boxLeft, boxTop, boxWidth, boxHeight] = data.frame;
  const num = (v) => String(Math.round(v * 1000) / 1000 + 0);
  const escaped = (t) => t.replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;');
  const line = (cls, x1, y1, x2, y2, more) =>
    '<line class="' + cls + '"' + (more || '') + ' x1="' + num(x1) + '" y1="' + num(y1) + '" x2="' + num(x2) +
    '" y2="' + num(y2) + '"/>';
  function drawPicture(v, e, root) {
    const end = (i) => [e[2 * i], e[2 * i + 1]];
    const point = (name) => {
      const m = /^s(\d+)\.([01])$/.exec(name);
      return m ? end(2 * Number(m[1]) + Number(m[2])) : v.crossings[name];
    };
    // The pixel y of segment j's line at pixel x; a vertical one gives its
    // top as a floor and its bottom as a roof (pixel y grows downwards).
    const y = (j, x, floor) => {
      const [a, b] = [end(2 * j), end(2 * j + 1)];
      if (a[0] === b[0]) return floor ? Math.min(a[1], b[1]) : Math.max(a[1], b[1]);
      return a[1] + (b[1] - a[1]) * (x - a[0]) / (b[0] - a[0]);
    };
    const floorAt = (c, x) => c.floor !== null ? y(c.floor, x, true) : boxTop + boxHeight;
    const roofAt = (c, x) => c.roof !== null ? y(c.roof, x, false) : boxTop;
    const wall = (p, none) => p !== null ? point(p)[0] : none;
    const segment = (name) => Number(name.slice(1));
    // Preorder, each node with its cell.
    const nodes = [];
    const stack = [[root, { left: null, right: null, floor: null, roof: null }]];
    while (stack.length) {
      const [n, cell] = stack.pop();
      nodes.push([n, cell]);
      if (!n) continue;
      const [below, above] = [{ ...cell }, { ...cell }];
      if (n.kind === 'E') [below.roof, above.floor] = [segment(n.name), segment(n.name)];
      else [below.right, above.left] = [n.name, n.name];
      stack.push([n.children[1], above], [n.children[0], below]);
    }
    const out = ['<rect class="view-box" x="' + num(boxLeft) + '" y="' + num(boxTop) + '" width="' + num(boxWidth) +
                 '" height="' + num(boxHeight) + '"/>'];
    let leaves = 0;
    for (const [n, c] of nodes) {
      if (n) continue;
      const l = wall(c.left, boxLeft), r = wall(c.right, boxLeft + boxWidth);
      const corner = (x, yy) => num(x) + ',' + num(yy);
      out.push('<polygon class="cell c' + (leaves++ % 4) + '" points="' + corner(l, floorAt(c, l)) + ' ' +
               corner(r, floorAt(c, r)) + ' ' + corner(r, roofAt(c, r)) + ' ' + corner(l, roofAt(c, l)) + '"/>');
    }
    const segments = e.length / 4;
    for (let i = 0; i < segments; ++i) out.push(line('segment', ...end(2 * i), ...end(2 * i + 1)));
    const counts = { V: 0, I: 0, E: 0 };
    for (const kind of ['V', 'I', 'E'])
      for (const [n, c] of nodes) {
        if (!n || n.kind !== kind) continue;
        ++counts[kind];
        if (kind === 'E') {
          const j = segment(n.name), a = end(2 * j), b = end(2 * j + 1);
          if (a[0] === b[0]) {
            out.push(line('edge-cut', ...a, ...b));
            continue;
          }
          const l = point(c.left)[0], r = point(c.right)[0];
          out.push(line('edge-cut', l, y(j, l, false), r, y(j, r, false)));
          continue;
        }
        const x = point(n.name)[0];
        out.push(line(kind === 'V' ? 'vertex-cut' : 'intersection-cut', x, floorAt(c, x), x, roofAt(c, x)));
      }
    for (let i = 0; i < 2 * segments; ++i)
      out.push('<circle class="endpoint" cx="' + num(end(i)[0]) + '" cy="' + num(end(i)[1]) + '" r="2.5"/>');
    for (const i of v.marked) out.push(line('marked', ...end(2 * i), ...end(2 * i + 1), ' data-segment="' + i + '"'));
    for (const [x, yy] of Object.values(v.crossings))
      out.push('<path class="crossing" d="M' + num(x - 4) + ' ' + num(yy - 4) + 'L' + num(x + 4) + ' ' + num(yy + 4) +
               'M' + num(x - 4) + ' ' + num(yy + 4) + 'L' + num(x + 4) + ' ' + num(yy - 4) + '"/>');
    v.caption.forEach((t, k) => {
      if (t) out.push('<text x="' + num(pad) + '" y="' + num(pad + 14 + lineHeight * k) + '">' + escaped(t) + '</text>');
    });
    const legendY = boxTop + boxHeight + legendHeight / 2 + 4;
    let x = pad;
    for (const [kind, key] of [['vertex', 'V'], ['intersection', 'I'], ['edge', 'E']]) {
      const t = kind + ' cuts: ' + counts[key];
      out.push(line('legend ' + kind + '-cut', x, legendY - 5, x + 28, legendY - 5));
      out.push('<text x="' + num(x + 34) + '" y="' + num(legendY) + '">' + t + '</text>');
      x += 34 + charWidth * t.length + 24;
    }
    return out.join('\n');
  }

  // Whether a cut's features name one of the segments: "s3.0", "s1xs4", "s2".
  function names(label, segments) {
    const ids = (label.match(/s(\d+)/g) || []).map((m) => Number(m.slice(1)));
    return ids.some((i) => segments.has(i));
  }
  function treeElement(n, marked) {
    if (!n) return text('div', '· leaf', 'node');
    const d = document.createElement('details');
    d.open = true;
    const summary = text('summary', n.label, 'node');
    d.appendChild(summary);
    if (names(n.label, marked)) d.classList.add('feature');
    for (const c of n.children) d.appendChild(treeElement(c, marked));
    return d;
  }

  function markedSegments(batch) {
    const out = new Set();
    if (batch) for (const f of batch.failing) for (const s of f.segments) out.add(s);
    return out;
  }

  const items = [];
  let selected = -1;
  function select(i) {
    if (i < 0 || i >= data.intervals.length) return;
    if (selected >= 0) items[selected].classList.remove('selected');
    selected = i;
    items[i].classList.add('selected');
    const v = data.intervals[i];
    const root = subtree(v.root);
    picture.innerHTML = data.style + drawPicture(v, endpoints[i], root);
    const batch = i > 0 ? data.batches[i - 1] : null;
    const info = el('event-info');
    info.replaceChildren();
    if (batch) {
      info.appendChild(text('h3', 'Batch ' + i + ' of ' + data.batches.length));
      const p = document.createElement('p');
      p.append('t = ', text('span', batch.time, 'time-exact'), ' ≈ ' + batch.approx);
      info.appendChild(p);
      const kinds = Object.entries(batch.events).map(([k, n]) => n + ' ' + k).join(', ');
      info.appendChild(text('p', kinds + (batch.changed ? '; the tree changed' : '; the tree did not change') +
          ', ' + batch.nodes_rebuilt + ' nodes made again, ' + batch.certificates + ' certificates in force'));
      const ul = document.createElement('ul');
      ul.id = 'failing';
      for (const f of batch.failing) {
        const li = document.createElement('li');
        li.append(text('code', f.kind), ' ', text('code', f.features));
        ul.appendChild(li);
      }
      info.appendChild(ul);
    } else {
      info.appendChild(text('h3', 'Before the first batch'));
    }
    const drawn = document.createElement('p');
    drawn.append('Drawn at t = ', text('span', v.instant, 'time-exact'), ': ' + v.nodes + ' nodes, height ' + v.height + '.');
    info.appendChild(drawn);
    const tree = el('tree');
    tree.replaceChildren(treeElement(root, markedSegments(batch)));
    reveal(items[i], info);
  }

  // Scrolls the timeline to the item, clear of the event's box, which
  // sticks to the top of the same column.
  function reveal(item, info) {
    item.scrollIntoView({ block: 'nearest' });
    const hidden = info.getBoundingClientRect().bottom - item.getBoundingClientRect().top;
    if (hidden > 0) el('left').scrollBy(0, -hidden);
  }

  const timeline = el('timeline');
  data.intervals.forEach((v, i) => {
    const b = i > 0 ? data.batches[i - 1] : null;
    const li = text('li', b ? 't ≈ ' + b.approx + ': ' + Object.entries(b.events).map(([k, n]) => n + ' ' + k).join(', ')
                            : 'start, t = ' + data.start);
    if (b && !b.changed) li.classList.add('unchanged');
    li.dataset.interval = i;
    if (b) li.dataset.time = b.time;
    li.addEventListener('click', () => select(i));
    timeline.appendChild(li);
    items.push(li);
  });
  el('previous').addEventListener('click', () => select(selected - 1));
  el('next').addEventListener('click', () => select(selected + 1));
  document.addEventListener('keydown', (e) => {
    if (e.altKey || e.ctrlKey || e.metaKey || e.shiftKey) return;  // the browser's own shortcuts
    const step = { ArrowLeft: -1, ArrowRight: 1 }[e.key];
    if (!step) return;
    e.preventDefault();
    select(selected + step);
  });
  select(0);
})();
