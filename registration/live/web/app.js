// The live page of `registration serve`: reads the JSON API of the server that sent it every 2 s and
// redraws. Plain ES2020, no library, nothing fetched from any other host. All numbers are in the API's
// file units (deg, m, s, 1). Data from the server goes into the page as text, never as HTML.
"use strict";

const POLL_MS = 2000;
const HOUR_S = 3600;
const SVG_NS = "http://www.w3.org/2000/svg";

// ---------- small helpers ----------

/** An HTML element with attributes and children (strings become text nodes). */
function el(tag, attrs = {}, ...children) {
  const node = document.createElement(tag);
  for (const [key, value] of Object.entries(attrs)) node.setAttribute(key, String(value));
  node.append(...children.map((c) => (typeof c === "string" ? document.createTextNode(c) : c)));
  return node;
}

/** An SVG element with attributes. */
function svgEl(tag, attrs = {}, text) {
  const node = document.createElementNS(SVG_NS, tag);
  for (const [key, value] of Object.entries(attrs)) node.setAttribute(key, String(value));
  if (text !== undefined) node.textContent = text;
  return node;
}

const isNum = (v) => typeof v === "number" && Number.isFinite(v);

/** Decimals that show sigma to two significant digits (0 to 8). */
function decimalsFor(sigma) {
  if (!isNum(sigma) || sigma <= 0) return 4;
  return Math.min(8, Math.max(0, 1 - Math.floor(Math.log10(sigma))));
}

/** "estimate ± sigma unit", both to the decimals of sigma's two significant digits (no "± sigma"
 * when sigma is 0 or missing, as for a fixed state). */
function formatPm(estimate, sigma, unit) {
  if (!isNum(estimate)) return "—";
  const d = decimalsFor(sigma);
  const pm = isNum(sigma) && sigma > 0 ? ` ± ${sigma.toFixed(d)}` : "";
  return `${estimate.toFixed(d)}${pm} ${unit}`.trim();
}

/** A number to three significant digits, without an exponent for everyday sizes. */
function formatSig(v, digits = 3) {
  if (!isNum(v)) return "—";
  return String(Number(v.toPrecision(digits)));
}

function formatFixed(v, decimals) {
  return isNum(v) ? v.toFixed(decimals) : "—";
}

function formatBytes(n) {
  if (!isNum(n)) return "—";
  const units = ["B", "KiB", "MiB", "GiB", "TiB"];
  let i = 0;
  while (n >= 1024 && i < units.length - 1) {
    n /= 1024;
    i += 1;
  }
  return `${i === 0 ? n : n.toFixed(1)} ${units[i]}`;
}

function formatDuration(s) {
  if (!isNum(s)) return "—";
  const h = Math.floor(s / 3600);
  const m = Math.floor((s % 3600) / 60);
  const sec = Math.floor(s % 60);
  return h > 0 ? `${h} h ${m} min` : m > 0 ? `${m} min ${sec} s` : `${sec} s`;
}

const byName = (a, b) => String(a).localeCompare(String(b), "en", { numeric: true });

// ---------- the API ----------

class Unreachable extends Error {}

async function getJson(path) {
  let response;
  try {
    response = await fetch(path, { cache: "no-store" });
  } catch (err) {
    throw new Unreachable(`${path}: ${err.message}`);
  }
  if (!response.ok) throw new Unreachable(`${path}: HTTP ${response.status}`);
  return response.json();
}

async function fetchAll() {
  const [estimates, status, residuals] = await Promise.all([
    getJson("api/estimates"),
    getJson("api/status"),
    getJson("api/residuals"),
  ]);
  // One sensor's history failing (say, a 404 for a sensor just seen) leaves the others drawn.
  const history = (n) =>
    getJson(`api/history?sensor=${encodeURIComponent(n)}`).catch((err) => ({
      sensor: n,
      states: [],
      error: err.message,
    }));
  const histories = await Promise.all((status.sensors || []).map((s) => history(s.sensor)));
  return { estimates, status, residuals, histories };
}

// ---------- rendering ----------

function renderHeader(status) {
  document.getElementById("data-time").textContent = formatFixed(status.data_time_s, 1);
  document.getElementById("uptime").textContent = formatDuration(status.uptime_s);
  document.getElementById("memory").textContent = formatBytes(status.memory_rss_bytes);
}

function renderAlarms(alarms) {
  const section = document.getElementById("alarms");
  const list = (alarms || []).slice().sort((a, b) => b.time_s - a.time_s);
  section.hidden = list.length === 0;
  document.getElementById("alarm-count").textContent = `(${list.length})`;
  document.getElementById("alarm-list").replaceChildren(
    ...list.map((a) => {
      const d = decimalsFor(a.sigma);
      const text =
        `t = ${formatFixed(a.time_s, 1)} s · ${a.object} ${a.state}: ` +
        `${formatFixed(a.before, d)} → ${formatFixed(a.after, d)} ${a.unit} ` +
        `(σ ${formatFixed(a.sigma, d)}, z ${formatFixed(a.z, 1)})`;
      return el("li", { "data-object": a.object, "data-state": a.state }, text);
    }),
  );
}

function renderConsistency(c) {
  const node = document.getElementById("consistency");
  const verdict = (c && c.verdict) || "no verdict yet";
  const band =
    c && Array.isArray(c.band) ? ` in band [${formatSig(c.band[0])}, ${formatSig(c.band[1])}]` : "";
  node.textContent = `${formatSig(c ? c.value : null)}${band}: ${verdict}`;
  node.dataset.verdict = verdict;
  node.className = `consistency ${verdict === "consistent" ? "ok" : c && c.verdict ? "bad" : ""}`;
}

function renderEstimates(data) {
  const rows = (data.estimates || []).slice().sort((a, b) => byName(a.object, b.object));
  document.querySelector("#estimates tbody").replaceChildren(
    ...rows.map((e) =>
      el(
        "tr",
        { "data-object": e.object, "data-state": e.state, "data-status": e.status },
        el("td", {}, e.object),
        el("td", {}, e.state),
        el("td", { class: "num value" }, formatPm(e.estimate, e.sigma, e.unit)),
        el("td", {}, el("span", { class: `status status-${e.status}` }, e.status)),
      ),
    ),
  );
}

function renderResiduals(data) {
  const rows = [];
  const maxRms = {};
  for (const s of data.sensors || []) {
    for (const c of s.channels || []) {
      rows.push([s.sensor, c]);
      if (isNum(c.rms)) maxRms[c.unit] = Math.max(maxRms[c.unit] || 0, c.rms);
    }
  }
  document.querySelector("#residuals tbody").replaceChildren(
    ...rows.map(([sensor, c]) => {
      const fill = el("span", { class: "fill" });
      fill.style.width = `${maxRms[c.unit] > 0 && isNum(c.rms) ? (100 * c.rms) / maxRms[c.unit] : 0}%`;
      return el(
        "tr",
        { "data-sensor": sensor, "data-channel": c.channel },
        el("td", {}, sensor),
        el("td", {}, c.channel),
        el("td", { class: "num" }, String(c.n)),
        el("td", { class: "num mean" }, `${formatSig(c.mean)} ${c.unit}`),
        el("td", { class: "num rms" }, `${formatSig(c.rms)} ${c.unit}`),
        el("td", { class: "barcell" }, el("span", { class: "bar" }, fill)),
      );
    }),
  );
}

function renderSensors(sensors) {
  const rows = (sensors || []).slice().sort((a, b) => byName(a.sensor, b.sensor));
  document.querySelector("#sensors tbody").replaceChildren(
    ...rows.map((s) =>
      el(
        "tr",
        {
          "data-sensor": s.sensor,
          "data-silent": String(Boolean(s.silent)),
          class: s.silent ? "silent" : "",
        },
        el("td", {}, s.sensor),
        el("td", { class: "num plots" }, String(s.plots)),
        el("td", { class: "num rate" }, formatFixed(s.rate_per_s, 1)),
        el("td", { class: "num" }, formatFixed(s.last_time_s, 1)),
        el("td", {}, s.silent ? el("span", { class: "badge" }, "silent") : ""),
      ),
    ),
  );
}

/** A <dl> of name: value pairs, each <dd> with data-key for the tests and scripts. */
function fillCounts(id, pairs) {
  const items = pairs.flatMap(([key, value]) => [
    el("dt", {}, key),
    el("dd", { "data-key": key, class: value === 0 ? "zero" : "" }, String(value)),
  ]);
  document.getElementById(id).replaceChildren(...(items.length ? items : [el("dd", {}, "none")]));
}

function renderIngest(ingest) {
  const i = ingest || {};
  fillCounts("ingest", [
    ["datagrams", i.datagrams],
    ["bytes", i.bytes],
    ["plots", i.plots],
    ["references", i.references],
  ]);
  const sorted = (o) => Object.entries(o || {}).sort(([a], [b]) => byName(a, b));
  fillCounts("categories", sorted(i.records_by_category).map(([k, v]) => [`CAT${k}`, v]));
  fillCounts("rejected", sorted(i.rejected));
}

// ---------- charts ----------

/** Round values (1, 2 or 5 times a power of ten) in [lo, hi], about count + 1 of them. */
function niceTicks(lo, hi, count) {
  const raw = (hi - lo) / Math.max(1, count);
  const power = 10 ** Math.floor(Math.log10(raw));
  const gap = (s) => Math.abs(Math.log(s / raw));
  const step = [1, 2, 5, 10].map((m) => m * power).reduce((best, s) => (gap(s) < gap(best) ? s : best));
  const ticks = [];
  for (let k = Math.ceil(lo / step); k * step <= hi + step * 1e-9; k += 1) ticks.push(k === 0 ? 0 : k * step);
  const decimals = Math.max(0, -Math.floor(Math.log10(step)));
  return ticks.map((v) => ({ value: v, label: v.toFixed(decimals) }));
}

function paddedRange(lo, hi) {
  if (!(hi > lo)) {
    const half = Math.abs(lo) * 0.1 || 1;
    return [lo - half, hi + half];
  }
  const pad = 0.05 * (hi - lo);
  return [lo - pad, hi + pad];
}

/** Runs of consecutive indices whose time and estimate are finite (a null breaks the line). */
function finiteRuns(time, estimate) {
  const runs = [];
  let run = [];
  for (let i = 0; i < time.length; i += 1) {
    if (isNum(time[i]) && isNum(estimate[i])) {
      run.push(i);
    } else if (run.length) {
      runs.push(run);
      run = [];
    }
  }
  if (run.length) runs.push(run);
  return runs;
}

const CHART = { width: 420, height: 170, left: 62, right: 10, top: 10, bottom: 34 };

/** One state's estimate over data time with its ±σ band, as an SVG with axes, ticks and units. */
function drawChart(state) {
  const tLast = Math.max(...state.time_s.filter(isNum));
  const keep = state.time_s.map((t) => isNum(t) && t >= tLast - HOUR_S);
  const time = state.time_s.map((t, i) => (keep[i] ? t : null));
  const est = state.estimate;
  const sig = state.sigma.map((s) => (isNum(s) ? s : 0));
  const runs = finiteRuns(time, est);
  const idx = runs.flat();
  const [t0, t1] = paddedRange(Math.min(...idx.map((i) => time[i])), tLast);
  const [y0, y1] = paddedRange(
    Math.min(...idx.map((i) => est[i] - sig[i])),
    Math.max(...idx.map((i) => est[i] + sig[i])),
  );
  const { width, height, left, right, top, bottom } = CHART;
  const x = (t) => (left + ((t - t0) / (t1 - t0)) * (width - left - right)).toFixed(1);
  const y = (v) => (top + ((y1 - v) / (y1 - y0)) * (height - top - bottom)).toFixed(1);

  const svg = svgEl("svg", {
    viewBox: `0 0 ${width} ${height}`,
    class: "chart",
    role: "img",
    "aria-label": `${state.state} (${state.unit}) over data time (s)`,
  });
  for (const tick of niceTicks(y0, y1, 4)) {
    const yt = y(tick.value);
    svg.append(svgEl("line", { class: "grid", x1: left, x2: width - right, y1: yt, y2: yt }));
    svg.append(svgEl("text", { class: "tick y", x: left - 4, y: yt }, tick.label));
  }
  for (const tick of niceTicks(t0, t1, 4)) {
    const xt = x(tick.value);
    svg.append(svgEl("line", { class: "grid", x1: xt, x2: xt, y1: top, y2: height - bottom }));
    svg.append(svgEl("text", { class: "tick x", x: xt, y: height - bottom + 13 }, tick.label));
  }
  const plotArea = { x: left, y: top, width: width - left - right, height: height - top - bottom };
  svg.append(svgEl("rect", { class: "frame", ...plotArea }));
  const band = runs
    .map((r) => {
      const upper = r.map((i) => `${x(time[i])},${y(est[i] + sig[i])}`);
      const lower = r.map((i) => `${x(time[i])},${y(est[i] - sig[i])}`).reverse();
      return `M${upper.join("L")}L${lower.join("L")}Z`;
    })
    .join("");
  const line = runs.map((r) => `M${r.map((i) => `${x(time[i])},${y(est[i])}`).join("L")}`).join("");
  svg.append(svgEl("path", { class: "band", d: band }));
  svg.append(svgEl("path", { class: "line", d: line, "data-points": idx.length }));
  svg.append(svgEl("text", { class: "axis-label y", x: 4, y: top + 2 }, state.unit));
  svg.append(svgEl("text", { class: "axis-label x", x: width - right, y: height - 4 }, "data time (s)"));
  return svg;
}

function renderCharts(histories) {
  const figures = histories
    .slice()
    .sort((a, b) => byName(a.sensor, b.sensor))
    .map((h) => {
      const noHistory = h.error ? `no history: ${h.error}` : "no history yet";
      const charts = (h.states || []).map((s) => {
        const has = (s.time_s || []).some(isNum) && (s.estimate || []).some(isNum);
        return el(
          "div",
          { class: "chart-box", "data-state": s.state },
          el("h4", {}, `${s.state} (${s.unit})`),
          has ? drawChart(s) : el("p", { class: "empty" }, "no estimate yet"),
        );
      });
      return el(
        "figure",
        { "data-sensor": h.sensor },
        el("figcaption", {}, h.sensor),
        ...(charts.length ? charts : [el("p", { class: "empty" }, noHistory)]),
      );
    });
  document.getElementById("charts").replaceChildren(...figures);
}

function render({ estimates, status, residuals, histories }) {
  renderHeader(status);
  renderAlarms(status.alarms);
  renderConsistency(status.consistency);
  renderEstimates(estimates);
  renderCharts(histories);
  renderResiduals(residuals);
  renderSensors(status.sensors);
  renderIngest(status.ingest);
}

// ---------- the loop ----------

function setConnection(text, ok) {
  const node = document.getElementById("connection");
  node.textContent = text;
  node.className = `connection ${ok ? "up" : "down"}`;
  document.body.classList.toggle("stale", !ok);
}

async function poll() {
  try {
    render(await fetchAll());
    setConnection(`live · updated ${new Date().toLocaleTimeString("en-GB")}`, true);
  } catch (err) {
    if (err instanceof Unreachable) {
      setConnection("service unreachable: showing the last data received", false);
    } else {
      setConnection(`page error: ${err.message}`, false);
      console.error(err);
    }
  } finally {
    setTimeout(poll, POLL_MS);
  }
}

poll();
