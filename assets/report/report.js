// eyehand report: the page's own code. It draws with the vendored three.js (the 3-D view)
// and uPlot (the plots); the data the Rust side wrote sits in the #report-data element.
'use strict';

const text = (id) => document.getElementById(id).textContent;
const data = JSON.parse(text('report-data'));
const el = (tag, attrs = {}, children = []) => {
  const node = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) node.setAttribute(k, v);
  for (const c of [].concat(children)) node.append(c);
  return node;
};
const PALETTE = ['#1f77b4', '#ff7f0e', '#2ca02c', '#9467bd', '#8c564b', '#e377c2', '#17becf', '#bcbd22', '#7f7f7f', '#ff7f0e'];
const ARM_COLOUR = 0xe07020;

// Numbers as a reader wants them: four significant digits, scientific below 1e-4.
function fmt(v) {
  if (v == null || !isFinite(v)) return '—';
  const a = Math.abs(v);
  if (a !== 0 && (a < 1e-4 || a >= 1e7)) return v.toExponential(3);
  return Number(v.toPrecision(4)).toString();
}

// three.js ships as ES modules that import each other by file name: each embedded file
// becomes a blob URL and the names it imports are pointed at those URLs.
async function loadThree() {
  const url = (src) => URL.createObjectURL(new Blob([src], { type: 'text/javascript' }));
  const core = url(text('three-core'));
  const main = url(text('three-module').split("'./three.core.js'").join(JSON.stringify(core)));
  const orbit = url(text('three-orbit').split("from 'three'").join('from ' + JSON.stringify(main)));
  const THREE = await import(main);
  const { OrbitControls } = await import(orbit);
  return { THREE, OrbitControls };
}

function base64Array(text, Type) {
  const bytes = Uint8Array.from(atob(text), (c) => c.charCodeAt(0));
  return new Type(bytes.buffer);
}

function shapeGeometry(THREE, shape, meshes) {
  switch (shape.kind) {
    case 'mesh': {
      const m = meshes[shape.mesh];
      const g = new THREE.BufferGeometry();
      g.setAttribute('position', new THREE.BufferAttribute(base64Array(m.positions, Float32Array), 3));
      g.setIndex(new THREE.BufferAttribute(base64Array(m.indices, Uint32Array), 1));
      g.computeVertexNormals();
      return g;
    }
    case 'box': return new THREE.BoxGeometry(...shape.size);
    case 'cylinder': return new THREE.CylinderGeometry(shape.radius, shape.radius, shape.length, 32).rotateX(Math.PI / 2);
    case 'capsule': return new THREE.CapsuleGeometry(shape.radius, shape.length, 8, 24).rotateX(Math.PI / 2);
    default: return new THREE.SphereGeometry(shape.radius, 24, 16);
  }
}

function place(object, pose) {
  object.position.set(pose[0], pose[1], pose[2]);
  object.quaternion.set(pose[3], pose[4], pose[5], pose[6]);
}

// The camera's field of view as lines: its centre to the corners of the image plane 10 cm
// ahead (f = 256 px on a 512-px image: ±0.1 m at 0.1 m), and the image's outline there.
function frustum(THREE) {
  const d = 0.1, h = d * 256 / 256;
  const c = [[-h, -h, d], [h, -h, d], [h, h, d], [-h, h, d]];
  const pts = [];
  for (const p of c) pts.push(0, 0, 0, ...p);
  for (let i = 0; i < 4; i++) pts.push(...c[i], ...c[(i + 1) % 4]);
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.Float32BufferAttribute(pts, 3));
  return new THREE.LineSegments(g, new THREE.LineBasicMaterial({ color: 0x0090c0 }));
}

async function drawArm(section) {
  const arm = data.arm;
  const view = el('div', { id: 'view3d' });
  const image = el('img', { id: 'camera-image', alt: 'the camera image at this pose' });
  const trialSelect = el('select', { id: 'trial' });
  const slider = el('input', { id: 'pose', type: 'range', min: '0', max: '0', value: '0' });
  const label = el('div', { id: 'pose-label' });
  const poseTable = el('table', { id: 'pose-table' });
  for (const t of data.trials) trialSelect.append(el('option', { value: t.trial }, `trial ${t.trial}`));
  section.append(el('div', { class: 'row' }, [view, el('div', { class: 'side' }, [
    el('div', { class: 'controls' }, [trialSelect, slider]), label, image, poseTable])]));
  const { THREE, OrbitControls } = await loadThree();
  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(1);
  renderer.setSize(640, 480);
  view.append(renderer.domElement);
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xf2f2f2);
  scene.add(new THREE.AmbientLight(0xffffff, 1.6));
  const sun = new THREE.DirectionalLight(0xffffff, 1.8);
  sun.position.set(1, -2, 3);
  scene.add(sun);
  const grid = new THREE.GridHelper(2, 20, 0x999999, 0xcccccc);
  grid.rotateX(Math.PI / 2);
  scene.add(grid);
  const material = new THREE.MeshLambertMaterial({ color: ARM_COLOUR });
  const bodies = [];
  for (let b = 0; b < arm.bodies; b++) { const g = new THREE.Group(); bodies.push(g); scene.add(g); }
  for (const part of arm.parts) {
    const mesh = new THREE.Mesh(shapeGeometry(THREE, part.shape, arm.meshes), material);
    place(mesh, part.origin);
    mesh.name = part.link;
    bodies[part.body].add(mesh);
  }
  const target = new THREE.Mesh(new THREE.SphereGeometry(0.02, 24, 16), new THREE.MeshLambertMaterial({ color: 0xd01010 }));
  const goal = new THREE.Mesh(new THREE.TorusGeometry(0.015, 0.003, 8, 24), new THREE.MeshBasicMaterial({ color: 0xd01010 }));
  const camera3 = frustum(THREE);
  const path = new THREE.Line(new THREE.BufferGeometry(), new THREE.LineBasicMaterial({ color: 0x9020c0 }));
  scene.add(target, goal, camera3, path);
  const v = data.view;
  const camera = new THREE.PerspectiveCamera(v.fov, 640 / 480, 0.01, 50);
  camera.up.set(0, 0, 1);
  camera.position.set(...v.eye);
  const controls = new OrbitControls(camera, renderer.domElement);
  controls.target.set(...v.target);
  controls.update();
  const render = () => renderer.render(scene, camera);
  controls.addEventListener('change', render);

  const show = () => {
    const trial = data.trials[trialSelect.selectedIndex];
    if (!trial) { arm.rest.forEach((p, b) => place(bodies[b], p)); render(); return; }
    const k = Number(slider.value);
    const pose = trial.poses[k];
    pose.bodies.forEach((p, b) => place(bodies[b], p));
    place(camera3, pose.camera);
    target.visible = goal.visible = trial.object != null;
    if (trial.object) { target.position.set(...trial.object); goal.position.set(...trial.goal); }
    const centres = trial.poses.slice(0, k + 1).flatMap((p) => p.camera.slice(0, 3));
    path.geometry.setAttribute('position', new THREE.Float32BufferAttribute(centres, 3));
    image.src = pose.image;
    const step = k === 0 ? 'start' : `after step ${k}`;
    label.textContent = `trial ${trial.trial}, pose ${k} of ${trial.poses.length - 1} (${step})` +
      (trial.failure ? ` — failed: ${trial.failure}` : '');
    const rows = [
      ['joints (°)', pose.joints_deg.map((q) => q.toFixed(2)).join(', ')],
      ['reading c', pose.reading ? pose.reading.map(fmt).join(', ') : `not seen: ${pose.not_seen}`],
      ['distance to the goal (mm)', fmt(pose.distance_mm)],
      ['simulated time (s)', fmt(pose.sim_time_s)],
      ['events in effect', trial.events.join(', ') || 'none'],
    ];
    poseTable.replaceChildren(...rows.map(([k, v]) => el('tr', {}, [el('th', {}, k), el('td', {}, v)])));
    render();
    document.documentElement.dataset.pose = `${trial.trial}:${k}`;
  };
  const chooseTrial = () => {
    const trial = data.trials[trialSelect.selectedIndex];
    slider.max = String(trial ? trial.poses.length - 1 : 0);
    slider.value = '0';
    show();
  };
  trialSelect.addEventListener('change', chooseTrial);
  slider.addEventListener('input', show);
  chooseTrial();
  // `#trial=N&pose=K` picks a trial and moves the slider, as a reader would.
  const asked = new URLSearchParams(location.hash.slice(1));
  if (asked.has('trial')) {
    const i = data.trials.findIndex((t) => String(t.trial) === asked.get('trial'));
    if (i >= 0) { trialSelect.selectedIndex = i; chooseTrial(); }
  }
  if (asked.has('pose')) {
    slider.value = asked.get('pose');
    slider.dispatchEvent(new Event('input'));
  }
}

// Event lines, dashed, each labelled with the event, stacked so labels do not overlap.
function eventsPlugin(events) {
  return {
    hooks: {
      draw: [(u) => {
        const ctx = u.ctx;
        ctx.save();
        ctx.font = `${12 * devicePixelRatio}px sans-serif`;
        events.forEach((ev, i) => {
          const x = u.valToPos(ev.trial, 'x', true);
          if (x < u.bbox.left || x > u.bbox.left + u.bbox.width) return;
          ctx.strokeStyle = '#c00000';
          ctx.setLineDash([6, 4]);
          ctx.beginPath();
          ctx.moveTo(x, u.bbox.top);
          ctx.lineTo(x, u.bbox.top + u.bbox.height);
          ctx.stroke();
          ctx.fillStyle = '#c00000';
          ctx.fillText(ev.label, x + 4, u.bbox.top + 14 * devicePixelRatio * (i + 1));
        });
        ctx.restore();
      }],
    },
  };
}

function drawPanel(container, panel) {
  const box = el('div', { class: 'panel' });
  const log = el('input', { type: 'checkbox' });
  log.checked = panel.log;
  box.append(el('div', { class: 'panel-head' }, [el('b', {}, `${panel.title} (${panel.unit})`),
    el('label', {}, [log, ' log axis']), el('span', { class: 'hint' }, 'drag to zoom a trial range, double-click to reset')]));
  const plotDiv = el('div');
  box.append(plotDiv);
  container.append(box);
  let chart = null;
  const make = () => {
    if (chart) chart.destroy();
    const series = [{ label: 'trial', value: (u, v) => v == null ? '—' : String(v) }].concat(panel.series.map((s, i) => ({
      label: s.label,
      stroke: s.faint ? 'rgba(90,110,200,0.35)' : PALETTE[(i - (panel.series[0].faint ? 1 : 0)) % PALETTE.length],
      width: s.faint ? 1 : 2,
      spanGaps: true,
      points: { show: false },
      value: (u, v) => fmt(v),
    })));
    const opts = {
      width: 640, height: 280,
      scales: { x: { time: false }, y: { distr: log.checked ? 3 : 1 } },
      axes: [{ label: 'trial' }, { label: panel.unit, size: 70, values: (u, splits) => splits.map(fmt) }],
      series,
      cursor: { drag: { x: true, y: false } },
      plugins: [eventsPlugin(data.events)],
    };
    const columns = [panel.x].concat(panel.series.map((s) => s.values.map((v) => (log.checked && v != null && v <= 0) ? null : v)));
    chart = new uPlot(opts, columns, plotDiv);
  };
  log.addEventListener('change', make);
  make();
}

function keyValueTable(rows) {
  return el('table', { class: 'kv' }, rows.map(([k, v, note]) =>
    el('tr', {}, [el('th', {}, k), el('td', {}, v), el('td', { class: 'note' }, note || '')])));
}

function summaryRows(value, prefix = '') {
  if (value && typeof value === 'object' && !Array.isArray(value)) {
    return Object.entries(value).flatMap(([k, v]) => summaryRows(v, prefix ? `${prefix}.${k}` : k));
  }
  const shown = typeof value === 'number' ? fmt(value) : Array.isArray(value) ? JSON.stringify(value) : String(value);
  return [[prefix, shown]];
}

function infoRows(info) {
  return info.split('\n').filter((l) => l.trim() !== '').map((line) => {
    if (line.startsWith('#')) return [line.replace(/^#\s*/, ''), '', ''];
    const [body, ...note] = line.split('  # ');
    const space = body.indexOf(' ');
    return space < 0 ? [body, '', note.join('  # ')] : [body.slice(0, space), body.slice(space + 1), note.join('  # ')];
  });
}

async function main() {
  document.getElementById('title').textContent = data.title;
  const root = document.getElementById('report');
  if (data.arm) {
    const section = el('section', { id: 'arm' });
    root.append(section);
    try {
      await drawArm(section);
    } catch (e) {
      section.append(el('p', { class: 'error' }, `The 3-D view could not be drawn: ${e}`));
      document.documentElement.dataset.scene = `failed: ${e}`;
      throw e;
    }
  }
  const plots = el('section', { id: 'plots' }, el('h2', {}, 'Panels'));
  root.append(plots);
  for (const panel of data.panels) drawPanel(plots, panel);
  const tables = el('section', { id: 'tables' }, el('h2', {}, 'Tables'));
  root.append(tables);
  if (data.table) tables.append(el('h3', {}, 'table.md'), el('pre', {}, data.table));
  if (data.summary) tables.append(el('h3', {}, 'summary.json'), keyValueTable(summaryRows(data.summary)));
  if (data.info) tables.append(el('h3', {}, 'info'), keyValueTable(infoRows(data.info)));
  document.documentElement.dataset.scene = 'drawn';
  // Milliseconds from the page's start to everything drawn.
  document.documentElement.dataset.drawnMs = performance.now().toFixed(0);
}

main().catch((e) => {
  document.documentElement.dataset.scene = document.documentElement.dataset.scene || `failed: ${e}`;
  console.error(e);
});
