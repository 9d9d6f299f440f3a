/* mrpt_topoeval HTML report (doc/report.md): draws the page from the JSON in #report-data.
 * Plain JavaScript written for this page, no library. Every string of the data is shown with
 * text nodes (textContent), never parsed as HTML. */
(function () {
  'use strict';
  const data = JSON.parse(document.getElementById('report-data').textContent);
  const app = document.getElementById('app');
  const SVGNS = 'http://www.w3.org/2000/svg';
  const C = data.colours;
  const STAGES = ['isomorphism', 'neighbour growing', 'placed by walls'];
  // Pairs of a map placed by its walls (stage 2).
  const byWalls = m => m.pairs.filter(p => p[2] === 2).length;

  // ---- small helpers

  /** An HTML element; string children become text nodes. */
  function el(tag, attrs, ...children) {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attrs || {})) {
      if (k === 'text') e.textContent = v;
      else if (k.startsWith('on')) e.addEventListener(k.slice(2), v);
      else e.setAttribute(k, v);
    }
    for (const c of children) {
      if (c === null || c === undefined) continue;
      e.appendChild(typeof c === 'string' ? document.createTextNode(c) : c);
    }
    return e;
  }
  function sv(tag, attrs) {
    const e = document.createElementNS(SVGNS, tag);
    for (const [k, v] of Object.entries(attrs || {})) e.setAttribute(k, v);
    return e;
  }
  function num(v, d) {
    return v === null || v === undefined || !isFinite(v) ? '\u2013' : Number(v).toFixed(d);
  }
  function groupColour(g) {
    return g < 0 ? C.no_group : C.groups[g % C.groups.length];
  }
  function degreeColour(v) {
    if (v.spurious) return C.spurious;
    return [C.no_group, C.degree1, C.degree2, C.degree3][v.degree] || C.degree4;
  }
  function card(title, ...children) {
    return el('section', {class: 'card'}, title ? el('h2', {text: title}) : null, ...children);
  }

  // ---- tooltip

  const tip = el('div', {id: 'tooltip', class: 'tooltip', role: 'tooltip'});
  tip.hidden = true;
  document.body.appendChild(tip);
  function showTip(evt, lines) {
    tip.textContent = '';
    for (const l of lines) tip.appendChild(el('div', {text: l}));
    tip.hidden = false;
    const x = Math.min(evt.clientX + 14, window.innerWidth - tip.offsetWidth - 6);
    const y = Math.min(evt.clientY + 14, window.innerHeight - tip.offsetHeight - 6);
    tip.style.left = Math.max(0, x) + 'px';
    tip.style.top = Math.max(0, y) + 'px';
  }
  function hideTip() { tip.hidden = true; }

  // ---- data unpacking

  function unpackMap(m) {
    if (m.vertices_unpacked) return m;
    m.vertices_unpacked = m.vertices.map(a => ({
      id: a[0], x: a[1], y: a[2], degree: a[3], clearance: a[4], spurious: a[5] === 1,
      active: a[6] === 1, min_angle: a[7], max_angle: a[8]}));
    m.edges_unpacked = m.edges.map(a => ({
      from: a[0], to: a[1], cls: a[2], length: a[3], clearance: a[4], d: a[5]}));
    return m;
  }
  function unpackPairs(entry) {
    if (entry.pairs_unpacked) return entry.pairs_unpacked;
    entry.pairs_unpacked = entry.match.pairs.map(a => ({
      gt: a[0], map: a[1], stage: a[2], similarity: a[3], iso: a[4], group: a[5],
      err_rel: a[6], err_group: a[7]}));
    return entry.pairs_unpacked;
  }

  // ---- the summary card

  function scoreBox(label, value, detail) {
    return el('div', {class: 'score'}, el('div', {class: 'label', text: label}),
              el('div', {class: 'value', text: value}),
              detail ? el('div', {class: 'detail', text: detail}) : null);
  }

  function summaryCard(entry, title) {
    const m = entry.match;
    const matched = m.pairs.length;
    const rel = entry.relative_accuracy, glob = entry.global_accuracy, b = entry.brokenness;
    const ew = entry.explained_walls;
    const boxes = el('div', {class: 'scores'},
      scoreBox('coverage', num(entry.coverage, 3),
               matched + ' of ' + entry.gt_vertices + ' ground-truth vertices matched (' +
               m.isomorphism + ' isomorphism, ' + m.neighbour_growing + ' neighbour growing' +
               (byWalls(m) ? ', ' + byWalls(m) + ' placed by walls' : '') + ')'),
      ew && ew.measured ?
        scoreBox('explained walls', num(ew.share, 3),
                 ew.explained + ' of ' + ew.wall_points + ' map wall points within ' +
                 num(ew.tolerance_m, 2) + ' m of a ground-truth wall under a part\u2019s fit') :
        null,
      scoreBox('relative accuracy', num(rel.score, 3),
               num(rel.rmse_m, 3) + ' m rmse after alignment (yaw ' +
               num(entry.transform.yaw_deg, 1) + '\u00b0)'),
      scoreBox('global accuracy', num(glob.score, 3),
               num(glob.rmse_m, 3) + ' m rmse in the ground truth\u2019s frame'),
      scoreBox('consistency', num(entry.consistency_score, 3),
               entry.consistency.map(c => c.name + ' ' + (c.pairs ? num(c.score, 2) : '\u2013'))
                 .join(', ')),
      scoreBox('brokenness', String(b.degree),
               b.groups.length + (b.groups.length === 1 ? ' group' : ' groups') +
               ', score ' + num(b.score, 3)));
    const cons = el('table', {id: 'consistency-table'},
      el('tr', {}, el('th', {class: 'text', text: 'consistency class'}),
         el('th', {text: 'graph distance [m]'}), el('th', {text: 'pairs'}),
         el('th', {text: 'mean error [m]'}), el('th', {text: 'score'})));
    for (const c of entry.consistency)
      cons.appendChild(el('tr', {}, el('td', {class: 'text', text: c.name}),
        el('td', {text: num(c.min_m, 1) + ' \u2013 ' + (c.max_m === null ? '\u221e' :
                                                         num(c.max_m, 1))}),
        el('td', {text: String(c.pairs)}), el('td', {text: num(c.mean_error_m, 3)}),
        el('td', {text: c.pairs ? num(c.score, 3) : '\u2013'})));
    const groups = el('table', {id: 'groups-table'},
      el('tr', {}, el('th', {class: 'text', text: 'brokenness group'}),
         el('th', {text: 'vertices'}), el('th', {text: 'rotation [\u00b0]'}),
         el('th', {text: 'shift x, y [m]'}), el('th', {text: 'mean sq. error [m\u00b2]'}),
         el('th', {text: 'off by [m]'})));
    b.groups.forEach((g, i) => groups.appendChild(el('tr', {},
      el('td', {class: 'text'}, el('span', {class: 'swatch', style: 'background:' +
                                            groupColour(i)}),
         'group ' + i + (g.by_walls ? ' (placed by its walls)' : '')),
      el('td', {text: String(g.vertices.length)}), el('td', {text: num(g.transform.yaw_deg, 2)}),
      el('td', {text: num(g.transform.x, 2) + ', ' + num(g.transform.y, 2)}),
      el('td', {text: num(g.squared_error_m2, 4)}),
      el('td', {text: i ? num(g.offset_m, 2) : '\u2013'}))));
    return card(title || 'Summary',
      el('div', {class: 'row'},
         el('div', {}, el('div', {class: 'muted', text: 'quality'}),
            el('div', {class: 'big', id: 'quality', text: num(entry.quality, 3)}),
            el('div', {class: 'muted', text: entry.map_vertices + ' matchable map vertices'}),
            entry.map_scale && entry.map_scale !== 1 ?
              el('div', {class: 'muted', id: 'map-scale',
                         text: 'map read at x ' + num(entry.map_scale, 4) + ' (the scale pass)'}) :
              null),
         el('div', {style: 'flex:1;min-width:300px'}, boxes)),
      el('div', {class: 'row', style: 'margin-top:10px'}, cons, groups));
  }

  // ---- the match viewer: both maps, their graphs and the match lines in one SVG

  function matchViewer(gt, entry, viewId) {
    gt = unpackMap(gt);
    const map = unpackMap(entry.map);
    const pairs = unpackPairs(entry);
    const H = Math.max(gt.size_y, map.size_y, 1);
    const sg = H / Math.max(gt.size_y, 1), sm = H / Math.max(map.size_y, 1);
    const gap = 0.06 * H, top = 0.06 * H;
    const ox = gt.size_x * sg + gap;
    const W = ox + map.size_x * sm;
    const full = {x: -0.02 * W, y: 0, w: W * 1.04, h: H + top + 0.02 * H};
    const svg = sv('svg', {class: 'match-view', id: viewId || 'match-view',
                           viewBox: [full.x, full.y, full.w, full.h].join(' '),
                           preserveAspectRatio: 'xMidYMid meet',
                           style: 'aspect-ratio:' + full.w.toFixed(0) + '/' + full.h.toFixed(0)});
    const root = sv('g', {transform: 'translate(0,' + top + ')'});
    svg.appendChild(root);
    let zoom = 1;
    const vertexEls = [];

    const gtOf = new Map(), mapOf = new Map();
    for (const p of pairs) { gtOf.set(p.gt, p); mapOf.set(p.map, p); }

    function panel(m, side, dx, s, title) {
      const g = sv('g', {transform: 'translate(' + dx + ',0) scale(' + s + ')',
                         'data-side': side});
      const t = sv('text', {class: 'panel-title', x: 0, y: -0.015 * H / s,
                            style: 'font-size:' + (0.03 * H / s) + 'px'});
      t.textContent = title + ': ' + m.name;
      g.appendChild(t);
      g.appendChild(sv('image', {href: m.image, x: 0, y: 0, width: m.size_x, height: m.size_y,
                                 preserveAspectRatio: 'none'}));
      const uw = entry.unexplained_walls;
      if (side === 'map' && uw && uw.cells.length) {
        // The map's walls that no matched part explains, a square per block of cells.
        let d = '';
        for (let i = 0; i + 1 < uw.cells.length; i += 2)
          d += 'M' + uw.cells[i] + ' ' + uw.cells[i + 1] + 'h' + uw.block + 'v' + uw.block +
               'h-' + uw.block + 'z';
        g.appendChild(sv('path', {class: 'unexplained', d: d, fill: C.unexplained}));
      }
      const edges = sv('g', {class: 'edges'});
      for (const e of m.edges_unpacked)
        edges.appendChild(sv('path', {d: e.d, fill: 'none', 'vector-effect': 'non-scaling-stroke',
          'stroke-width': 1.6, stroke: [C.edge, C.dead_end, C.spurious][e.cls]}));
      g.appendChild(edges);
      const verts = sv('g', {class: 'vertices'});
      for (const v of m.vertices_unpacked) {
        const p = side === 'gt' ? gtOf.get(v.id) : mapOf.get(v.id);
        const fill = p ? groupColour(p.group) : v.spurious ? C.spurious : C.unmatched;
        if (side === 'gt' && v.active && !p)
          verts.appendChild(sv('circle', {class: 'missing-ring', cx: v.x, cy: v.y, fill: 'none',
            stroke: C.missing, 'stroke-width': 2, 'vector-effect': 'non-scaling-stroke',
            'data-r': 1.8}));
        const c = sv('circle', {class: 'vertex', id: 'v-' + (viewId || 'match-view') + '-' +
                                side + '-' + v.id, cx: v.x, cy: v.y, fill: fill, stroke: '#000',
                                'stroke-width': 1, 'vector-effect': 'non-scaling-stroke',
                                'data-side': side, 'data-id': v.id, 'data-r': 1});
        c.addEventListener('mouseenter', evt => { highlight(p, true); showTip(evt,
          vertexLines(side, v, p)); });
        c.addEventListener('mousemove', evt => showTip(evt, vertexLines(side, v, p)));
        c.addEventListener('mouseleave', () => { highlight(p, false); hideTip(); });
        verts.appendChild(c);
      }
      g.appendChild(verts);
      vertexEls.push({group: verts, scale: s});
      return g;
    }

    function vertexLines(side, v, p) {
      const lines = [(side === 'gt' ? 'ground-truth' : 'map') + ' vertex ' + v.id,
        'degree ' + v.degree + (v.spurious ? ' (spurious)' : '') + ', clearance ' +
          num(v.clearance, 2) + ' m',
        'angles between corridors: ' + num(v.min_angle, 0) + '\u00b0 \u2013 ' +
          num(v.max_angle, 0) + '\u00b0'];
      if (p) {
        lines.push('matched to ' + (side === 'gt' ? 'map' : 'ground-truth') + ' vertex ' +
                   (side === 'gt' ? p.map : p.gt) + ' by ' + STAGES[p.stage] +
                   ', similarity ' + num(p.similarity, 3));
        lines.push(p.group >= 0 ? 'brokenness group ' + p.group + ', error ' +
                   num(p.err_group, 3) + ' m' : 'in no brokenness group');
        lines.push('error after the relative alignment ' + num(p.err_rel, 3) + ' m');
      } else if (side === 'gt' && v.active) lines.push('not matched (missing)');
      else lines.push(v.active ? 'not matched' : 'not matchable');
      return lines;
    }

    root.appendChild(panel(gt, 'gt', 0, sg, 'ground truth'));
    root.appendChild(panel(map, 'map', ox, sm, 'map'));
    const gtV = new Map(gt.vertices_unpacked.map(v => [v.id, v]));
    const mapV = new Map(map.vertices_unpacked.map(v => [v.id, v]));
    const lines = sv('g', {class: 'match-lines'});
    const lineOf = new Map();
    for (const stage of [0, 1, 2]) for (const p of pairs) {
      if (p.stage !== stage) continue;
      const a = gtV.get(p.gt), b = mapV.get(p.map);
      if (!a || !b) continue;
      const l = sv('line', {class: 'match-line', x1: a.x * sg, y1: a.y * sg, x2: ox + b.x * sm,
        y2: b.y * sm, stroke: [C.isomorphism, C.growing, C.walls][stage], 'stroke-width': 2,
        'stroke-opacity': 0.85, 'vector-effect': 'non-scaling-stroke', 'data-gt': p.gt,
        'data-map': p.map});
      const info = () => ['match: ground-truth vertex ' + p.gt + ' \u2194 map vertex ' + p.map,
        STAGES[p.stage] + (p.iso >= 0 ? (p.stage === 2 ? ' (part ' : ' (isomorphism ') + p.iso + ')' : ''),
        'similarity ' + num(p.similarity, 3),
        p.group >= 0 ? 'brokenness group ' + p.group + ', error ' + num(p.err_group, 3) + ' m'
                     : 'in no brokenness group',
        'error after the relative alignment ' + num(p.err_rel, 3) + ' m'];
      l.addEventListener('mouseenter', evt => { highlight(p, true); showTip(evt, info()); });
      l.addEventListener('mousemove', evt => showTip(evt, info()));
      l.addEventListener('mouseleave', () => { highlight(p, false); hideTip(); });
      lines.appendChild(l);
      lineOf.set(p, l);
    }
    root.appendChild(lines);

    function highlight(p, on) {
      if (!p) return;
      const id = viewId || 'match-view';
      for (const [side, vid] of [['gt', p.gt], ['map', p.map]]) {
        const e = document.getElementById('v-' + id + '-' + side + '-' + vid);
        if (e) e.classList.toggle('hl', on);
      }
      const l = lineOf.get(p);
      if (l) l.classList.toggle('hl', on);
    }

    // Vertex marks keep their size on screen while zooming.
    function sizeMarks() {
      const r0 = 0.0075 * H / zoom;
      for (const {group, scale} of vertexEls)
        for (const c of group.children)
          c.setAttribute('r', r0 * Number(c.getAttribute('data-r')) / scale);
    }

    // Zoom (wheel, buttons) and pan (drag) by changing the viewBox.
    let vb = Object.assign({}, full);
    function apply() {
      svg.setAttribute('viewBox', [vb.x, vb.y, vb.w, vb.h].join(' '));
      zoom = full.w / vb.w;
      sizeMarks();
    }
    function toUser(clientX, clientY) {
      const r = svg.getBoundingClientRect();
      const s = Math.max(vb.w / r.width, vb.h / r.height);
      const cx = vb.x + vb.w / 2 + (clientX - r.left - r.width / 2) * s;
      const cy = vb.y + vb.h / 2 + (clientY - r.top - r.height / 2) * s;
      return {x: cx, y: cy, s: s};
    }
    function zoomAt(f, x, y) {
      const w = Math.min(full.w * 1.5, Math.max(full.w / 200, vb.w / f));
      const k = w / vb.w;
      vb = {x: x - (x - vb.x) * k, y: y - (y - vb.y) * k, w: w, h: vb.h * k};
      apply();
    }
    svg.addEventListener('wheel', evt => {
      evt.preventDefault();
      const p = toUser(evt.clientX, evt.clientY);
      zoomAt(evt.deltaY < 0 ? 1.25 : 0.8, p.x, p.y);
    }, {passive: false});
    let drag = null;
    svg.addEventListener('pointerdown', evt => {
      if (evt.button !== 0) return;
      drag = {x: evt.clientX, y: evt.clientY, vb: Object.assign({}, vb)};
      svg.classList.add('dragging');
    });
    window.addEventListener('pointermove', evt => {
      if (!drag) return;
      const s = toUser(0, 0).s;
      vb.x = drag.vb.x - (evt.clientX - drag.x) * s;
      vb.y = drag.vb.y - (evt.clientY - drag.y) * s;
      apply();
    });
    window.addEventListener('pointerup', () => { drag = null; svg.classList.remove('dragging'); });
    svg.addEventListener('dblclick', () => { vb = Object.assign({}, full); apply(); });

    const centre = () => ({x: vb.x + vb.w / 2, y: vb.y + vb.h / 2});
    const toggle = (label, cls) => {
      const box = el('input', {type: 'checkbox', checked: ''});
      box.addEventListener('change', () => {
        for (const g of svg.querySelectorAll(cls)) g.style.display = box.checked ? '' : 'none';
      });
      return el('label', {}, box, ' ' + label);
    };
    const toolbar = el('div', {class: 'toolbar'},
      el('button', {type: 'button', id: 'zoom-in', onclick: () => {
        const c = centre(); zoomAt(1.5, c.x, c.y); }}, '+'),
      el('button', {type: 'button', id: 'zoom-out', onclick: () => {
        const c = centre(); zoomAt(1 / 1.5, c.x, c.y); }}, '\u2212'),
      el('button', {type: 'button', id: 'zoom-reset', onclick: () => {
        vb = Object.assign({}, full); apply(); }}, 'fit'),
      toggle('match lines', '.match-lines'), toggle('graphs', '.edges'),
      toggle('unexplained walls', '.unexplained'),
      el('span', {class: 'muted', text: 'wheel: zoom, drag: pan, double-click: fit; hover a ' +
                                       'vertex or a match line for its attributes'}));
    const legend = el('div', {class: 'legend'},
      el('span', {}, el('span', {class: 'bar', style: 'background:' + C.isomorphism}),
         'isomorphism: ' + entry.match.isomorphism),
      el('span', {}, el('span', {class: 'bar', style: 'background:' + C.growing}),
         'neighbour growing: ' + entry.match.neighbour_growing),
      ...(byWalls(entry.match) ? [el('span', {}, el('span', {class: 'bar', style: 'background:' +
                                    C.walls}), 'placed by walls: ' + byWalls(entry.match))] : []),
      el('span', {}, el('span', {class: 'swatch', style: 'background:none;border-color:' +
                                 C.missing}), 'missing: ' + entry.match.missing),
      ...entry.brokenness.groups.map((g, i) => el('span', {},
        el('span', {class: 'swatch', style: 'background:' + groupColour(i)}),
        'group ' + i + ': ' + g.vertices.length + ' vertices, yaw ' +
        num(g.transform.yaw_deg, 1) + '\u00b0' +
        (i ? ', off by ' + num(g.offset_m, 2) + ' m' : '') +
        (g.by_walls ? ', placed by its walls' : ''))),
      el('span', {}, el('span', {class: 'swatch', style: 'background:' + C.no_group}),
         'matched, in no group'),
      el('span', {}, el('span', {class: 'swatch', style: 'background:' + C.unmatched}),
         'not matched'),
      entry.explained_walls && entry.explained_walls.measured ?
        el('span', {}, el('span', {class: 'swatch', style: 'background:' + C.unexplained}),
           'map walls no part explains: ' +
           (entry.explained_walls.wall_points - entry.explained_walls.explained)) : null,
      el('span', {}, el('span', {class: 'bar', style: 'background:' + C.edge}), 'edge'),
      el('span', {}, el('span', {class: 'bar', style: 'background:' + C.dead_end}), 'dead end'),
      el('span', {}, el('span', {class: 'bar', style: 'background:' + C.spurious}), 'spurious'));
    sizeMarks();
    return el('div', {class: 'viewer'}, toolbar, svg, legend);
  }

  // ---- text sections

  function messagesCard(messages, title) {
    if (!messages || !messages.length) return null;
    return card(title || 'Messages', el('ul', {class: 'messages', id: 'messages'},
                                        ...messages.map(m => el('li', {text: m}))));
  }
  function iniCard() {
    const parts = [el('details', {}, el('summary', {text: 'Parameters in effect (INI)'}),
                      el('pre', {id: 'parameters', text: data.parameters_ini}))];
    if (data.extra_ini)
      parts.push(el('details', {}, el('summary', {text: 'SLAM configuration (INI)'}),
                    el('pre', {id: 'extra-ini', text: data.extra_ini})));
    return card('Configuration', ...parts);
  }
  function timingText(entry) {
    const t = Object.entries(entry.timing_ms || {});
    return t.length ? 'time [ms]: ' + t.map(([k, v]) => k + ' ' + num(v, 1)).join(', ') : '';
  }
  function compareView(entry, viewId) {
    return [summaryCard(entry),
            card('Maps and match', matchViewer(data.ground_truth, entry, viewId),
                 el('p', {class: 'muted', text: timingText(entry)})),
            messagesCard(entry.messages)];
  }

  // ---- pages

  function comparePage() {
    const entry = data.entries[0];
    for (const c of compareView(entry)) if (c) app.appendChild(c);
    const m = messagesCard(data.messages, 'Run');
    if (m) app.appendChild(m);
    app.appendChild(iniCard());
  }

  const RANK_COLUMNS = [
    {key: 'rank', label: 'rank', get: (e, i) => rankValue(i), fmt: (e, i) => data.ranks[i] || ''},
    {key: 'thumb', label: 'match', sortable: false},
    {key: 'name', label: 'map', text: true, get: e => e.name},
    {key: 'quality', label: 'quality', get: e => e.quality, d: 3},
    {key: 'coverage', label: 'coverage', get: e => e.coverage, d: 3},
    {key: 'walls', label: 'explained walls', get: e => explained(e), d: 3},
    {key: 'rel', label: 'rel. accuracy', get: e => e.relative_accuracy.score, d: 3},
    {key: 'rmse', label: 'rel. rmse [m]', get: e => e.relative_accuracy.rmse_m, d: 3, asc: true},
    {key: 'short', label: 'short', get: e => cls(e, 0), d: 2},
    {key: 'medium', label: 'medium', get: e => cls(e, 1), d: 2},
    {key: 'long', label: 'long', get: e => cls(e, 2), d: 2},
    {key: 'broken', label: 'brokenness', get: e => e.match.pairs.length ? e.brokenness.degree :
                                                   null, d: 0, asc: true},
    {key: 'glob', label: 'global accuracy', get: e => e.global_accuracy.score, d: 3},
    {key: 'vertices', label: 'map vertices', get: e => e.map_vertices, d: 0}];
  function cls(e, i) {
    const c = e.consistency[i];
    return c && c.pairs ? c.score : null;
  }
  function explained(e) {
    const w = e.explained_walls;
    return w && w.measured ? w.share : null;
  }
  function rankValue(i) {
    const r = data.ranks[i];
    return r ? parseInt(r, 10) : null;
  }

  function rankPage() {
    const entries = data.entries;
    const table = el('table', {id: 'rank-table'});
    const head = el('tr', {});
    const detail = el('div', {id: 'map-detail'});
    let sortKey = 'rank', sortAsc = true;
    const rows = entries.map((e, i) => {
      const tr = el('tr', {id: 'row-' + i, 'data-index': i});
      if (e.error) {
        tr.appendChild(el('td', {}));
        tr.appendChild(el('td', {}));
        tr.appendChild(el('td', {class: 'text', text: e.name}));
        tr.appendChild(el('td', {class: 'error', colspan: RANK_COLUMNS.length - 3,
                                 text: 'error: ' + e.error}));
        return tr;
      }
      for (const col of RANK_COLUMNS) {
        if (col.key === 'thumb') {
          tr.appendChild(el('td', {}, el('a', {href: '#map-' + i},
            el('img', {src: e.thumbnail, alt: 'match of ' + e.name, loading: 'lazy'}))));
        } else if (col.key === 'name') {
          tr.appendChild(el('td', {class: 'text'}, el('a', {href: '#map-' + i, text: e.name})));
        } else {
          const v = col.get(e, i);
          tr.appendChild(el('td', {text: col.fmt ? col.fmt(e, i) :
                                         v === null ? '\u2013' : num(v, col.d)}));
        }
      }
      return tr;
    });
    for (const col of RANK_COLUMNS) {
      const th = el('th', {class: col.text ? 'text' : '', 'data-key': col.key, text: col.label});
      if (col.sortable !== false) th.addEventListener('click', () => {
        sortAsc = sortKey === col.key ? !sortAsc : (col.key === 'rank' || col.text || col.asc);
        sortKey = col.key;
        sortRows();
      });
      head.appendChild(th);
    }
    table.appendChild(head);
    function sortRows() {
      const col = RANK_COLUMNS.find(c => c.key === sortKey);
      const idx = entries.map((e, i) => i);
      idx.sort((a, b) => {
        const ea = entries[a], eb = entries[b];
        if (ea.error || eb.error) return (ea.error ? 1 : 0) - (eb.error ? 1 : 0) || a - b;
        const va = col.get(ea, a), vb = col.get(eb, b);
        if (va === null || vb === null) return (va === null) - (vb === null) || a - b;
        const c = col.text ? String(va).localeCompare(String(vb)) : va - vb;
        return (sortAsc ? c : -c) || a - b;
      });
      for (const th of head.children) {
        th.classList.remove('sorted-asc', 'sorted-desc');
        if (th.getAttribute('data-key') === sortKey)
          th.classList.add(sortAsc ? 'sorted-asc' : 'sorted-desc');
      }
      for (const i of idx) table.appendChild(rows[i]);
    }
    sortRows();
    app.appendChild(card('Ranking (' + entries.length + ' maps; click a column to sort, a map ' +
                         'for its compare view)', el('div', {style: 'overflow-x:auto'}, table)));
    app.appendChild(detail);
    const m = messagesCard(data.messages, 'Run');
    if (m) app.appendChild(m);
    app.appendChild(iniCard());

    function show() {
      const match = /^#map-(\d+)$/.exec(location.hash);
      let i = match ? parseInt(match[1], 10) : -1;
      if (!(i >= 0 && i < entries.length) || entries[i].error) {
        i = entries.findIndex((e, k) => !e.error && data.ranks[k] === '1');
        if (i < 0) i = entries.findIndex(e => !e.error);
      }
      detail.textContent = '';
      for (const r of rows) r.classList.remove('selected');
      if (i < 0) return;
      rows[i].classList.add('selected');
      detail.setAttribute('data-index', i);
      detail.appendChild(el('h2', {id: 'map-' + i, text: 'Compare view: ' + entries[i].name}));
      for (const c of compareView(entries[i])) if (c) detail.appendChild(c);
    }
    window.addEventListener('hashchange', () => {
      show();
      detail.scrollIntoView();
    });
    show();
  }

  const SERIES = [
    {key: 'quality', label: 'quality', colour: '#111111', get: e => e.quality},
    {key: 'coverage', label: 'coverage', colour: '#1f77b4', get: e => e.coverage},
    {key: 'rel', label: 'relative accuracy', colour: '#2ca02c',
     get: e => e.relative_accuracy.score},
    {key: 'short', label: 'consistency short', colour: '#ff7f0e', get: e => cls(e, 0)},
    {key: 'medium', label: 'consistency medium', colour: '#9467bd', get: e => cls(e, 1)},
    {key: 'long', label: 'consistency long', colour: '#8c564b', get: e => cls(e, 2)},
    {key: 'walls', label: 'explained walls', colour: '#ff0000', get: e => explained(e)}];

  function seriesPage() {
    const entries = data.entries;
    const n = entries.length;
    // Time if every snapshot has one, else the entry (rawlog) or the number in the map's
    // name (series) if they increase, else the snapshot's step.
    const useTime = n > 0 && entries.every(e => e.time_s !== null && e.time_s !== undefined);
    const useEntry = !useTime && entries.every((e, i) => i === 0 || e.entry > entries[i - 1].entry);
    const xOf = e => useTime ? e.time_s : useEntry ? e.entry : e.step;
    const xLabel = useTime ? 'time [s]' : !useEntry ? 'snapshot' :
                   data.kind === 'rawlog' ? 'rawlog entry' : 'map number';
    const Wp = 900, Hp = 300, L = 44, R = 16, T = 12, B = 34;
    const xs = entries.map(xOf);
    let x0 = Math.min(...xs), x1 = Math.max(...xs);
    if (!(x1 > x0)) { x0 -= 1; x1 += 1; }
    const px = x => L + (x - x0) / (x1 - x0) * (Wp - L - R);
    const py = y => T + (1 - y) * (Hp - T - B);
    const plot = sv('svg', {class: 'plot', id: 'score-plot', viewBox: '0 0 ' + Wp + ' ' + Hp,
                            preserveAspectRatio: 'none'});
    for (let k = 0; k <= 5; ++k) {
      const y = py(k / 5);
      plot.appendChild(sv('line', {class: 'grid', x1: L, x2: Wp - R, y1: y, y2: y}));
      const t = sv('text', {x: L - 6, y: y + 4, 'text-anchor': 'end'});
      t.textContent = (k / 5).toFixed(1);
      plot.appendChild(t);
    }
    // Ticks at 1, 2 or 5 x 10^k, whole numbers unless the axis is time.
    const raw = (x1 - x0) / 6, mag = Math.pow(10, Math.floor(Math.log10(raw)));
    let tick = [1, 2, 5, 10].map(f => f * mag).find(t => t >= raw);
    if (!useTime) tick = Math.max(1, Math.round(tick));
    const decimals = Math.max(0, -Math.floor(Math.log10(tick)));
    for (let x = Math.ceil(x0 / tick) * tick; x <= x1 + 1e-9; x += tick) {
      const t = sv('text', {x: px(x), y: Hp - B + 16, 'text-anchor': 'middle'});
      t.textContent = x.toFixed(decimals);
      plot.appendChild(t);
    }
    const xl = sv('text', {x: (L + Wp - R) / 2, y: Hp - 4, 'text-anchor': 'middle'});
    xl.textContent = xLabel;
    plot.appendChild(xl);
    plot.appendChild(sv('line', {class: 'axis', x1: L, x2: L, y1: T, y2: Hp - B}));
    plot.appendChild(sv('line', {class: 'axis', x1: L, x2: Wp - R, y1: Hp - B, y2: Hp - B}));
    const shown = new Set(SERIES.map(s => s.key));
    const seriesEls = {};
    for (const s of SERIES) {
      const g = sv('g', {'data-series': s.key});
      let d = '';
      entries.forEach(e => {
        const v = s.get(e);
        if (v === null || v === undefined) return;
        d += (d ? ' L' : 'M') + px(xOf(e)).toFixed(1) + ' ' + py(v).toFixed(1);
      });
      g.appendChild(sv('path', {class: 'series', d: d, stroke: s.colour}));
      entries.forEach(e => {
        const v = s.get(e);
        if (v === null || v === undefined) return;
        g.appendChild(sv('circle', {cx: px(xOf(e)), cy: py(v), r: 3, fill: s.colour}));
      });
      plot.appendChild(g);
      seriesEls[s.key] = g;
    }
    const cursor = sv('line', {class: 'cursor', y1: T, y2: Hp - B});
    plot.appendChild(cursor);
    const nearest = evt => {
      const r = plot.getBoundingClientRect();
      const x = (evt.clientX - r.left) / r.width * Wp;
      let best = 0;
      entries.forEach((e, i) => {
        if (Math.abs(px(xOf(e)) - x) < Math.abs(px(xOf(entries[best])) - x)) best = i;
      });
      return best;
    };
    plot.addEventListener('mousemove', evt => {
      const i = nearest(evt), e = entries[i];
      showTip(evt, ['snapshot ' + e.step + ' (' + xLabel + ' ' + num(xOf(e), useTime ? 1 : 0) +
                    ')', ...SERIES.filter(s => shown.has(s.key)).map(
                      s => s.label + ' ' + num(s.get(e), 3)),
                    'brokenness ' + e.brokenness.degree + ', ' + e.map_vertices + ' vertices',
                    'click to show this snapshot']);
    });
    plot.addEventListener('mouseleave', hideTip);
    plot.addEventListener('click', evt => select(nearest(evt)));
    const legend = el('div', {class: 'legend'}, ...SERIES.map(s => {
      const box = el('input', {type: 'checkbox', checked: ''});
      box.addEventListener('change', () => {
        if (box.checked) shown.add(s.key); else shown.delete(s.key);
        seriesEls[s.key].style.display = box.checked ? '' : 'none';
      });
      return el('label', {}, box, el('span', {class: 'bar', style: 'background:' + s.colour}),
                s.label);
    }));
    app.appendChild(card('Scores over time (' + n + ' snapshots; hover for values, click for ' +
                         'the snapshot)', plot, legend));

    const slider = el('input', {type: 'range', id: 'snapshot-slider', min: 0,
                                max: Math.max(0, n - 1), step: 1, value: Math.max(0, n - 1)});
    const label = el('span', {id: 'snapshot-label'});
    const view = el('div', {id: 'snapshot-view', style: 'display:flex;flex-direction:column;' +
                                                        'gap:16px'});
    app.appendChild(card('Snapshots', el('div', {class: 'slider-row'},
                         el('span', {class: 'muted', text: 'snapshot'}), slider, label)));
    app.appendChild(view);
    function select(i) {
      if (!(i >= 0 && i < n)) return;
      slider.value = i;
      const e = entries[i];
      view.setAttribute('data-index', i);
      const last = i === n - 1;
      label.textContent = 'step ' + e.step + ' of ' + n + ', ' + xLabel + ' ' +
                          num(xOf(e), useTime ? 1 : 0) + (e.scans ? ', ' + e.scans + ' scans' :
                          '') + ' \u2013 ' + e.name + (last ? ' (final map)' : '');
      cursor.setAttribute('x1', px(xOf(e)));
      cursor.setAttribute('x2', px(xOf(e)));
      view.textContent = '';
      const title = (last ? 'Final map' : 'Snapshot ' + e.step) + ': ' + e.name;
      const parts = compareView(e, 'match-view');
      parts[0] = summaryCard(e, title);
      for (const c of parts) if (c) view.appendChild(c);
    }
    slider.addEventListener('input', () => select(parseInt(slider.value, 10)));
    if (n) select(n - 1);
    const m = messagesCard(data.messages, 'Run');
    if (m) app.appendChild(m);
    app.appendChild(iniCard());
  }

  if (!data.entries.length) {
    app.appendChild(card('Nothing to show', el('p', {text: 'This run scored no map.'})));
    app.appendChild(iniCard());
  } else if (data.kind === 'compare') comparePage();
  else if (data.kind === 'rank') rankPage();
  else seriesPage();
  document.body.setAttribute('data-ready', '1');
})();
