// panels.js: the measurement panel's log-log plot and the timed-practice panel's clock, drawn by the
// browser as SVG (an anywidget front end for reference_impl/kit/panels.py; no build step, no network).
//
// kind "loglog": `series` = [{name, ns, ts, slope}] plotted on log-log axes with decade ticks, one
//   colour per contender, the fitted slope in the legend; redrawn when the kernel sends new timings.
// kind "clock": `deadline` and `total` (seconds) and `now` (the kernel's clock when it sent them);
//   the page counts down by itself, once a second, with no message to the kernel.  The bar turns red
//   once the time is up.  The picture is role="timer" with the time left as its label.
// Both are pictures (role img / timer, an aria-label saying what they show), not tab stops: their
// panels' buttons are the controls.  el.__kitPanelStats.draws counts the drawings.

const NS = "http://www.w3.org/2000/svg";
const CYCLE = ["#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f"];

function esc(s) {
  return String(s).replace(/&/g, "&amp;").replace(/</g, "&lt;").replace(/>/g, "&gt;").replace(/"/g, "&quot;");
}

function fmt(v) {
  const e = Math.round(Math.log10(v));
  return Math.abs(Math.log10(v) - e) < 1e-9 ? (e >= -2 && e <= 4 ? String(+v.toPrecision(1)) : `1e${e}`) : String(+v.toPrecision(2));
}

function ticks(lo, hi) {          // decades, or 1-2-5 inside a range shorter than two decades
  const out = [];
  const mult = hi - lo < 2 ? [1, 2, 5] : [1];
  for (let e = Math.floor(lo); e <= Math.ceil(hi); e++) {
    for (const m of mult) {
      const v = m * 10 ** e, l = Math.log10(v);
      if (l >= lo - 1e-9 && l <= hi + 1e-9) out.push(v);
    }
  }
  return out;
}

function loglog(model) {
  const w = model.get("width") || 480, h = model.get("height") || 340;
  const series = (model.get("series") || []).filter(s => s.ns.length);
  const L = 62, R = 14, T = 26, B = 40;
  const out = [`<rect x="0" y="0" width="${w}" height="${h}" fill="white"/>`];
  const title = model.get("title") || "";
  if (title) out.push(`<text x="${w / 2}" y="16" font-size="13" text-anchor="middle">${esc(title)}</text>`);
  out.push(`<rect x="${L}" y="${T}" width="${w - L - R}" height="${h - T - B}" fill="none" stroke="#333"/>`);
  const xs = [], ys = [];
  for (const s of series) s.ns.forEach((n, k) => { if (n > 0 && s.ts[k] > 0) { xs.push(n); ys.push(s.ts[k]); } });
  if (!xs.length) {
    out.push(`<text x="${(L + w - R) / 2}" y="${(T + h - B) / 2}" font-size="13" text-anchor="middle">press measure</text>`);
    return { svg: out.join(""), said: "log-log plot of the timings: nothing measured yet" };
  }
  let [x0, x1] = [Math.log10(Math.min(...xs)), Math.log10(Math.max(...xs))];
  let [y0, y1] = [Math.log10(Math.min(...ys)), Math.log10(Math.max(...ys))];
  if (x1 - x0 < 0.2) { x0 -= 0.3; x1 += 0.3; }
  if (y1 - y0 < 0.2) { y0 -= 0.48; y1 += 0.48; }          // one value: a factor of 3 each way
  const px = (x1 - x0) * 0.05, py = (y1 - y0) * 0.08;
  x0 -= px; x1 += px; y0 -= py; y1 += py;
  const X = v => L + (Math.log10(v) - x0) / (x1 - x0) * (w - L - R);
  const Y = v => h - B - (Math.log10(v) - y0) / (y1 - y0) * (h - T - B);
  for (const v of ticks(x0, x1)) {
    out.push(`<path d="M${X(v).toFixed(1)} ${h - B}v5" stroke="#333"/>`,
      `<text x="${X(v).toFixed(1)}" y="${h - B + 17}" font-size="11" text-anchor="middle">${fmt(v)}</text>`);
  }
  for (const v of ticks(y0, y1)) {
    out.push(`<path d="M${L} ${Y(v).toFixed(1)}h-5" stroke="#333"/>`,
      `<text x="${L - 8}" y="${(Y(v) + 4).toFixed(1)}" font-size="11" text-anchor="end">${fmt(v)}</text>`);
  }
  out.push(`<text x="${(L + w - R) / 2}" y="${h - 6}" font-size="12" text-anchor="middle">n</text>`,
    `<text x="14" y="${(T + h - B) / 2}" font-size="12" text-anchor="middle" transform="rotate(-90 14 ${(T + h - B) / 2})">seconds</text>`);
  const said = [];
  series.forEach((s, k) => {
    const c = CYCLE[k % CYCLE.length];
    const pts = s.ns.map((n, j) => [n, s.ts[j]]).filter(([n, t]) => n > 0 && t > 0);
    out.push(`<path class="kit-series" d="${pts.map(([n, t], j) => (j ? "L" : "M") + X(n).toFixed(1) + " " + Y(t).toFixed(1)).join("")}" ` +
      `fill="none" stroke="${c}" stroke-width="1.5"/>`);
    for (const [n, t] of pts) out.push(`<circle cx="${X(n).toFixed(1)}" cy="${Y(t).toFixed(1)}" r="3.5" fill="${c}"/>`);
    const legend = s.name + (s.slope === null || s.slope === undefined ? "" : ` (slope ${s.slope.toFixed(2)})`);
    out.push(`<path d="M${L + 8} ${T + 12 + 15 * k}h18" stroke="${c}" stroke-width="1.5"/>`,
      `<text x="${L + 30}" y="${T + 16 + 15 * k}" font-size="11">${esc(legend)}</text>`);
    said.push(`${legend}: ${pts.length} sizes`);
  });
  return { svg: out.join(""), said: "log-log plot of the timings: " + said.join("; ") };
}

function clockText(left) {
  const s = Math.floor(Math.abs(left)) , text = `${String(Math.floor(s / 60)).padStart(2, "0")}:${String(s % 60).padStart(2, "0")}`;
  return left < 0 ? `late by ${text}` : `${text} left`;
}

function clock(model, offset) {
  const w = model.get("width") || 420, h = model.get("height") || 90;
  const deadline = model.get("deadline"), total = model.get("total") || 1800, head = model.get("title") || "";
  let text, frac = 0, late = false;
  if (deadline === null || deadline === undefined || deadline < 0) {
    text = model.get("idle") || `${head}: press start`;
  } else {
    const left = deadline - (Date.now() / 1000 + offset);
    text = `${head}: ${clockText(left)}`;
    frac = Math.min(1, Math.max(0, 1 - left / total));
    late = left < 0;
  }
  const bx = 0.02 * w, bw = 0.96 * w, by = 0.55 * h, bh = 0.3 * h;
  const svg = `<rect x="0" y="0" width="${w}" height="${h}" fill="white"/>` +
    `<text class="kit-clock-text" x="${bx}" y="${0.3 * h + 6}" font-size="17">${esc(text)}</text>` +
    `<rect x="${bx}" y="${by}" width="${(bw * frac).toFixed(1)}" height="${bh}" fill="${late ? "#d62728" : "#2a7f2a"}"/>` +
    `<rect x="${bx}" y="${by}" width="${bw}" height="${bh}" fill="none" stroke="black" stroke-width="1.5"/>`;
  return { svg, said: text };
}

function render({ model, el }) {
  const svg = document.createElementNS(NS, "svg");
  svg.classList.add("kit-panel-picture");
  el.appendChild(svg);
  const stats = { draws: 0 };
  el.__kitPanelStats = stats;
  svg.__kitPanelStats = stats;
  const kind = model.get("kind");
  let offset = 0;             // the kernel's clock minus the page's, when the deadline was sent
  function draw() {
    const w = model.get("width"), h = model.get("height");
    svg.setAttribute("viewBox", `0 0 ${w} ${h}`);
    svg.setAttribute("width", w);
    svg.setAttribute("height", h);
    const got = kind === "clock" ? clock(model, offset) : loglog(model);
    svg.innerHTML = got.svg;
    svg.setAttribute("role", kind === "clock" ? "timer" : "img");
    svg.setAttribute("aria-label", got.said);
    stats.draws += 1;
    svg.dataset.draws = String(stats.draws);
  }
  const sync = () => { offset = (model.get("now") || Date.now() / 1000) - Date.now() / 1000; draw(); };
  for (const name of ["series", "title", "width", "height", "deadline", "total", "idle"]) model.on(`change:${name}`, draw);
  model.on("change:now", sync);
  sync();
  if (kind === "clock") {
    const tick = setInterval(draw, 1000);
    return () => clearInterval(tick);
  }
}

export default { render };
