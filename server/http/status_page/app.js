// locatord status page: polls /api/stats (GetStatsResponse as proto JSON:
// 64-bit integers arrive as strings) and /api/history, draws the query heat
// map with hot regions, start points and an edge sample, and over the heat
// map the domain's boundary and holes and the breaklines of a constrained
// dataset; charts cost and throughput, and records what it rendered in data
// attributes for scripts and tests. With several datasets (/v1/datasets), a
// select switches the dataset shown (?dataset=NAME on every /api/ path; the
// page's own ?dataset= picks the first one shown).
//
// When locatord wants tokens, /api/stats, /api/edges and /v1/datasets want
// the data token: the page then shows "token required" and a token field,
// and sends what is typed there as "Authorization: Bearer <token>" (a link
// may carry it as #token=TOKEN: the fragment never reaches a server, and the
// page removes it from the address bar). The token lives in the page only.
'use strict';

const REFRESH_MS = 1500;
const HOT_CELLS_LISTED = 10;
const COLORS = {
  edge: 'rgba(160, 174, 196, 0.4)',
  boundary: '#f6ad55',
  breakline: '#b794f4',
  hot: '#4fd1c5',
  start: '#f6e05e',
  axis: '#8b97aa',
  cost: '#f687b3',
  qps: '#63b3ed',
};

let dataset = new URLSearchParams(location.search).get('dataset') || '';
let token = new URLSearchParams(location.hash.slice(1)).get('token') || '';
if (location.hash !== '') {
  history.replaceState(null, '', location.pathname + location.search);
}
// /api/edges: the edge sample, the domain's boundary and the breaklines.
const NO_EDGES = {segments: [], boundary: [], breaklines: []};
let mapEdges = NO_EDGES;
let edgesGeneration = null;  // dataset and generation mapEdges are of
let renderCount = 0;

function setText(id, text) {
  document.getElementById(id).textContent = text;
}

// Sets a figure's text and its raw value (data-value).
function setFigure(id, value, text) {
  const element = document.getElementById(id);
  element.dataset.value = value === null ? '' : String(value);
  element.textContent = text;
}

function formatCount(n) {
  return Number(n).toLocaleString('en-US');
}

function formatNumber(x, digits) {
  return x === null || x === undefined ? '–' : Number(x).toFixed(digits);
}

function formatBytes(bytes) {
  const units = ['B', 'KiB', 'MiB', 'GiB'];
  let value = Number(bytes);
  let unit = 0;
  while (value >= 1024 && unit < units.length - 1) {
    value /= 1024;
    unit++;
  }
  return (unit === 0 ? value : value.toFixed(1)) + ' ' + units[unit];
}

// A canvas sized to its CSS box at the device's pixel ratio; returns its
// context scaled to CSS pixels, plus the width and height in CSS pixels.
function prepareCanvas(id) {
  const canvas = document.getElementById(id);
  const ratio = window.devicePixelRatio || 1;
  const width = canvas.clientWidth || canvas.width;
  const height = canvas.clientHeight || canvas.height;
  canvas.width = Math.round(width * ratio);
  canvas.height = Math.round(height * ratio);
  const ctx = canvas.getContext('2d');
  ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
  ctx.clearRect(0, 0, width, height);
  return {ctx, width, height};
}

// Maps data coordinates into a width x height canvas, keeping the aspect
// ratio, y up, with a small margin.
function mapTransform(box, width, height) {
  const margin = 8;
  const boxWidth = Math.max(box.max_x - box.min_x, 1e-300);
  const boxHeight = Math.max(box.max_y - box.min_y, 1e-300);
  const scale = Math.min((width - 2 * margin) / boxWidth,
                         (height - 2 * margin) / boxHeight);
  const left = (width - scale * boxWidth) / 2;
  const top = (height - scale * boxHeight) / 2;
  return {
    x: (x) => left + (x - box.min_x) * scale,
    y: (y) => top + (box.max_y - y) * scale,
    scale,
  };
}

// Heat colour for a share in [0, 1]: dark red to bright yellow.
function heatColor(share) {
  const hue = 10 + 45 * share;
  const lightness = 25 + 40 * share;
  return `hsla(${hue}, 100%, ${lightness}%, ${0.35 + 0.6 * share})`;
}

// The histogram's cells with a positive count, hottest first.
function hotCells(tuning) {
  const cells = [];
  const n = tuning.grid_size;
  tuning.histogram.forEach((count, index) => {
    if (count > 0) cells.push({i: index % n, j: Math.floor(index / n), count});
  });
  cells.sort((a, b) => b.count - a.count);
  return cells;
}

// Strokes every [x0, y0, x1, y1] of `segments` through the transform t.
function strokeSegments(ctx, t, segments, color, lineWidth) {
  ctx.strokeStyle = color;
  ctx.lineWidth = lineWidth;
  ctx.beginPath();
  for (const [x0, y0, x1, y1] of segments) {
    ctx.moveTo(t.x(x0), t.y(y0));
    ctx.lineTo(t.x(x1), t.y(y1));
  }
  ctx.stroke();
}

function drawMap(stats) {
  const {ctx, width, height} = prepareCanvas('map');
  const tuning = stats.tuning;
  const t = mapTransform(stats.dataset.bounding_box, width, height);

  strokeSegments(ctx, t, mapEdges.segments, COLORS.edge, 0.8);

  const n = tuning.grid_size;
  const cells = hotCells(tuning);
  if (n > 0 && cells.length > 0) {
    const grid = tuning.grid_box;
    const cellWidth = (grid.max_x - grid.min_x) / n;
    const cellHeight = (grid.max_y - grid.min_y) / n;
    const logMax = Math.log1p(cells[0].count);
    for (const {i, j, count} of cells) {
      const x0 = t.x(grid.min_x + i * cellWidth);
      const y1 = t.y(grid.min_y + (j + 1) * cellHeight);
      ctx.fillStyle = heatColor(Math.log1p(count) / logMax);
      ctx.fillRect(x0, y1, cellWidth * t.scale, cellHeight * t.scale);
    }
  }

  // Over the heat map: breaklines, then the boundary on top of them.
  strokeSegments(ctx, t, mapEdges.breaklines, COLORS.breakline, 1.5);
  strokeSegments(ctx, t, mapEdges.boundary, COLORS.boundary, 2);
  const layers = document.getElementById('domain-layers');
  layers.dataset.boundary = String(mapEdges.boundary.length);
  layers.dataset.breaklines = String(mapEdges.breaklines.length);
  document.getElementById('domain-legend').hidden =
      mapEdges.boundary.length === 0 && mapEdges.breaklines.length === 0;

  ctx.strokeStyle = COLORS.hot;
  ctx.lineWidth = 2;
  for (const r of tuning.hot_regions) {
    ctx.strokeRect(t.x(r.min_x), t.y(r.max_y), (r.max_x - r.min_x) * t.scale,
                   (r.max_y - r.min_y) * t.scale);
  }

  ctx.fillStyle = COLORS.start;
  for (const {x, y} of tuning.start_points) {
    ctx.fillRect(t.x(x) - 1, t.y(y) - 1, 2, 2);
  }

  document.getElementById('hot-cells').dataset.cells =
      JSON.stringify(cells.slice(0, HOT_CELLS_LISTED));
}

// A line chart of values over times (null values leave gaps).
function drawChart(id, times, values, color) {
  const {ctx, width, height} = prepareCanvas(id);
  const left = 48, right = 8, top = 10, bottom = 22;
  const finite = values.filter((v) => v !== null);
  ctx.fillStyle = COLORS.axis;
  ctx.font = '11px system-ui, sans-serif';
  if (finite.length === 0) {
    ctx.fillText('no data yet', left, height / 2);
    return;
  }
  const max = Math.max(...finite) * 1.1 || 1;
  const t0 = times[0];
  const span = Math.max(times[times.length - 1] - t0, 1);
  const px = (t) => left + (t - t0) / span * (width - left - right);
  const py = (v) => height - bottom - v / max * (height - top - bottom);

  ctx.strokeStyle = COLORS.axis;
  ctx.lineWidth = 1;
  ctx.beginPath();
  ctx.moveTo(left, top);
  ctx.lineTo(left, height - bottom);
  ctx.lineTo(width - right, height - bottom);
  ctx.stroke();
  ctx.fillText(max >= 100 ? formatCount(Math.round(max)) : max.toPrecision(3),
               2, top + 8);
  ctx.fillText('0', 2, height - bottom);
  ctx.fillText(`-${Math.round(span)} s`, left, height - 6);
  ctx.fillText('now', width - right - 22, height - 6);

  ctx.strokeStyle = color;
  ctx.lineWidth = 2;
  ctx.beginPath();
  let drawing = false;
  values.forEach((v, k) => {
    if (v === null) {
      drawing = false;
      return;
    }
    if (drawing) {
      ctx.lineTo(px(times[k]), py(v));
    } else {
      ctx.moveTo(px(times[k]), py(v));
      drawing = true;
    }
  });
  ctx.stroke();
}

function renderFigures(stats, history) {
  const tuning = stats.tuning;
  const dataset = stats.dataset;
  const source = dataset.source || '(redacted)';
  setText('dataset', `${source}: ${formatCount(dataset.vertices)} ` +
                         `points, ${formatCount(dataset.triangles)} triangles`);
  setText('strategy', `strategy ${stats.strategy}`);
  const queries = Number(stats.queries_served);
  setFigure('queries', queries, formatCount(queries));
  const qps = history.qps.length > 0 ? history.qps[history.qps.length - 1]
                                     : null;
  setFigure('qps', qps, formatNumber(qps, 0));
  setFigure('mean-cost-recent', stats.mean_cost_recent,
            formatNumber(stats.mean_cost_recent, 2));
  setFigure('mean-cost-lifetime', stats.mean_cost_lifetime,
            formatNumber(stats.mean_cost_lifetime, 2));
  const count = (id, value) => setFigure(id, Number(value), formatCount(value));
  const bytes = (id, value) => setFigure(id, Number(value), formatBytes(value));
  setFigure('snapshot-version', Number(tuning.snapshot_version),
            String(tuning.snapshot_version));
  setFigure('retunes', Number(tuning.retune_count), String(tuning.retune_count));
  count('hot-queries', tuning.hot_queries);
  count('fallback-queries', tuning.fallback_queries);
  count('start-points', tuning.start_point_count);
  bytes('triangulation-bytes', stats.memory.triangulation_bytes);
  bytes('tuning-bytes', stats.memory.tuning_bytes);
}

function render(stats, history) {
  const state = document.getElementById('state');
  state.textContent = 'serving';
  state.className = 'state serving';
  renderFigures(stats, history);
  drawMap(stats);
  drawChart('cost-chart', history.t, history.mean_cost, COLORS.cost);
  drawChart('qps-chart', history.t, history.qps, COLORS.qps);
  renderCount++;
  document.body.dataset.renderedVersion = String(stats.tuning.snapshot_version);
  document.body.dataset.renderedQueries = String(stats.queries_served);
  document.body.dataset.renderCount = String(renderCount);
}

function showState(text, className) {
  const state = document.getElementById('state');
  state.textContent = text;
  state.className = 'state ' + className;
}

// An /api/ path for the dataset shown.
function api(path) {
  return dataset ? `${path}?dataset=${encodeURIComponent(dataset)}` : path;
}

async function fetchJson(path) {
  const headers = token === '' ? {} : {Authorization: `Bearer ${token}`};
  const response = await fetch(path, {cache: 'no-store', headers});
  const body = await response.json();
  return {status: response.status, body};
}

// Asks for the data token: the server answered 401 or 403.
function askForToken(status) {
  showState(status === 401 ? 'token required' : 'token not accepted',
            'locked');
  document.getElementById('token').hidden = false;
}

// Fetches the map's edges once per serving generation (they change only
// when a reload swaps the dataset).
async function ensureEdges(generation) {
  const key = `${dataset}/${generation}`;
  if (key === edgesGeneration) return;
  const edges = await fetchJson(api('/api/edges'));
  if (edges.status !== 200) return;
  mapEdges = edges.body;
  edgesGeneration = key;
}

// Fills the dataset select from /v1/datasets when the server holds more
// than one (it stays hidden otherwise, and when the API wants a token).
async function loadDatasets() {
  try {
    const list = await fetchJson('/v1/datasets');
    const datasets = list.status === 200 ? list.body.datasets || [] : [];
    const select = document.getElementById('dataset-select');
    if (datasets.length < 2 || select.options.length > 0) return;
    for (const entry of datasets) {
      const option = document.createElement('option');
      option.value = entry.name;
      option.textContent = entry.is_default ? `${entry.name} (default)` :
                                              entry.name;
      option.selected = entry.name === dataset ||
                        (dataset === '' && entry.is_default);
      select.appendChild(option);
    }
    select.hidden = false;
    select.addEventListener('change', () => {
      dataset = select.value;
      mapEdges = NO_EDGES;
      const url = new URL(location.href);
      url.searchParams.set('dataset', dataset);
      history.replaceState(null, '', url);
    });
  } catch (error) {
    // The page works without the list: it shows the default dataset.
  }
}

async function refresh() {
  try {
    const stats = await fetchJson(api('/api/stats'));
    if (stats.status === 200) {
      const history = await fetchJson(api('/api/history'));
      await ensureEdges(stats.body.generation);
      render(stats.body, history.body);
    } else if (stats.status === 401 || stats.status === 403) {
      askForToken(stats.status);
    } else {
      showState(stats.body.state || `HTTP ${stats.status}`, 'loading');
    }
  } catch (error) {
    showState(`unreachable (${error.message})`, 'error');
  } finally {
    setTimeout(refresh, REFRESH_MS);
  }
}

document.getElementById('token').addEventListener('change', (event) => {
  token = event.target.value.trim();
  loadDatasets();
});
loadDatasets().then(refresh);
