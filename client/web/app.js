// locator web example: draws a dataset's edge sample (/api/edges) as the
// map and locates the point clicked with the HTTP/JSON API
// (POST /v1/datasets/{name}:locate), outlining the triangle found and
// showing its value. Answers are locator.v1 messages in protobuf's JSON
// mapping (64-bit integers arrive as strings).
//
// Query parameters: server=URL (where locatord's HTTP server is; default:
// this page's origin), dataset=NAME (the one shown first), click=X,Y (after
// the map is drawn, click the pixel at dataset point (X, Y), as a user
// would: scripts and tests use it). The fragment may carry #token=TOKEN
// (it never reaches a server; the page removes it from the address bar).
//
// The token typed in goes to this page's own origin only: before it goes to
// another (a ?server= elsewhere, which anyone can put in a link), the user
// is asked, naming that origin, and the answer holds for the page's life.
'use strict';

const params = new URLSearchParams(location.search);
const SERVER = (params.get('server') || '').replace(/\/$/, '');
// Origin -> whether the user agreed to send it the token.
const tokenConsent = new Map([[location.origin, true]]);
const MARGIN_PX = 16;
const DRAG_THRESHOLD_PX = 4;

const canvas = document.getElementById('map');
const context = canvas.getContext('2d');
const style = getComputedStyle(document.documentElement);

let dataset = params.get('dataset') || '';
let segments = [];
// Dataset coordinates -> canvas pixels: px = (x - centerX) * scale + w / 2,
// py = h / 2 - (y - centerY) * scale.
const view = {centerX: 0, centerY: 0, scale: 1};
let answer = null;  // {point: [x, y], response}

function toPixel(x, y) {
  return [(x - view.centerX) * view.scale + canvas.width / 2,
          canvas.height / 2 - (y - view.centerY) * view.scale];
}

function toPoint(px, py) {
  return [(px - canvas.width / 2) / view.scale + view.centerX,
          (canvas.height / 2 - py) / view.scale + view.centerY];
}

// The canvas pixel under a mouse event.
function eventPixel(event) {
  const rect = canvas.getBoundingClientRect();
  return [(event.clientX - rect.left) * canvas.width / rect.width,
          (event.clientY - rect.top) * canvas.height / rect.height];
}

function setStatus(text) {
  document.getElementById('status').textContent = text;
}

function showError(message) {
  const error = document.getElementById('error');
  error.textContent = message;
  error.hidden = message === '';
}

// Sets a result field's text and raw value (data-value).
function setField(id, value, text) {
  const element = document.getElementById(id);
  element.dataset.value = value === undefined ? '' : String(value);
  element.textContent = text === undefined ? '–' : text;
}

// Whether the token may go to `url`: always to this page's origin, to
// another once the user has agreed (asked once per origin).
function mayReceiveToken(url) {
  const origin = new URL(url, location.href).origin;
  if (!tokenConsent.has(origin)) {
    tokenConsent.set(origin, confirm(
        `Send your token to ${origin}? This page is ${location.origin}; ` +
        'send it only to a server you trust.'));
  }
  return tokenConsent.get(origin);
}

async function call(method, path, body) {
  const headers = {};
  const token = document.getElementById('token').value.trim();
  if (token !== '' && mayReceiveToken(SERVER + path)) {
    headers.Authorization = `Bearer ${token}`;
  }
  if (body !== undefined) headers['Content-Type'] = 'application/json';
  const response = await fetch(SERVER + path, {
    method,
    headers,
    body: body === undefined ? undefined : JSON.stringify(body),
    cache: 'no-store',
  });
  const json = await response.json();
  if (!response.ok) {
    throw new Error(json.message || json.state || `HTTP ${response.status}`);
  }
  return json;
}

function fitView() {
  let minX = Infinity, minY = Infinity, maxX = -Infinity, maxY = -Infinity;
  for (const [x0, y0, x1, y1] of segments) {
    minX = Math.min(minX, x0, x1);
    maxX = Math.max(maxX, x0, x1);
    minY = Math.min(minY, y0, y1);
    maxY = Math.max(maxY, y0, y1);
  }
  if (!(minX <= maxX)) return;
  view.centerX = (minX + maxX) / 2;
  view.centerY = (minY + maxY) / 2;
  const width = Math.max(maxX - minX, 1e-12);
  const height = Math.max(maxY - minY, 1e-12);
  view.scale = Math.min((canvas.width - 2 * MARGIN_PX) / width,
                        (canvas.height - 2 * MARGIN_PX) / height);
}

function draw() {
  context.clearRect(0, 0, canvas.width, canvas.height);
  context.lineWidth = 1;
  context.strokeStyle = style.getPropertyValue('--edge');
  context.beginPath();
  for (const [x0, y0, x1, y1] of segments) {
    context.moveTo(...toPixel(x0, y0));
    context.lineTo(...toPixel(x1, y1));
  }
  context.stroke();
  if (answer === null) return;
  const hit = style.getPropertyValue('--hit');
  const corners = answer.response.vertices || [];
  if (corners.length === 3 && answer.response.triangle_id !== '-1') {
    context.beginPath();
    corners.forEach((v, i) => {
      const [px, py] = toPixel(v.x, v.y);
      if (i === 0) context.moveTo(px, py); else context.lineTo(px, py);
    });
    context.closePath();
    context.fillStyle = 'rgba(214, 51, 108, 0.15)';
    context.fill();
    context.lineWidth = 2;
    context.strokeStyle = hit;
    context.stroke();
  }
  const [px, py] = toPixel(...answer.point);
  context.fillStyle = hit;
  context.beginPath();
  context.arc(px, py, 4, 0, 2 * Math.PI);
  context.fill();
}

function showAnswer(point, response) {
  const result = document.getElementById('result');
  result.dataset.x = String(point[0]);
  result.dataset.y = String(point[1]);
  setField('result-point', point.join(','),
           `(${point[0].toPrecision(8)}, ${point[1].toPrecision(8)})`);
  setField('result-type', response.type,
           response.type.replace('LOCATION_TYPE_', '').toLowerCase()
               .replace(/_/g, ' '));
  setField('result-triangle', response.triangle_id, response.triangle_id);
  const ids = response.vertex_ids || [];
  setField('result-vertices', ids.join(','), ids.join(', '));
  setField('result-value', response.value,
           response.value === undefined ? undefined :
                                          Number(response.value).toPrecision(8));
  setField('result-cost', response.cost.total, String(response.cost.total));
  result.dataset.state = 'done';
}

async function locate(point) {
  const result = document.getElementById('result');
  result.dataset.state = 'pending';
  showError('');
  try {
    const response = await call(
        'POST', `/v1/datasets/${encodeURIComponent(dataset)}:locate`,
        {point: {x: point[0], y: point[1]}});
    answer = {point, response};
    showAnswer(point, response);
    draw();
  } catch (error) {
    result.dataset.state = 'error';
    showError(error.message);
  }
}

async function showDataset(name) {
  dataset = name;
  answer = null;
  setStatus(`loading ${name}…`);
  const edges = await call(
      'GET', `/api/edges?dataset=${encodeURIComponent(name)}`);
  segments = edges.segments;
  fitView();
  draw();
  setStatus(`${name}: ${segments.length} edges shown`);
  document.body.dataset.shown = name;
}

// Pan by dragging, zoom about the cursor with the wheel, locate on a click
// that did not drag.
function listen() {
  let drag = null;
  canvas.addEventListener('pointerdown', (event) => {
    drag = {start: eventPixel(event), center: [view.centerX, view.centerY],
            moved: false};
    canvas.setPointerCapture(event.pointerId);
  });
  canvas.addEventListener('pointermove', (event) => {
    if (drag === null) return;
    const [px, py] = eventPixel(event);
    const dx = px - drag.start[0], dy = py - drag.start[1];
    if (Math.hypot(dx, dy) > DRAG_THRESHOLD_PX) drag.moved = true;
    if (!drag.moved) return;
    view.centerX = drag.center[0] - dx / view.scale;
    view.centerY = drag.center[1] + dy / view.scale;
    draw();
  });
  canvas.addEventListener('pointerup', () => {
    // The click event that follows reads it.
    setTimeout(() => { drag = null; }, 0);
  });
  canvas.addEventListener('click', (event) => {
    if (drag !== null && drag.moved) return;
    locate(toPoint(...eventPixel(event)));
  });
  canvas.addEventListener('wheel', (event) => {
    event.preventDefault();
    const [px, py] = eventPixel(event);
    const [x, y] = toPoint(px, py);
    view.scale *= Math.exp(-event.deltaY / 500);
    // Keep (x, y) under the cursor.
    view.centerX = x - (px - canvas.width / 2) / view.scale;
    view.centerY = y + (py - canvas.height / 2) / view.scale;
    draw();
  }, {passive: false});
  document.getElementById('dataset').addEventListener('change', (event) => {
    showDataset(event.target.value).catch((error) => showError(error.message));
  });
}

// Clicks the pixel at dataset point (x, y), as a user would.
function clickAt(x, y) {
  const [px, py] = toPixel(x, y);
  const rect = canvas.getBoundingClientRect();
  canvas.dispatchEvent(new MouseEvent('click', {
    bubbles: true,
    clientX: rect.left + px * rect.width / canvas.width,
    clientY: rect.top + py * rect.height / canvas.height,
  }));
}

// Fills the dataset select and shows the chosen dataset; again when a
// token is entered (the list needs one if the server wants tokens).
async function loadDatasets() {
  showError('');
  try {
    const list = await call('GET', '/v1/datasets');
    const select = document.getElementById('dataset');
    select.replaceChildren();
    for (const entry of list.datasets) {
      const option = document.createElement('option');
      option.value = entry.name;
      option.textContent = entry.name + (entry.serving ? '' : ' (loading)');
      select.appendChild(option);
      if (dataset === '' && entry.is_default) dataset = entry.name;
    }
    select.value = dataset;
    await showDataset(dataset);
    const click = params.get('click');
    if (click !== null) clickAt(...click.split(',').map(Number));
  } catch (error) {
    setStatus('error');
    showError(error.message);
  }
}

listen();
const linkToken = new URLSearchParams(location.hash.slice(1)).get('token');
if (linkToken !== null) {
  document.getElementById('token').value = linkToken;
  history.replaceState(null, '', location.pathname + location.search);
}
document.getElementById('token').addEventListener('change', loadDatasets);
loadDatasets();
