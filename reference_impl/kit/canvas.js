// canvas.js: the point picker's picture, drawn by the browser as SVG (an anywidget front end).
//
// Loaded by reference_impl/kit/canvas.py (SceneView); nothing to build, no network.
// The kernel sends a *scene* (scene.py: paths, circles, dots and text in image pixels)
// and the picker's points in pixels.  This module draws them and turns the mouse into
// messages for the kernel:
//   {kind: "add", x, y}                        a click on empty space
//   {kind: "remove", i}                        a click on point i
//   {kind: "move", i, x, y, seq, drag, end}    point i dragged to (x, y); end on release
// Invariants:
//   - while point i is dragged, every vertex, dot, label and circle of the scene that
//     refers to i is drawn at the pointer, in the same frame as the pointer event;
//   - at most one move is waiting for the kernel; the next one leaves when the kernel
//     has answered (its `ack` equals the move's seq) and at least 50 ms after the last,
//     and the release is always sent;
//   - el.__kitStats records, per drawn move, the time to draw it and from the pointer
//     event to the frame, and per answered move the time until the kernel's answer.
// Without a mouse (the picture takes the focus: tabindex 0, a focus ring):
//   arrow keys      move the + cursor, or the selected point (4 px; Shift: 20 px), sent as
//                   the moves of one drag that ends when the key is released
//   Enter           {kind: "add"} at the cursor
//   ] / [ / Space   select the next / previous point / the one nearest the cursor; Escape: none
//   Delete, Backspace  {kind: "remove", i} of the selected point
// A player's picture (`stepper`): left / right arrow {kind: "step", by: -1 / 1} (Shift: 5),
// Home / End by -1e6 / 1e6, Space {kind: "play"} (play / pause).  Keys the picture uses do not reach JupyterLab's shortcuts.
// `label` is the picture's aria-label; `announce` fills a polite live region (the status line).

const NS = "http://www.w3.org/2000/svg";
const THROTTLE_MS = 50;
const DRAG_START_PX = 3;
const KEY_STEP_PX = 4, KEY_BIG_STEP_PX = 20;
const ARROWS = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, -1], ArrowDown: [0, 1] };

function esc(s) {
  return String(s).replace(/&/g, "&amp;").replace(/</g, "&lt;").replace(/>/g, "&gt;").replace(/"/g, "&quot;");
}

function at(list, k) {
  return list && list.length ? list[k % list.length] : undefined;
}

function circumcircle(a, b, c) {
  const bx = b[0] - a[0], by = b[1] - a[1], cx = c[0] - a[0], cy = c[1] - a[1];
  const d = 2 * (bx * cy - by * cx);
  if (d === 0) return null;
  const b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  const ux = (cy * b2 - by * c2) / d, uy = (bx * c2 - cx * b2) / d;
  return [a[0] + ux, a[1] + uy, Math.hypot(ux, uy)];
}

function paint(fill, fo, stroke, so, lw, dash) {
  let s = ` fill="${fill ?? "none"}"`;
  if (fill && fill !== "none" && fo !== undefined && fo < 1) s += ` fill-opacity="${fo}"`;
  if (stroke && stroke !== "none" && lw > 0) {
    s += ` stroke="${stroke}" stroke-width="${lw}"`;
    if (so !== undefined && so < 1) s += ` stroke-opacity="${so}"`;
    if (dash) s += ` stroke-dasharray="${dash}"`;
  } else {
    s += ` stroke="none"`;
  }
  return s;
}

function textSvg(item, x, y) {
  const lines = String(item.s).split("\n");
  const lh = 1.2 * item.size;
  const anchor = { left: "start", center: "middle", right: "end" }[item.ha] || "start";
  // matplotlib stacks a multi-line text around its anchor by the vertical alignment
  let first;
  if (item.va === "top") first = item.size * 0.8;
  else if (item.va === "center") first = -((lines.length - 1) * lh) / 2 + item.size * 0.35;
  else first = -(lines.length - 1) * lh - (item.va === "bottom" ? item.size * 0.25 : 0);
  const rot = item.rot ? ` transform="rotate(${-item.rot} ${x} ${y})"` : "";
  const spans = lines.map((line, k) =>
    `<tspan x="${x}" y="${(y + first + k * lh).toFixed(2)}">${esc(line)}</tspan>`).join("");
  return `<text font-size="${item.size}" fill="${item.color}" text-anchor="${anchor}" ` +
    `font-family="DejaVu Sans, Verdana, sans-serif"${rot}>${spans}</text>`;
}

let views = 0;

function render({ model, el }) {
  const clipId = `kit-clip-${++views}-${Math.random().toString(36).slice(2, 8)}`;
  const svg = document.createElementNS(NS, "svg");
  svg.classList.add("kit-canvas", "kit-picker-image");
  svg.style.touchAction = "none";
  svg.style.userSelect = "none";
  svg.style.display = "block";
  el.appendChild(svg);
  const stats = { frames: [], answers: [], draws: 0 };
  el.__kitStats = stats;
  svg.__kitStats = stats;

  let press = null;      // {i, x, y, moved}
  let drag = null;       // {i, x, y, id, endSeq}
  let ghost = null;      // [x, y]: a click's new point, until the kernel's points arrive
  let seq = 0, inflight = null, pending = false, lastSend = -1e9, timer = null, dragId = 0;
  const sentAt = new Map();
  let sel = null;        // the point the keyboard has selected
  let cursor = null;     // [x, y]: the keyboard's + cursor, in image pixels
  let focused = false;
  // the live region: screen readers read out the status line when it changes
  const say = document.createElement("div");
  say.className = "kit-live";
  say.setAttribute("role", "status");
  say.setAttribute("aria-live", "polite");
  el.appendChild(say);

  function pts() { return model.get("points") || []; }
  function pos(i, P) {
    if (drag && drag.i === i) return [drag.x, drag.y];
    return [P[2 * i], P[2 * i + 1]];
  }

  function draw() {
    const scene = model.get("scene") || {};
    const w = scene.w || 440, h = scene.h || 400;
    svg.setAttribute("viewBox", `0 0 ${w} ${h}`);
    svg.setAttribute("width", w);
    svg.setAttribute("height", h);
    const P = pts();
    const out = [`<rect x="0" y="0" width="${w}" height="${h}" fill="white"/>`];
    const [cx0, cy0, cw, ch] = scene.clip || [0, 0, w, h];
    out.push(`<defs><clipPath id="${clipId}"><rect x="${cx0}" y="${cy0}" width="${cw}" height="${ch}"/></clipPath></defs>`);
    let open = false;     // inside the clipped group: consecutive clipped items share one <g>
    if (scene.raster) out.push(`<image href="${scene.raster}" x="0" y="0" width="${w}" height="${h}"/>`);
    for (const item of scene.items || []) {
      if (!!item.clip !== open) { out.push(open ? "</g>" : `<g clip-path="url(#${clipId})">`); open = !open; }
      if (item.t === "path") {
        const parts = [];
        let j = 0;
        for (const n of item.n) {
          let d = "";
          for (let k = 0; k < n; k++, j++) {
            const r = item.ref[j];
            const [x, y] = r >= 0 ? pos(r, P) : [item.xy[2 * j], item.xy[2 * j + 1]];
            d += (k ? "L" : "M") + x.toFixed(2) + " " + y.toFixed(2);
          }
          parts.push(item.closed ? d + "Z" : d);
        }
        // one <path> for all parts only when they are outlines of one style: filled parts drawn as one
        // path would cancel where they overlap with opposite windings, and translucent ones must
        // darken where they overlap, as Agg draws them
        const uniform = [item.fill, item.fo, item.stroke, item.so, item.lw].every(l => !l || l.length <= 1);
        const outlines = !item.fill || item.fill.every(f => f === "none");
        if (uniform && (outlines || parts.length === 1)) {
          out.push(`<path d="${parts.join("")}"${paint(at(item.fill, 0), at(item.fo, 0), at(item.stroke, 0),
            at(item.so, 0), at(item.lw, 0), item.dash)}/>`);
        } else {
          parts.forEach((d, k) => out.push(`<path d="${d}"${paint(at(item.fill, k), at(item.fo, k),
            at(item.stroke, k), at(item.so, k), at(item.lw, k), item.dash)}/>`));
        }
      } else if (item.t === "circle") {
        let [cx, cy] = item.c, r = item.r;
        if (item.through && item.through.length === 3 && drag && item.through.includes(drag.i)) {
          const cc = circumcircle(...item.through.map(i => pos(i, P)));
          if (cc) [cx, cy, r] = cc;
        }
        out.push(`<circle cx="${cx.toFixed(2)}" cy="${cy.toFixed(2)}" r="${r.toFixed(2)}"${paint(at(item.fill, 0),
          at(item.fo, 0), at(item.stroke, 0), at(item.so, 0), at(item.lw, 0), item.dash)}/>`);
      } else if (item.t === "dots") {
        const m = item.xy.length / 2;
        for (let k = 0; k < m; k++) {
          const r = item.ref[k];
          const [x, y] = r >= 0 ? pos(r, P) : [item.xy[2 * k], item.xy[2 * k + 1]];
          out.push(`<circle cx="${x.toFixed(2)}" cy="${y.toFixed(2)}" r="${at(item.r, k)}"${paint(at(item.fill, k),
            at(item.fo, k), at(item.stroke, k), at(item.so, k), at(item.lw, k), "")}/>`);
        }
      } else if (item.t === "text") {
        let [x, y] = item.xy;
        if (item.ref >= 0) { const p = pos(item.ref, P); x = p[0] + item.dx; y = p[1] + item.dy; }
        out.push(textSvg(item, x, y));
      }
    }
    if (open) out.push("</g>");
    if (drag) out.push(`<circle cx="${drag.x}" cy="${drag.y}" r="6" fill="none" stroke="#d62728" stroke-width="1.5"/>`);
    if (focused && live()) {
      if (sel !== null && sel < P.length / 2) {
        const [sx, sy] = pos(sel, P);
        out.push(`<circle class="kit-selected" cx="${sx.toFixed(2)}" cy="${sy.toFixed(2)}" r="9" fill="none" ` +
          `stroke="#ff7f0e" stroke-width="2.5"/>`);
      } else {
        const [ux, uy] = cursorAt();
        out.push(`<path class="kit-cursor" d="M${ux - 8} ${uy}H${ux + 8}M${ux} ${uy - 8}V${uy + 8}" ` +
          `stroke="#1a73e8" stroke-width="2"/>`);
      }
    }
    if (ghost) out.push(`<circle cx="${ghost[0]}" cy="${ghost[1]}" r="4" fill="#1f4e9c" fill-opacity="0.5"/>`);
    svg.innerHTML = out.join("");
    stats.draws += 1;
  }

  function local(ev) {
    const box = svg.getBoundingClientRect();
    const vb = svg.viewBox.baseVal;
    return [(ev.clientX - box.left) * (vb.width / box.width), (ev.clientY - box.top) * (vb.height / box.height)];
  }

  function hit(x, y) {
    const P = pts(), reach = model.get("hit") || 9;
    let best = null, bestD = reach;
    for (let i = 0; i < P.length / 2; i++) {
      const d = Math.hypot(P[2 * i] - x, P[2 * i + 1] - y);
      if (d <= bestD) { best = i; bestD = d; }
    }
    return best;
  }

  function sendMove(end) {
    if (!drag) return;
    const now = performance.now();
    if (!end && (inflight !== null || now - lastSend < THROTTLE_MS)) {
      pending = true;
      if (!timer) timer = setTimeout(() => { timer = null; if (pending && inflight === null) sendMove(false); },
        Math.max(1, THROTTLE_MS - (now - lastSend)));
      return;
    }
    seq += 1;
    inflight = seq;
    pending = false;
    lastSend = now;
    sentAt.set(seq, now);
    if (end) drag.endSeq = seq;
    model.send({ kind: "move", i: drag.i, x: drag.x, y: drag.y, seq, drag: drag.id, end: !!end });
  }

  const live = () => model.get("interactive") !== false;
  svg.classList.toggle("kit-interactive", live());
  svg.addEventListener("pointerdown", ev => {
    if (ev.button !== 0 || !live()) return;
    svg.focus({ preventScroll: true });     // the keys work after a click too
    const [x, y] = local(ev);
    press = { i: hit(x, y), x, y, moved: false };
    svg.setPointerCapture(ev.pointerId);
    ev.preventDefault();
  });
  svg.addEventListener("pointermove", ev => {
    if (!press || press.i === null) return;
    const [x, y] = local(ev);
    if (!press.moved && Math.hypot(x - press.x, y - press.y) < DRAG_START_PX) return;
    if (!press.moved) { dragId += 1; drag = { i: press.i, x, y, id: dragId, endSeq: null }; }
    press.moved = true;
    drag.x = x; drag.y = y;
    const t0 = performance.now();
    draw();
    const t1 = performance.now();
    const stamp = ev.timeStamp;
    requestAnimationFrame(() => {
      stats.frames.push({ draw: t1 - t0, toFrame: performance.now() - stamp });
      if (stats.frames.length > 2000) stats.frames.shift();
    });
    sendMove(false);
  });
  svg.addEventListener("pointerup", ev => {
    if (!press) return;
    const [x, y] = local(ev);
    const was = press;
    press = null;
    if (was.i === null) {
      if (Math.hypot(x - was.x, y - was.y) < DRAG_START_PX) {
        ghost = [was.x, was.y];
        draw();
        model.send({ kind: "add", x: was.x, y: was.y });
      }
    } else if (was.moved) {
      drag.x = x; drag.y = y;
      if (timer) { clearTimeout(timer); timer = null; }
      sendMove(true);
    } else {
      model.send({ kind: "remove", i: was.i });
    }
  });

  // -- the keyboard
  function clip() {
    const scene = model.get("scene") || {};
    return scene.clip || [0, 0, scene.w || 440, scene.h || 400];
  }
  function inside(x, y) {
    const [x0, y0, w, h] = clip();
    return [Math.min(Math.max(x, x0), x0 + w), Math.min(Math.max(y, y0), y0 + h)];
  }
  function cursorAt() {
    if (!cursor) { const [x0, y0, w, h] = clip(); cursor = [x0 + w / 2, y0 + h / 2]; }
    return cursor;
  }
  function keyMove(ev, dx, dy) {
    const P = pts();
    const d = ev.shiftKey ? KEY_BIG_STEP_PX : KEY_STEP_PX;
    if (sel === null || sel >= P.length / 2) {
      sel = null;
      const [ux, uy] = cursorAt();
      cursor = inside(ux + dx * d, uy + dy * d);
      draw();
      return;
    }
    if (!drag || drag.i !== sel || drag.endSeq !== null || !drag.keys) {   // a key press starts a drag
      const [x, y] = drag && drag.i === sel ? [drag.x, drag.y] : pos(sel, P);
      dragId += 1;
      drag = { i: sel, x, y, id: dragId, endSeq: null, keys: true };
    }
    [drag.x, drag.y] = inside(drag.x + dx * d, drag.y + dy * d);
    const t0 = performance.now();
    draw();
    const t1 = performance.now();
    const stamp = ev.timeStamp;
    requestAnimationFrame(() => {
      stats.frames.push({ draw: t1 - t0, toFrame: performance.now() - stamp, key: true });
      if (stats.frames.length > 2000) stats.frames.shift();
    });
    sendMove(false);
  }
  function nearest(x, y) {
    const P = pts();
    let best = null, bestD = Infinity;
    for (let i = 0; i < P.length / 2; i++) {
      const d = Math.hypot(P[2 * i] - x, P[2 * i + 1] - y);
      if (d < bestD) { best = i; bestD = d; }
    }
    return best;
  }
  function onKey(ev) {
    if (ev.altKey || ev.ctrlKey || ev.metaKey) return;
    const n = pts().length / 2;
    if (!live()) {
      if (!model.get("stepper")) return;
      const by = { ArrowLeft: -1, ArrowRight: 1, ArrowUp: -1, ArrowDown: 1, Home: -1e6, End: 1e6 }[ev.key];
      if (ev.key === " ") model.send({ kind: "play" });
      else if (by === undefined) return;
      else model.send({ kind: "step", by: Math.abs(by) === 1 && ev.shiftKey ? 5 * by : by });
    } else if (ARROWS[ev.key]) {
      keyMove(ev, ...ARROWS[ev.key]);
    } else if (ev.key === "Enter") {
      if (ev.repeat) { ev.preventDefault(); ev.stopPropagation(); return; }
      const [ux, uy] = cursorAt();
      ghost = [ux, uy];
      draw();
      model.send({ kind: "add", x: ux, y: uy });
    } else if (ev.key === "]" || ev.key === "[") {
      if (!n) return;
      sel = sel === null ? (ev.key === "]" ? 0 : n - 1) : (sel + (ev.key === "]" ? 1 : n - 1)) % n;
      draw();
    } else if (ev.key === " ") {
      sel = sel === null ? nearest(...cursorAt()) : null;
      draw();
    } else if (ev.key === "Escape") {
      sel = null;
      draw();
    } else if (ev.key === "Delete" || ev.key === "Backspace") {
      if (sel === null || sel >= n) return;
      model.send({ kind: "remove", i: sel });
      sel = null;
      draw();
    } else {
      return;
    }
    ev.preventDefault();
    ev.stopPropagation();        // not a notebook shortcut (Enter, arrows, ...) while the picture has the focus
  }
  svg.setAttribute("data-lm-suppress-shortcuts", "true");
  svg.addEventListener("keydown", onKey);
  svg.addEventListener("keyup", ev => {
    if (ARROWS[ev.key] && drag && drag.keys && drag.endSeq === null) {   // the key's drag ends: send the release
      if (timer) { clearTimeout(timer); timer = null; }
      sendMove(true);
    }
  });
  svg.addEventListener("focus", () => { focused = true; draw(); });
  svg.addEventListener("blur", () => { focused = false; draw(); });
  function describe() {
    const keys = live() || model.get("stepper");     // a picture that takes keys is a tab stop; a mere picture is not
    if (keys) svg.setAttribute("tabindex", "0"); else svg.removeAttribute("tabindex");
    svg.setAttribute("role", keys ? "application" : "img");
    svg.setAttribute("aria-label", model.get("label") || (live() ? "point picker" : "picture"));
    if (say.textContent !== (model.get("announce") || "")) say.textContent = model.get("announce") || "";
  }
  describe();
  model.on("change:label", describe);
  model.on("change:stepper", describe);
  model.on("change:interactive", () => { svg.classList.toggle("kit-interactive", live()); describe(); });
  model.on("change:announce", describe);

  model.on("change:ack", () => {
    const a = model.get("ack");
    if (sentAt.has(a)) {
      stats.answers.push(performance.now() - sentAt.get(a));
      if (stats.answers.length > 2000) stats.answers.shift();
      sentAt.delete(a);
    }
    if (inflight !== null && a >= inflight) inflight = null;
    if (drag && drag.endSeq !== null && a >= drag.endSeq) drag = null;   // the kernel has the release
    if (pending && inflight === null) sendMove(false);
    draw();
  });
  model.on("change:scene", draw);
  model.on("change:points", () => {
    ghost = null;
    if (sel !== null && sel >= pts().length / 2) sel = null;   // removed (by a click or the text box)
    draw();
  });
  draw();
  return () => { if (timer) clearTimeout(timer); };
}

export default { render };
