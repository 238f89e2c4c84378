// acanthus preview in a real browser (headless Chromium driven by puppeteer-core): the page
// loads the render, follows edits of the rule file on disk, shows a diagnostic at its line and
// keeps the last good picture, re-renders when a slider moves, and draws a flow stroke with the
// growth library. ACANTHUS_PREVIEW_SCREENSHOTS=DIR saves the pictures docs/preview.md shows.
// Usage: node browser.test.js ACANTHUS CHROMIUM
"use strict";
const { spawn } = require("child_process");
const fs = require("fs");
const os = require("os");
const path = require("path");
const puppeteer = require("puppeteer-core");

const [acanthus, chromium] = process.argv.slice(2).map((p, i) => (i === 0 ? path.resolve(p) : p));
const here = __dirname;
const root = path.resolve(here, "../..");
const shots = process.env.ACANTHUS_PREVIEW_SCREENSHOTS;
let failures = 0;
const servers = [];

function check(ok, what) {
  console.log((ok ? "ok: " : "FAIL: ") + what);
  if (!ok) failures += 1;
}

function startServer(ruleFile, args, cwd) {
  return new Promise((resolve, reject) => {
    const child = spawn(acanthus, ["preview", ruleFile, "--port", "0", ...args],
                        { cwd, stdio: ["ignore", "pipe", "inherit"], detached: true });
    servers.push(child);
    let out = "";
    const timer = setTimeout(() => reject(new Error("the server did not start")), 20000);
    child.stdout.on("data", (d) => {
      out += d;
      const m = out.match(/http:\/\/[^ \n]+/);
      if (m) { clearTimeout(timer); resolve({ child, url: m[0] }); }
    });
    child.on("exit", (code) => reject(new Error("the server exited with " + code)));
  });
}

// A scratch folder for one test, removed when the tests end.
const workDirs = [];
function workDir() {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), "acanthus-browser-test."));
  workDirs.push(dir);
  return dir;
}
// After the servers are gone, so that none writes into a folder being removed.
async function removeWorkDirs() {
  const running = servers.filter((c) => c.exitCode === null && c.signalCode === null);
  await Promise.all(running.map((c) => new Promise((done) => {
    c.once("exit", done);
    setTimeout(done, 6000).unref();
  })));
  for (const dir of workDirs) fs.rmSync(dir, { recursive: true, force: true });
}

function stopServers() {
  for (const child of servers) {
    if (child.exitCode !== null) continue;
    try { process.kill(-child.pid, "SIGINT"); } catch (e) { /* gone */ }
    setTimeout(() => { try { process.kill(-child.pid, "SIGKILL"); } catch (e) { /* gone */ } }, 5000).unref();
  }
}

async function status(url) { return (await fetch(url + "status.json")).json(); }

// Waits until the page shows a render newer than `after` (or an error after it).
async function waitShown(page, after, state = "ok", timeout = 90000) {
  await page.waitForFunction((a, s) => {
    const b = document.body.dataset;
    if (Number(b.revision) <= a || b.state !== s) return false;
    return s !== "ok" || Number(b.shown) === Number(b.revision);
  }, { timeout, polling: 100 }, after, state);
  return Number(await page.evaluate(() => document.body.dataset.revision));
}

function save(file, text) { fs.writeFileSync(file + ".tmp", text); fs.renameSync(file + ".tmp", file); }

async function shot(page, name) {
  if (!shots) return;
  fs.mkdirSync(shots, { recursive: true });
  await page.screenshot({ path: path.join(shots, name) });
  console.log("saved " + path.join(shots, name));
}

// The page works under its own Content-Security-Policy: nothing it does is refused.
async function watchPolicy(page) {
  await page.evaluateOnNewDocument(() => {
    window.refused = [];
    document.addEventListener("securitypolicyviolation", (e) => window.refused.push(e.violatedDirective + " " + e.blockedURI));
  });
}
async function checkPolicy(page, what) {
  const refused = await page.evaluate(() => window.refused);
  check(refused.length === 0, what + ": nothing refused by the page's Content-Security-Policy " + JSON.stringify(refused));
}

async function rulesAndSliders(browser) {
  const work = workDir();
  const rules = path.join(work, "bubbles.acr");
  const good = fs.readFileSync(path.join(here, "fixtures", "bubbles.acr"), "utf8");
  save(rules, good);
  // The editor: a script that writes down how it was called.
  const opened = path.join(work, "opened.txt"), recorder = path.join(work, "editor.js");
  fs.writeFileSync(recorder, `require("fs").writeFileSync(${JSON.stringify(opened)}, process.argv.slice(2).join(" "));\n`);
  const { url } = await startServer("bubbles.acr", ["--region", "rect:120,80", "--editor",
                                                    `'${process.execPath}' '${recorder}' {file} {line} {column}`], work);
  const page = await browser.newPage();
  await watchPolicy(page);
  await page.setViewport({ width: 1280, height: 760 });
  await page.goto(url);
  let rev = await waitShown(page, 0);
  check(rev >= 1, "the page shows the first render");
  // The page shows a PNG drawn at its size; the server is told that size, from the page only.
  const light = await page.evaluate(() => ({ type: page.pictureBytes.type, shown: document.body.dataset.picture }));
  check(light.type === "image/png" && light.shown === "render", "the page shows the render as PNG: " + JSON.stringify(light));
  const foreign = await fetch(url + "status.json?view=100x100", { headers: { Origin: "http://example.com" } });
  check(foreign.status === 403, "another site cannot set the view size: " + foreign.status);
  check((await fetch(url + "status.json?view=100x9")).status === 400, "a view size out of range is refused");
  const sliders = await page.$$eval("#params input[type=range]", (l) => l.map((s) => [s.name, s.min, s.max]));
  check(JSON.stringify(sliders[0]) === JSON.stringify(["max_radius", "0.5", "10"]),
        "a slider per numeric parameter, with the declared range: " + JSON.stringify(sliders));
  check(await page.$("#params input[type=checkbox]") !== null, "a checkbox for the bool parameter");
  check(await page.$eval("#fidelity", (d) => d.hidden), "no fidelity panel without the growth library");
  check(await page.$("#strokekinds button") === null && await page.$eval("#stroketools", (d) => d.hidden) &&
        await page.$eval("#brushlabel", (d) => d.hidden),
        "no stroke tools for a program that imports no library declaring them");
  const rulesShown = await page.$$eval("#rules tbody tr", (rows) => rows.map((r) => r.cells[0].textContent));
  check(rulesShown.includes("dot --> dot"), "per-rule metrics in the page");
  const firstSvg = await (await fetch(url + "render.svg")).text();
  const scaleOf = () => page.$eval("#canvas", (c) => new DOMMatrix(getComputedStyle(c).transform).a);
  const fitted = await scaleOf();
  const vb = await (await page.$("#view")).boundingBox();
  await page.mouse.move(vb.x + vb.width / 2, vb.y + vb.height / 2);
  await page.mouse.wheel({ deltaY: -400 });
  await page.waitForFunction((f) => new DOMMatrix(getComputedStyle(document.getElementById("canvas")).transform).a > f * 1.5,
                             { timeout: 5000, polling: 50 }, fitted);
  check(true, "the wheel zooms in");
  // Zoomed in past the PNG's pixels: the sharp SVG takes its place.
  await page.waitForFunction(() => document.body.dataset.picture === "svg" && page.pictureBytes.type === "image/svg+xml",
                             { timeout: 10000, polling: 50 });
  check(true, "zoomed in past the PNG, the page shows the SVG");
  await page.click("#zoomfit");
  check(Math.abs((await scaleOf()) - fitted) < 1e-6, "Fit goes back");

  // Edit on disk: the new picture appears by itself.
  save(rules, good.replace("%param double max_radius = 3.0 in [0.5, 10];",
                           "%param double max_radius = 6.0 in [0.5, 10];"));
  rev = await waitShown(page, rev);
  const editedSvg = await (await fetch(url + "render.svg")).text();
  check(editedSvg !== firstSvg, "saving the rule file shows a new picture (revision " + rev + ")");
  // The PNG of a render after the page said its size fits the page's view of the picture.
  const room = await page.$eval("#view", (v) => { const r = v.getBoundingClientRect(); return [Math.round(r.width), Math.round(r.height)]; });
  const png = (await status(url)).picture.png;
  const viewPng = await fetch(url + "view.png");
  check(png && png[0] <= room[0] && png[1] <= room[1] && (png[0] >= room[0] - 1 || png[1] >= room[1] - 1) &&
        viewPng.headers.get("content-type") === "image/png" &&
        await page.evaluate(() => document.body.dataset.picture) === "render",
        `the PNG shown fits the page's view (${png} in ${room})`);
  await shot(page, "preview-page.png");

  // Broken: the diagnostic at its line, the last good picture still there.
  save(rules, good.replace("    $$.sterile = 1;", "    $$.sterile = 1;\n    $7.radius = 2;"));
  rev = await waitShown(page, rev, "error");
  const diag = await page.$eval("#diagnostics", (d) => (d.hidden ? "" : d.textContent));
  check(/bubbles\.acr:26:5: error: '\$7' refers to static child 7/.test(diag) &&
        diag.includes("   26 |     $7.radius = 2;"), "the diagnostic at line 26, column 5, with its source line");
  const stillShown = await page.$eval("#picture", (img) => img.complete && img.naturalWidth > 0 &&
                                                           getComputedStyle(img).visibility !== "hidden");
  check(stillShown, "the last good picture stays while the file is broken");
  await shot(page, "preview-error.png");
  // The source around it, the line highlighted and its column marked; file:line opens the editor.
  const source = await page.evaluate(() => {
    const box = document.getElementById("sources");
    return { hidden: box.hidden, link: box.querySelector("a.open").textContent,
             hit: box.querySelector(".line.hit").textContent, caret: box.querySelector(".caret").textContent,
             lines: box.querySelectorAll(".line").length };
  });
  check(!source.hidden && source.link.endsWith("bubbles.acr:26:5") && source.hit === "26 |     $7.radius = 2;\n" &&
        source.caret === "   |     ^\n" && source.lines === 5,
        "the source around the error, its line highlighted and its column marked: " + JSON.stringify(source));
  await page.click("#sources a.open");
  for (let i = 0; i < 100 && !fs.existsSync(opened); i += 1) await new Promise((r) => setTimeout(r, 50));
  const openedWith = fs.existsSync(opened) ? fs.readFileSync(opened, "utf8") : "not run";
  check(openedWith === `${fs.realpathSync(rules)} 26 5`, "clicking file:line opens the editor there: " + openedWith);
  // A page opened (or reloaded) while the file is broken: the error over the last good picture.
  const late = await browser.newPage();
  await late.goto(url);
  await late.waitForFunction(() => document.body.dataset.state === "error" && document.body.dataset.shown !== undefined,
                             { timeout: 30000, polling: 50 });
  const lateShows = await late.$eval("#picture", (img) => img.complete && img.naturalWidth > 0 &&
                                                         getComputedStyle(img).visibility !== "hidden");
  const lateDiag = await late.$eval("#diagnostics", (d) => (d.hidden ? "" : d.textContent));
  check(lateShows && lateDiag.includes("bubbles.acr:26:5: error:"),
        "a page opened on the broken file shows the error and the last good picture");
  await late.close();

  // Fixed: back to a picture.
  save(rules, good);
  rev = await waitShown(page, rev);
  check(await page.$eval("#diagnostics", (d) => d.hidden) && await page.$eval("#sources", (d) => d.hidden),
        "fixing the file clears the diagnostic and its source");
  const fixedSvg = await (await fetch(url + "render.svg")).text();

  // A slider moved with the mouse: the program runs again with the new value.
  const slider = await page.$("#params input[name=max_radius]");
  const box = await slider.boundingBox();
  await page.mouse.click(box.x + box.width * 0.1, box.y + box.height / 2);
  rev = await waitShown(page, rev);
  const s = await status(url);
  const value = Number(s.settings.params.max_radius);
  check(value > 0.5 && value < 3, "the slider set max_radius to " + value);
  const sliderSvg = await (await fetch(url + "render.svg")).text();
  check(sliderSvg !== fixedSvg, "moving the slider changes the picture");
  check(s.command.includes("--param max_radius="), "the command line shows the parameter");

  // A seed placed by clicking, then the rng seed shuffled.
  await page.click("#modes button[data-mode=seed]");
  const pic = await (await page.$("#picture")).boundingBox();
  await page.mouse.click(pic.x + pic.width * 0.3, pic.y + pic.height * 0.4);
  rev = await waitShown(page, rev);
  let after = await status(url);
  const seed = (after.settings.seeds[0] || "").split(",").map(Number);
  check(after.settings.seeds.length === 1 && seed[0] > 20 && seed[0] < 50 && seed[1] > 20 && seed[1] < 45,
        "a click placed a seed at " + seed + " (region 120 x 80)");
  await page.click("#modes button[data-mode=pan]");
  await page.click("#shuffle");
  rev = await waitShown(page, rev);
  after = await status(url);
  check(after.settings.rng_seed !== "" && after.command.includes("--rng-seed " + after.settings.rng_seed),
        "shuffle set the rng seed to " + after.settings.rng_seed);

  // The panel picker, then an SVG file dropped onto the picture.
  await page.select("#panel", "heart.svg");
  rev = await waitShown(page, rev);
  after = await status(url);
  check(after.settings.panel === "heart.svg" && after.command.includes("heart.svg"), "panel chosen from the list");
  const star = fs.readFileSync(path.join(root, "examples/panels/star.svg"), "utf8");
  await page.evaluate((text) => {
    const dt = new DataTransfer();
    dt.items.add(new File([text], "star.svg", { type: "image/svg+xml" }));
    document.getElementById("view").dispatchEvent(new DragEvent("drop", { dataTransfer: dt, bubbles: true }));
  }, star);
  rev = await waitShown(page, rev);
  after = await status(url);
  check(after.settings.panel === "uploaded", "a dropped SVG becomes the panel");

  // Growth animation: frames of the growth, then a debug frame (Figure 8) stepped to.
  await page.click("#play");
  await page.waitForFunction(() => /^\d+\/\d+$/.test(document.getElementById("frameinfo").textContent),
                             { timeout: 60000, polling: 100 });
  const frames = Number(await page.$eval("#framepos", (r) => r.max));
  check(frames > 5, "growth played as " + frames + " frames");
  await page.waitForFunction(() => { const f = document.getElementById("frame"); return !f.hidden && f.complete && f.naturalWidth > 0; },
                             { timeout: 30000, polling: 100 });
  await page.$eval("#debugit", (i) => { i.value = "59"; });
  await page.click("#debugnext");
  await page.waitForFunction(() => { const f = document.getElementById("frame");
                                     return f.src.includes("iteration=60") && f.complete && f.naturalWidth > 0; },
                             { timeout: 30000, polling: 100 });
  check(true, "debug frame of iteration 60 shown");
  await shot(page, "preview-debug-frame.png");
  await page.click("#showrender");
  await checkPolicy(page, "render, sliders, seeds, panels, frames");

  // The page state is in the address: a link opens the same view, and pages follow changes.
  const linked = await browser.newPage();
  await linked.goto(url + "?rng=7&panel=heart.svg&seed=30,30&p.max_radius=2");
  await linked.waitForFunction(() => document.body.dataset.state === "ok" &&
                                     /rng=7/.test(location.search) && /p.max_radius=2/.test(location.search),
                               { timeout: 90000, polling: 100 });
  const linkedStatus = await status(url);
  check(linkedStatus.settings.rng_seed === "7" && linkedStatus.settings.panel === "heart.svg" &&
        JSON.stringify(linkedStatus.settings.seeds) === JSON.stringify(["30,30"]) &&
        linkedStatus.settings.params.max_radius === "2",
        "a link with the page state sets it: " + JSON.stringify(linkedStatus.settings));
  await page.waitForFunction(() => /rng=7/.test(location.search) && /panel=heart.svg/.test(location.search) &&
                                   /seed=30%2C30/.test(location.search),
                             { timeout: 30000, polling: 100 });
  check(true, "the other page's address follows: " + await page.evaluate(() => location.search));
  await linked.close();
  await page.close();
}

async function growthTools(browser) {
  const work = workDir();
  const rules = path.join(work, "arrangement.acr");
  fs.copyFileSync(path.join(root, "rules", "arrangement.acr"), rules);
  const { url } = await startServer(rules, ["--region", path.join(root, "examples/panels/rectangle.svg")], root);
  const page = await browser.newPage();
  await watchPolicy(page);
  await page.setViewport({ width: 1280, height: 760 });
  await page.goto(url);
  let rev = await waitShown(page, 0);
  const before = await (await fetch(url + "render.svg")).text();
  check(JSON.stringify(await page.$$eval("#strokekinds button", (l) => l.map((b) => b.dataset.mode))) ===
        JSON.stringify(["flow", "boundary", "spray"]) && !(await page.$eval("#stroketools", (d) => d.hidden)),
        "the growth library's stroke tools, as its registration declares them, for a growth rule file");
  // The growth library's fidelity report, from --metrics, in a panel of its own.
  const g = (await status(url)).metrics.growth;
  const fidelity = await page.evaluate(() => ({
    hidden: document.getElementById("fidelity").hidden,
    rows: Object.fromEntries([...document.querySelectorAll("#fidelitytable tbody tr")]
      .map((r) => [r.dataset.key, [...r.cells].slice(1).map((c) => c.textContent)])),
    bars: document.querySelectorAll("#nnhistogram rect").length,
  }));
  check(g && !fidelity.hidden && fidelity.rows.motifs[0] === String(g.motifs) &&
        fidelity.rows["NN median"][0] === g.nn_median.toFixed(3) &&
        fidelity.rows["NN median inner"][0] === g.nn_median_inner.toFixed(3) &&
        fidelity.rows["NN median inner"][1] === g.nn_median_reference_inner.toFixed(3) &&
        Object.keys(g.symbols).every((k) => fidelity.rows[k][1] === (100 * g.symbols[k].reference).toFixed(1) + "%") &&
        fidelity.rows["largest hole"][0] === g.largest_hole.toFixed(2) &&
        fidelity.bars === g.nn_histogram.result.length + g.nn_histogram.reference.length,
        "the fidelity panel shows the growth report: " + JSON.stringify(fidelity));
  const region = (await status(url)).metrics.region;
  check(region && region.bounds.length === 4 && region.bounds[2] > region.bounds[0] && region.area > 0,
        "--metrics carries the region's bounds: " + JSON.stringify(region));
  await page.click("#modes button[data-mode=flow]");
  const view = await (await page.$("#picture")).boundingBox();
  const y = view.y + view.height * 0.5;
  await page.mouse.move(view.x + view.width * 0.15, y + view.height * 0.2);
  await page.mouse.down();
  for (let i = 1; i <= 20; i += 1) {
    const t = i / 20;
    await page.mouse.move(view.x + view.width * (0.15 + 0.7 * t), y + view.height * 0.2 * Math.cos(Math.PI * t));
  }
  await page.mouse.up();
  rev = await waitShown(page, rev, "ok", 120000);
  const s = await status(url);
  check(s.settings.params.growth_mode === "flow" && s.settings.params.growth_guides,
        "a flow stroke sets growth_mode=flow and growth_guides");
  const guides = await (await fetch(url + "guides.svg")).text();
  check(/<polyline class="flow"/.test(guides), "the stroke is saved as a guides SVG with class flow");
  const beside = path.join(work, "arrangement.guides.svg");
  check(s.settings.params.growth_guides === beside && fs.readFileSync(beside, "utf8") === guides,
        "the guides are saved beside the rule file, where the command shown finds them");
  check((await (await fetch(url + "render.svg")).text()) !== before, "the flow stroke changes the picture");
  check(s.command.includes("--param growth_guides=") && s.command.includes("--param growth_mode=flow"),
        "the page shows the command that makes it again: " + s.command);
  await shot(page, "preview-growth.png");

  // Spray and boundary strokes join the same guides file.
  for (const [tool, dy] of [["spray", -0.25], ["boundary", 0.3]]) {
    await page.click(`#modes button[data-mode=${tool}]`);
    await page.mouse.move(view.x + view.width * 0.2, y + view.height * dy);
    await page.mouse.down();
    for (let i = 1; i <= 10; i += 1) await page.mouse.move(view.x + view.width * (0.2 + 0.06 * i), y + view.height * dy);
    await page.mouse.up();
    rev = await waitShown(page, rev, "ok", 120000);
  }
  const all = await (await fetch(url + "guides.svg")).text();
  check(/class="flow"/.test(all) && /class="spray"[^>]*stroke-width="(?!1")[0-9.]+"/.test(all) && /class="boundary"/.test(all),
        "flow, spray (with its brush width) and boundary strokes in the guides");
  // Clear strokes: back to the rule file's own growth, a valid render, no guides or mode set.
  await page.click("#clearstrokes");
  await page.waitForFunction((a) => Number(document.body.dataset.revision) > a && document.body.dataset.state !== "running",
                             { timeout: 120000, polling: 100 }, rev);
  const cleared = await status(url);
  check(cleared.state === "ok" && cleared.settings.params.growth_guides === undefined &&
        cleared.settings.params.growth_mode === undefined,
        "Clear strokes after a flow stroke renders again without guides: " + cleared.state + " " +
        JSON.stringify(cleared.settings.params) + " " + cleared.output);
  await checkPolicy(page, "growth tools");
  await page.close();
}

// A colour parameter (a string whose default is #rrggbb) gets a colour picker beside its text.
async function colourPickers(browser) {
  const work = workDir();
  const rules = path.join(work, "flowers.acr");
  fs.copyFileSync(path.join(root, "rules", "flowers.acr"), rules);
  const { url } = await startServer(rules, ["--region", "rect:120,80"], root);
  const page = await browser.newPage();
  await watchPolicy(page);
  await page.setViewport({ width: 1280, height: 760 });
  await page.goto(url);
  let rev = await waitShown(page, 0);
  const pickers = await page.$$eval("#params .row", (rows) => rows.filter((r) => r.querySelector("input[type=color]"))
    .map((r) => [r.dataset.param, r.querySelector("input[type=color]").value]));
  check(JSON.stringify(pickers) === JSON.stringify([["petal_color", "#d8434e"], ["heart_color", "#f2c14e"], ["green", "#3f7d3a"]]),
        "colour pickers for the colour parameters, at their defaults: " + JSON.stringify(pickers));
  const before = await (await fetch(url + "render.svg")).text();
  await page.$eval("#params .row[data-param=petal_color] input[type=color]", (p) => {
    p.value = "#22aa44"; p.dispatchEvent(new Event("input", { bubbles: true }));
  });
  rev = await waitShown(page, rev);
  const s = await status(url);
  const text = await page.$eval("#params .row[data-param=petal_color] input[type=text]", (t) => t.value);
  const after = await (await fetch(url + "render.svg")).text();
  check(s.settings.params.petal_color === "#22aa44" && text === "#22aa44" && after !== before &&
        /#22aa44/i.test(after) && !/#d8434e/i.test(after),
        "picking a colour sets the parameter, its text field and the picture's petals");
  // The copy button puts the command shown on the clipboard.
  // (Headless Chromium has no system clipboard to read back: the page's call is recorded.)
  await page.evaluate(() => { navigator.clipboard.writeText = async (t) => { window.copiedText = t; }; });
  await page.click("#copycommand");
  await page.waitForFunction(() => document.getElementById("copied").textContent === "copied", { timeout: 5000, polling: 50 });
  const copied = await page.evaluate(() => window.copiedText);
  check(copied === s.command && copied.includes("petal_color") && copied.includes("#22aa44"),
        "Copy puts the command on the clipboard: " + copied);
  await checkPolicy(page, "colour pickers");
  await page.close();
}

// Earlier revisions beside the current picture; the variations sheet: the render with nine
// other rng seeds, one click takes a seed.
async function revisionsAndVariations(browser) {
  const work = workDir();
  const rules = path.join(work, "bubbles.acr");
  // Dots of random sizes: each rng seed grows its own picture.
  const good = fs.readFileSync(path.join(here, "fixtures", "bubbles.acr"), "utf8")
    .split("min( max_radius, $goal.radius )").join("min( max_radius * rng.uniform( 0.4, 1.0 ), $goal.radius )");
  check(good.includes("rng.uniform"), "the random fixture is made");
  save(rules, good);
  const { url } = await startServer("bubbles.acr", ["--region", "rect:120,80"], work);
  const page = await browser.newPage();
  await watchPolicy(page);
  await page.setViewport({ width: 1280, height: 900 });
  await page.goto(url);
  let rev = await waitShown(page, 0);
  const firstSvg = await (await fetch(url + "render.svg")).text();
  const firstPng = Buffer.from(await (await fetch(url + "view.png")).arrayBuffer());
  check(await page.$eval("#revisions", (d) => d.hidden), "no earlier revisions at first");
  save(rules, good.replace("%param double max_radius = 3.0 in [0.5, 10];", "%param double max_radius = 6.0 in [0.5, 10];"));
  rev = await waitShown(page, rev);
  await page.waitForFunction(() => document.querySelectorAll("#revgrid figure").length === 1, { timeout: 10000, polling: 50 });
  await page.click("#revgrid figure");
  await page.waitForFunction(() => { const i = document.getElementById("besideimg"); return i.complete && i.naturalWidth > 0; },
                             { timeout: 10000, polling: 50 });
  const beside = await page.evaluate(() => ({ hidden: document.getElementById("beside").hidden,
                                              label: document.getElementById("besidelabel").textContent,
                                              n: document.getElementById("beside").dataset.revision }));
  const kept = await (await fetch(url + `revision.svg?n=${beside.n}`)).text();
  const current = await (await fetch(url + "render.svg")).text();
  check(!beside.hidden && beside.label === `revision ${beside.n}` && kept === firstSvg && current !== firstSvg,
        "an earlier revision shown beside the current picture: " + JSON.stringify(beside));
  const keptPng = Buffer.from(await (await fetch(url + `revision.png?n=${beside.n}`)).arrayBuffer());
  check(keptPng.equals(firstPng) && (await page.$eval("#besideimg", (i) => i.src)).includes("/revision.png?n="),
        "the page shows an earlier revision's PNG, the one it showed then");
  check((await fetch(url + "revision.svg?n=999")).status === 404, "a revision not kept is 404");
  await shot(page, "preview-revisions.png");

  await page.click("#varshow");
  await page.waitForFunction(() => document.querySelectorAll("#vargrid figure[data-loaded]").length === 9,
                             { timeout: 120000, polling: 100 });
  const seeds = await page.$$eval("#vargrid figure", (f) => f.map((x) => x.dataset.seed));
  check(JSON.stringify(seeds) === JSON.stringify(["2", "3", "4", "5", "6", "7", "8", "9", "10"]),
        "nine variations, the rng seeds after the current one: " + seeds.join(" "));
  const png = async (seed) => Buffer.from(await (await fetch(url + `variation.png?rng=${seed}`)).arrayBuffer());
  const [a, b, a2] = [await png(4), await png(5), await png(4)];
  check(a.subarray(0, 4).toString("latin1") === "\x89PNG" && !a.equals(b) && a.equals(a2),
        "each variation is its own seed's picture, the same again for the same seed");
  await shot(page, "preview-variations.png");
  await page.click("#vargrid figure[data-seed='4']");
  rev = await waitShown(page, rev);
  const s = await status(url);
  check(s.settings.rng_seed === "4" && (await page.$eval("#rng", (i) => i.value)) === "4",
        "clicking a variation takes its seed: " + s.settings.rng_seed);
  const cross = await fetch(url + "variation.png?rng=4", { headers: { "Sec-Fetch-Site": "cross-site" } });
  check(cross.status === 403, "a variation is refused to another site (" + cross.status + ")");
  await checkPolicy(page, "revisions and variations");
  await page.close();
}

// 20 tabs over 3 browsers (contexts) all update after a save: each browser shares one event
// stream among its tabs (a browser opens about six connections per host); when the tab that
// holds it closes, another takes it over.
async function manyTabs(browser) {
  const work = workDir();
  const rules = path.join(work, "bubbles.acr");
  const good = fs.readFileSync(path.join(here, "fixtures", "bubbles.acr"), "utf8");
  save(rules, good);
  const { url } = await startServer("bubbles.acr", ["--region", "rect:60,40"], work);
  const contexts = [];
  for (let i = 0; i < 3; i += 1) contexts.push(await browser.createIncognitoBrowserContext());
  const pages = [];
  for (let i = 0; i < 20; i += 1) {
    const page = await contexts[i % 3].newPage();
    await page.setViewport({ width: 800, height: 600 });
    await page.goto(url);
    pages.push(page);
  }
  const shownAll = async (rev, list, what) => {
    const results = await Promise.allSettled(list.map((p) => waitShown(p, rev - 1, "ok", 60000)));
    const missing = results.map((r, i) => (r.status === "fulfilled" ? -1 : i)).filter((i) => i >= 0);
    check(missing.length === 0, `${what}: all ${list.length} tabs show revision ${rev}` +
          (missing.length ? ` (not tabs ${missing.join(", ")})` : ""));
  };
  await shownAll(1, pages, "opened");
  let s = await status(url);
  check(s.event_streams <= 3, `one event stream per browser: ${s.event_streams} open for 20 tabs in 3 browsers`);
  save(rules, good.replace("%param double max_radius = 3.0 in [0.5, 10];", "%param double max_radius = 5.0 in [0.5, 10];"));
  await shownAll(2, pages, "after a save");
  // The tab holding a browser's stream closes: another of that browser takes it over.
  const leaders = [];
  for (const p of pages) if (await p.evaluate(() => document.body.dataset.leader === "1")) leaders.push(p);
  check(leaders.length === 3, `one tab per browser holds the stream (${leaders.length})`);
  await leaders[0].close();
  const rest = pages.filter((p) => p !== leaders[0]);
  save(rules, good.replace("%param double max_radius = 3.0 in [0.5, 10];", "%param double max_radius = 4.0 in [0.5, 10];"));
  await shownAll(3, rest, "after the stream's tab closed and a save");
  // The closed tab's stream ends when the server next fails to write to it (a load of 13 once
  // had it open still when the other tabs had the new revision).
  s = await status(url);
  for (let i = 0; i < 200 && s.event_streams > 3; i += 1) {  // (a status every 15 s at least)
    await new Promise((r) => setTimeout(r, 100));
    s = await status(url);
  }
  check(s.event_streams <= 3, `still one stream per browser: ${s.event_streams}`);
  for (const c of contexts) await c.close();
}

// While it grows, the page shows the growth so far (/partial.png, about every 0.1 s), each
// picture with more of it; a render that fails after some growth goes back to the last good one.
async function partialPictures(browser) {
  const work = workDir();
  const rules = path.join(work, "bubbles.acr");
  // Each new dot waits 2 ms: a growth of a second or two, whatever the machine.
  // (split and join: String.replace would read the rule file's `$$` as a pattern.)
  const swap = (text, from, to) => text.split(from).join(to);
  const slow = swap(swap(fs.readFileSync(path.join(here, "fixtures", "bubbles.acr"), "utf8"),
                         "%source\n", "%source\n#include <thread>\n"),
                    "    $$0.order = dot_count++;\n    return SUCCESS;\n}\n%endrule\n\n%draw",
                    "    $$0.order = dot_count++;\n    std::this_thread::sleep_for( std::chrono::milliseconds( 2 ) );\n" +
                    "    return SUCCESS;\n}\n%endrule\n\n%draw");
  check(slow.includes("sleep_for"), "the slow fixture is made");
  save(rules, slow);
  const { url } = await startServer("bubbles.acr", ["--region", "rect:160,120"], work);
  const page = await browser.newPage();
  await watchPolicy(page);
  await page.setViewport({ width: 1280, height: 760 });
  // Every partial picture the page shows (its number), and its ink (pixels drawn: the dots
  // and the panel's outline), read from the PNG the page shows (it hands the fetched body on as
  // a Blob, which puppeteer's response events then cannot read; and its policy refuses a fetch
  // of the image's blob: address).
  await page.evaluateOnNewDocument(() => {
    window.partials = [];
    window.partialDots = {};
    window.ink = async (blob) => {
      const image = await createImageBitmap(blob);
      const canvas = new OffscreenCanvas(image.width, image.height), g = canvas.getContext("2d");
      g.drawImage(image, 0, 0);
      const data = g.getImageData(0, 0, image.width, image.height).data;
      let n = 0;
      for (let i = 3; i < data.length; i += 4) if (data[i] > 127) n += 1;
      return n;
    };
    new MutationObserver(() => {
      const shown = document.body.dataset.picture;
      // (`page` is the page script's own state)
      if (shown === "render") window.renderInk = window.ink(page.pictureBytes);
      if (shown !== "partial") return;
      const n = Number(document.body.dataset.partial);
      window.partials.push(n);
      window.partialDots[n] = window.ink(page.pictureBytes);
    }).observe(document, { attributes: true, subtree: true, attributeFilter: ["data-partial", "data-picture"] });
  });
  await page.goto(url);
  let rev = await waitShown(page, 0);
  const shownDots = (from) => page.evaluate((f) => Promise.all(window.partials.slice(f).map((n) => window.partialDots[n])), from);
  const first = await shownDots(0);
  const finalDots = await page.evaluate(() => window.renderInk);
  const s = await status(url);
  check(first.length >= 2, `the page showed the growth so far while it grew (${first.length} pictures in ` +
        `${s.timings.grow.toFixed(2)} s of growth)`);
  check(first.length > 0 && first.every((d, i) => d > 0 && (i === 0 || d >= first[i - 1])) &&
        first[first.length - 1] < finalDots,
        "each partial picture has more of the growth, all less ink than the finished one: " +
        JSON.stringify(first) + " then " + finalDots);
  check(await page.evaluate(() => document.body.dataset.picture) === "render", "the finished picture replaces the last partial one");
  await checkPolicy(page, "partial pictures");

  // A body that fails after a while: partial pictures, then the error over the last good picture.
  const seen = await page.evaluate(() => window.partials.length);
  save(rules, swap(slow, "    $$0.order = dot_count++;\n    std::this_thread",
                   "    if ( dot_count > 300 ) throw std::runtime_error( \"late\" );\n" +
                   "    $$0.order = dot_count++;\n    std::this_thread"));
  rev = await waitShown(page, rev, "error");
  await page.waitForFunction(() => document.body.dataset.picture === "render", { timeout: 10000, polling: 50 });
  const late = await shownDots(seen);
  const back = await page.evaluate(() => document.body.dataset.picture);
  check(late.length >= 1 && late.every((d) => d > 0) && back === "render",
        `a render that fails after ${late.length} partial picture(s) (${JSON.stringify(late)} pixels of ink) goes back to the last good picture`);
  await page.close();
}

// The finished picture is shown as soon as the program has drawn it, before the run ends (the
// SVG drawn by a copy of the program, here held up 1.5 s): the page shows it while the status
// is still running, and the render's status then names it, so the page does not fetch it again.
// A run that fails after it (the SVG's drawing crashing) goes back to the last good picture.
async function finishedPictureEarly(browser) {
  const work = workDir();
  const rules = path.join(work, "bubbles.acr");
  const swap = (text, from, to) => text.split(from).join(to);
  const fixture = fs.readFileSync(path.join(here, "fixtures", "bubbles.acr"), "utf8");
  const withDraw = (helper, call) => swap(swap(fixture, "int dot_count = 0;\n",
                                               "int dot_count = 0;\n#include <unistd.h>\n#include <chrono>\n#include <stdexcept>\n" +
                                               "#include <thread>\nstatic const pid_t main_process = getpid();\n" + helper),
                                          "%draw dot\n", `%draw dot\n${call};\n`);
  // In a copy of the program (the SVG's, the partial pictures'), the first dot waits 1.5 s.
  const slow = withDraw("static bool slept = false;\nstatic void slow_in_copies() {\n" +
                        "    if ( slept || getpid() == main_process ) return;\n    slept = true;\n" +
                        "    std::this_thread::sleep_for( std::chrono::milliseconds( 1500 ) );\n}\n", "slow_in_copies()");
  check(slow.includes("slow_in_copies();"), "the slow-copy fixture is made");
  save(rules, slow);
  const { url } = await startServer("bubbles.acr", ["--region", "rect:120,80"], work);
  const page = await browser.newPage();
  await watchPolicy(page);
  await page.setViewport({ width: 1280, height: 760 });
  await page.evaluateOnNewDocument(() => {
    window.pictures = [];  // [data-picture, data-state] each time the picture changed
    new MutationObserver(() => {
      const b = document.body.dataset;
      window.pictures.push([b.picture, b.state, b.final || "", b.shown || ""]);
    }).observe(document, { attributes: true, subtree: true, attributeFilter: ["data-picture", "data-final", "data-shown"] });
  });
  await page.goto(url);
  const rev = await waitShown(page, 0);
  const early = await page.evaluate(() => window.pictures);
  check(early.some(([picture, state]) => picture === "final" && state === "running"),
        "the finished picture is shown while the run still goes on: " + JSON.stringify(early));
  const s = await status(url);
  check(s.final > 0 && early.some(([picture, , n]) => picture === "final" && Number(n) === s.final),
        `the render's status names the picture shown early as its own (final ${s.final})`);
  const fetched = await page.evaluate((r) => performance.getEntriesByType("resource")
    .filter((e) => e.name.includes(`/view.png?revision=${r}`)).length, rev);
  check(fetched === 0, `the page did not fetch the render's picture again (${fetched} fetches of /view.png)`);
  const shown = Buffer.from(await page.evaluate(async () => Array.from(new Uint8Array(await page.pictureBytes.arrayBuffer()))));
  const view = Buffer.from(await (await fetch(url + "view.png")).arrayBuffer());
  check(shown.equals(view) && await page.evaluate(() => document.body.dataset.picture) === "render",
        `the picture shown is the render's, byte for byte (${shown.length} and ${view.length} bytes)`);

  // The SVG's drawing fails (in the copy, then 1.5 s into the program's own try) after the view
  // was drawn: an error, and the last good picture.
  const before = await page.evaluate(() => window.pictures.length);
  save(rules, withDraw("static int draws_here = 0;\nstatic void fail_after_first_picture() {\n" +
                       "    if ( getpid() != main_process ) std::abort();\n" +
                       "    if ( ++draws_here <= dot_count ) return;\n" +
                       "    std::this_thread::sleep_for( std::chrono::milliseconds( 1500 ) );\n" +
                       "    throw std::runtime_error( \"second picture refused\" );\n}\n",
                       "fail_after_first_picture()"));
  const failed = await waitShown(page, rev, "error");
  await page.waitForFunction(() => document.body.dataset.picture === "render", { timeout: 10000, polling: 50 }).catch(() => {});
  const after = (await page.evaluate(() => window.pictures)).slice(before);
  const end = await page.evaluate(() => [document.body.dataset.picture, document.getElementById("diagnostics").textContent]);
  const back = Buffer.from(await page.evaluate(async () => Array.from(new Uint8Array(await page.pictureBytes.arrayBuffer()))));
  check(after.some(([picture]) => picture === "final"), "the failing run's finished picture was shown: " + JSON.stringify(after));
  check(end[0] === "render" && back.equals(view) && end[1].includes("second picture refused"),
        `a run that fails after its finished picture is an error (revision ${failed}) over the last good picture: ` +
        JSON.stringify(end));
  await checkPolicy(page, "the finished picture early");
  await page.close();
}

(async () => {
  let browser;
  const watchdog = setTimeout(() => { console.log("FAIL: the browser tests took over 8 minutes"); stopServers(); process.exit(1); }, 480000);
  try {
    browser = await puppeteer.launch({ executablePath: chromium, headless: "new",
                                       args: ["--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage"] });
    // ACANTHUS_BROWSER_TESTS=name,name runs only those.
    const only = (process.env.ACANTHUS_BROWSER_TESTS || "").split(",").filter(Boolean);
    for (const test of [rulesAndSliders, growthTools, colourPickers, partialPictures, finishedPictureEarly,
                        revisionsAndVariations, manyTabs])
      if (!only.length || only.includes(test.name)) await test(browser);
  } catch (e) {
    console.log("FAIL: " + (e && e.stack ? e.stack : e));
    failures += 1;
  } finally {
    if (browser) await browser.close();
    stopServers();
    clearTimeout(watchdog);
    await removeWorkDirs();
  }
  if (failures) console.log(failures + " check(s) failed");
  process.exitCode = failures ? 1 : 0;
})();
