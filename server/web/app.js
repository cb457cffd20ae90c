// The SAASGAPS dashboard: the job list, and a job page that follows a running job through its event
// stream. Plain DOM and fetch, no framework and no build step; served by `saasgaps serve`.
"use strict";

const view = document.getElementById("view");
let closeJobView = () => {};

// ---------------------------------------------------------------------------------------------
// Talking to the API. A server started with --token-file wants a bearer token: asked for once and
// kept for the tab; EventSource and <img> cannot send headers, so they pass it as access_token.

function token() { return sessionStorage.getItem("saasgaps-token") || ""; }

function withToken(path) {
  if (!token()) return path;
  return path + (path.includes("?") ? "&" : "?") + "access_token=" + encodeURIComponent(token());
}

async function api(path, options = {}) {
  const headers = Object.assign({}, options.headers || {});
  if (token()) headers["Authorization"] = "Bearer " + token();
  const response = await fetch(path, Object.assign({}, options, { headers }));
  if (response.status === 401) {
    const entered = prompt("This server needs its access token:");
    if (entered) {
      sessionStorage.setItem("saasgaps-token", entered.trim());
      return api(path, options);
    }
  }
  const text = await response.text();
  const body = text ? JSON.parse(text) : null;
  if (!response.ok) {
    const problem = body || {};
    const details = (problem.errors || []).slice(0, 5).map(e => `${e.pointer || "(document)"}: ${e.detail}`);
    throw new Error([problem.detail || response.statusText].concat(details).join("\n"));
  }
  return body;
}

function cell(row, text, className) {
  const td = row.insertCell();
  td.textContent = text;
  if (className) td.className = className;
  return td;
}

function stateBadge(element, state) {
  element.textContent = state;
  element.className = "state " + state;
}

function number(value, digits) {
  return typeof value === "number" ? value.toFixed(digits) : "";
}

// The API's times are UTC ("2026-11-23T13:31:23Z"); people read them in their own zone, named.
const localTime = new Intl.DateTimeFormat(undefined, {
  year: "numeric", month: "2-digit", day: "2-digit", hour: "2-digit", minute: "2-digit", second: "2-digit",
  timeZoneName: "short",
});
function when(iso) {
  if (!iso) return "";
  const date = new Date(iso);
  return isNaN(date) ? iso : localTime.format(date);
}

// Marks the view usable (its data shown, its controls live): the browser test waits for this.
function ready(name) {
  document.body.dataset.ready = name;
  window.saasgapsReadyAt = performance.now();
}

// " [psi]" for a quantity the model names a unit for, else "".
function unitOf(units, kind) {
  return units && units[kind] ? ` [${units[kind]}]` : "";
}

// ---------------------------------------------------------------------------------------------
// The job list.

async function showList() {
  view.replaceChildren(document.getElementById("list-view").content.cloneNode(true));
  const tbody = view.querySelector("#jobs tbody");
  const filter = view.querySelector("#state-filter");
  const more = view.querySelector("#more");
  let next = null;

  async function load(append) {
    const params = new URLSearchParams({ page_size: "25" });
    if (filter.value) params.set("state", filter.value);
    if (append && next) params.set("page_token", next);
    const page = await api("/v1/jobs?" + params);
    if (!append) tbody.replaceChildren();
    for (const job of page.jobs) {
      const row = tbody.insertRow();
      const link = document.createElement("a");
      link.href = `#/jobs/${job.id}`;
      link.textContent = job.id;
      row.insertCell().append(link);
      cell(row, job.title);
      const stateCell = row.insertCell();
      stateBadge(stateCell.appendChild(document.createElement("span")), job.state);
      if (job.error) {
        // Why it failed, at a glance: the first line here, the whole text on hover.
        const reason = stateCell.appendChild(document.createElement("div"));
        reason.className = "reason";
        reason.textContent = job.error.split("\n")[0];
        reason.title = job.error;
      }
      cell(row, `${job.iteration} / ${job.max_iterations}`);
      cell(row, when(job.created_at));
      cell(row, when(job.finished_at));
    }
    next = page.next_page_token;
    more.hidden = !next;
  }

  filter.addEventListener("change", () => load(false));
  more.addEventListener("click", () => load(true));
  view.querySelector("#submit-form").addEventListener("submit", async event => {
    event.preventDefault();
    const status = view.querySelector("#submit-status");
    const file = view.querySelector("#model-file").files[0];
    if (!file) { status.textContent = "choose a model file first"; return; }
    try {
      const job = await api("/v1/jobs", { method: "POST", headers: { "Content-Type": "application/json" }, body: await file.text() });
      location.hash = `#/jobs/${job.id}`;
    } catch (error) {
      status.textContent = error.message;
    }
  });
  await load(false);
  ready("list");
  const timer = setInterval(() => { if (!more.hidden) return; load(false).catch(() => {}); }, 3000);
  closeJobView = () => clearInterval(timer);
}

// ---------------------------------------------------------------------------------------------
// One job, followed live.

async function showJob(id) {
  view.replaceChildren(document.getElementById("job-view").content.cloneNode(true));
  const $ = selector => view.querySelector(selector);
  const base = `/v1/jobs/${id}`;
  const rows = new Map();

  let units = {};
  let headerDone = false;

  // The watched elements' and gaps' columns, as the CLI prints them: named from the first row.
  function addWatchHeader(row) {
    if (headerDone) return;
    headerDone = true;
    const head = $("#iterations thead tr");
    const stress = unitOf(units, "stress");
    for (const e of (row.watch || {}).elements || []) {
      for (const name of ["s_r", "s_th", "eff"]) {
        head.appendChild(Object.assign(document.createElement("th"), { textContent: `el ${e.id} ${name}${stress}` }));
      }
    }
    for (const g of (row.watch || {}).gaps || []) {
      for (const name of [`E_M${stress}`, "clos %", `s_M${stress}`]) {
        head.appendChild(Object.assign(document.createElement("th"), { textContent: `gap ${g.id} ${name}` }));
      }
    }
  }

  function addRow(row) {
    if (rows.has(row.iteration)) return;
    addWatchHeader(row);
    const tr = document.createElement("tr");
    tr.dataset.iteration = row.iteration;
    // A stepped model's row says where on the load path it is: "7 (2/3)" is iteration 7, step 2, increment 3.
    const iteration = row.step ? `${row.iteration} (${row.step}/${row.increment})` : row.iteration;
    for (const [text, digits] of [[iteration, 0], [row.tensile_modulus, 4], [row.closed_gaps, 0],
                                  [row.iteration === 1 ? "-" : row.nonconverged_gaps, 0], [row.average_closure, 1],
                                  [row.max_closure, 1], [row.yielded_elements, 0], [row.nonconverged_plastic, 0]]) {
      cell(tr, typeof text === "number" && digits > 0 ? number(text, digits) : String(text));
    }
    cell(tr, row.extrapolated ? "yes" : "");
    cell(tr, row.attempt);
    cell(tr, number(row.seconds, 3));
    for (const e of (row.watch || {}).elements || []) {
      for (const value of [e.sigma_r, e.sigma_theta, e.effective]) cell(tr, number(value, 1));
    }
    for (const g of (row.watch || {}).gaps || []) {
      cell(tr, typeof g.modulus === "number" ? g.modulus.toPrecision(5) : "");
      cell(tr, number(g.closure, 2));
      cell(tr, number(g.sigma_m, 1));
    }
    rows.set(row.iteration, tr);
    // Keep the table ordered even if rows arrive out of order (a reconnect after a gap).
    const later = [...rows.keys()].filter(k => k > row.iteration).sort((a, b) => a - b)[0];
    $("#iterations tbody").insertBefore(tr, later === undefined ? null : rows.get(later));
  }

  function showState(job) {
    $("#job-title").textContent = job.title;
    $("#job-id").textContent = job.id;
    stateBadge($("#job-state"), job.state);
    $("#job-iteration").textContent = job.iteration;
    $("#job-max").textContent = job.max_iterations;
    $("#job-attempts").textContent = job.attempts;
    $("#job-created").textContent = when(job.created_at);
    $("#job-started").textContent = when(job.started_at) || "not yet";
    $("#job-finished").textContent = when(job.finished_at) || "not yet";
    // A failed job says why, in full; other jobs show the run's message.
    $("#job-error").hidden = !job.error;
    $("#job-error").textContent = job.error ? `Failed: ${job.error}` : "";
    $("#job-message").textContent = job.error ? "" : (job.message || "");
    const active = ["queued", "running", "interrupted"].includes(job.state);
    $("#cancel").disabled = !active || job.cancel_requested;
    $("#resume").disabled = ["queued", "running", "converged"].includes(job.state);
    const hasResult = !["queued", "running"].includes(job.state);
    if (job.last_row && Array.isArray(job.last_row.gap_closures)) hasGaps = job.last_row.gap_closures.length > 0;
    $("#links").replaceChildren(...[["model", base + "/model"], ["iterations", base + "/iterations"]]
      .concat(hasResult ? [["result (JSON)", base + "/result"], ["result (VTU for ParaView)", base + "/result.vtu"]] : [])
      .concat(hasResult && hasGaps ? [["contact pressure (CSV)", base + "/plots/contact_pressure.csv"]] : [])
      .map(([label, href]) => Object.assign(document.createElement("a"), { href: withToken(href), textContent: label })));
    if (hasResult && !plotsShown) showPlots();
  }

  // Plots are drawn for the space they get: the figure's width in device pixels, so a PNG is sharp
  // and no larger than the screen needs (a 10^5-element SVG is tens of MB; its PNG is not).
  // [image, plot name, the options it takes]
  const plots = [["#contour-plot", () => $("#plot-field").value, contourOptions], ["#contact-plot", () => "contact_pressure", rowOptions],
                 ["#closure-plot", () => "closure", rowOptions], ["#convergence-plot", () => "convergence", () => ({})]];
  let plotsShown = false;
  let plotStamp = -1;

  function plotUrl(name, width, height, extra) {
    const format = $("#plot-format").value;
    const params = new URLSearchParams(Object.assign({ width: String(width), height: String(height) }, extra || {}));
    return withToken(`${base}/plots/${name}.${format}?${params}`);
  }

  // The gap row of the contact and closure plots: which gaps, in which order, against what.
  function rowOptions() {
    const options = { along: $("#plot-along").value };
    const gaps = $("#plot-gaps").value.replace(/\s+/g, "");
    if (gaps) options.gaps = gaps;
    return options;
  }

  function contourOptions() {
    const options = {};
    if ($("#plot-deformed").checked) options.deformed = "auto";
    if ($("#plot-mesh").checked) options.mesh = "1";
    if ($("#plot-levels").value !== "quantile") options.levels = $("#plot-levels").value;
    return options;
  }

  let hasGaps = true;

  function showPlots() {
    plotsShown = true;
    plotStamp = rows.size;
    const ratio = window.devicePixelRatio || 1;
    // A model without gaps has no gap plots: their figures go before the others are measured.
    const gapPlot = selector => selector === "#contact-plot" || selector === "#closure-plot";
    for (const [selector] of plots) $(selector).parentElement.hidden = gapPlot(selector) && !hasGaps;
    for (const [selector, name, optionsOf] of plots) {
      const img = $(selector);
      if (gapPlot(selector) && !hasGaps) continue;
      const width = Math.min(4000, Math.max(320, Math.round(img.parentElement.clientWidth * ratio)));
      const height = Math.round(width * 0.62);
      const options = optionsOf();
      const extra = Object.assign({ t: String(rows.size) }, options);  // new rows: a new picture
      img.onload = () => { img.hidden = false; img.parentElement.hidden = false; $("#plot-note").textContent = ""; };
      img.onerror = () => {
        img.hidden = true;
        img.parentElement.hidden = selector !== "#contour-plot";
        // Say why, e.g. a gap row naming a gap the model does not have.
        fetch(img.src).then(r => r.json()).then(p => { $("#plot-note").textContent = `${name()}: ${p.detail}`; }).catch(() => {});
      };
      img.dataset.plot = name();
      img.dataset.width = String(width);
      img.dataset.extra = JSON.stringify(options);
      img.src = plotUrl(name(), width, height, extra);
    }
  }

  // A plot clicked opens full size: drawn again for the whole window.
  function openFull(img) {
    const ratio = window.devicePixelRatio || 1;
    const width = Math.min(4000, Math.round(window.innerWidth * 0.96 * ratio));
    const height = Math.min(4000, Math.round(window.innerHeight * 0.9 * ratio));
    const overlay = document.getElementById("full-view");
    const big = overlay.querySelector("img");
    big.src = plotUrl(img.dataset.plot, width, height, JSON.parse(img.dataset.extra || "{}"));
    overlay.querySelector("a").href = plotUrl(img.dataset.plot, width, height,
                                              Object.assign({}, JSON.parse(img.dataset.extra || "{}")));
    overlay.hidden = false;
  }

  for (const [selector] of plots) $(selector).addEventListener("click", event => openFull(event.currentTarget));
  $("#delete").addEventListener("click", async () => {
    if (!confirm(`Delete job ${id} with its iterations and result? This cannot be undone.`)) return;
    try {
      await api(base, { method: "DELETE" });
      location.hash = "#/";
    } catch (error) { $("#action-status").textContent = error.message; }
  });

  for (const control of ["#plot-field", "#plot-deformed", "#plot-mesh", "#plot-levels", "#plot-format", "#plot-gaps",
                         "#plot-along"]) {
    $(control).addEventListener("change", showPlots);
  }
  $("#cancel").addEventListener("click", async () => {
    try { showState(await api(base + "/cancel", { method: "POST", body: "" })); }
    catch (error) { $("#action-status").textContent = error.message; }
  });
  $("#resume-form").addEventListener("submit", async event => {
    event.preventDefault();
    const body = {};
    const schedule = $("#resume-schedule").value.trim();
    if (schedule) body.tensile_schedule = schedule.split(/[\s,]+/).map(Number);
    if ($("#resume-max").value) body.max_iterations = Number($("#resume-max").value);
    if ($("#resume-xfact").value) body.extrapolation_factor = Number($("#resume-xfact").value);
    try {
      showState(await api(base + "/resume", { method: "POST", headers: { "Content-Type": "application/json" }, body: JSON.stringify(body) }));
      $("#action-status").textContent = "resumed";
      follow();
    } catch (error) { $("#action-status").textContent = error.message; }
  });

  const [job, history, named] = await Promise.all([api(base), api(base + "/iterations"),
                                                   api(base + "/units").catch(() => ({}))]);
  units = named || {};
  const unitNames = Object.entries(units).map(([kind, name]) => `${kind} ${name}`);
  $("#job-units").textContent = unitNames.length ? unitNames.join(", ") : "not named in the model";
  for (const row of history.iterations) addRow(row);
  showState(job);
  ready("job");

  // The event stream: one event per iteration and per state change. EventSource reconnects by
  // itself with Last-Event-ID; the server ends the stream when the job stops changing.
  let source = null;
  function follow() {
    if (source) source.close();
    source = new EventSource(withToken(base + "/events"));
    source.addEventListener("iteration", event => {
      addRow(JSON.parse(event.data));
      api(base).then(showState).catch(() => {});
    });
    source.addEventListener("state", () => api(base).then(job => {
      const redraw = plotsShown && plotStamp !== rows.size;
      showState(job);
      if (redraw) showPlots();
    }).catch(() => {}), { once: false });
    source.onerror = () => {
      // A finished job closes its stream; stop reconnecting then.
      api(base).then(job => { if (!["queued", "running", "interrupted"].includes(job.state)) source.close(); })
        .catch(() => source.close());
    };
  }
  follow();
  closeJobView = () => { if (source) source.close(); };
}

// ---------------------------------------------------------------------------------------------

async function route() {
  closeJobView();
  closeJobView = () => {};
  const match = location.hash.match(/^#\/jobs\/(\d+)/);
  try {
    if (match) await showJob(match[1]); else await showList();
  } catch (error) {
    view.textContent = error.message;
  }
}

async function health() {
  try {
    const h = await (await fetch("/healthz")).json();
    document.getElementById("health").textContent = `${h.workers} worker(s), ${h.running} running, ${h.queue_length} queued`;
  } catch (error) {
    document.getElementById("health").textContent = "server unreachable";
  }
}

// The full-size view closes on a click or Escape.
const fullView = document.getElementById("full-view");
fullView.addEventListener("click", event => { if (event.target.tagName !== "A") fullView.hidden = true; });
document.addEventListener("keydown", event => { if (event.key === "Escape") fullView.hidden = true; });

window.addEventListener("hashchange", route);
route();
health();
setInterval(health, 5000);
