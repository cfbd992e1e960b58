// canvas3d.js: a 3D player's picture, drawn by the browser on a <canvas> (an anywidget front end).
//
// Loaded by reference_impl/kit/canvas3d.py (View3D); nothing to build, no network.
// The kernel sends the geometry once (`geometry`: points, edges, faces, marks as flat arrays,
// scaled into the unit ball) and the steps once (`steps`: per step a turn `yaw` in radians and a
// caption).  Everything after that happens in the page:
//   - `step` (1-based) is linked in the page to the Play widget and the slider: each change is drawn
//     at once from the cached geometry, so play never waits for the kernel and never skips a step;
//   - a mouse drag turns the picture (left-right: about the vertical axis, up-down: tilts it);
//     no message per frame, the final view is saved (`yaw`, `pitch`) when the button is released;
//   - the keyboard, once the picture has the focus (Tab; a focus ring):
//       arrow keys          turn it (5 degrees a press; Shift: 20); saved when the key is released
//       Page Down / Page Up the next / previous step;  Home / End: the first / last step
//       Space               play / pause (sets `playing`, linked to the Play widget)
//       0                   back to the starting view
// `label` is the canvas's aria-label; the caption line is also a polite live region.
// el.__kit3dStats (and the canvas's data-draws attribute) count every drawing: `draws`, `steps`
// (the step of each drawing, in order), `drawMs` (the time to draw one), `stepMs` (from a step's
// change to the frame that shows it), `turnMs` (from a drag or key event to its frame).

const VIRIDIS = [[68, 1, 84], [72, 40, 120], [62, 74, 137], [49, 104, 142], [38, 130, 142],
  [31, 158, 137], [53, 183, 121], [109, 205, 89], [180, 222, 44], [253, 231, 37]];
const TURN = Math.PI / 36, BIG_TURN = Math.PI / 9, DRAG_RAD_PER_PX = 0.01;
const KEEP = 4000;

function viridis(t) {
  const x = Math.min(Math.max(t, 0), 1) * (VIRIDIS.length - 1);
  const k = Math.min(Math.floor(x), VIRIDIS.length - 2), f = x - k;
  const a = VIRIDIS[k], b = VIRIDIS[k + 1];
  return `rgb(${Math.round(a[0] + f * (b[0] - a[0]))},${Math.round(a[1] + f * (b[1] - a[1]))},` +
    `${Math.round(a[2] + f * (b[2] - a[2]))})`;
}

function esc(s) {
  return String(s).replace(/&/g, "&amp;").replace(/</g, "&lt;").replace(/>/g, "&gt;");
}

function push(list, v) {
  list.push(v);
  if (list.length > KEEP) list.shift();
}

function render({ model, el }) {
  const wrap = document.createElement("div");
  wrap.className = "kit-3d";
  const canvas = document.createElement("canvas");
  canvas.className = "kit-canvas3d";
  canvas.tabIndex = 0;
  canvas.setAttribute("role", "application");
  canvas.setAttribute("data-lm-suppress-shortcuts", "true");
  canvas.style.touchAction = "none";
  const caption = document.createElement("div");
  caption.className = "kit-3d-caption kit-live-caption";
  caption.setAttribute("role", "status");
  caption.setAttribute("aria-live", "polite");
  wrap.append(canvas, caption);
  el.appendChild(wrap);

  const stats = { draws: 0, steps: [], drawMs: [], stepMs: [], turnMs: [] };
  el.__kit3dStats = stats;
  canvas.__kit3dStats = stats;
  let geo = null;
  let view = { yaw: model.get("yaw") || 0, pitch: model.get("pitch") || 0 };
  let press = null;
  let focused = false;

  function load() {
    const g = model.get("geometry") || {};
    geo = {
      xyz: Float64Array.from(g.xyz || []),
      edges: Int32Array.from(g.edges || []),
      faces: Int32Array.from(g.faces || []),
      marks: new Set(g.marks || []),
      depthColors: !!g.depth_colors,
      edgeColor: g.edge_color || "#555555", faceColor: g.face_color || "#f4a6a6",
      faceAlpha: g.face_alpha ?? 0.25, pointColor: g.point_color || "#1f4e9c",
      markColor: g.mark_color || "#d62728", pointR: g.point_r ?? 3, markR: g.mark_r ?? 6,
      lw: g.lw ?? 0.8,
    };
  }

  function stepIndex() {
    const n = (model.get("steps") || []).length;
    return Math.max(0, Math.min(n - 1, (model.get("step") || 1) - 1));
  }

  function describe() {
    const steps = model.get("steps") || [];
    const k = stepIndex();
    const said = steps.length ? `step ${k + 1}/${steps.length}: ${steps[k].caption || ""}` : "";
    caption.innerHTML = steps.length ? `<b>step ${k + 1}/${steps.length}</b>: ${esc(steps[k].caption || "")}` : "";
    canvas.setAttribute("aria-label", (model.get("label") || "3D picture") + (said ? ". Now " + said : ""));
  }

  function draw() {
    const t0 = performance.now();
    if (!geo) load();
    const w = model.get("width") || 480, h = model.get("height") || 400;
    const dpr = window.devicePixelRatio || 1;
    if (canvas.width !== Math.round(w * dpr) || canvas.height !== Math.round(h * dpr)) {
      canvas.width = Math.round(w * dpr);
      canvas.height = Math.round(h * dpr);
      canvas.style.width = w + "px";
      canvas.style.height = h + "px";
    }
    const ctx = canvas.getContext("2d");
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    ctx.fillStyle = "white";
    ctx.fillRect(0, 0, w, h);
    const steps = model.get("steps") || [];
    const k = stepIndex();
    const yaw = (steps.length ? steps[k].yaw || 0 : 0) + view.yaw, pitch = view.pitch;
    const cy = Math.cos(yaw), sy = Math.sin(yaw), cp = Math.cos(pitch), sp = Math.sin(pitch);
    const n = geo.xyz.length / 3;
    const X = new Float64Array(n), Y = new Float64Array(n), Z = new Float64Array(n);
    const scale = 0.44 * Math.min(w, h), ox = w / 2, oy = h / 2;
    let zmin = Infinity, zmax = -Infinity;
    for (let i = 0; i < n; i++) {
      const x = geo.xyz[3 * i], y = geo.xyz[3 * i + 1], z = geo.xyz[3 * i + 2];
      const qx = cy * x - sy * z, qz = sy * x + cy * z;     // turned about the vertical axis
      const py = cp * y - sp * qz, pz = sp * y + cp * qz;   // then tilted towards the viewer
      X[i] = ox + scale * qx;
      Y[i] = oy - scale * py;
      Z[i] = pz;                                            // larger: farther from the viewer
      if (pz < zmin) zmin = pz;
      if (pz > zmax) zmax = pz;
    }
    const span = zmax - zmin || 1;
    const near = i => 1 - (Z[i] - zmin) / span;             // 1 nearest, 0 farthest
    // faces, far ones first, translucent: the marked point shows through
    const F = geo.faces.length / 3;
    if (F) {
      const order = Array.from({ length: F }, (_, f) => f);
      const depth = order.map(f => Z[geo.faces[3 * f]] + Z[geo.faces[3 * f + 1]] + Z[geo.faces[3 * f + 2]]);
      order.sort((a, b) => depth[b] - depth[a]);
      ctx.globalAlpha = geo.faceAlpha;
      ctx.fillStyle = geo.faceColor;
      for (const f of order) {
        const a = geo.faces[3 * f], b = geo.faces[3 * f + 1], c = geo.faces[3 * f + 2];
        ctx.beginPath();
        ctx.moveTo(X[a], Y[a]); ctx.lineTo(X[b], Y[b]); ctx.lineTo(X[c], Y[c]);
        ctx.closePath();
        ctx.fill();
      }
      ctx.globalAlpha = 1;
    }
    // edges, far ones first (coloured by depth, or one colour)
    const E = geo.edges.length / 2;
    ctx.lineWidth = geo.lw;
    if (geo.depthColors) {
      const order = Array.from({ length: E }, (_, e) => e);
      const depth = order.map(e => Z[geo.edges[2 * e]] + Z[geo.edges[2 * e + 1]]);
      order.sort((a, b) => depth[b] - depth[a]);
      for (const e of order) {
        const a = geo.edges[2 * e], b = geo.edges[2 * e + 1];
        ctx.strokeStyle = viridis(0.5 * (near(a) + near(b)));
        ctx.beginPath(); ctx.moveTo(X[a], Y[a]); ctx.lineTo(X[b], Y[b]); ctx.stroke();
      }
    } else if (E) {
      ctx.strokeStyle = geo.edgeColor;
      ctx.beginPath();
      for (let e = 0; e < E; e++) {
        const a = geo.edges[2 * e], b = geo.edges[2 * e + 1];
        ctx.moveTo(X[a], Y[a]); ctx.lineTo(X[b], Y[b]);
      }
      ctx.stroke();
    }
    // points, far ones first; the marked ones (the new point) last and larger
    const order = Array.from({ length: n }, (_, i) => i).sort((a, b) => Z[b] - Z[a]);
    for (const pass of [false, true]) {
      for (const i of order) {
        if (geo.marks.has(i) !== pass) continue;
        ctx.beginPath();
        ctx.arc(X[i], Y[i], pass ? geo.markR : geo.pointR, 0, 2 * Math.PI);
        ctx.fillStyle = pass ? geo.markColor : geo.depthColors ? viridis(near(i)) : geo.pointColor;
        ctx.fill();
      }
    }
    if (focused) {         // the turn, for keyboard users
      ctx.fillStyle = "#1a73e8";
      ctx.font = "11px DejaVu Sans, Verdana, sans-serif";
      ctx.fillText(`turned ${Math.round(yaw * 180 / Math.PI)}°, tilted ${Math.round(pitch * 180 / Math.PI)}°`, 6, h - 6);
    }
    stats.draws += 1;
    push(stats.steps, k + 1);
    push(stats.drawMs, performance.now() - t0);
    canvas.dataset.draws = String(stats.draws);
    canvas.dataset.step = String(k + 1);
  }

  function drawn(list, since) {     // draw now; when the frame is on screen, record since -> frame
    draw();
    requestAnimationFrame(() => push(list, performance.now() - since));
  }

  let saving = false;
  function saveView() {
    saving = true;            // both at once: a change event must not read one new and one old value
    try {
      model.set({ yaw: view.yaw, pitch: view.pitch });
      model.save_changes();
    } finally {
      saving = false;
    }
  }

  function setStep(v) {
    const n = (model.get("steps") || []).length;
    const s = Math.max(1, Math.min(n, v));
    if (s === model.get("step")) return;
    model.set("step", s);
    model.save_changes();      // the link to the slider and the Play widget runs in the page
  }

  // -- the mouse: drag to turn
  canvas.addEventListener("pointerdown", ev => {
    if (ev.button !== 0) return;
    canvas.focus({ preventScroll: true });
    press = { x: ev.clientX, y: ev.clientY, yaw: view.yaw, pitch: view.pitch, moved: false };
    canvas.setPointerCapture(ev.pointerId);
    ev.preventDefault();
  });
  canvas.addEventListener("pointermove", ev => {
    if (!press) return;
    press.moved = true;
    view.yaw = press.yaw + (ev.clientX - press.x) * DRAG_RAD_PER_PX;
    view.pitch = Math.max(-Math.PI / 2, Math.min(Math.PI / 2, press.pitch + (ev.clientY - press.y) * DRAG_RAD_PER_PX));
    drawn(stats.turnMs, ev.timeStamp);
  });
  const release = () => {
    if (!press) return;
    const moved = press.moved;
    press = null;
    if (moved) saveView();
  };
  canvas.addEventListener("pointerup", release);
  canvas.addEventListener("pointercancel", release);

  // -- the keyboard
  const TURNS = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, -1], ArrowDown: [0, 1] };
  canvas.addEventListener("keydown", ev => {
    if (ev.altKey || ev.ctrlKey || ev.metaKey) return;
    const n = (model.get("steps") || []).length;
    if (TURNS[ev.key]) {
      const d = ev.shiftKey ? BIG_TURN : TURN, [dy, dp] = TURNS[ev.key];
      view.yaw += dy * d;
      view.pitch = Math.max(-Math.PI / 2, Math.min(Math.PI / 2, view.pitch + dp * d));
      drawn(stats.turnMs, ev.timeStamp);
    } else if (ev.key === "PageDown" || ev.key === "PageUp") {
      setStep((model.get("step") || 1) + (ev.key === "PageDown" ? 1 : -1));
    } else if (ev.key === "Home" || ev.key === "End") {
      setStep(ev.key === "Home" ? 1 : n);
    } else if (ev.key === " ") {
      model.set("playing", !model.get("playing"));
      model.save_changes();
    } else if (ev.key === "0") {
      view = { yaw: 0, pitch: model.get("start_pitch") || 0 };
      draw();
      saveView();
    } else {
      return;
    }
    ev.preventDefault();
    ev.stopPropagation();      // not a notebook shortcut while the picture has the focus
  });
  canvas.addEventListener("keyup", ev => { if (TURNS[ev.key]) saveView(); });
  canvas.addEventListener("focus", () => { focused = true; draw(); });
  canvas.addEventListener("blur", () => { focused = false; draw(); });

  model.on("change:step", () => {
    const t0 = performance.now();
    describe();
    drawn(stats.stepMs, t0);
  });
  model.on("change:geometry", () => { load(); draw(); });
  model.on("change:steps", () => { describe(); draw(); });
  model.on("change:label", describe);
  const fromKernel = () => {
    if (press || saving) return;
    view = { yaw: model.get("yaw") || 0, pitch: model.get("pitch") || 0 };
    draw();
  };
  model.on("change:yaw", fromKernel);
  model.on("change:pitch", fromKernel);
  describe();
  draw();
}

export default { render };
