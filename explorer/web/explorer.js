// The explorer's page: reads the form, asks bounce's front door (bounce.js, the library compiled to
// WebAssembly) what `bounce collide`, `bounce curve` and `bounce materials` print as JSON, and
// draws it with uPlot. No physics here: every number comes from the library.
"use strict";
(function () {
  const $ = (id) => document.getElementById(id);
  const state = { call: null, text: null, models: {}, collideText: "", historyText: "", curve: null, plots: {},
                  draws: 0, pending: false, timings: {} };
  window.bounceExplorer = state;

  // One command of the front door: {code, value} with the CLI's exit code; value is the
  // parsed JSON or {parameter, message} for an error.
  function run(command, inputs) {
    const code = state.call(command, JSON.stringify(inputs));
    const text = state.text();
    return { code, text, value: JSON.parse(text) };
  }

  const format = (x) => (x === null || x === undefined ? "—" : Number(x).toPrecision(6));
  // An axis tick: null for a tick uPlot leaves unlabelled (log axes).
  const compact = (x) => {
    if (x === null) return "";
    return (Math.abs(x) >= 1e-2 && Math.abs(x) < 1e4) || x === 0 ? String(+x.toPrecision(3)) : x.toExponential(1);
  };

  // What the user typed, by the CLI's parameter names, as text.
  function pairInputs() {
    const inputs = {};
    if ($("material").value === "custom") {
      for (const name of ["E", "nu", "density", "gamma"]) inputs[name] = $(name).value.trim();
    } else {
      inputs.material = $("material").value;
    }
    const second = $("material2").value;
    if (second === "wall") inputs.wall = true;
    else if (second !== "same") inputs.material2 = second;
    inputs.radius = $("radius").value.trim();
    inputs.model = $("model").value;
    if (state.models[inputs.model]) inputs.tvis = $("tvis").value.trim();
    return inputs;
  }

  function clearMarks() {
    for (const el of document.querySelectorAll(".invalid")) {
      el.classList.remove("invalid");
      el.removeAttribute("aria-invalid");
    }
    $("message").textContent = "";
  }

  // The CLI's message, and the field it names marked; no number is left on show.
  function showError(error) {
    const field = error.parameter ? document.querySelector(`#inputs [name="${error.parameter}"]`) : null;
    if (field) {
      field.classList.add("invalid");
      field.setAttribute("aria-invalid", "true");
    }
    $("message").textContent = error.message;
    for (const id of ["cor", "outcome", "contact-time", "v-stick"]) $(id).textContent = "—";
    delete $("cor").dataset.value;
    $("results").classList.add("stale");
  }

  function showSummary(collision, curve) {
    $("cor").textContent = format(collision.cor);
    $("cor").dataset.value = String(collision.cor);
    $("outcome").textContent = collision.outcome;
    $("contact-time").textContent = collision.contact_time === null ? "none (sticks)" : format(collision.contact_time);
    const sticking = curve.boundaries.filter((b) => b.below === "stick").map((b) => format(b.velocity));
    $("v-stick").textContent = sticking.length ? sticking.join(", ") : "none in the range";
    const warnings = $("warnings");
    warnings.replaceChildren(...(collision.warnings || []).map((w) => Object.assign(document.createElement("li"), { textContent: w })));
  }

  function showBudget(energy) {
    const body = $("budget").querySelector("tbody");
    const rows = Object.keys(energy).sort().map((key) => {
      const tr = document.createElement("tr");
      const share = energy.initial_kinetic > 0 ? energy[key] / energy.initial_kinetic : 0;
      const bar = `<span class="bar" style="width:${Math.min(60, Math.abs(share) * 60).toFixed(1)}%"></span>`;
      tr.innerHTML = `<td>${key}</td><td>${format(energy[key])}</td><td>${bar}${(100 * share).toFixed(2)} %</td>`;
      return tr;
    });
    body.replaceChildren(...rows);
  }

  // Vertical dashed lines at the sticking velocities and a dot at the chosen speed.
  function drawMarks(u) {
    const ctx = u.ctx;
    ctx.save();
    ctx.strokeStyle = "#b00";
    ctx.setLineDash([6, 4]);
    for (const b of (state.curve ? state.curve.boundaries : [])) {
      const x = u.valToPos(b.velocity, "x", true);
      ctx.beginPath();
      ctx.moveTo(x, u.bbox.top);
      ctx.lineTo(x, u.bbox.top + u.bbox.height);
      ctx.stroke();
    }
    if (state.marker) {
      ctx.setLineDash([]);
      ctx.fillStyle = "#b00";
      ctx.beginPath();
      ctx.arc(u.valToPos(state.marker[0], "x", true), u.valToPos(state.marker[1], "y", true), 5, 0, 2 * Math.PI);
      ctx.fill();
    }
    ctx.restore();
    state.draws += 1;
    $("curve-plot").dataset.draws = String(state.draws);
  }

  function plotWidth() {
    return Math.max(320, Math.min(900, $("results").clientWidth - 10));
  }

  function curvePlot(data) {
    if (state.plots.curve) return state.plots.curve.setData(data);
    state.plots.curve = new uPlot({
      width: plotWidth(), height: 300,
      scales: { x: { distr: 3 }, y: { range: [0, 1] } },
      axes: [{ label: "impact velocity v [m/s]", values: (u, ticks) => ticks.map(compact) }, { label: "ε" }],
      series: [{ label: "v [m/s]" }, { label: "ε", stroke: "#1f5fa8", width: 2, points: { show: false } }],
      hooks: { draw: [drawMarks] },
    }, data, $("curve-plot"));
  }

  function historyPlot(trajectory) {
    const column = (key) => trajectory.map((row) => row[key]);
    const force = trajectory.map((row) => row.elastic_force + row.dissipative_force);
    const data = [column("time"), column("overlap"), column("contact_radius"), force];
    if (state.plots.history) return state.plots.history.setData(data);
    const values = (u, ticks) => ticks.map(compact);
    state.plots.history = new uPlot({
      width: plotWidth(), height: 300,
      scales: { x: { time: false }, m: {}, N: {} },
      axes: [{ label: "time t [s]", values }, { scale: "m", label: "δ, a [m]", values, size: 70 },
             { scale: "N", label: "F [N]", side: 1, values, size: 70, grid: { show: false } }],
      series: [{ label: "t [s]" },
               { label: "overlap δ [m]", scale: "m", stroke: "#1f5fa8", width: 2 },
               { label: "contact radius a [m]", scale: "m", stroke: "#2a8f3c", width: 2 },
               { label: "force F = F_E + F_D [N]", scale: "N", stroke: "#b00", width: 1.5 }],
    }, data, $("history-plot"));
  }

  // The curve's command: "LO:HI:N" as typed (100 velocities by default), log-spaced.
  function curveInputs(pair) {
    return { ...pair, velocities: $("velocities").value.trim(), log: true };
  }

  function update() {
    state.pending = false;
    clearMarks();
    const pair = pairInputs();
    // ε and the budget as `bounce collide` gives them (a force law may use its master curve),
    // the history from the same collision integrated with its trajectory (--trajectory).
    const velocity = $("velocity").value.trim();
    const collision = run("collide", { ...pair, velocity });
    if (collision.code !== 0) return showError(collision.value);
    const history = run("collide", { ...pair, velocity, trajectory: true });
    if (history.code !== 0) return showError(history.value);
    const start = performance.now();
    const curve = run("curve", curveInputs(pair));
    if (curve.code !== 0) return showError(curve.value);
    state.collideText = collision.text;
    state.historyText = history.text;
    state.curve = curve.value;
    state.marker = [collision.value.velocity, collision.value.cor];
    $("results").classList.remove("stale");
    curvePlot([curve.value.points.map((p) => p.velocity), curve.value.points.map((p) => p.cor)]);
    state.timings.curve_ms = performance.now() - start;
    historyPlot(history.value.trajectory);
    showSummary(collision.value, curve.value);
    showBudget(collision.value.energy);
    $("timing").textContent = `${curve.value.points.length}-velocity curve: ${state.timings.curve_ms.toFixed(0)} ms`;
  }

  function schedule() {
    if (state.pending) return;
    state.pending = true;
    requestAnimationFrame(update);
  }

  // A log slider beside each number field: moving it writes the field, typing moves it.
  function linkSlider(name) {
    const field = $(name), slider = $(`${name}-slider`);
    const sync = () => {
      const x = Number(field.value);
      if (x > 0 && Number.isFinite(x)) slider.value = String(Math.log10(x));
    };
    sync();
    slider.addEventListener("input", () => {
      field.value = Math.pow(10, Number(slider.value)).toExponential(2);
      schedule();
    });
    field.addEventListener("change", () => {
      sync();
      schedule();
    });
  }

  function fillSelects() {
    const materials = run("materials", {}).value.map((m) => m.name);
    const option = (value, text) => Object.assign(document.createElement("option"), { value, textContent: text || value });
    $("material").replaceChildren(...materials.map((n) => option(n)), option("custom", "typed in (E, ν, ρ, γ)"));
    $("material").value = "water-ice";
    $("material2").replaceChildren(option("same", "the same as body 1"), option("wall", "a flat wall of body 1's material"),
                                   ...materials.map((n) => option(n, `${n} sphere of the same radius`)));
    // The models whose inputs the page has: the adhesive and viscoelastic ones (T_vis) and Hertz.
    for (const m of run("models", {}).value.models) {
      const names = m.parameters.map((p) => p.name);
      if (names.includes("tvis")) state.models[m.name] = true;
      else if (m.name === "hertz") state.models[m.name] = false;
    }
    $("model").replaceChildren(...Object.keys(state.models).map((n) => option(n)));
    $("model").value = "krijt";
  }

  function download(name, type, text) {
    const link = document.createElement("a");
    link.href = URL.createObjectURL(new Blob([text], { type }));
    link.download = name;
    link.click();
    setTimeout(() => URL.revokeObjectURL(link.href), 1000);
  }

  // The curve as `bounce curve --csv` lays it out (its columns, one row per velocity).
  function curveCsv() {
    const columns = ["velocity", "cor", "outcome", "contact_time", "max_overlap", "bulk_dissipated", "crack_dissipated"];
    const cell = (p, c) => {
      const v = c in p.energy ? p.energy[c] : p[c];
      return v === null || v === undefined ? "" : String(v);
    };
    return [columns.join(","), ...state.curve.points.map((p) => columns.map((c) => cell(p, c)).join(","))].join("\n") + "\n";
  }

  function wire() {
    for (const name of ["radius", "velocity", "tvis"]) linkSlider(name);
    for (const id of ["material", "material2", "model", "E", "nu", "density", "gamma", "velocities"]) $(id).addEventListener("change", schedule);
    $("material").addEventListener("change", () => { $("custom").hidden = $("material").value !== "custom"; });
    $("model").addEventListener("change", () => { $("tvis").disabled = $("tvis-slider").disabled = !state.models[$("model").value]; });
    $("download-json").addEventListener("click", () => download("collide.json", "application/json", `${state.collideText}\n`));
    $("download-trajectory").addEventListener("click", () => download("collide-trajectory.json", "application/json", `${state.historyText}\n`));
    $("download-csv").addEventListener("click", () => download("curve.csv", "text/csv", curveCsv()));
  }

  createBounce().then((module) => {
    state.timings.module_ready_ms = performance.now();
    state.call = module.cwrap("bounce_explorer_call", "number", ["string", "string"]);
    state.text = module.cwrap("bounce_explorer_text", "string", []);
    fillSelects();
    wire();
    update();
    state.timings.first_render_ms = performance.now();
    document.body.dataset.ready = "true";
  });
})();
