// ccd-exact's query page: draws DATA (written by ccd-picture) on 2D canvases.
// Each body is {c + M·y : |y| <= 1}; its outline under the orthographic view
// is the ellipse with shape P·M·Mᵀ·Pᵀ (P: the view's right and up rows).
(function () {
  "use strict";
  const D = DATA;
  const view = document.getElementById("view");
  const ctx = view.getContext("2d");
  const strip = document.getElementById("strip");
  const sctx = strip.getContext("2d");
  const slider = document.getElementById("slider");
  const readout = document.getElementById("readout");
  const playButton = document.getElementById("play");
  const T0 = D.span[0], T1 = D.span[1];
  const S = D.samples;
  let yaw = -0.9, pitch = 0.35, t = T0, playing = false, fit = null;

  document.getElementById("verdict").textContent = D.verdict;

  function dot(a, b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

  // The view: camera direction v (towards the viewer), right r, up u.
  function basis() {
    const cy = Math.cos(yaw), sy = Math.sin(yaw), cp = Math.cos(pitch), sp = Math.sin(pitch);
    return {
      r: [-sy, cy, 0],
      u: [-sp * cy, -sp * sy, cp],
      v: [cp * cy, cp * sy, sp],
    };
  }

  // The pose of body `k` ("a" or "b") at time `time`, linear between samples.
  function poseAt(k, time) {
    const ts = S.t, rows = S[k];
    let lo = 0, hi = ts.length - 1;
    if (time <= ts[0]) return unpack(rows[0]);
    if (time >= ts[hi]) return unpack(rows[hi]);
    while (hi - lo > 1) {
      const mid = (lo + hi) >> 1;
      if (ts[mid] <= time) lo = mid; else hi = mid;
    }
    const w = (time - ts[lo]) / (ts[hi] - ts[lo] || 1);
    return unpack(rows[lo].map((x, i) => x + w * (rows[hi][i] - x)));
  }
  function unpack(p) {
    return { c: [p[0], p[1], p[2]], m: [[p[3], p[4], p[5]], [p[6], p[7], p[8]], [p[9], p[10], p[11]]] };
  }
  function column(m, j) { return [m[0][j], m[1][j], m[2][j]]; }

  // The outline ellipse of a pose in view coordinates.
  function outline(p, B) {
    let a = 0, b = 0, c = 0;
    for (let j = 0; j < 3; j++) {
      const col = column(p.m, j);
      const x = dot(B.r, col), y = dot(B.u, col);
      a += x * x; b += x * y; c += y * y;
    }
    const mean = (a + c) / 2, root = Math.sqrt(((a - c) / 2) ** 2 + b * b);
    return {
      x: dot(B.r, p.c), y: dot(B.u, p.c), depth: dot(B.v, p.c),
      ra: Math.sqrt(Math.max(mean + root, 0)), rb: Math.sqrt(Math.max(mean - root, 0)),
      angle: 0.5 * Math.atan2(2 * b, a - c),
      halfW: Math.sqrt(a), halfH: Math.sqrt(c),
    };
  }

  // Scale and offset that keep every sampled body in the canvas.
  function computeFit() {
    const B = basis();
    let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
    for (const k of ["a", "b"]) {
      for (const row of S[k]) {
        const e = outline(unpack(row), B);
        x0 = Math.min(x0, e.x - e.halfW); x1 = Math.max(x1, e.x + e.halfW);
        y0 = Math.min(y0, e.y - e.halfH); y1 = Math.max(y1, e.y + e.halfH);
      }
    }
    const pad = 30;
    const s = Math.min((view.width - 2 * pad) / (x1 - x0 || 1), (view.height - 2 * pad) / (y1 - y0 || 1));
    return { s: s, cx: (x0 + x1) / 2, cy: (y0 + y1) / 2 };
  }
  function screen(x, y) {
    return [view.width / 2 + fit.s * (x - fit.cx), view.height / 2 - fit.s * (y - fit.cy)];
  }

  // The state at `time`: a contact instant within 1/500 of the span wins.
  function stateAt(time) {
    const eps = (T1 - T0) / 500;
    for (let i = 0; i < D.contacts.length; i++) {
      if (Math.abs(D.contacts[i].t - time) <= eps) return { state: "touch", contact: i };
    }
    for (const g of D.gaps) if (g.lo <= time && time <= g.hi) return { state: "undecided" };
    for (const s of D.timeline) {
      if (s.start < s.end && s.start <= time && time <= s.end) return { state: s.state, certified: s.certified };
    }
    return { state: "undecided" };
  }

  function drawAxes(B) {
    const o = [50, view.height - 40], names = ["x", "y", "z"], cols = ["#c33", "#393", "#33c"];
    for (let k = 0; k < 3; k++) {
      const e = [0, 0, 0]; e[k] = 1;
      const dx = 28 * dot(B.r, e), dy = -28 * dot(B.u, e);
      ctx.strokeStyle = cols[k]; ctx.lineWidth = 2;
      ctx.beginPath(); ctx.moveTo(o[0], o[1]); ctx.lineTo(o[0] + dx, o[1] + dy); ctx.stroke();
      ctx.fillStyle = cols[k]; ctx.font = "12px sans-serif";
      ctx.fillText(names[k], o[0] + dx * 1.2 - 3, o[1] + dy * 1.2 + 4);
    }
  }

  function drawView() {
    const B = basis();
    ctx.fillStyle = "#ffffff";
    ctx.fillRect(0, 0, view.width, view.height);
    const st = stateAt(t);
    const edge = D.colors[st.state] || D.colors.undecided;
    const bodies = [["a", "A", D.colors.a], ["b", "B", D.colors.b]].map(function (k) {
      return { key: k[0], name: k[1], fill: k[2], e: outline(poseAt(k[0], t), B) };
    });
    bodies.sort(function (p, q) { return p.e.depth - q.e.depth; });
    for (const body of bodies) {
      const e = body.e, [x, y] = screen(e.x, e.y);
      ctx.beginPath();
      ctx.ellipse(x, y, Math.max(e.ra * fit.s, 0.5), Math.max(e.rb * fit.s, 0.5), -e.angle, 0, 2 * Math.PI);
      ctx.fillStyle = body.fill; ctx.fill();
      ctx.lineWidth = 4; ctx.strokeStyle = edge; ctx.stroke();
      ctx.fillStyle = "#ffffff"; ctx.font = "bold 16px sans-serif";
      ctx.fillText(body.name, x - 5, y + 6);
    }
    if (st.contact !== undefined) {
      const c = D.contacts[st.contact];
      if (c.point) {
        const [px, py] = screen(dot(B.r, c.point), dot(B.u, c.point));
        const nx = dot(B.r, c.normal), ny = dot(B.u, c.normal), len = Math.hypot(nx, ny) || 1;
        ctx.strokeStyle = "#000"; ctx.lineWidth = 2.5;
        ctx.beginPath(); ctx.moveTo(px, py); ctx.lineTo(px + 60 * nx / len, py - 60 * ny / len); ctx.stroke();
        ctx.beginPath(); ctx.arc(px, py, 6, 0, 2 * Math.PI);
        ctx.fillStyle = "#000"; ctx.fill(); ctx.lineWidth = 2; ctx.strokeStyle = "#fff"; ctx.stroke();
      }
    }
    drawAxes(B);
  }

  function xOf(time) { return 10 + (strip.width - 20) * (time - T0) / (T1 - T0); }

  function drawStrip() {
    sctx.fillStyle = "#ffffff";
    sctx.fillRect(0, 0, strip.width, strip.height);
    const y = 22, h = 20;
    for (const s of D.timeline) {
      if (s.start >= s.end) continue;
      sctx.fillStyle = D.colors[s.state];
      sctx.fillRect(xOf(s.start), y, Math.max(xOf(s.end) - xOf(s.start), 0.5), h);
    }
    sctx.fillStyle = D.colors.undecided;
    for (const g of D.gaps) sctx.fillRect(xOf(g.lo), y, Math.max(xOf(g.hi) - xOf(g.lo), 0.5), h);
    sctx.strokeStyle = "#444"; sctx.lineWidth = 1;
    sctx.strokeRect(10, y, strip.width - 20, h);
    sctx.font = "11px sans-serif"; sctx.fillStyle = "#000";
    D.contacts.forEach(function (c, i) {
      const x = xOf(c.t);
      sctx.fillRect(x - 1, y - 6, 2, h + 12);
      sctx.fillText("t" + (i + 1), x - 6, y - 8);
    });
    if (D.first_contact !== null) {
      const x = xOf(D.first_contact);
      sctx.font = "bold 11px sans-serif";
      sctx.fillText("first contact", Math.min(Math.max(x - 30, 2), strip.width - 75), y + h + 16);
    }
    const x = xOf(t);
    sctx.strokeStyle = "#000"; sctx.lineWidth = 2;
    sctx.beginPath(); sctx.moveTo(x, y - 4); sctx.lineTo(x, y + h + 4); sctx.stroke();
  }

  function draw() {
    drawView();
    drawStrip();
    const st = stateAt(t);
    let text = "t = " + t.toPrecision(12) + "   state: " + st.state;
    if (st.contact !== undefined) {
      const c = D.contacts[st.contact];
      text += " (contact t" + (st.contact + 1) + " ∈ " + c.enclosure + (c.certified ? ", certified" : ", NOT certified") + ")";
    } else if (st.certified === false) {
      text += " (not proven)";
    }
    readout.textContent = text;
  }

  function setTime(time, fromSlider) {
    t = Math.min(Math.max(time, T0), T1);
    if (!fromSlider) slider.value = String(Math.round(1000 * (t - T0) / (T1 - T0)));
    draw();
  }

  slider.addEventListener("input", function () { setTime(T0 + (T1 - T0) * slider.value / 1000, true); });
  playButton.addEventListener("click", function () {
    playing = !playing;
    playButton.textContent = playing ? "pause" : "play";
    if (playing) {
      if (t >= T1) t = T0;
      let last = null;
      const step = function (now) {
        if (!playing) return;
        if (last !== null) setTime(t + (T1 - T0) * (now - last) / 8000, false);
        last = now;
        if (t >= T1) { playing = false; playButton.textContent = "play"; return; }
        requestAnimationFrame(step);
      };
      requestAnimationFrame(step);
    }
  });
  const list = document.getElementById("contacts");
  D.contacts.forEach(function (c, i) {
    const b = document.createElement("button");
    b.textContent = "t" + (i + 1) + " ≈ " + c.approx;
    b.title = c.enclosure;
    b.addEventListener("click", function () { setTime(c.t, false); });
    list.appendChild(b);
  });
  let drag = null;
  view.addEventListener("mousedown", function (e) { drag = [e.clientX, e.clientY]; });
  window.addEventListener("mouseup", function () { drag = null; });
  window.addEventListener("mousemove", function (e) {
    if (!drag) return;
    yaw -= (e.clientX - drag[0]) * 0.01;
    pitch = Math.min(Math.max(pitch + (e.clientY - drag[1]) * 0.01, -1.5), 1.5);
    drag = [e.clientX, e.clientY];
    fit = computeFit();
    draw();
  });

  fit = computeFit();
  const asked = /[#&]t=([-+0-9.eE]+)/.exec(location.hash);
  const start = asked ? parseFloat(asked[1]) : (D.first_contact !== null ? D.first_contact : T0);
  setTime(start, false);
})();
