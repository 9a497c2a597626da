#include "report/MechanismAnimation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "report/PageData.h"

namespace rollerdyn {

namespace {

// The drawing script. It reads the frames (#mech-data) and draws frame k: per cart a lane with
// the shaft axis, the crank circle, crank arm and pin A_j, the rod A_j-B_j, the cart on its
// guide (guide rollers in a channel, compacting rollers on the mix) and the force arrows, each
// kind scaled so its largest value over the run has a fixed length. Play/pause, the slider and
// the speed choice move through the frames; the shown time goes out as "rollerdyn-time".
const char* const kScript = R"JS((function () {
  'use strict';
  var D = JSON.parse(document.getElementById('mech-data').textContent);
  var sec = document.getElementById('mechanism'), cv = document.getElementById('mech-canvas');
  var slider = document.getElementById('mech-slider'), btn = document.getElementById('mech-play');
  var speedSel = document.getElementById('mech-speed'), label = document.getElementById('mech-time');
  var ctx = cv.getContext('2d');
  var G = D.geometry, cg = G.cart, C = D.carts, n = C.length, N = D.t.length;
  var selftest = /selftest/.test(location.hash);

  // Extents [m]: x over every frame; y of one lane (room for the force arrows).
  var U = Math.max(G.r, G.cam_radius, 0.05);        // drawing unit: the crank radius
  var arrowN = 0.9 * U, arrowF = 1.4 * U;            // full-scale arrow lengths [m]
  // A scene without cart geometry (all of a, b, p, D, d zero: a point-mass cart) gets a block
  // around B, its two guide reactions drawn side by side at B.
  var block = !(cg.a > 0 || cg.b > 0 || cg.p > 0 || cg.D > 0 || cg.d > 0);
  var guideHalf = block ? 0.03 * U : cg.d / 2;       // half height of the guide channel [m]
  var xFront = block ? -0.12 * U : cg.p - cg.b, xRear = block ? 0.12 * U : cg.p + cg.b;
  var yMix = block ? -0.5 * U : -cg.e;                // surface of the mix
  var reach = Math.max(cg.a + cg.D / 2, cg.b + cg.d / 2);
  var c0 = block ? -0.9 * U : Math.min(0, cg.p - reach), c1 = block ? 0.9 * U : cg.p + reach;  // cart extent from B
  // Per-cart values (crank.angles_deg, crank.angle_error_deg, carts.mass as a list): labelled per lane.
  var ownMass = G.masses.some(function (m) { return m !== G.masses[0]; });
  var ownAngle = G.phases.some(function (p, j) { return G.offset === null || Math.abs(p - j * G.offset) > 1e-9; });
  var travel = [];                                   // per cart: x range of its cart over the run
  var xmin = -1.15 * U, xmax = 1.15 * U;
  for (var j = 0; j < n; j++) {
    var s = G.sides[j], hx = C[j].hinge_x, lo = Infinity, hi = -Infinity;
    for (var k = 0; k < N; k++) {
      var e0 = hx[k] + s * c0, e1 = hx[k] + s * c1;
      lo = Math.min(lo, e0, e1); hi = Math.max(hi, e0, e1);
      if (G.cam) { var tip = hx[k] - s * arrowF; xmin = Math.min(xmin, tip); xmax = Math.max(xmax, tip); }  // cam force arrow
    }
    travel.push([lo, hi]);
    xmin = Math.min(xmin, lo - 0.1 * U); xmax = Math.max(xmax, hi + 0.1 * U);
  }
  var yRoll = -cg.e + cg.D / 2;                      // compacting-roller centre
  var yTop = Math.max(G.r, cg.com_height, guideHalf + arrowN) + 0.35 * U;
  var yBot = Math.min(yMix, -G.r, -guideHalf - arrowN) - 0.15 * U;
  var W = cv.width, legendH = D.has_forces ? 46 : 22, maxH = 760, padL = 6, padR = 54;  // padR: arrow labels
  var scale = Math.min((W - padL - padR) / (xmax - xmin), (maxH - legendH) / (n * (yTop - yBot)));
  var laneH = scale * (yTop - yBot), H = Math.ceil(legendH + n * laneH);
  var dpr = window.devicePixelRatio || 1;
  cv.style.width = W + 'px'; cv.style.height = H + 'px';
  cv.width = Math.round(W * dpr); cv.height = Math.round(H * dpr);
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  var ox = padL + (W - padL - padR - scale * (xmax - xmin)) / 2;
  function X(x) { return ox + scale * (x - xmin); }
  function Y(j, y) { return legendH + j * laneH + scale * (yTop - y); }

  function line(x1, y1, x2, y2, color, width, dash) {
    ctx.beginPath(); ctx.setLineDash(dash || []); ctx.strokeStyle = color; ctx.lineWidth = width;
    ctx.moveTo(x1, y1); ctx.lineTo(x2, y2); ctx.stroke(); ctx.setLineDash([]);
  }
  function circle(x, y, rad, stroke, fill, width) {
    ctx.beginPath(); ctx.arc(x, y, Math.max(rad, 1), 0, 2 * Math.PI);
    if (fill) { ctx.fillStyle = fill; ctx.fill(); }
    if (stroke) { ctx.strokeStyle = stroke; ctx.lineWidth = width || 1; ctx.stroke(); }
  }
  function arrow(x1, y1, x2, y2, color) {      // canvas px, head at (x2, y2)
    var dx = x2 - x1, dy = y2 - y1, len = Math.hypot(dx, dy);
    if (len < 1.5) return;
    line(x1, y1, x2, y2, color, 2.2);
    var ux = dx / len, uy = dy / len, hl = Math.min(9, 0.5 * len), hw = 0.5 * hl;
    ctx.beginPath(); ctx.fillStyle = color; ctx.moveTo(x2, y2);
    ctx.lineTo(x2 - hl * ux - hw * uy, y2 - hl * uy + hw * ux);
    ctx.lineTo(x2 - hl * ux + hw * uy, y2 - hl * uy - hw * ux); ctx.closePath(); ctx.fill();
  }
  function kN(v) { return (v / 1000).toFixed(Math.abs(v) < 1e4 ? 2 : 1) + ' kN'; }
  function text(s, x, y, color, align) {
    ctx.fillStyle = color || '#222'; ctx.textAlign = align || 'left'; ctx.fillText(s, x, y);
  }

  function drawLegend(k) {
    ctx.font = '12px "DejaVu Sans", Arial, sans-serif'; ctx.textBaseline = 'middle';
    text('t = ' + D.t[k].toFixed(3) + ' s', 6, 12, '#000');
    var deg = ((D.phi[k] * 180 / Math.PI) % 360 + 360) % 360;
    text('\u03c6\u2082 = ' + deg.toFixed(1) + '\u00b0', 110, 12, '#000');
    if (D.has_forces) {
      ctx.font = '11px "DejaVu Sans", Arial, sans-serif';
      text('arrows to scale: guide reaction (green), full length = ' + kN(D.N_abs_max) + ';', 6, 27, '#444');
      text('rod force on the cart (red tension, blue compression), full length = ' + kN(D.F_rod_abs_max), 6, 40, '#444');
    }
    var bar = [0.1, 0.2, 0.25, 0.5, 1, 2].find(function (b) { return b * scale >= 60; }) || 2;
    var bx = W - 10 - bar * scale;
    line(bx, 12, W - 10, 12, '#000', 2); line(bx, 8, bx, 16, '#000', 1.5); line(W - 10, 8, W - 10, 16, '#000', 1.5);
    ctx.font = '11px "DejaVu Sans", Arial, sans-serif'; text(bar + ' m', bx - 4, 12, '#000', 'right');
  }

  function drawCart(j, k) {
    var c = C[j], s = G.sides[j], xB = c.hinge_x[k], y0 = Y(j, 0);
    var laneTop = legendH + j * laneH;
    line(0, laneTop, W, laneTop, '#ddd', 1);
    ctx.font = '11px "DejaVu Sans", Arial, sans-serif'; ctx.textBaseline = 'top';
    text('cart ' + (j + 1) + (s > 0 ? ' (+x side)' : ' (\u2212x side)') + ', crank at \u03c6\u2082 + ' +
         (G.phases[j] * 180 / Math.PI).toFixed(ownAngle ? 1 : 0) + '\u00b0' +
         (ownMass ? ', m\u2032_B = ' + G.masses[j].toFixed(0) + ' kg' : '') +
         (block ? '; no cart geometry in the scene: drawn as a block' : '') +
         (G.cam ? '; cam drive: the model puts B on the shaft axis at mid-stroke' : ''), 4, laneTop + 3, '#555');
    var xs = X(0);
    if (G.cam) {                                       // the cam under the cart, outline only
      var th = D.phi[k] + G.phases[j], rc = scale * G.cam_radius;
      circle(xs, y0, rc, 'rgba(160,110,20,0.8)', null, 1.5);
      line(xs, y0, xs + rc * Math.cos(th), y0 - rc * Math.sin(th), 'rgba(160,110,20,0.9)', 2.5);
    }
    ctx.textBaseline = 'middle';
    function P(xp) { return X(xB + s * xp); }          // a point of the cart at x' from B
    // Guide channel and mix surface over the cart's travel.
    var t0 = X(travel[j][0]), t1 = X(travel[j][1]);
    line(t0, Y(j, guideHalf), t1, Y(j, guideHalf), '#666', 2.5);
    line(t0, Y(j, -guideHalf), t1, Y(j, -guideHalf), '#666', 2.5);
    ctx.fillStyle = '#e8dcc8'; ctx.fillRect(t0, Y(j, yMix), t1 - t0, Math.min(8, scale * 0.05));
    line(t0, Y(j, yMix), t1, Y(j, yMix), '#8c6d46', 1.5);
    // Chassis, guide rollers on their arms, compacting rollers, hinge B.
    var chTop = -guideHalf - 0.06 * U, chBot = block ? yMix : Math.min(yRoll, chTop - 0.12 * U);
    var xa = block ? c0 : Math.min(0, cg.p - Math.max(cg.a, cg.b)), xb = block ? c1 : cg.p + Math.max(cg.a, cg.b);
    ctx.fillStyle = 'rgba(120,140,170,0.55)';
    ctx.fillRect(Math.min(P(xa), P(xb)), Y(j, chTop), Math.abs(P(xb) - P(xa)), Y(j, chBot) - Y(j, chTop));
    if (!block) {
      [xFront, xRear].forEach(function (xp) {
        line(P(xp), Y(j, chTop), P(xp), y0, '#445', 2);
        circle(P(xp), y0, scale * cg.d / 2, '#223', '#9ab', 1.5);
      });
      [cg.p - cg.a, cg.p + cg.a].forEach(function (xp) {
        circle(P(xp), Y(j, yRoll), scale * cg.D / 2, '#333', '#bbb', 1.5);
      });
    }
    line(P(0), y0, P(0), Y(j, chTop), '#445', 2.5);
    // Shaft, crank (or cam), rod.
    if (!G.cam) {
      circle(xs, y0, scale * G.r, '#aaa', null, 1);
      var ax = X(c.pin_x[k]), ay = Y(j, c.pin_y[k]);
      line(xs, y0, ax, ay, '#333', 5);
      line(ax, ay, X(xB), y0, '#777', 4);
      circle(ax, ay, 4, '#000', '#fff', 1.5);
    }
    circle(xs, y0, 5, '#000', '#000');
    circle(X(xB), y0, 4, '#000', '#fff', 1.5);
    if (!D.has_forces) return;
    // Guide reactions at the guide rollers: N > 0 presses the roller down, drawn from above.
    [[xFront, c.N_front[k]], [xRear, c.N_rear[k]]].forEach(function (f, i) {
      var len = arrowN * Math.abs(f[1]) / (D.N_abs_max || 1), x = P(f[0]);
      var tip = f[1] >= 0 ? guideHalf : -guideHalf, tail = f[1] >= 0 ? tip + len : tip - len;
      arrow(x, Y(j, tail), x, Y(j, tip), '#2ca02c');
      var left = block && (i === 0) === (s > 0);         // block: the two labels on either side
      if (len * scale > 8) text(kN(f[1]), left ? x - 4 : x + 4, Y(j, tail), '#1d6b1d', left ? 'right' : 'left');
    });
    // Rod force on the cart at B, along the rod (tension pulls B towards A), drawn beside it.
    var ux = -s, uy = 0;
    if (!G.cam) {
      var dx = c.pin_x[k] - xB, dy = c.pin_y[k], dl = Math.hypot(dx, dy) || 1;
      ux = dx / dl; uy = dy / dl;
    }
    var F = c.F_rod[k], lenF = arrowF * Math.abs(F) / (D.F_rod_abs_max || 1);
    var nx = -uy * 0.08 * U, ny = ux * 0.08 * U;      // offset beside the rod
    var bx = xB + nx, by = ny, tx = bx + ux * lenF, ty = by + uy * lenF;
    var col = F >= 0 ? '#d62728' : '#1f77b4';
    if (F >= 0) arrow(X(bx), Y(j, by), X(tx), Y(j, ty), col); else arrow(X(tx), Y(j, ty), X(bx), Y(j, by), col);
    var away = tx < xB ? 'right' : 'left';             // label beyond the arrow's far end
    if (lenF * scale > 8) text(kN(F), X(tx) + (away === 'right' ? -4 : 4), Y(j, ty) - 9, col, away);
  }

  function pixelHash() {
    var d = ctx.getImageData(0, 0, cv.width, cv.height).data, h = 0;
    for (var i = 0; i < d.length; i += 28) h = (Math.imul(h, 31) + d[i] + 3 * d[i + 1] + 7 * d[i + 2]) >>> 0;
    return h;
  }

  var k = 0, playing = false, speed = 1, simT0 = D.t[0], wall0 = 0;
  // Under #selftest (the browser test) the frames are scheduled by timers on a synthetic clock,
  // 40 ms per callback, instead of requestAnimationFrame: headless Chromium paces animation
  // frames by the wall clock, timers by its virtual time, so a load under a virtual-time budget
  // then shows the same frames however loaded the machine is.
  var selftestNow = 0;
  function clockNow() { return selftest ? selftestNow : performance.now(); }
  function nextFrame(fn) {
    if (!selftest) { requestAnimationFrame(fn); return; }
    setTimeout(function () { selftestNow += 40; fn(selftestNow); }, 40);
  }
  function frameAt(T) {                  // last frame with t <= T
    var lo = 0, hi = N - 1;
    while (lo < hi) { var mid = (lo + hi + 1) >> 1; if (D.t[mid] <= T) lo = mid; else hi = mid - 1; }
    return lo;
  }
  function show(kk) {
    k = kk;
    ctx.clearRect(0, 0, W, H);
    drawLegend(k);
    for (var j = 0; j < n; j++) drawCart(j, k);
    slider.value = k;
    label.textContent = 't = ' + D.t[k].toFixed(3) + ' s';
    sec.setAttribute('data-frame', String(k));
    sec.setAttribute('data-t', D.t[k].toFixed(4));
    if (selftest) {
      sec.setAttribute('data-pixels', String(pixelHash()));
      if (!sec.hasAttribute('data-frame-first')) {  // the first frame drawn, to tell that it moved
        sec.setAttribute('data-frame-first', String(k));
        sec.setAttribute('data-t-first', D.t[k].toFixed(4));
        sec.setAttribute('data-pixels-first', sec.getAttribute('data-pixels'));
      }
    }
    document.dispatchEvent(new CustomEvent('rollerdyn-time', {detail: {t: D.t[k]}}));
  }
  function restartClock() { simT0 = D.t[k]; wall0 = clockNow(); }
  function tick(now) {
    if (!playing) return;
    var span = D.t[N - 1] - D.t[0], T = simT0 + (now - wall0) / 1000 * speed;
    if (span > 0 && T > D.t[N - 1]) { T = D.t[0] + (T - D.t[0]) % span; simT0 = T; wall0 = now; }
    var kk = frameAt(T);
    if (kk !== k) show(kk);
    nextFrame(tick);
  }
  function play() { playing = true; btn.textContent = '\u275a\u275a pause'; restartClock(); nextFrame(tick); }
  function pause() { playing = false; btn.textContent = '\u25b6 play'; }
  btn.addEventListener('click', function () { if (playing) pause(); else play(); });
  slider.addEventListener('input', function () { show(+slider.value); restartClock(); });
  speedSel.addEventListener('change', function () { speed = +speedSel.value; restartClock(); });
  document.addEventListener('rollerdyn-seek', function (e) { show(frameAt(e.detail.t)); restartClock(); });
  // "report.html#t=8.2" opens paused at t = 8.2 s; otherwise the animation plays from the start.
  var at = /(?:^#|[#&])t=([0-9.eE+-]+)/.exec(location.hash);
  if (at) { show(frameAt(parseFloat(at[1]))); restartClock(); }
  else { show(0); if (N > 1) play(); }
})();)JS";

int cartCount(const Table& ts) {
  int n = 0;
  while (ts.has("x_cart_" + std::to_string(n + 1))) ++n;
  return n;
}

// The number of carts of the time series, checked against the scene.
int checkedCartCount(const Scene& scene, const Table& ts) {
  const int n = cartCount(ts);
  if (!ts.has("t") || !ts.has("phi_crank") || n == 0)
    throw std::invalid_argument("mechanism animation: the time series needs t, phi_crank and x_cart_1 ...");
  if (n != scene.carts.count)
    throw std::invalid_argument("mechanism animation: the time series has " + std::to_string(n) +
                                " carts, the scene " + std::to_string(scene.carts.count));
  return n;
}

MechanismGeometry mechanismGeometry(const Scene& scene, int n) {
  MechanismGeometry g;
  g.crank_radius = scene.crank.radius;
  g.cam_drive = scene.hasCamDrive();
  g.rod_length = g.cam_drive ? 0.0 : scene.rods.length;
  g.crank_offset = scene.crank.offset;
  for (int j = 0; j < n; ++j) {
    g.crank_phases.push_back(scene.crankPhase(j));
    g.masses.push_back(scene.cartMass(j));
  }
  g.sides = scene.carts.side;
  g.cart = scene.carts.geometry;
  g.cam_radius = g.cam_drive ? 0.5 * scene.cam.pusher_distance : 0.0;
  return g;
}

// Where each frame's values are: the time series' t, φ2 and cart positions, and (when `forces`)
// the reactions' guide reactions and rod force of each cart.
struct FrameColumns {
  int t = -1, phi = -1;
  std::vector<int> x;
  bool forces = false;
  std::vector<int> N_front, N_rear, F_rod;
};

// The reactions' columns of every cart, when the reactions hold them all.
void findForceColumns(const Table& rx, int n, FrameColumns& c) {
  c.N_front.resize(n);
  c.N_rear.resize(n);
  c.F_rod.resize(n);
  for (int j = 0; c.forces && j < n; ++j) {
    const std::string k = std::to_string(j + 1);
    c.forces = rx.has("N_front_" + k) && rx.has("N_rear_" + k) && rx.has("F_rod_" + k);
    if (c.forces) {
      c.N_front[j] = rx.index("N_front_" + k);
      c.N_rear[j] = rx.index("N_rear_" + k);
      c.F_rod[j] = rx.index("F_rod_" + k);
    }
  }
}

FrameColumns frameColumns(const Table& ts, const Table& rx, int n) {
  FrameColumns c;
  c.t = ts.index("t");
  c.phi = ts.index("phi_crank");
  c.x.resize(n);
  for (int j = 0; j < n; ++j) c.x[j] = ts.index("x_cart_" + std::to_string(j + 1));
  // Reactions of the same rows (both models write them at the same output times).
  c.forces = rx.rows.size() == ts.rows.size() && rx.has("t");
  findForceColumns(rx, n, c);
  const int irt = c.forces ? rx.index("t") : -1;
  for (std::size_t i = 0; c.forces && i < ts.rows.size(); ++i)
    c.forces = std::abs(rx.rows[i][irt] - ts.rows[i][c.t]) <= 1e-9 * std::max(1.0, std::abs(ts.rows[i][c.t]));
  return c;
}

// Cart j's forces of one reactions row, and the largest magnitudes so far.
void addCartForces(MechanismFrames& f, int j, const std::vector<double>& r, const FrameColumns& col) {
  CartFrames& c = f.carts[j];
  c.N_front.push_back(r[col.N_front[j]]);
  c.N_rear.push_back(r[col.N_rear[j]]);
  c.F_rod.push_back(r[col.F_rod[j]]);
  for (double v : {r[col.N_front[j]], r[col.N_rear[j]]})
    if (std::isfinite(v)) f.N_abs_max = std::max(f.N_abs_max, std::abs(v));
  if (std::isfinite(r[col.F_rod[j]])) f.F_rod_abs_max = std::max(f.F_rod_abs_max, std::abs(r[col.F_rod[j]]));
}

// The frame of output row i: time, crank angle, and per cart its crank pin, hinge and forces.
void addFrame(MechanismFrames& f, const Scene& scene, const Table& ts, const Table& rx, std::size_t i,
              const FrameColumns& col) {
  const std::vector<double>& row = ts.rows[i];
  f.rows.push_back(i);
  f.t.push_back(row[col.t]);
  f.phi_crank.push_back(row[col.phi]);
  for (int j = 0; j < int(f.carts.size()); ++j) {
    CartFrames& c = f.carts[j];
    // Crank pin of cart j: θ_j = φ_2 + j·Δφ (Scene::crankPhase, the multibody model's pin).
    const double theta = row[col.phi] + scene.crankPhase(j);
    if (!f.geometry.cam_drive) {
      c.pin_x.push_back(f.geometry.crank_radius * std::cos(theta));
      c.pin_y.push_back(f.geometry.crank_radius * std::sin(theta));
    }
    c.hinge_x.push_back(row[col.x[j]]);
    if (col.forces) addCartForces(f, j, rx.rows[i], col);
  }
}

}  // namespace

MechanismFrames mechanismFrames(const Scene& scene, const Table& ts, const Table& rx, std::size_t max_frames) {
  const int n = checkedCartCount(scene, ts);
  MechanismFrames f;
  f.geometry = mechanismGeometry(scene, n);
  const FrameColumns col = frameColumns(ts, rx, n);
  f.has_forces = col.forces;
  const std::size_t rows = ts.rows.size();
  const std::size_t stride = std::max<std::size_t>(1, (rows + max_frames - 1) / std::max<std::size_t>(1, max_frames));
  f.carts.resize(n);
  for (std::size_t i = 0; i < rows; i += stride) {
    if (!std::isfinite(ts.rows[i][col.phi])) continue;  // a row of an aborted run
    addFrame(f, scene, ts, rx, i, col);
  }
  return f;
}

namespace {

nlohmann::json geometryJson(const MechanismGeometry& g) {
  return {{"r", g.crank_radius},  {"l", g.rod_length}, {"offset", g.crank_offset},
          {"phases", g.crank_phases}, {"masses", g.masses},
          {"sides", g.sides},      {"cam", g.cam_drive}, {"cam_radius", g.cam_radius},
          {"cart", {{"a", g.cart.a}, {"b", g.cart.b}, {"p", g.cart.p}, {"e", g.cart.e}, {"D", g.cart.D},
                    {"d", g.cart.d}, {"com_height", g.cart.com_height}}}};
}

// One cart's frames: the hinge, the crank pin (crank drives) and the forces (when there are).
nlohmann::json cartFramesJson(const CartFrames& c, bool cam_drive, bool has_forces) {
  nlohmann::json cj = {{"hinge_x", roundedArray(c.hinge_x, 6)}};
  if (!cam_drive) {
    cj["pin_x"] = roundedArray(c.pin_x, 6);
    cj["pin_y"] = roundedArray(c.pin_y, 6);
  }
  if (has_forces) {
    cj["N_front"] = roundedArray(c.N_front, 5);
    cj["N_rear"] = roundedArray(c.N_rear, 5);
    cj["F_rod"] = roundedArray(c.F_rod, 5);
  }
  return cj;
}

}  // namespace

nlohmann::json mechanismFramesJson(const MechanismFrames& f) {
  using nlohmann::json;
  json j;
  j["geometry"] = geometryJson(f.geometry);
  j["t"] = roundedArray(f.t, 7);
  j["phi"] = roundedArray(f.phi_crank, 6);
  j["has_forces"] = f.has_forces;
  j["N_abs_max"] = f.N_abs_max;
  j["F_rod_abs_max"] = f.F_rod_abs_max;
  j["carts"] = json::array();
  for (const CartFrames& c : f.carts) j["carts"].push_back(cartFramesJson(c, f.geometry.cam_drive, f.has_forces));
  return j;
}

std::string mechanismAnimationHtml(const MechanismFrames& f) {
  if (f.empty()) return "";
  std::string h = "<section id=\"mechanism\" class=\"mech\" data-frame=\"0\" data-t=\"0\">\n";
  h += "<div class=\"mech-controls\"><button id=\"mech-play\" type=\"button\">&#9654; play</button> "
       "<input id=\"mech-slider\" type=\"range\" min=\"0\" max=\"" + std::to_string(f.t.size() - 1) +
       "\" step=\"1\" value=\"0\" aria-label=\"time\"> <span id=\"mech-time\">t = 0 s</span> "
       "<label>speed <select id=\"mech-speed\"><option value=\"0.1\">0.1&times;</option>"
       "<option value=\"0.25\">0.25&times;</option><option value=\"0.5\">0.5&times;</option>"
       "<option value=\"1\" selected>1&times;</option><option value=\"2\">2&times;</option></select></label></div>\n";
  h += "<canvas id=\"mech-canvas\" width=\"540\" height=\"400\"></canvas>\n";
  h += jsonScriptBlock("mech-data", mechanismFramesJson(f));
  h += inlineScriptBlock(kScript);
  h += "</section>\n";
  return h;
}

}  // namespace rollerdyn
