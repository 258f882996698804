// The kvd view page of a scene of moving segments: reads the
// kvd-segment-view/1 data that `kvd view` inlines (src/view/segment_page.hpp):
// one picture and one tree for each interval of the run (before the first
// batch, then after each), and the batches. Exact numbers stay strings.
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

  // "(V s3.0 L R)" -> {label: 'V s3.0', children: [L, R]}; "." -> null.
  function parseTree(s) {
    const tokens = s.match(/\(|\)|[^\s()]+/g) || [];
    let at = 0;
    function node() {
      const t = tokens[at++];
      if (t === '.') return null;
      if (t !== '(') throw new Error('unexpected ' + t + ' in the tree');
      const label = tokens[at++] + ' ' + tokens[at++];
      const children = [node(), node()];
      if (tokens[at++] !== ')') throw new Error('unbalanced tree');
      return { label, children };
    }
    return node();
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
    picture.innerHTML = data.style + v.picture;
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
    tree.replaceChildren(treeElement(parseTree(v.tree), markedSegments(batch)));
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
