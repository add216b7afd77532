#!/usr/bin/env node
// The explorer in a real browser (docs/explorer.md): Debian's chromium, headless, driven by
// playwright-core, opens out/explorer/index.html from file:// (the hardest host: no server) and
//   1. sets ice/ice, 1 µm, 3 m/s, krijt, T_vis = 1e-12 s and reads ε from the page; compares it and
//      the collision JSON the page downloads with `bounce collide --json` (same inputs), and the
//      one with its trajectory with `bounce collide --trajectory --json`;
//      the same for every other model the page offers;
//   2. moves the T_vis slider with the keyboard and sees the ε(v) curve redrawn with new values;
//   3. types a negative radius and sees the field marked and the CLI's own message, no NaN;
//   4. measures the first render and a 100-velocity curve in the browser beside the native CLI
//      (printed as JSON; measured, not asserted: docs/benchmarks.md).
//
//   browser_test.js --page DIR --bounce CLI [--screenshot PNG] [--require]
// Exit 0 passed, 1 failed, 77 skipped (no chromium, or no page built: `make explorer`) unless
// --require or BOUNCE_REQUIRE_BROWSER=1 (.ci/run), where a missing browser or page fails.
"use strict";
const fs = require("fs");
const path = require("path");
const { execFileSync, spawnSync } = require("child_process");

const SKIP = 77;
// Agreement with the CLI: the browser's libm (musl) and the native one (glibc) differ in the last
// bit of pow/exp/cbrt; integrated over a collision (tolerance 1e-10, docs/adhesive.md) that stays
// well inside 1e-9 of each quantity's scale.
const TOLERANCE = 1e-9;

function options() {
  const args = process.argv.slice(2);
  const value = (name) => (args.includes(name) ? args[args.indexOf(name) + 1] : undefined);
  return { page: value("--page"), bounce: value("--bounce"), screenshot: value("--screenshot"),
           require: args.includes("--require") || process.env.BOUNCE_REQUIRE_BROWSER === "1", chromium: process.env.BOUNCE_CHROMIUM || "/usr/bin/chromium" };
}

function skipOrFail(opts, why) {
  console.log(`${opts.require ? "FAILED" : "skipped"}: ${why}`);
  process.exit(opts.require ? 1 : SKIP);
}

function check(condition, what) {
  if (!condition) throw new Error(`check failed: ${what}`);
  console.log(`ok: ${what}`);
}

// The CLI's arguments for the page's inputs (the same names, as options).
function cliArgs(command, inputs) {
  const args = [command];
  for (const [name, value] of Object.entries(inputs)) {
    args.push(`--${name.replace(/_/g, "-")}`);
    if (value !== true) args.push(value);
  }
  return args;
}

// Every number of `page` against `cli` within TOLERANCE of its scale: its own size, the largest
// of its column (a trajectory) or the initial kinetic energy (the budget); text and keys equal.
function compareJson(page, cli) {
  const problems = [];
  const scales = new Map();
  for (const row of cli.trajectory || []) {
    for (const [k, v] of Object.entries(row)) scales.set(k, Math.max(scales.get(k) || 0, Math.abs(v)));
  }
  const walk = (a, b, where, scale) => {
    if (typeof a === "number" && typeof b === "number") {
      if (Math.abs(a - b) > TOLERANCE * Math.max(Math.abs(a), Math.abs(b), scale)) problems.push(`${where}: ${a} != ${b}`);
    } else if (a && b && typeof a === "object" && typeof b === "object") {
      const ka = Object.keys(a).sort().join(","), kb = Object.keys(b).sort().join(",");
      if (ka !== kb) return problems.push(`${where}: keys ${ka} != ${kb}`);
      for (const k of Object.keys(a)) {
        const s = where.startsWith("$.trajectory") ? scales.get(k) || 0 : where === "$.energy" ? cli.energy.initial_kinetic : scale;
        walk(a[k], b[k], `${where}.${k}`, s);
      }
    } else if (a !== b) {
      problems.push(`${where}: ${JSON.stringify(a)} != ${JSON.stringify(b)}`);
    }
  };
  walk(page, cli, "$", 0);
  return problems;
}

async function setInputs(page, inputs) {
  await page.selectOption("#material", inputs.material);
  await page.selectOption("#material2", "same");
  await page.selectOption("#model", inputs.model);
  for (const name of ["radius", "velocity", "tvis"]) {
    if (!(await page.isEnabled(`#${name}`))) continue;  // T_vis with a model that takes none
    await page.fill(`#${name}`, inputs[name]);
    await page.dispatchEvent(`#${name}`, "change");
  }
  await waitForUpdate(page);
}

// Waits until the page has drawn what its inputs ask for (one animation frame after a change).
async function waitForUpdate(page) {
  await page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))));
  await page.waitForFunction(() => !window.bounceExplorer.pending);
}

async function downloadedJson(page, button) {
  const [download] = await Promise.all([page.waitForEvent("download"), page.click(button)]);
  return fs.readFileSync(await download.path(), "utf8");
}

// A download against the CLI's JSON for the same inputs.
async function checkDownload(page, opts, button, inputs) {
  const cli = JSON.parse(execFileSync(opts.bounce, cliArgs("collide", { ...inputs, json: true })).toString());
  const problems = compareJson(JSON.parse(await downloadedJson(page, button)), cli);
  const flags = inputs.trajectory ? " --trajectory" : "";
  check(problems.length === 0, `${button}: bounce collide${flags} --json's keys and values (${problems.slice(0, 3).join("; ")})`);
}

async function checkEpsilon(page, opts, inputs) {
  await setInputs(page, inputs);
  const epsPage = Number(await page.getAttribute("#cor", "data-value"));
  const cli = JSON.parse(execFileSync(opts.bounce, cliArgs("collide", { ...inputs, json: true })).toString());
  const relative = Math.abs(epsPage - cli.cor) / Math.abs(cli.cor);
  console.log(`epsilon: page ${epsPage}, bounce collide ${cli.cor}, relative difference ${relative.toExponential(2)}`);
  check(cli.outcome === "bounce" && relative <= TOLERANCE, "ε on the page equals bounce collide's to 1e-9 (ice/ice, 1 µm, 3 m/s)");
  await checkDownload(page, opts, "#download-json", inputs);
  await checkDownload(page, opts, "#download-trajectory", { ...inputs, trajectory: true });
  return { eps_page: epsPage, eps_cli: cli.cor, eps_relative_difference: relative };
}

// Every model the page offers, at the same inputs: ε as bounce collide gives it.
async function checkModels(page, opts, inputs) {
  const models = await page.$$eval("#model option", (options) => options.map((o) => o.value));
  for (const model of models) {
    const takesTvis = await page.evaluate((m) => window.bounceExplorer.models[m], model);
    await setInputs(page, { ...inputs, model });
    const epsPage = Number(await page.getAttribute("#cor", "data-value"));
    const given = takesTvis ? { ...inputs, model } : { material: inputs.material, radius: inputs.radius, velocity: inputs.velocity, model };
    const cli = JSON.parse(execFileSync(opts.bounce, cliArgs("collide", { ...given, json: true })).toString());
    const relative = Math.abs(epsPage - cli.cor) / Math.max(Math.abs(cli.cor), 1e-300);
    check(epsPage === cli.cor || relative <= TOLERANCE, `${model}: ε on the page ${epsPage}, bounce collide ${cli.cor}`);
  }
  await setInputs(page, inputs);
}

async function checkSlider(page) {
  const before = await page.evaluate(() => ({ draws: window.bounceExplorer.draws, cor: window.bounceExplorer.curve.points.map((p) => p.cor) }));
  const tvisBefore = await page.inputValue("#tvis");
  await page.focus("#tvis-slider");
  for (let i = 0; i < 10; ++i) await page.keyboard.press("ArrowRight");
  await waitForUpdate(page);
  const after = await page.evaluate(() => ({ draws: window.bounceExplorer.draws, cor: window.bounceExplorer.curve.points.map((p) => p.cor) }));
  const tvisAfter = await page.inputValue("#tvis");
  check(tvisAfter !== tvisBefore, `the T_vis slider moved the field (${tvisBefore} -> ${tvisAfter})`);
  check(after.draws > before.draws && after.cor.some((c, i) => c !== before.cor[i]), "the ε(v) curve was redrawn with new values");
}

async function checkBadRadius(page, opts, inputs) {
  await page.fill("#radius", "-1e-6");
  await page.dispatchEvent("#radius", "change");
  await waitForUpdate(page);
  const cli = spawnSync(opts.bounce, cliArgs("collide", { ...inputs, radius: "-1e-6", json: true }));
  const expected = cli.stderr.toString().trim().replace(/^bounce: error: /, "");
  const shown = (await page.textContent("#message")).trim();
  console.log(`message: ${shown}`);
  check(cli.status === 2 && shown === expected, "a negative radius shows the CLI's message");
  check((await page.getAttribute("#radius", "aria-invalid")) === "true", "the radius field is marked");
  check(!/NaN/.test(await page.textContent("body")), "no NaN on the page");
}

// Median wall time of `run` over `n` runs, in ms.
async function median(n, run) {
  const times = [];
  for (let i = 0; i < n; ++i) times.push(await run());
  return times.sort((a, b) => a - b)[Math.floor(n / 2)];
}

async function measure(page, opts, inputs) {
  const curve = { ...inputs, velocities: "0.1:30:100", log: true };
  delete curve.velocity;
  const browser = await median(5, () => page.evaluate((c) => {
    const start = performance.now();
    window.bounceExplorer.call("curve", JSON.stringify(c));
    return performance.now() - start;
  }, curve));
  const wall = (args) => median(5, async () => {
    const start = process.hrtime.bigint();
    execFileSync(opts.bounce, args);
    return Number(process.hrtime.bigint() - start) / 1e6;
  });
  // The CLI's time includes its start-up: one collision's process shows how much.
  return { curve_100_ms_browser: browser, curve_100_ms_native_cli: await wall(cliArgs("curve", { ...curve, json: true })),
           collide_1_ms_native_cli: await wall(cliArgs("collide", { ...inputs, json: true })) };
}

async function main() {
  const opts = options();
  if (!fs.existsSync(opts.chromium)) skipOrFail(opts, `no chromium at ${opts.chromium} (apt-get install chromium; .ci/run installs it)`);
  const index = path.resolve(opts.page || "", "index.html");
  if (!fs.existsSync(index) || !fs.existsSync(path.resolve(opts.page, "bounce.js"))) skipOrFail(opts, `no explorer page at ${index} (make explorer)`);
  const { chromium } = require(path.join(__dirname, "..", "..", "explorer", "node_modules", "playwright-core"));
  const browser = await chromium.launch({ executablePath: opts.chromium, args: ["--no-sandbox"] });
  try {
    const page = await browser.newPage({ viewport: { width: 1280, height: 900 } });
    const errors = [];
    page.on("pageerror", (e) => errors.push(String(e)));
    await page.goto(`file://${index}`);
    await page.waitForSelector("body[data-ready=true]");
    const { first_render_ms: firstRender, module_ready_ms: moduleReady } = await page.evaluate(() => window.bounceExplorer.timings);
    const inputs = { material: "water-ice", radius: "1e-6", velocity: "3", model: "krijt", tvis: "1e-12" };
    const eps = await checkEpsilon(page, opts, inputs);
    if (opts.screenshot) await page.screenshot({ path: opts.screenshot, fullPage: true });
    const timings = await measure(page, opts, inputs);
    await checkModels(page, opts, inputs);
    await checkSlider(page);
    await checkBadRadius(page, opts, inputs);
    check(errors.length === 0, `no script error on the page (${errors.join("; ")})`);
    console.log(JSON.stringify({ first_render_ms: firstRender, wasm_ready_ms: moduleReady, ...timings, ...eps }));
  } finally {
    await browser.close();
  }
}

main().catch((e) => {
  console.error(e.stack || String(e));
  process.exit(1);
});
