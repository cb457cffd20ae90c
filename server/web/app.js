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
    const error = new Error([problem.detail || response.statusText].concat(details).join("\n"));
    error.problem = problem;  // every error with its pointer, for showProblem
    throw error;
  }
  return body;
}

function cell(row, text, className) {
  const td = row.insertCell();
  td.textContent = text;
  if (className) td.className = className;
  return td;
}

// A converged run whose message carries warnings (job.warnings) is not a clean convergence: it
// gets its own amber badge that says so.
function warned(job) {
  return job.state === "converged" && (job.warnings || []).length > 0;
}

function stateBadge(element, job) {
  const count = (job.warnings || []).length;
  element.textContent = warned(job) ? (count === 1 ? "converged with warning" : `converged with ${count} warnings`) : job.state;
  element.className = "state " + job.state + (warned(job) ? " warned" : "");
  element.dataset.state = job.state;
}

// A problem document in box: its detail, then every error at its JSON Pointer (an import's or a
// model's 422 lists them all).
function showProblem(box, error) {
  const problem = error.problem || { detail: error.message };
  const head = Object.assign(document.createElement("p"), { textContent: problem.detail || error.message });
  const list = document.createElement("ul");
  for (const e of problem.errors || []) {
    const item = list.appendChild(document.createElement("li"));
    item.appendChild(Object.assign(document.createElement("code"), { textContent: e.pointer || "(document)" }));
    item.append(" " + e.detail);
  }
  box.replaceChildren(head, ...(list.children.length ? [list] : []));
  box.hidden = false;
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

// A contact pair with Coulomb friction (the result's pair carries its mu only when it is > 0).
function pairHasFriction(pair) {
  return typeof pair.friction === "number" && pair.friction > 0;
}

// A contact pair of the result (its points along side A) as a table: its points, those in
// contact, the peak pressure and the largest gap, with where they are.
function contactPairTable(pair, index, units) {
  const table = Object.assign(document.createElement("table"), { className: "grid numbers contact-pair" });
  table.dataset.pair = String(index + 1);
  const [a, b] = pair.surfaces || ["?", "?"];
  table.createCaption().textContent = `Pair ${index + 1}: ${a} against ${b}`;
  const points = pair.points || [];
  const touching = points.filter(p => p.state !== "open");
  const peak = points.reduce((best, p) => (best === null || p.pressure > best.pressure ? p : best), null);
  const widest = points.reduce((best, p) => (best === null || p.gap > best.gap ? p : best), null);
  const at = p => (p ? ` at (${p.r.toPrecision(5)}, ${p.z.toPrecision(5)})` : "");
  const rows = [
    ["points along " + a, String(points.length), "points"],
    ["points in contact", String(touching.length), "in-contact"],
    ["peak pressure" + unitOf(units, "stress"), peak ? peak.pressure.toPrecision(5) + at(peak) : "", "peak-pressure"],
    ["largest gap" + unitOf(units, "length"), widest ? widest.gap.toPrecision(4) + at(widest) : "", "largest-gap"],
  ];
  // A pair with friction: its mu, the points that stick and slip (state), and the largest shear
  // and accumulated slip in magnitude (signed, with where they are).
  if (pairHasFriction(pair)) {
    const largest = key => points.reduce((best, p) => (best === null || Math.abs(p[key] || 0) > Math.abs(best[key] || 0) ? p : best), null);
    const shear = largest("shear"), slip = largest("slip");
    rows.push(["friction \u03bc", String(pair.friction), "friction"],
              ["points sticking", String(points.filter(p => p.state === "stick").length), "sticking"],
              ["points slipping", String(points.filter(p => p.state === "slip").length), "slipping"],
              ["peak shear" + unitOf(units, "stress"), shear ? (shear.shear || 0).toPrecision(5) + at(shear) : "", "peak-shear"],
              ["largest slip" + unitOf(units, "length"), slip ? (slip.slip || 0).toPrecision(4) + at(slip) : "", "largest-slip"]);
  }
  const body = table.createTBody();
  for (const [label, value, key] of rows) {
    const tr = body.insertRow();
    tr.dataset.key = key;
    const th = document.createElement("th");
    th.textContent = label;
    tr.appendChild(th);
    cell(tr, value);
  }
  return table;
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
      stateBadge(stateCell.appendChild(document.createElement("span")), job);
      if (job.error || job.message) {
        // Why it failed, or how the run ended (its warnings first): the start here, all on hover.
        const reason = stateCell.appendChild(document.createElement("div"));
        reason.className = job.error ? "reason" : warned(job) ? "reason warning" : "reason note";
        reason.textContent = job.error ? job.error.split("\n")[0] : warned(job) ? "warning: " + job.warnings.join("; ") : job.message;
        reason.title = job.error || job.message;
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
      status.textContent = "";
      showProblem(view.querySelector("#import-errors"), error);
    }
  });
  // An assembly and the files it names, as POST /v1/imports takes them (docs/import.md): imported
  // and submitted in one request; a bad assembly lists every problem at its pointer.
  view.querySelector("#import-form").addEventListener("submit", async event => {
    event.preventDefault();
    const status = view.querySelector("#import-status");
    const errors = view.querySelector("#import-errors");
    errors.hidden = true;
    const assembly = view.querySelector("#assembly-file").files[0];
    if (!assembly) { status.textContent = "choose the assembly document first"; return; }
    const form = new FormData();
    form.append("assembly", assembly, assembly.name);
    // Each file under its own name, which is how the assembly names it ("mesh": "ring-fit.geo").
    for (const file of view.querySelector("#assembly-parts").files) form.append("file", file, file.name);
    status.textContent = "importing " + assembly.name + " ...";
    try {
      const job = await api("/v1/imports?submit=true", { method: "POST", body: form });
      location.hash = `#/jobs/${job.id}`;
    } catch (error) {
      status.textContent = "";
      showProblem(errors, error);
    }
  });
  await load(false);
  await loadStudies(view.querySelector("#studies-section"));
  ready("list");
  const timer = setInterval(() => {
    loadStudies(view.querySelector("#studies-section")).catch(() => {});
    if (!more.hidden) return;
    load(false).catch(() => {});
  }, 3000);
  closeJobView = () => clearInterval(timer);
}

// ---------------------------------------------------------------------------------------------
// Studies (docs/studies.md): the list under the jobs, and a page per study with its points and
// each output drawn against each parameter.

// The studies table (GET /v1/studies), shown when there is a study.
async function loadStudies(section) {
  const { studies } = await api("/v1/studies");
  section.hidden = studies.length === 0;
  const tbody = section.querySelector("tbody");
  tbody.replaceChildren();
  for (const study of studies) {
    const row = tbody.insertRow();
    const link = document.createElement("a");
    link.href = `#/studies/${study.id}`;
    link.textContent = study.id;
    row.insertCell().append(link);
    cell(row, study.title);
    cell(row, String(study.points_total));
    cell(row, String(study.finished));
    cell(row, String(study.converged));
    cell(row, when(study.created_at));
  }
}

// One output against one parameter, a dot per point that has the output. With more parameters
// (a grid), the points that share the other parameters' values are joined by a line, one colour
// each. A parameter whose values are not numbers (a mesh file) is spread evenly in the order of
// its values.
function studyPlotSvg(study, parameter, output) {
  const W = 420, H = 280, left = 76, right = 30, top = 30, bottom = 44;
  const { svg, add } = svgCanvas(W, H);
  // Tick labels short enough for the margins: 4 digits, or 3 and an exponent when large or small.
  const tick = v => (v !== 0 && (Math.abs(v) >= 1e5 || Math.abs(v) < 1e-2) ? v.toExponential(2)
                                                                          : Number(v.toPrecision(4)).toString());
  svg.dataset.parameter = parameter;
  svg.dataset.output = output;
  const points = study.points.filter(p => typeof (p.outputs || {})[output] === "number");
  const values = [...new Set(study.points.map(p => JSON.stringify(p.parameters[parameter])))].map(v => JSON.parse(v));
  const numeric = values.every(v => typeof v === "number");
  const xOf = v => (numeric ? v : values.findIndex(w => JSON.stringify(w) === JSON.stringify(v)));
  const xs = values.map(xOf), ys = points.map(p => p.outputs[output]);
  const x0 = Math.min(...xs), x1 = Math.max(...xs), xSpan = x1 - x0 || 1;
  const y0 = Math.min(...ys, ...(ys.length ? [] : [0])), y1 = Math.max(...ys, ...(ys.length ? [] : [1]));
  const ySpan = y1 - y0 || Math.abs(y1) || 1;
  const x = v => left + (W - left - right) * (xs.length > 1 ? (xOf(v) - x0) / xSpan : 0.5);
  const y = v => H - bottom - (H - top - bottom) * (v - y0 + (y1 === y0 ? ySpan / 2 : 0)) / ySpan;
  add("text", { x: 8, y: 18, class: "title" }, `${output} against ${parameter}`);
  add("line", { x1: left, y1: H - bottom, x2: W - right, y2: H - bottom, stroke: "#999" });
  add("line", { x1: left, y1: top, x2: left, y2: H - bottom, stroke: "#999" });
  for (const v of y1 === y0 ? [y0] : [y0, y1]) {
    add("text", { x: left - 6, y: y(v) + 4, "text-anchor": "end" }, tick(v));
  }
  for (const v of values) {
    add("text", { x: x(v), y: H - bottom + 16, "text-anchor": "middle" }, typeof v === "number" ? tick(v) : String(v));
  }
  add("text", { x: (left + W - right) / 2, y: H - 6, "text-anchor": "middle" }, parameter);
  // One series per combination of the other parameters' values.
  const others = Object.keys(study.points[0] ? study.points[0].parameters : {}).filter(n => n !== parameter);
  const series = new Map();
  for (const p of points) {
    const key = others.map(n => `${n} = ${JSON.stringify(p.parameters[n])}`).join(", ");
    if (!series.has(key)) series.set(key, []);
    series.get(key).push(p);
  }
  const colours = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e"];
  [...series.entries()].forEach(([key, members], k) => {
    const colour = colours[k % colours.length];
    members.sort((a, b) => xOf(a.parameters[parameter]) - xOf(b.parameters[parameter]));
    if (members.length > 1) {
      add("polyline", { points: members.map(p => `${x(p.parameters[parameter])},${y(p.outputs[output])}`).join(" "),
                        fill: "none", stroke: colour, "stroke-width": 2, "data-series": key });
    }
    for (const p of members) {
      add("circle", { cx: x(p.parameters[parameter]), cy: y(p.outputs[output]), r: 3.5, fill: colour,
                      "data-point": p.index, "data-value": p.outputs[output] });
    }
    if (key) add("text", { x: left + 8, y: top + 14 * (k + 1), fill: colour }, key);
  });
  return svg;
}

async function showStudy(id) {
  view.replaceChildren(document.getElementById("study-view").content.cloneNode(true));
  let timer = null, closed = false;
  async function draw() {
    const study = await api(`/v1/studies/${id}`);
    if (closed) return false;
    view.querySelector("#study-title").textContent = study.title || `study ${id}`;
    view.querySelector("#study-id").textContent = study.id;
    const status = view.querySelector("#study-status");
    status.textContent = study.status;
    status.className = "state " + study.status;
    view.querySelector("#study-created").textContent = when(study.created_at);
    view.querySelector("#study-message").textContent = study.message;
    const parameters = Object.keys(study.points[0] ? study.points[0].parameters : {});
    const outputs = [...new Set(study.points.flatMap(p => Object.keys(p.outputs || {})))];
    const table = view.querySelector("#study-points");
    const head = table.tHead;
    head.replaceChildren();
    const headings = head.insertRow();
    for (const h of ["point", ...parameters, "status", "cached", "job", ...outputs, "message"]) {
      headings.appendChild(document.createElement("th")).textContent = h;
    }
    const body = table.tBodies[0];
    body.replaceChildren();
    for (const p of study.points) {
      const row = body.insertRow();
      cell(row, String(p.index));
      for (const n of parameters) {
        const v = p.parameters[n];
        cell(row, typeof v === "number" ? Number(v.toPrecision(6)).toString() : JSON.stringify(v));
      }
      const state = row.insertCell().appendChild(document.createElement("span"));
      state.textContent = p.status;
      state.className = "state " + p.status;
      cell(row, p.cached ? "yes" : "");
      const jobCell = row.insertCell();
      if (p.job !== null && p.job !== undefined) {
        const link = jobCell.appendChild(document.createElement("a"));
        link.href = `#/jobs/${p.job}`;
        link.textContent = p.job;
      }
      for (const o of outputs) {
        const v = (p.outputs || {})[o];
        cell(row, typeof v === "number" ? Number(v.toPrecision(6)).toString() : "");
      }
      cell(row, p.message || "", p.status === "failed" ? "reason" : "");
    }
    const plots = view.querySelector("#study-plots");
    plots.replaceChildren();
    for (const o of outputs) {
      for (const n of parameters) plots.appendChild(document.createElement("figure")).append(studyPlotSvg(study, n, o));
    }
    return study.status === "running";
  }
  const again = async () => {
    try {
      if (await draw()) timer = setTimeout(again, 2000);
    } catch (error) {
      view.querySelector("#study-message").textContent = error.message;
    }
  };
  if (await draw()) timer = setTimeout(again, 2000);
  ready("study");
  closeJobView = () => { closed = true; clearTimeout(timer); };
}

// ---------------------------------------------------------------------------------------------
// One job, followed live.

// The iteration table's columns, chosen by a row as the CLI chooses them: exact contact rows (they
// carry active_set_iterations) show the node pairs in contact, the complementarity residual and the
// active sets tried instead of the classic E tension and non-converged count (which mean nothing
// there); rows of a stepped load show their step and increment, rows of a run with friction the
// points that stick and slip and the friction residual. [heading, field, text of a row]
// A row of a run with friction carries stick_points, slip_points and friction_residual together.
function hasFrictionColumns(row) {
  return typeof row.stick_points === "number";
}

// The forces a row carries at the end of a converged increment: each support set's summed
// reactions and each contact pair's force, as [name, fr, fz].
function rowForces(row) {
  return (row.set_reactions || []).map(s => [`set ${s.set}`, s.fr, s.fz])
    .concat((row.pair_forces || []).map(p => [`pair ${p.surfaces.join(" / ")}`, p.fr, p.fz]));
}

// An empty SVG of W x H user units that scales with its box, and add(tag, attributes, text) that
// appends an element to it and returns the element: what every plot drawn here starts from.
function svgCanvas(W, H) {
  const ns = "http://www.w3.org/2000/svg";
  const svg = document.createElementNS(ns, "svg");
  svg.setAttribute("viewBox", `0 0 ${W} ${H}`);
  svg.setAttribute("role", "img");
  const add = (tag, attributes, text) => {
    const e = svg.appendChild(document.createElementNS(ns, tag));
    for (const [key, value] of Object.entries(attributes)) e.setAttribute(key, String(value));
    if (text !== undefined) e.textContent = text;
    return e;
  };
  return { svg, add };
}

// Each force (fz, or fr where fz stays 0) against the increments of the load path, one polyline
// per support set or pair (an SVG drawn from the rows, so it grows while the job runs).
function forceSvg(history) {
  const W = 520, H = 300, left = 70, right = 12, top = 28, bottom = 40;
  const { svg, add } = svgCanvas(W, H);
  const ends = history.filter(r => rowForces(r).length > 0);
  const series = new Map();  // name -> [[x, value]]
  ends.forEach((r, i) => {
    for (const [name, fr, fz] of rowForces(r)) {
      if (!series.has(name)) series.set(name, { fr: [], fz: [] });
      series.get(name).fr.push([i + 1, fr]);
      series.get(name).fz.push([i + 1, fz]);
    }
  });
  const lines = [...series.entries()].map(([name, s]) =>
    (s.fz.some(([, v]) => v !== 0) || !s.fr.some(([, v]) => v !== 0) ? [`${name} fz`, s.fz] : [`${name} fr`, s.fr]));
  const values = lines.flatMap(([, points]) => points.map(([, v]) => v)).concat([0]);
  const lo = Math.min(...values), hi = Math.max(...values), span = hi - lo || 1;
  const x = i => left + (W - left - right) * (ends.length > 1 ? (i - 1) / (ends.length - 1) : 0.5);
  const y = v => H - bottom - (H - top - bottom) * (v - lo) / span;
  add("text", { x: 8, y: 18, class: "title" }, "Force at the end of each increment");
  add("line", { x1: left, y1: y(0), x2: W - right, y2: y(0), stroke: "#999" });
  for (const v of [lo, hi]) add("text", { x: left - 6, y: y(v) + 4, "text-anchor": "end" }, v.toPrecision(4));
  add("text", { x: (left + W - right) / 2, y: H - 8, "text-anchor": "middle" }, "increment of the load path");
  const colours = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e"];
  lines.forEach(([name, points], k) => {
    const colour = colours[k % colours.length];
    add("polyline", { points: points.map(([i, v]) => `${x(i)},${y(v)}`).join(" "), fill: "none", stroke: colour,
                      "stroke-width": 2, "data-series": name });
    for (const [i, v] of points) add("circle", { cx: x(i), cy: y(v), r: 3, fill: colour, "data-value": v });
    add("text", { x: left + 8, y: top + 14 * (k + 1), fill: colour }, name);
  });
  return svg;
}

// Models without gap elements (no gap closures, not exact contact) show no gap columns: their
// rows hold 0 there, which reads as a measurement.
function hasGapColumns(row) {
  return typeof row.active_set_iterations === "number" || (Array.isArray(row.gap_closures) && row.gap_closures.length > 0);
}

function columnsFor(row) {
  const exact = typeof row.active_set_iterations === "number";
  const gapless = !hasGapColumns(row);
  const count = key => r => (typeof r[key] === "number" ? String(r[key]) : "");
  const fixed = (key, digits) => r => number(r[key], digits);
  const columns = [["iter", "iteration", count("iteration")]];
  for (const key of ["step", "increment"]) if (key in row) columns.push([key, key, count(key)]);
  if (!exact) columns.push(["E tension", "tensile_modulus", fixed("tensile_modulus", 4)]);
  // The words of docs/results.md ("Gap words"): exact rows count the closed gaps (touching), classic
  // rows the report's gaps past 100 %; the average is over those, "-" when there are none.
  columns.push([exact ? "closed" : "> 100 %", "closed_gaps", count("closed_gaps")]);
  // The report leaves iteration 1's non-converged count blank: there is nothing to compare with.
  if (!exact) columns.push(["non-conv", "nonconverged_gaps", r => (r.iteration === 1 ? "-" : count("nonconverged_gaps")(r))]);
  columns.push([exact ? "avg clos %" : "avg > 100 %", "average_closure",
                r => (r.closed_gaps > 0 ? fixed("average_closure", 1)(r) : "-")],
               ["max clos %", "max_closure", fixed("max_closure", 1)]);
  if (exact) {
    columns.push(["contact pairs", "contact_pairs", count("contact_pairs")],
                 ["complementarity", "complementarity",
                  r => (typeof r.complementarity === "number" ? r.complementarity.toExponential(2) : "")],
                 ["active sets", "active_set_iterations", count("active_set_iterations")]);
  }
  columns.push(["yielded", "yielded_elements", count("yielded_elements")],
               ["N-L non-conv", "nonconverged_plastic", count("nonconverged_plastic")]);
  if (!exact) columns.push(["extrap.", "extrapolated", r => (r.extrapolated ? "yes" : "")]);
  // Runs with friction: the points that stick and slip and the residual of Coulomb's law.
  if (hasFrictionColumns(row)) {
    columns.push(["stick", "stick_points", count("stick_points")], ["slip", "slip_points", count("slip_points")],
                 ["friction residual", "friction_residual",
                  r => (typeof r.friction_residual === "number" ? r.friction_residual.toExponential(2) : "")]);
  }
  columns.push(["attempt", "attempt", count("attempt")], ["s", "seconds", fixed("seconds", 3)]);
  const gapFields = ["tensile_modulus", "closed_gaps", "nonconverged_gaps", "average_closure", "max_closure", "extrapolated"];
  return gapless ? columns.filter(([, field]) => !gapFields.includes(field)) : columns;
}

// The exact mode's convergence, drawn here from the history rows (an SVG): per iteration (or load
// increment) the active sets the contact solve tried and the node pairs it left in contact, as
// labelled bars, and below them its complementarity residual on a log scale. One row is one group
// of bars that reads as such, not the classic plot's single dot of closures.
function exactConvergenceSvg(history) {
  const W = 520, H = 330, left = 62, right = 12;
  const { svg, add } = svgCanvas(W, H);
  const label = r => ("step" in r ? `${r.step}.${r.increment ?? ""}` : String(r.iteration));
  const slot = (W - left - right) / history.length;
  const middle = i => left + slot * (i + 0.5);
  add("text", { x: 8, y: 18, class: "title" }, "Exact contact solve per iteration");

  // Upper panel: active sets and pairs in contact, on a count axis of 1, 2 or 5 times a power of ten.
  const top = 48, bottom = 165;
  const most = Math.max(1, ...history.map(r => Math.max(r.active_set_iterations || 0, r.contact_pairs || 0)));
  const power = 10 ** Math.floor(Math.log10(most / 4 || 1));
  const step = [1, 2, 5, 10].map(m => m * power).find(s => most / s <= 5) || 10 * power;
  const ceiling = Math.max(step, Math.ceil(most / step) * step);
  const y = v => bottom - (bottom - top) * v / ceiling;
  for (let v = 0; v <= ceiling; v += step) {
    add("line", { x1: left, x2: W - right, y1: y(v), y2: y(v), class: "grid" });
    add("text", { x: left - 6, y: y(v) + 4, class: "tick end" }, String(v));
  }
  add("text", { x: 14, y: (top + bottom) / 2, class: "axis-label", transform: `rotate(-90 14 ${(top + bottom) / 2})` }, "count");
  const bar = Math.min(44, slot * 0.36);
  history.forEach((r, i) => {
    for (const [value, offset, kind] of [[r.active_set_iterations || 0, -bar, "active-sets"], [r.contact_pairs || 0, 0, "pairs"]]) {
      add("rect", { x: middle(i) + offset, y: y(value), width: bar, height: bottom - y(value), class: "bar " + kind });
      if (bar >= 12) add("text", { x: middle(i) + offset + bar / 2, y: y(value) - 4, class: "tick middle" }, String(value));
    }
  });
  add("rect", { x: W - 262, y: 26, width: 11, height: 11, class: "swatch active-sets" });
  add("text", { x: W - 246, y: 36, class: "tick" }, "active sets tried");
  add("rect", { x: W - 128, y: 26, width: 11, height: 11, class: "swatch pairs" });
  add("text", { x: W - 112, y: 36, class: "tick" }, "pairs in contact");

  // Lower panel: the complementarity residual, log10, a tick per decade (fewer when many).
  const top2 = 200, bottom2 = 282;
  const logs = history.map(r => Math.log10(Math.max(r.complementarity || 0, 1e-300)));
  const low = Math.floor(Math.min(...logs)), high = Math.max(Math.ceil(Math.max(...logs)), low + 1);
  const y2 = v => bottom2 - (bottom2 - top2) * (v - low) / (high - low);
  const every = Math.ceil((high - low) / 5);
  for (let v = low; v <= high; v += every) {
    add("line", { x1: left, x2: W - right, y1: y2(v), y2: y2(v), class: "grid" });
    add("text", { x: left - 6, y: y2(v) + 4, class: "tick end" }, `1e${v}`);
  }
  add("text", { x: 14, y: (top2 + bottom2) / 2, class: "axis-label", transform: `rotate(-90 14 ${(top2 + bottom2) / 2})` },
      "complementarity");
  add("polyline", { points: logs.map((v, i) => `${middle(i)},${y2(v)}`).join(" "), class: "residual" });
  logs.forEach((v, i) => add("circle", { cx: middle(i), cy: y2(v), r: 3.5, class: "residual" }));

  // The iteration (step.increment) under each group, thinned to what fits.
  const stride = Math.ceil(32 / slot);
  history.forEach((r, i) => {
    if (i % stride === 0) add("text", { x: middle(i), y: bottom2 + 20, class: "tick middle" }, label(r));
  });
  add("text", { x: (left + W - right) / 2, y: H - 8, class: "axis-label middle" },
      history.some(r => "step" in r) ? "step.increment" : "iteration");
  return svg;
}

// The heat conduction table's columns (GET /v1/jobs/{id}/thermal rows): steady rows by pass,
// transient rows by output time, as the CLI's thermal lines show them.
function thermalColumns(row) {
  const number = value => (typeof value === "number" ? String(Number(value.toPrecision(6))) : "");  // 6 digits, as the CLI
  const columns = row.kind === "steady"
    ? [["pass", r => String(r.pass)], ["solves", r => String(r.iterations)], ["max |dT|", r => number(r.max_change)],
       ["pass |dT|", r => number(r.pass_change)]]
    : [["time", r => number(r.time)], ["steps", r => String(r.time_steps)], ["max step |dT|", r => number(r.max_change)]];
  return columns.concat([["min T", r => number(r.min_T)], ["max T", r => number(r.max_T)]]);
}

async function showJob(id) {
  view.replaceChildren(document.getElementById("job-view").content.cloneNode(true));
  const $ = selector => view.querySelector(selector);
  const base = `/v1/jobs/${id}`;
  const rows = new Map();     // iteration -> its table row
  const rowData = new Map();  // iteration -> its history row

  let units = {};
  let columns = null;  // chosen by the first row
  let exact = false;   // exact contact rows

  // The columns, and the watched elements' and gaps' columns as the CLI prints them: named from the
  // first row.
  function addHeader(row) {
    if (columns) return;
    columns = columnsFor(row);
    exact = columns.some(([, field]) => field === "active_set_iterations");
    const head = $("#iterations thead tr");
    const th = (text, title) => head.appendChild(Object.assign(document.createElement("th"), { textContent: text, title: title || "" }));
    for (const [text, field] of columns) th(text, field);
    const stress = unitOf(units, "stress");
    for (const e of (row.watch || {}).elements || []) {
      for (const name of ["s_r", "s_th", "eff"]) th(`el ${e.id} ${name}${stress}`);
    }
    for (const g of (row.watch || {}).gaps || []) {
      for (const name of [`E_M${stress}`, "clos %", `s_M${stress}`]) th(`gap ${g.id} ${name}`);
    }
    $("#no-iterations").hidden = true;
  }

  // The first row with friction columns after rows without (nothing touched yet): the table is
  // drawn again with the friction columns, the earlier rows blank in them.
  function addFrictionColumns(row) {
    if (!columns || !hasFrictionColumns(row) || columns.some(([, field]) => field === "stick_points")) return;
    const earlier = historyRows();
    columns = null;
    rows.clear();
    rowData.clear();
    $("#iterations thead tr").replaceChildren();
    $("#iterations tbody").replaceChildren();
    addHeader(row);
    for (const r of earlier) addRow(r);
  }

  function addRow(row) {
    if (rows.has(row.iteration)) return;
    addFrictionColumns(row);
    addHeader(row);
    const tr = document.createElement("tr");
    tr.dataset.iteration = row.iteration;
    for (const [, , text] of columns) cell(tr, text(row));
    for (const e of (row.watch || {}).elements || []) {
      for (const value of [e.sigma_r, e.sigma_theta, e.effective]) cell(tr, number(value, 1));
    }
    for (const g of (row.watch || {}).gaps || []) {
      cell(tr, typeof g.modulus === "number" ? g.modulus.toPrecision(5) : "");
      cell(tr, number(g.closure, 2));
      cell(tr, number(g.sigma_m, 1));
    }
    rows.set(row.iteration, tr);
    rowData.set(row.iteration, row);
    if (rowForces(row).length > 0) showForces();
    // Keep the table ordered even if rows arrive out of order (a reconnect after a gap).
    const later = [...rows.keys()].filter(k => k > row.iteration).sort((a, b) => a - b)[0];
    $("#iterations tbody").insertBefore(tr, later === undefined ? null : rows.get(later));
  }
  const historyRows = () => [...rowData.keys()].sort((a, b) => a - b).map(k => rowData.get(k));

  // The last increment's forces in the table, every increment's in the plot.
  function showForces() {
    const history = historyRows();
    const last = [...history].reverse().find(r => rowForces(r).length > 0);
    if (!last) return;
    const force = unitOf(units, "force");
    $("#forces thead tr").children[1].textContent = `fr${force}`;
    $("#forces thead tr").children[2].textContent = `fz${force}`;
    const at = "step" in last ? `step ${last.step}, increment ${last.increment}` : `iteration ${last.iteration}`;
    $("#forces tbody").replaceChildren(...rowForces(last).map(([name, fr, fz]) => {
      const tr = document.createElement("tr");
      tr.dataset.name = name;
      cell(tr, name);
      cell(tr, number(fr, 2));
      cell(tr, number(fz, 2));
      cell(tr, at);
      return tr;
    }));
    $("#force-plot").replaceChildren(forceSvg(history));
    $("#forces-section").hidden = false;
  }

  const thermalRows = new Map();  // index -> its table row
  function addThermalRow(row) {
    if (thermalRows.has(row.index)) return;
    const columns = thermalColumns(row);
    if (thermalRows.size === 0) {
      $("#thermal thead tr").replaceChildren(...columns.map(([title]) => {
        const th = document.createElement("th");
        th.textContent = title;
        return th;
      }));
      $("#thermal-section").hidden = false;
    }
    const tr = document.createElement("tr");
    tr.dataset.index = row.index;
    for (const [, format] of columns) cell(tr, format(row));
    thermalRows.set(row.index, tr);
    const later = [...thermalRows.keys()].filter(k => k > row.index).sort((a, b) => a - b)[0];
    $("#thermal tbody").insertBefore(tr, later === undefined ? null : thermalRows.get(later));
  }

  // Adaptive jobs: the cycles stored so far (job.adaptation) and their convergence plot.
  function showAdaptation(job) {
    if (!Array.isArray(job.adaptation)) return;
    $("#adapt-section").hidden = false;
    const cell = text => Object.assign(document.createElement("td"), { textContent: text });
    $("#adapt tbody").replaceChildren(...job.adaptation.map(c => {
      const tr = document.createElement("tr");
      const s = c.seconds || {};
      const t = [s.mesh, s.import, s.solve, s.estimate].map(v => (v || 0).toFixed(2)).join(" / ");
      tr.append(cell(c.cycle), cell(c.nodes), cell(c.elements), cell(c.unknowns),
                cell(`${(100 * c.relative_error).toPrecision(3)} %`), cell(t));
      return tr;
    }));
    if (job.adaptation.length) $("#adapt-plot").src = withToken(`${base}/plots/adaptation.svg?n=${job.adaptation.length}&state=${job.state}`);
  }

  function showState(job) {
    showAdaptation(job);
    $("#job-title").textContent = job.title;
    $("#job-id").textContent = job.id;
    stateBadge($("#job-state"), job);
    $("#job-iteration").textContent = job.iteration;
    $("#job-max").textContent = job.max_iterations;
    $("#job-progress").textContent = job.progress ? job.progress.text : "";
    // A finished result's estimated stress error (docs/recovery.md), worded as the command line's summary.
    const estimate = job.error_estimate;
    $("#job-error-estimate").hidden = !estimate;
    $("#job-error-estimate").textContent = estimate ? `Estimated stress error ${(100 * estimate.relative).toFixed(2)} % ` +
      `in the energy norm (error_estimate.relative ${Number(estimate.relative.toPrecision(4))})` : "";
    $("#job-attempts").textContent = job.attempts;
    $("#job-created").textContent = when(job.created_at);
    $("#job-started").textContent = when(job.started_at) || "not yet";
    $("#job-finished").textContent = when(job.finished_at) || "not yet";
    // A failed job says why, in full; other jobs show the run's message (amber with warnings).
    $("#job-error").hidden = !job.error;
    $("#job-error").textContent = job.error ? `Failed: ${job.error}` : "";
    $("#job-message").textContent = job.error ? "" : (job.message || "");
    $("#job-message").className = warned(job) ? "message warning" : "message";
    const active = ["queued", "running", "interrupted"].includes(job.state);
    $("#cancel").disabled = !active || job.cancel_requested;
    $("#resume").disabled = ["queued", "running", "converged"].includes(job.state);
    const hasResult = !active;
    if (job.last_row && Array.isArray(job.last_row.gap_closures)) hasGaps = job.last_row.gap_closures.length > 0;
    if (job.last_row) hasGapRows = hasGapColumns(job.last_row);
    showLinks(hasResult);
    if (hasResult && !plotsShown) showPlots();
    if (!hasResult) showRunning();
    if (hasResult && !contactAsked) loadContact(hasResult);
  }

  function showLinks(hasResult) {
    $("#links").replaceChildren(...[["model", base + "/model"], ["iterations", base + "/iterations"]]
      .concat(hasResult ? [["result (JSON)", base + "/result"], ["result (VTU for ParaView)", base + "/result.vtu"]] : [])
      .concat(hasResult && (hasGaps || hasContact()) ? [["contact pressure (CSV)", base + "/plots/contact_pressure.csv"]] : [])
      .concat(hasResult && hasFriction() ? [["friction (CSV)", base + "/plots/friction.csv"]] : [])
      .map(([label, href]) => Object.assign(document.createElement("a"), { href: withToken(href), textContent: label })));
  }

  // Contact surfaces: the result's pairs (GET .../contact, the result's contact member alone), a
  // table each, and the contact-pressure plot, which then draws them.
  let contact = [], contactAsked = false;
  const hasContact = () => contact.length > 0;
  const hasFriction = () => contact.some(pairHasFriction);
  function loadContact(hasResult) {
    contactAsked = true;
    api(base + "/contact").then(answer => {
      contact = Array.isArray(answer.contact) ? answer.contact : [];
      if (!hasContact()) return;
      $("#contact-pairs").replaceChildren(...contact.map((pair, k) => contactPairTable(pair, k, units)));
      $("#contact-section").hidden = false;
      $("#contact-caption").textContent = "contact pressure and gap along each contact pair";
      $("#contact-plot").alt = "contact pressure and gap along each contact pair";
      showLinks(hasResult);
      if (plotsShown) {
        $("#contact-plot").parentElement.hidden = false;
        if ($("#contact-plot").hidden) placeholder("#contact-plot", "drawing ...");
        loadPlot("#contact-plot", "contact_pressure", rowOptions());
        // Pairs with friction: shear and mu x pressure along each, stick and slip zones.
        if (hasFriction()) {
          $("#friction-plot").parentElement.hidden = false;
          if ($("#friction-plot").hidden) placeholder("#friction-plot", "drawing ...");
          loadPlot("#friction-plot", "friction", {});
        }
      }
    }).catch(() => { contactAsked = false; });
  }

  // Plots are drawn for the space they get: the figure's width in device pixels, so a PNG is sharp
  // and no larger than the screen needs (a 10^5-element SVG is tens of MB; its PNG is not).
  // [image, plot name, the options it takes]
  const plots = [["#contour-plot", () => $("#plot-field").value, contourOptions], ["#contact-plot", () => "contact_pressure", rowOptions],
                 ["#friction-plot", () => "friction", () => ({})],
                 ["#closure-plot", () => "closure", rowOptions], ["#convergence-plot", () => "convergence", () => ({})]];
  let plotsShown = false;

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
    options.levels = $("#plot-levels").value;  // the server's default is even; quantile must be asked for
    return options;
  }

  let hasGaps = true;
  const gapPlot = selector => selector === "#contact-plot" || selector === "#closure-plot";
  // A model without gaps has no gap plots; with contact surfaces, the contact plot draws those.
  // The friction plot only for a result with a contact pair with friction.
  let hasGapRows = true;  // the gap convergence plot: models with gaps or exact contact only
  const noPlot = selector => (gapPlot(selector) && !hasGaps && !(selector === "#contact-plot" && hasContact())) ||
                             (selector === "#convergence-plot" && !hasGapRows) ||
                             (selector === "#friction-plot" && !hasFriction());

  // A figure's placeholder says what the figure waits for (or why it cannot be drawn); it shows
  // whenever its picture does not.
  function placeholder(selector, text) {
    const img = $(selector);
    img.hidden = true;
    img.parentElement.querySelector(".placeholder").textContent = text;
    img.parentElement.querySelector(".placeholder").hidden = false;
  }

  // Loads a plot into its image: fetched first, shown only once it has loaded, so a figure never
  // shows a broken or half-drawn picture, and a late answer to an older request is dropped.
  function loadPlot(selector, name, options, done) {
    const img = $(selector);
    const ratio = window.devicePixelRatio || 1;
    const width = Math.min(4000, Math.max(320, Math.round(img.parentElement.clientWidth * ratio)));
    const height = Math.round(width * 0.62);
    const url = plotUrl(name, width, height, Object.assign({ t: String(rows.size) }, options));  // new rows: a new picture
    img.dataset.wanted = url;
    const probe = new Image();
    probe.onload = () => {
      if (img.dataset.wanted === url) {
        img.src = url;
        img.hidden = false;
        img.parentElement.hidden = false;
        img.parentElement.querySelector(".placeholder").hidden = true;
        if (plotsShown) $("#plot-note").textContent = "";
        img.dataset.plot = name;
        img.dataset.width = String(width);
        img.dataset.extra = JSON.stringify(options);
      }
      if (done) done(true);
    };
    probe.onerror = () => {
      if (done) done(false);
      if (img.dataset.wanted !== url) return;
      // Say why, e.g. a gap row naming a gap the model does not have.
      fetch(url).then(r => r.json()).then(p => {
        $("#plot-note").textContent = `${name}: ${p.detail}`;
        placeholder(selector, p.detail);
        if (plotsShown && selector !== "#contour-plot") img.parentElement.hidden = true;
      }).catch(() => placeholder(selector, `${name}: cannot be drawn`));
    };
    probe.src = url;
  }

  // The exact mode's convergence figure: drawn here, from the rows.
  function drawExactConvergence() {
    const box = $("#exact-convergence");
    box.replaceChildren(exactConvergenceSvg(historyRows()));
    box.hidden = false;
    $("#convergence-plot").hidden = true;
    $("#convergence-plot").parentElement.querySelector(".placeholder").hidden = true;
    $("#convergence-caption").textContent = "exact contact solve per iteration";
  }

  // While the job runs: the result's plots wait for the result; the convergence is drawn from the
  // rows so far and redrawn as rows arrive, at most every 2 s and never while the last drawing is
  // still on its way.
  let convergenceBusy = false, convergenceAt = -Infinity, convergenceTimer = null;
  function showRunning() {
    plotsShown = false;
    for (const [selector] of plots) {
      if (selector !== "#convergence-plot") placeholder(selector, "drawn when the job has a result");
      $(selector).parentElement.hidden = noPlot(selector);
    }
    if (noPlot("#convergence-plot")) return;
    if (rows.size === 0) {
      placeholder("#convergence-plot", "drawn after the first iteration");
      return;
    }
    const wait = convergenceAt + 2000 - performance.now();
    if (convergenceBusy || wait > 0) {
      if (!convergenceTimer) {
        convergenceTimer = setTimeout(() => { convergenceTimer = null; if (!plotsShown) showRunning(); }, Math.max(wait, 250));
      }
      return;
    }
    convergenceAt = performance.now();
    if (exact) { drawExactConvergence(); return; }
    convergenceBusy = true;
    loadPlot("#convergence-plot", "convergence", {}, () => { convergenceBusy = false; });
  }

  function showPlots() {
    plotsShown = true;
    // A model without gaps has no gap plots: their figures go before the others are measured.
    for (const [selector] of plots) $(selector).parentElement.hidden = noPlot(selector);
    for (const [selector, name, optionsOf] of plots) {
      if (noPlot(selector)) continue;
      if (selector === "#convergence-plot" && exact) { drawExactConvergence(); continue; }
      if ($(selector).hidden) placeholder(selector, "drawing ...");
      loadPlot(selector, name(), optionsOf());
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

  const [job, history, named, thermal] = await Promise.all([api(base), api(base + "/iterations"),
                                                            api(base + "/units").catch(() => ({})),
                                                            api(base + "/thermal").catch(() => ({ thermal: [] }))]);
  units = named || {};
  const unitNames = Object.entries(units).map(([kind, name]) => `${kind} ${name}`);
  $("#job-units").textContent = unitNames.length ? unitNames.join(", ") : "not named in the model";
  for (const row of history.iterations) addRow(row);
  for (const row of thermal.thermal) addThermalRow(row);
  showState(job);
  ready("job");

  // The event stream: one event per iteration, per thermal row and per state change. EventSource reconnects by
  // itself with Last-Event-ID; the server ends the stream when the job stops changing.
  let source = null;
  function follow() {
    if (source) source.close();
    source = new EventSource(withToken(base + "/events"));
    source.addEventListener("iteration", event => {
      addRow(JSON.parse(event.data));
      api(base).then(showState).catch(() => {});
    });
    source.addEventListener("thermal", event => addThermalRow(JSON.parse(event.data)));
    source.addEventListener("adapt_cycle", () => api(base).then(showState).catch(() => {}));
    source.addEventListener("state", () => api(base).then(showState).catch(() => {}));
    source.onerror = () => {
      // A finished job closes its stream; stop reconnecting then.
      api(base).then(job => { if (!["queued", "running", "interrupted"].includes(job.state)) source.close(); })
        .catch(() => source.close());
    };
  }
  follow();
  closeJobView = () => {
    if (source) source.close();
    clearTimeout(convergenceTimer);
  };
}

// ---------------------------------------------------------------------------------------------

async function route() {
  closeJobView();
  closeJobView = () => {};
  const match = location.hash.match(/^#\/jobs\/(\d+)/);
  const study = location.hash.match(/^#\/studies\/(\d+)/);
  try {
    if (match) await showJob(match[1]); else if (study) await showStudy(study[1]); else await showList();
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
