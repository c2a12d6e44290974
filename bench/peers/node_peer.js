// Node.js peer for bench/http_bench.sh: one process, node:http, no npm dependencies. It does the
// same kind of work as cutcalc for two endpoints:
//   POST /v1/roughness/groove-wall   R2-R5 and Ra (R9-R12) of spec roughness.md (port of
//                                    cutcalc's domain/roughness/crest_branches.cpp,
//                                    pitch_profile.cpp and groove_wall.cpp)
//   POST /v1/entry-length            E1, E2, E14 of spec entry-and-main-time.md, straight entry
//                                    edge only, no exit
// i.e. Content-Type check (415), JSON.parse (400), field validation collecting every error (422
// application/problem+json with JSON pointers; unknown fields rejected), the formula, and the
// answer with cutcalc's fields in cutcalc's order, integral doubles printed as 12.0 like cutcalc.
// Not modelled: duplicate keys (cutcalc: 400), target_rz_um and bearing_points (rejected here as
// unknown), the other contours, exit, length_mm.
// Any other POST path: answers 200 with the request body as application/json (a bare echo, like
// bench/peers/httplib_echo.cpp); the per-endpoint table of http_bench.sh relies on that.
// usage: node node_peer.js PORT [HOST]     prints "listening on HOST:PORT" once bound.
'use strict';
const http = require('node:http');

const port = Number.parseInt(process.argv[2] ?? '', 10);
const host = process.argv[3] ?? '127.0.0.1';
if (!Number.isInteger(port) || port < 0 || port > 65535) {
  console.error('usage: node node_peer.js PORT [HOST]');
  process.exit(2);
}

const MAX_BODY_BYTES = 64 * 1024;  // cutcalc's default body limit (413 above it)
const RAD_PER_DEG = Math.PI / 180;  // 0.017453292519943295, as cutcalc's kRadPerDeg
const UM_PER_MM = 1000;

// A JSON number as cutcalc (nlohmann::json) prints a double: integral values with ".0".
function num(x) {
  return Number.isInteger(x) && Math.abs(x) < 1e21 ? `${x}.0` : `${x}`;
}

function send(res, status, type, text) {
  res.writeHead(status, {
    'Content-Type': type,
    'Content-Length': Buffer.byteLength(text),
    'X-Content-Type-Options': 'nosniff',
  });
  res.end(text);
}

function problem(res, status, title, detail, errors) {
  send(res, status, 'application/problem+json', JSON.stringify({
    type: 'about:blank', title, status, detail, errors,
  }));
}

// 422 listing every field error; the detail names the first, as cutcalc's does.
function invalid(res, errors) {
  const first = errors[0];
  const more = errors.length > 1 ? ` (and ${errors.length - 1} more)` : '';
  const field = first.pointer.slice(1).replaceAll('/', '.');
  problem(res, 422, 'Invalid input', `${field} ${first.detail}${more}`, errors);
}

function isObject(v) {
  return v !== null && typeof v === 'object' && !Array.isArray(v);
}

// Field checks; each pushes {pointer, detail} onto errors and returns the value (or undefined).
class Checker {
  constructor(obj, base, errors) {
    this.obj = obj;
    this.base = base;
    this.errors = errors;
  }

  fail(name, detail) {
    this.errors.push({ pointer: `${this.base}/${name}`, detail });
  }

  number(name, { required = false, fallback, ok = () => true, rule = '' } = {}) {
    const v = this.obj[name];
    if (v === undefined) {
      if (required) this.fail(name, 'is required');
      return fallback;
    }
    if (typeof v !== 'number') {
      this.fail(name, 'must be a number');
    } else if (!Number.isFinite(v)) {
      this.fail(name, 'must be a finite number');
    } else if (!ok(v)) {
      this.fail(name, rule);
    }
    return v;
  }

  unknown(known) {
    for (const name of Object.keys(this.obj)) {
      if (!known.includes(name)) this.fail(name, 'is not a known field');
    }
  }
}

// --- POST /v1/roughness/groove-wall (R2-R5; Ra by R9-R12) ------------------------------------

// sqrt(a) sqrt(b) rather than sqrt(a b): the product could overflow for huge lengths.
function sqrtProduct(a, b) {
  return Math.sqrt(Math.max(a, 0)) * Math.sqrt(Math.max(b, 0));
}

// sin, cos, tan of phi1 and 2 sin^2(phi1/2) (1 - cos(phi1) without cancellation).
function edgeAngle(phi1) {
  const sinHalf = Math.sin(0.5 * phi1);
  return {
    sin: Math.sin(phi1), cos: Math.cos(phi1), tan: Math.tan(phi1), twoSinSqHalf: 2 * sinHalf * sinHalf,
  };
}

// Where a nose arc reaches height y <= rho: u = sqrt(y (2 rho - y)).
function noseArcAbscissa(y, rho) {
  return Math.sqrt(Math.max(y, 0)) * Math.sqrt(Math.max(2 * rho - y, 0));
}

// R2-R5 and R9 (phi1 > 0): the crest Rz of one pitch, its branch, where the profile's left side
// ends (uC) and its height there (yLeftEnd: Rz, or rho where the profile jumps to Rz).
function pitchProfile(S, rho, a) {
  const S_AB = 2 * rho * a.sin;  // R2
  const S_BC = rho + rho / a.sin;
  if (S <= S_AB) {  // R3
    const h = 0.5 * S;
    const Rz = h * (h / (rho + sqrtProduct(rho - h, rho + h)));
    return { S, rho, a, Rz, branch: 'nose_arc', uC: S / 2, yLeftEnd: Rz };
  }
  if (S <= S_BC) {  // R4, the bracket multiplied by its conjugate
    const Ssin = S * a.sin;
    const root = sqrtProduct(Ssin, 2 * rho - Ssin);
    const bracket = S * ((S - S_AB) / (S * a.cos + root));
    const Rz = rho * a.twoSinSqHalf + a.sin * bracket;
    return {
      S, rho, a, Rz, branch: 'nose_arc_and_minor_edge', uC: Math.min(noseArcAbscissa(Rz, rho), rho), yLeftEnd: Rz,
    };
  }
  const Rz = rho + (S - S_BC) * a.tan;  // R5
  return { S, rho, a, Rz, branch: 'minor_edge_and_main_edge', uC: rho, yLeftEnd: rho };
}

// th - sin(th): its series below 0.1 rad, where the difference would lose its digits (R11).
function thetaMinusSine(th) {
  if (th < 0.1) {
    const th2 = th * th;
    return th * th2 * (1 / 6 - th2 * (1 / 120 - th2 * (1 / 5040 - th2 / 362880)));
  }
  return th - Math.sin(th);
}

// R11: the area under a nose arc over [0, x].
function noseArcArea(x, rho) {
  const th = Math.asin(Math.min(Math.max(x / rho, 0), 1));
  const sinHalf = Math.sin(th / 2);
  return rho * rho * (Math.sin(th) * sinHalf * sinHalf - thetaMinusSine(th) / 2);
}

// The minor edge is y = v tan(phi1) - minorEdgeOffset (R9).
function minorEdgeOffset(p) {
  return p.rho * p.a.twoSinSqHalf / p.a.cos;
}

// R11: I_R(v), the area under the right side (trailing arc, then the minor edge).
function rightSideArea(p, v) {
  const vA = p.rho * p.a.sin;
  if (v <= vA) return noseArcArea(v, p.rho);
  return noseArcArea(vA, p.rho) + p.a.tan * (v - vA) * (v + vA) / 2 - minorEdgeOffset(p) * (v - vA);
}

// Where the right side reaches height y: the arc below y_a = 2 rho sin^2(phi1/2), the edge above.
function rightSideAbscissa(p, y) {
  const yA = p.rho * p.a.twoSinSqHalf;
  const v = y <= yA ? noseArcAbscissa(y, p.rho) : (y + minorEdgeOffset(p)) / p.a.tan;
  return Math.min(v, p.S - p.uC);
}

// The exponent e of a positive finite x: 2^e <= x < 2^(e+1) (C's ilogb).
function ilogb(x) {
  let e = Math.floor(Math.log2(x));
  while (2 ** e > x) e -= 1;
  while (2 ** (e + 1) <= x) e += 1;
  return e;
}

// R10, R12: Ra in mm, twice the area between the mean line and the profile below it, on the
// profile scaled by a power of two near max(S, rho) (exact) so that no area overflows.
function arithmeticMeanDeviation(S, rho, a) {
  const scale = 2 ** ilogb(Math.max(S, rho));
  const p = pitchProfile(S / scale, rho / scale, a);
  const ybar = (noseArcArea(p.uC, p.rho) + rightSideArea(p, p.S - p.uC)) / p.S;  // R10
  const uL = ybar < p.yLeftEnd ? Math.min(noseArcAbscissa(ybar, p.rho), p.uC) : p.uC;
  const vR = rightSideAbscissa(p, ybar);
  const below = ybar * (uL + vR) - noseArcArea(uL, p.rho) - rightSideArea(p, vR);
  return Math.max(2 * below / p.S, 0) * scale;
}

function grooveWall(S, rho, phi1Deg) {
  const phi1 = phi1Deg * RAD_PER_DEG;
  if (phi1 === 0) {  // R4 with phi1 = 0: the minor edge is the wall itself; the profile is flat
    return { rz_mm: 0, ra_mm: 0, branch: 'nose_arc_and_minor_edge' };
  }
  const a = edgeAngle(phi1);
  const p = pitchProfile(S, rho, a);
  return { rz_mm: p.Rz, ra_mm: arithmeticMeanDeviation(S, rho, a), branch: p.branch };
}

function handleGrooveWall(res, body) {
  const errors = [];
  const c = new Checker(body, '', errors);
  const S = c.number('feed_mm', { required: true, ok: (v) => v > 0, rule: 'must be > 0' });
  const rho = c.number('nose_radius_mm', { required: true, ok: (v) => v > 0, rule: 'must be > 0' });
  const phi1 = c.number('minor_edge_angle_deg', {
    required: true, ok: (v) => v >= 0 && v < 90, rule: 'must be in [0, 90)',
  });
  c.unknown(['feed_mm', 'nose_radius_mm', 'minor_edge_angle_deg']);
  if (errors.length) {
    invalid(res, errors);
    return;
  }
  const crest = grooveWall(S, rho, phi1);
  const rz = crest.rz_mm * UM_PER_MM;
  const ra = crest.ra_mm * UM_PER_MM;
  if (!Number.isFinite(rz) || !Number.isFinite(ra)) {
    problem(res, 422, 'Input impossible for the model', 'the crest height exceeds the range of a double',
      [{ pointer: '', detail: 'the crest height exceeds the range of a double' }]);
    return;
  }
  send(res, 200, 'application/json',
    `{"branch":"${crest.branch}","ra_um":${num(ra)},"rz_um":${num(rz)}}`);
}

// --- POST /v1/entry-length, straight entry edge (E1, E2, E14) ---------------------------------

// E1: s(u) = sqrt((r - u)(r + u)), clamped at 0 (tangency stays exact).
function halfChord(r, u) {
  const p = (r - u) * (r + u);
  return p > 0 ? Math.sqrt(p) : 0;
}

function entryLength(D, K, Lpod, B, alphaDeg) {
  const h = B / 2;  // E3
  const r = D / 2;  // E1
  const lowReach = K - r;
  const highReach = K + r;
  const a = Math.max(lowReach, -h);  // E2
  const b = Math.min(highReach, h);
  const W = b - a;
  if (!(W > 0)) return null;
  // cot(90) = 0 and cos(90) = 0 exactly (cos(pi/2) is not 0 in doubles).
  let cot = 0;
  let cos = 0;
  if (alphaDeg !== 90) {
    const alpha = alphaDeg * RAD_PER_DEG;
    cos = Math.cos(alpha);
    cot = cos / Math.sin(alpha);
  }
  // E14 g(y) = s(y - K) - (y + h) cot(alpha), with u = y - K exact at the band ends (-r or +r
  // where the band ends on the cutter's edge, -h - K or h - K on the workpiece's edge).
  const g = (y, u) => halfChord(r, u) - (y + h) * cot;
  const uA = lowReach >= -h ? -r : -h - K;
  const uB = highReach <= h ? r : h - K;
  const gA = g(a, uA);
  const gB = g(b, uB);
  const uStar = -r * cos;  // y* - K, y* = clamp(K - r cos(alpha), a, b)
  let gStar;
  if (uStar <= uA) gStar = gA;
  else if (uStar >= uB) gStar = gB;
  else gStar = g(K + uStar, uStar);
  const Xn = Lpod + gStar;
  const Lvr1 = gStar - Math.min(gA, gB);
  return { Lvr1, Lvr: Lpod + Lvr1, Xn, Yn: h + K, W };
}

function handleEntryLength(res, body) {
  const errors = [];
  const c = new Checker(body, '', errors);
  const D = c.number('cutter_diameter_mm', { required: true, ok: (v) => v > 0, rule: 'must be > 0' });
  const K = c.number('offset_mm', { fallback: 0 });
  const Lpod = c.number('approach_mm', { fallback: 2, ok: (v) => v >= 0, rule: 'must be >= 0' });
  c.unknown(['cutter_diameter_mm', 'offset_mm', 'approach_mm', 'entry']);
  const entry = body.entry;
  let B;
  let alpha;
  if (entry === undefined) {
    c.fail('entry', 'is required');
  } else if (!isObject(entry)) {
    c.fail('entry', 'must be an object');
  } else {
    const e = new Checker(entry, '/entry', errors);
    if (entry.contour === undefined) {
      e.fail('contour', 'is required');
    } else if (entry.contour !== 'straight') {
      e.fail('contour', 'must be "straight" (the only contour this peer models)');
    }
    B = e.number('width_mm', { required: true, ok: (v) => v > 0, rule: 'must be > 0' });
    alpha = e.number('angle_deg', {
      fallback: 90, ok: (v) => v > 0 && v < 180, rule: 'must be in (0, 180)',
    });
    e.unknown(['contour', 'width_mm', 'angle_deg']);
  }
  if (errors.length) {
    invalid(res, errors);
    return;
  }
  const out = entryLength(D, K, Lpod, B, alpha);
  if (out === null) {
    const detail = 'the tool does not reach the workpiece: there is no contact';
    problem(res, 422, 'Input impossible for the model', detail, [{ pointer: '', detail }]);
    return;
  }
  send(res, 200, 'application/json',
    `{"engagement_length_mm":${num(out.Lvr1)},"entry_length_mm":${num(out.Lvr)},` +
    `"start":{"x_mm":${num(out.Xn)},"y_mm":${num(out.Yn)}},"steady_width_mm":${num(out.W)}}`);
}

// --- HTTP -------------------------------------------------------------------------------------

const routes = {
  '/v1/roughness/groove-wall': handleGrooveWall,
  '/v1/entry-length': handleEntryLength,
};

function isJson(contentType) {
  if (contentType === undefined) return false;
  const semi = contentType.indexOf(';');
  const media = (semi < 0 ? contentType : contentType.slice(0, semi)).trim().toLowerCase();
  return media === 'application/json';
}

function answer(req, res, raw) {
  const handler = routes[req.url];
  if (handler === undefined) {  // bare echo
    res.writeHead(200, { 'Content-Type': 'application/json', 'Content-Length': raw.length });
    res.end(raw);
    return;
  }
  if (!isJson(req.headers['content-type'])) {
    problem(res, 415, 'Unsupported media type', 'send the request body as application/json', []);
    return;
  }
  let body;
  try {
    body = JSON.parse(raw.toString('utf8'));
  } catch (err) {
    problem(res, 400, 'Malformed JSON', `the request body is not valid JSON: ${err.message}`, []);
    return;
  }
  if (!isObject(body)) {
    const detail = 'the request body must be a JSON object';
    problem(res, 422, 'Invalid input', detail, [{ pointer: '', detail }]);
    return;
  }
  handler(res, body);
}

const server = http.createServer((req, res) => {
  if (req.method !== 'POST') {
    res.writeHead(404, { 'Content-Length': 0 });
    res.end();
    return;
  }
  const chunks = [];
  let size = 0;
  let tooLarge = false;
  req.on('data', (chunk) => {
    size += chunk.length;
    if (size > MAX_BODY_BYTES) tooLarge = true;
    else chunks.push(chunk);
  });
  req.on('end', () => {
    if (tooLarge) {
      problem(res, 413, 'Payload too large', `the request body exceeds ${MAX_BODY_BYTES} bytes`, []);
      return;
    }
    answer(req, res, chunks.length === 1 ? chunks[0] : Buffer.concat(chunks));
  });
});
// Same keep-alive policy as cutcalc's tuning; Node's defaults otherwise (noDelay is on).
server.keepAliveTimeout = 5000;
server.maxRequestsPerSocket = 10000;

const stop = () => {
  server.close();
  server.closeAllConnections();
  process.exit(0);
};
process.on('SIGTERM', stop);
process.on('SIGINT', stop);

server.listen({ port, host, backlog: 1024 }, () => {
  console.log(`listening on ${host}:${server.address().port}`);
});
