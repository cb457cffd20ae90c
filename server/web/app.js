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
      stateBadge(row.insertCell().appendChild(document.createElement("span")), job.state);
      cell(row, `${job.iteration} / ${job.max_iterations}`);
      cell(row, job.created_at.replace("T", " ").replace("Z", ""));
      cell(row, (job.finished_at || "").replace("T", " ").replace("Z", ""));
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

  function addRow(row) {
    if (rows.has(row.iteration)) return;
    const tr = document.createElement("tr");
    tr.dataset.iteration = row.iteration;
    for (const [text, digits] of [[row.iteration, 0], [row.tensile_modulus, 4], [row.closed_gaps, 0],
                                  [row.iteration === 1 ? "-" : row.nonconverged_gaps, 0], [row.average_closure, 1],
                                  [row.max_closure, 1], [row.yielded_elements, 0], [row.nonconverged_plastic, 0]]) {
      cell(tr, typeof text === "number" && digits > 0 ? number(text, digits) : String(text));
    }
    cell(tr, row.extrapolated ? "yes" : "");
    cell(tr, row.attempt);
    cell(tr, number(row.seconds, 3));
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
    $("#job-message").textContent = job.error || job.message || "";
    const active = ["queued", "running", "interrupted"].includes(job.state);
    $("#cancel").disabled = !active || job.cancel_requested;
    $("#resume").disabled = ["queued", "running", "converged"].includes(job.state);
    const hasResult = !["queued", "running"].includes(job.state);
    $("#links").replaceChildren(...[["model", base + "/model"], ["iterations", base + "/iterations"]]
      .concat(hasResult ? [["result (JSON)", base + "/result"], ["result (VTU for ParaView)", base + "/result.vtu"]] : [])
      .map(([label, href]) => Object.assign(document.createElement("a"), { href: withToken(href), textContent: label })));
    if (hasResult) showPlots();
  }

  function plotUrl(name, extra) {
    const params = new URLSearchParams(Object.assign({ width: "900", height: "560" }, extra || {}));
    return withToken(`${base}/plots/${name}.svg?${params}`);
  }

  function showPlots() {
    const field = $("#plot-field").value;
    const options = {};
    if ($("#plot-deformed").checked) options.deformed = "auto";
    if ($("#plot-mesh").checked) options.mesh = "1";
    const stamp = { t: String(rows.size) };  // a new picture after new iterations
    $("#contour-plot").src = plotUrl(field, Object.assign(options, stamp));
    $("#closure-plot").src = plotUrl("closure", stamp);
    $("#convergence-plot").src = plotUrl("convergence", stamp);
    for (const img of view.querySelectorAll(".plots img")) {
      img.onload = () => { img.hidden = false; $("#plot-note").textContent = ""; };
      img.onerror = () => { img.hidden = true; };
    }
  }

  for (const control of ["#plot-field", "#plot-deformed", "#plot-mesh"]) {
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

  showState(await api(base));
  for (const row of (await api(base + "/iterations")).iterations) addRow(row);

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
    source.addEventListener("state", () => api(base).then(showState).catch(() => {}));
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

window.addEventListener("hashchange", route);
route();
health();
setInterval(health, 5000);
