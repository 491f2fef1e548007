// locator's web map, on MapLibre GL JS. A dataset with a CRS is shown where
// it is: its hillshade tiles (/v1/datasets/{name}/hillshade/...) as the map,
// draped over 3D terrain from its terrain tiles (tiles.json, Terrarium);
// with no network there is no basemap, and none is needed. A dataset without
// a CRS has no place on the Earth: its coordinates are laid linearly on a
// stand-in square of the map and its edge sample (/api/edges) is drawn.
// A click locates the point (POST /v1/datasets/{name}:locate, in lon/lat
// with crs EPSG:4326 where the dataset has a CRS) and outlines the triangle
// found; "draw a line" and two clicks ask for the line's exact profile
// (POST ...:profile) and chart it. Answers are locator.v1 messages in
// protobuf's JSON mapping (64-bit integers arrive as strings).
//
// Query parameters: server=URL (where locatord's HTTP server is; default:
// this page's origin), dataset=NAME (the one shown first), click=X,Y and
// profile=X1,Y1;X2,Y2 (once the map is drawn, click there as a user would,
// in lon/lat on a dataset with a CRS and in its own coordinates otherwise:
// scripts and tests use them). The fragment may carry #token=TOKEN (it
// never reaches a server; the page removes it from the address bar).
//
// The token typed in goes to this page's own origin only: before it goes to
// another (a ?server= elsewhere, which anyone can put in a link), the user
// is asked, naming that origin, and the answer holds for the page's life.
// Map tiles are fetched with it as the API calls are.
'use strict';

const params = new URLSearchParams(location.search);
const SERVER = (params.get('server') || '').replace(/\/$/, '');
const API_ORIGIN = new URL(SERVER || location.origin, location.href).origin;
// Origin -> whether the user agreed to send it the token.
const tokenConsent = new Map([[location.origin, true]]);
const REQUEST_CRS = 'EPSG:4326';
// Half the side of the stand-in square a dataset without a CRS is laid on,
// in degrees: small enough that Web Mercator barely bends it.
const PLAIN_HALF_SIDE = 10;
const EMPTY = {type: 'FeatureCollection', features: []};

let datasets = new Map();  // name -> ListDatasets entry
let dataset = params.get('dataset') || '';
// Dataset coordinates <-> map lon/lat: the identity (through the server's
// PROJ) for a dataset with a CRS, a linear map for one without.
let frame = null;
let lineStart = null;  // the first end of a line being drawn
let drawing = false;

function setStatus(text) {
  document.getElementById('status').textContent = text;
}

function showError(message) {
  const error = document.getElementById('error');
  error.textContent = message;
  error.hidden = message === '';
}

// Sets a field's text and raw value (data-value).
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

// The Authorization header for a request to `url`, if a token may go there.
function authorization(url) {
  const token = document.getElementById('token').value.trim();
  if (token === '' || !mayReceiveToken(url)) return {};
  return {Authorization: `Bearer ${token}`};
}

async function call(method, path, body) {
  const headers = authorization(SERVER + path);
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

const map = new maplibregl.Map({
  container: 'map',
  style: {
    version: 8,
    sources: {},
    layers: [{id: 'background', type: 'background',
              paint: {'background-color': '#e9edf2'}}],
  },
  center: [0, 0],
  zoom: 1,
  maxPitch: 70,
  attributionControl: false,
  // Tiles of the API's origin carry the token, as its calls do.
  transformRequest: (url) => {
    if (new URL(url, location.href).origin !== API_ORIGIN) return {url};
    return {url, headers: authorization(url)};
  },
});
map.addControl(new maplibregl.NavigationControl({visualizePitch: true}));
map.addControl(new maplibregl.ScaleControl());

// The dataset's own layers, removed when another is shown.
const DATASET_LAYERS = ['relief', 'edges'];
const DATASET_SOURCES = ['relief', 'terrain', 'edges'];

function clearDataset() {
  map.setTerrain(null);
  for (const id of DATASET_LAYERS) if (map.getLayer(id)) map.removeLayer(id);
  for (const id of DATASET_SOURCES) if (map.getSource(id)) map.removeSource(id);
  for (const id of ['hit', 'line']) map.getSource(id).setData(EMPTY);
}

// The answers drawn over every dataset: the triangle found and the line.
function addOverlays() {
  map.addSource('hit', {type: 'geojson', data: EMPTY});
  map.addSource('line', {type: 'geojson', data: EMPTY});
  map.addLayer({id: 'hit-fill', type: 'fill', source: 'hit',
                filter: ['==', '$type', 'Polygon'],
                paint: {'fill-color': '#d6336c', 'fill-opacity': 0.15}});
  map.addLayer({id: 'hit-outline', type: 'line', source: 'hit',
                filter: ['==', '$type', 'Polygon'],
                paint: {'line-color': '#d6336c', 'line-width': 2}});
  map.addLayer({id: 'hit-point', type: 'circle', source: 'hit',
                filter: ['==', '$type', 'Point'],
                paint: {'circle-color': '#d6336c', 'circle-radius': 4}});
  map.addLayer({id: 'line', type: 'line', source: 'line',
                paint: {'line-color': '#1c7ed6', 'line-width': 3}});
}

// The linear frame of a dataset without a CRS: its box onto a square of
// 2 * PLAIN_HALF_SIDE degrees around (0, 0), aspect kept.
function plainFrame(box) {
  const cx = (box.min_x + box.max_x) / 2, cy = (box.min_y + box.max_y) / 2;
  const side = Math.max(box.max_x - box.min_x, box.max_y - box.min_y, 1e-300);
  const scale = 2 * PLAIN_HALF_SIDE / side;
  return {
    geographic: false,
    toMap: ([x, y]) => [(x - cx) * scale, (y - cy) * scale],
    toData: ([lng, lat]) => [lng / scale + cx, lat / scale + cy],
    bounds: [[(box.min_x - cx) * scale, (box.min_y - cy) * scale],
             [(box.max_x - cx) * scale, (box.max_y - cy) * scale]],
  };
}

async function showGeographic(name) {
  const path = `/v1/datasets/${encodeURIComponent(name)}`;
  const tileJson = await call('GET', `${path}/tiles.json?encoding=terrarium`);
  const [west, south, east, north] = tileJson.bounds;
  frame = {geographic: true, toMap: (p) => p, toData: (p) => p,
           bounds: [[west, south], [east, north]]};
  map.addSource('terrain', {
    type: 'raster-dem', tiles: [SERVER + `${path}/tiles/{z}/{x}/{y}.png`],
    encoding: 'terrarium', tileSize: 256, bounds: tileJson.bounds,
    maxzoom: tileJson.maxzoom,
  });
  map.addSource('relief', {
    type: 'raster', tiles: [SERVER + `${path}/hillshade/{z}/{x}/{y}.png`],
    tileSize: 256, bounds: tileJson.bounds, maxzoom: tileJson.maxzoom + 2,
  });
  map.addLayer({id: 'relief', type: 'raster', source: 'relief'}, 'hit-fill');
  map.setTerrain({source: 'terrain', exaggeration: 1});
}

async function showPlain(name, box) {
  frame = plainFrame(box);
  const edges = await call(
      'GET', `/api/edges?dataset=${encodeURIComponent(name)}`);
  const lines = edges.segments.map(([x0, y0, x1, y1]) =>
      [frame.toMap([x0, y0]), frame.toMap([x1, y1])]);
  map.addSource('edges', {type: 'geojson', data: {
    type: 'Feature', properties: {},
    geometry: {type: 'MultiLineString', coordinates: lines}}});
  map.addLayer({id: 'edges', type: 'line', source: 'edges',
                paint: {'line-color': 'rgba(102, 112, 133, 0.6)',
                        'line-width': 1}}, 'hit-fill');
}

async function showDataset(name) {
  dataset = name;
  lineStart = null;
  setStatus(`loading ${name}…`);
  clearDataset();
  const entry = datasets.get(name);
  const stats = entry.stats || {};
  const geographic = stats.crs !== undefined && stats.has_values === true;
  if (geographic) {
    await showGeographic(name);
  } else {
    await showPlain(name, stats.bounding_box);
  }
  map.fitBounds(frame.bounds, {padding: 24, animate: false});
  setStatus(`${name}: ${geographic ? stats.crs.name : 'no CRS'}`);
  document.body.dataset.shown = name;
}

// The located point and triangle on the map, and the answer in the panel.
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
  const features = [{type: 'Feature', properties: {},
                     geometry: {type: 'Point', coordinates: frame.toMap(point)}}];
  const corners = response.vertices || [];
  if (corners.length === 3 && response.triangle_id !== '-1') {
    const ring = corners.map((v) => frame.toMap([v.x, v.y]));
    features.push({type: 'Feature', properties: {},
                   geometry: {type: 'Polygon', coordinates: [[...ring, ring[0]]]}});
  }
  map.getSource('hit').setData({type: 'FeatureCollection', features});
  result.dataset.state = 'done';
}

// What a request about `points` (map lon/lat) says about where they are.
function located(points) {
  const data = points.map((p) => frame.toData(p));
  return frame.geographic ? {points: data, crs: REQUEST_CRS} : {points: data};
}

async function locate(lngLat) {
  const result = document.getElementById('result');
  result.dataset.state = 'pending';
  showError('');
  const where = located([lngLat]);
  const point = where.points[0];
  const body = {point: {x: point[0], y: point[1]}};
  if (where.crs) Object.assign(body, {crs: where.crs, vertices_in_request_crs: true});
  try {
    const response = await call(
        'POST', `/v1/datasets/${encodeURIComponent(dataset)}:locate`, body);
    showAnswer(point, response);
  } catch (error) {
    result.dataset.state = 'error';
    showError(error.message);
  }
}

// Draws the profile's value against distance: the exact breakpoints joined,
// broken where the line leaves the data (a breakpoint without a value).
function chart(profile) {
  const svg = document.getElementById('profile-chart');
  svg.replaceChildren();
  const breakpoints = profile.breakpoints || [];
  const values = breakpoints.filter((p) => p.value !== undefined)
                     .map((p) => Number(p.value));
  if (values.length < 2) return;
  const length = Number(profile.length) || 1;
  const low = Math.min(...values), high = Math.max(...values);
  const span = high > low ? high - low : 1;
  const [width, height, pad] = [320, 140, 8];
  let path = '';
  let broken = true;
  for (const p of breakpoints) {
    if (p.value === undefined) {
      broken = true;
      continue;
    }
    const x = pad + (width - 2 * pad) * Number(p.distance || 0) / length;
    const y = height - pad - (height - 2 * pad) * (Number(p.value) - low) / span;
    path += `${broken ? 'M' : 'L'}${x.toFixed(2)},${y.toFixed(2)}`;
    broken = false;
  }
  const line = document.createElementNS('http://www.w3.org/2000/svg', 'path');
  line.setAttribute('d', path);
  line.setAttribute('class', 'profile-line');
  svg.appendChild(line);
}

async function profile(from, to) {
  const section = document.getElementById('profile');
  section.dataset.state = 'pending';
  showError('');
  map.getSource('line').setData({type: 'Feature', properties: {},
                                 geometry: {type: 'LineString', coordinates: [from, to]}});
  const where = located([from, to]);
  section.dataset.from = where.points[0].join(',');
  section.dataset.to = where.points[1].join(',');
  const body = {vertices: where.points.map(([x, y]) => ({x, y}))};
  if (where.crs) body.crs = where.crs;
  try {
    const answer = await call(
        'POST', `/v1/datasets/${encodeURIComponent(dataset)}:profile`, body);
    const breakpoints = answer.breakpoints || [];
    setField('profile-length', answer.length, Number(answer.length).toPrecision(6));
    setField('profile-crossings', answer.crossings, String(answer.crossings));
    setField('profile-points', breakpoints.length, String(breakpoints.length));
    chart(answer);
    section.dataset.state = 'done';
  } catch (error) {
    section.dataset.state = 'error';
    showError(error.message);
  }
}

function onClick(lngLat) {
  const point = [lngLat.lng, lngLat.lat];
  if (!drawing) {
    locate(point);
    return;
  }
  if (lineStart === null) {
    lineStart = point;
    return;
  }
  const from = lineStart;
  lineStart = null;
  setDrawing(false);
  profile(from, point);
}

function setDrawing(on) {
  drawing = on;
  lineStart = null;
  const button = document.getElementById('draw-line');
  button.setAttribute('aria-pressed', String(on));
  map.getCanvas().style.cursor = on ? 'crosshair' : '';
}

// Clicks the pixel over point `p` (the dataset's coordinates, lon/lat on a
// dataset with a CRS), as a user would.
function clickAt(p) {
  const pixel = map.project(frame.toMap(p));
  const rounded = new maplibregl.Point(Math.round(pixel.x), Math.round(pixel.y));
  map.fire('click', {point: rounded, lngLat: map.unproject(rounded)});
}

// The clicks the query parameters ask for, once the map is drawn.
async function clickAsAsked() {
  const profileAt = params.get('profile');
  if (profileAt !== null) {
    const [from, to] = profileAt.split(';').map((p) => p.split(',').map(Number));
    setDrawing(true);
    clickAt(from);
    clickAt(to);
  }
  const click = params.get('click');
  if (click !== null) clickAt(click.split(',').map(Number));
}

// Fills the dataset select and shows the chosen dataset; again when a
// token is entered (the list needs one if the server wants tokens).
async function loadDatasets() {
  showError('');
  try {
    const list = await call('GET', '/v1/datasets');
    const select = document.getElementById('dataset');
    select.replaceChildren();
    datasets = new Map();
    for (const entry of list.datasets) {
      datasets.set(entry.name, entry);
      const option = document.createElement('option');
      option.value = entry.name;
      option.textContent = entry.name + (entry.serving ? '' : ' (loading)');
      select.appendChild(option);
      if (dataset === '' && entry.is_default) dataset = entry.name;
    }
    select.value = dataset;
    await showDataset(dataset);
    await clickAsAsked();
  } catch (error) {
    setStatus('error');
    showError(error.message);
  }
}

map.on('click', (event) => onClick(event.lngLat));
document.getElementById('draw-line').addEventListener(
    'click', () => setDrawing(!drawing));
document.getElementById('dataset').addEventListener('change', (event) => {
  showDataset(event.target.value).catch((error) => showError(error.message));
});
const linkToken = new URLSearchParams(location.hash.slice(1)).get('token');
if (linkToken !== null) {
  document.getElementById('token').value = linkToken;
  history.replaceState(null, '', location.pathname + location.search);
}
document.getElementById('token').addEventListener('change', loadDatasets);
map.on('load', () => {
  addOverlays();
  loadDatasets();
});
