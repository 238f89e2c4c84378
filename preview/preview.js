// acanthus preview: the page. Plain JavaScript, no build step, nothing from the network but
// this server. State arrives as server-sent events (/events); controls POST to /settings.
"use strict";

const $ = (id) => document.getElementById(id);
const SVGNS = "http://www.w3.org/2000/svg";

const page = {
  status: null,
  revision: -1,
  paramSignature: "",
  size: { width: 800, height: 600 },  // the render's page units (its viewBox)
  view: { x: 0, y: 0, scale: 1 },
  mode: "pan",
  seeds: [],                           // region coordinates
  strokes: [],                         // {kind, width, points: [[x, y]...]} in region coordinates
  strokeTool: null,                    // the stroke tools of a library the program imports
  strokeToolKey: "",
  frames: 0,
  pictureUrl: null,
  pictureBytes: null,                  // the picture shown, as fetched (the browser test reads it)
  askedForLastGood: false,             // opened on a broken file: the last good picture asked for
  lastElements: 0,
  pictureTicket: 0,                    // the latest render asked for (see loadPicture)
  showingPartial: false,               // the picture is the growth so far, not a finished render
  finalShown: 0,                       // the partial picture shown is the finished one (its number)
  finalLoaded: false, finalAdopted: null,  // ... its <img> loaded; the render it became before that
  partialAsked: 0, partialWanted: 0, partialBusy: false,
};

// --- where the region lands on the page (runtime/src/output/page_layout.cpp) ---------------
function layout() {
  const b = page.status && page.status.metrics && page.status.metrics.region &&
            page.status.metrics.region.bounds;
  if (!b) return null;
  const bw = b[2] - b[0] > 0 ? b[2] - b[0] : 1, bh = b[3] - b[1] > 0 ? b[3] - b[1] : 1;
  const margin = 0.02 * Math.max(bw, bh);
  const sx = bw + 2 * margin, sy = bh + 2 * margin;
  const width = page.size.width, height = Math.max(1, Math.round(width * sy / sx));
  const scale = Math.min(width / sx, height / sy);
  const cx = (b[0] + b[2]) / 2, cy = (b[1] + b[3]) / 2;
  return { scale, ox: width / 2 - cx * scale, oy: height / 2 - cy * scale };
}
function toPage(p) { const l = layout(); return l ? [l.ox + p[0] * l.scale, l.oy + p[1] * l.scale] : p; }
function toRegion(p) { const l = layout(); return l ? [(p[0] - l.ox) / l.scale, (p[1] - l.oy) / l.scale] : p; }

// --- talking to the server ----------------------------------------------------------------
async function post(path, body, type) {
  const r = await fetch(path, { method: "POST", body: typeof body === "string" ? body : JSON.stringify(body),
                                headers: { "Content-Type": type || "application/json" } });
  if (!r.ok) { const t = await r.text(); showNote(`${path}: ${t}`); throw new Error(t); }
  return r.json();
}
let noteTimer = null;
function showNote(text) {
  const n = $("dropnote"); n.textContent = text; n.hidden = false;
  clearTimeout(noteTimer); noteTimer = setTimeout(() => { n.hidden = true; }, 4000);
}
let settingsTimer = null, pendingSettings = {};
function sendSettings(change) {  // coalesces quick changes (a slider being dragged)
  Object.assign(pendingSettings, change);
  clearTimeout(settingsTimer);
  settingsTimer = setTimeout(() => { const s = pendingSettings; pendingSettings = {}; post("/settings", s); }, 120);
}

// --- status ---------------------------------------------------------------------------------
function update(status) {
  page.status = status;
  if (status.file && $("file").textContent !== status.file) {
    $("file").textContent = status.file;
    document.title = `${status.file.split("/").pop()} — acanthus preview`;
  }
  const state = $("state");
  state.textContent = status.state === "running" ? status.phase : status.state;
  state.className = "badge " + status.state;
  $("phase").textContent = status.state === "running" ? "" : `${status.phase}`;
  const p = status.progress || {};
  const limit = (status.settings && status.settings.time_limit) || 20;
  if (status.state === "ok") page.lastElements = status.elements;
  if (status.state === "running" && status.phase === "growing") {
    // Against the last picture's elements when there is one (the same file usually grows about
    // as far), else against the time limit.
    $("progress").value = page.lastElements ? Math.min(0.99, (p.elements || 0) / page.lastElements)
                                            : Math.min(1, (p.seconds || 0) / limit);
    $("elements").textContent = `${p.elements || 0} elements`;
    $("seconds").textContent = `${(p.seconds || 0).toFixed(1)} s`;
  } else {
    $("progress").value = status.state === "running" ? 0 : 1;
    $("elements").textContent = `${status.elements} elements`;
    $("seconds").textContent = `${status.seconds.toFixed(2)} s`;
  }
  $("revision").textContent = `revision ${status.revision}`;
  $("command").textContent = status.command || "";
  const diag = $("diagnostics");
  if (status.state === "error") { diag.textContent = status.output; diag.hidden = false; }
  else if (status.state === "ok") diag.hidden = true;
  if (status.state !== "running") fillSources(status.state === "error" ? status.diagnostics : []);
  if (status.state === "ok" && status.revision !== page.revision) {
    // The finished picture came before the run ended (status.final): it is this render's.
    if (page.showingPartial && page.finalShown && status.final === page.finalShown) adoptFinal(status);
    else loadPicture(status.revision);
  }
  // The growth so far while it grows; a render that failed goes back to the last good picture.
  if (status.state === "running" && status.partial) loadPartial(status.partial);
  if (status.state === "error" && page.showingPartial) loadPicture(status.revision);
  // Opened on a broken file: the server still has the last good picture (404 when none).
  if (status.state === "error" && page.pictureUrl === null && !page.askedForLastGood) {
    page.askedForLastGood = true;
    loadPicture(status.revision);
  }
  if (status.state !== "running") page.revision = status.revision;
  document.body.dataset.revision = String(status.revision);
  document.body.dataset.state = status.state;
  buildParams(status);
  syncSettings(status.settings || {});
  followAddress(status.settings);
  fillRules(status.metrics && status.metrics.rules);
  if (status.state === "ok") fillFidelity(status.metrics && status.metrics.growth);
  if (status.state !== "running") fillRevisions(status);
  showStrokeTools((status.stroke_tools || [])[0] || null);
}

// --- the stroke tools of a library the program imports (its guides), as it declares them ------
function showStrokeTools(tool) {
  const key = JSON.stringify(tool);
  if (key === page.strokeToolKey) return;
  page.strokeToolKey = key;
  page.strokeTool = tool;
  const kinds = $("strokekinds");
  kinds.textContent = "";
  for (const kind of tool ? tool.kinds : []) {
    const b = document.createElement("button");
    b.dataset.mode = kind;
    b.title = `Draw a ${kind} stroke (${tool.library})`;
    b.textContent = kind.charAt(0).toUpperCase() + kind.slice(1);
    kinds.append(" ", b);  // spaced like the buttons written in the page
  }
  if (!tool || !tool.kinds.includes(page.mode)) setMode("pan");
  else setMode(page.mode);
  $("brushlabel").hidden = !tool || tool.width_kinds.length === 0;
  $("stroketools").hidden = !tool;
  if (tool) {
    $("stroketitle").textContent = `${tool.library.charAt(0).toUpperCase()}${tool.library.slice(1)} strokes`;
    $("strokehint").textContent = `${tool.kinds.join(", ")} strokes are saved as the SVG --param ${tool.file_param} names`;
  }
  drawOverlay();
}

// A picture of the growth so far (/partial.png, number n): one fetch at a time, the latest wins.
function loadPartial(n) {
  if (n <= page.partialAsked) return;
  if (page.partialBusy) { page.partialWanted = n; return; }
  page.partialAsked = n;
  page.partialBusy = true;
  loadPicture(null, n).finally(() => {
    page.partialBusy = false;
    const s = page.status;
    if (page.partialWanted > page.partialAsked && s && s.state === "running") loadPartial(page.partialWanted);
  });
}

// The finished picture, shown while the run still ended (the server's partial picture marked
// final), becomes the render's: no fetch again.
function adoptFinal(status) {
  ++page.pictureTicket;  // (a picture still loading for before is stale)
  page.showingPartial = false;
  page.finalShown = 0;
  const picture = status.picture;
  if (picture && picture.width > 0 && (picture.width !== page.size.width || picture.height !== page.size.height)) {
    page.size = { width: picture.width, height: picture.height };
    sizePicture();
  }
  page.shown = { revision: status.revision, svg: false, pixels: page.shown ? page.shown.pixels : 0 };
  if (page.finalLoaded) {
    document.body.dataset.adopted = document.body.dataset.final;  // (the bench's paint timer reads it)
    document.body.dataset.picture = "render";
    document.body.dataset.shown = String(status.revision);
  } else page.finalAdopted = status.revision;  // (its <img> has not loaded yet: marked then)
  queueMicrotask(() => { drawOverlay(); loadSharp(); });  // (once page.revision is this one)
}

function sizePicture() {
  for (const el of [$("picture"), $("frame"), $("overlay")]) {
    el.style.width = page.size.width + "px"; el.style.height = page.size.height + "px";
  }
  $("overlay").setAttribute("viewBox", `0 0 ${page.size.width} ${page.size.height}`);
}

// The page shows PNGs drawn at its own size (/view.png, /partial.png): Chromium took 0.1 to
// 1.4 s to parse a render's SVG (1 to 5 MB) in the <img>. The SVG comes only when the picture
// is zoomed in past the PNG's pixels (loadSharp), and for the SVG download.
async function pngSize(bytes) {
  const head = new DataView(await bytes.slice(0, 24).arrayBuffer());
  return head.byteLength === 24 ? { width: head.getUint32(16), height: head.getUint32(20) } : null;
}
// The SVG's page size (its viewBox), from the root element's tag alone: parsing the whole
// document here cost as much again as the <img> decoding it.
async function svgSize(bytes) {
  const open = /<svg\b[^>]*>/.exec(await bytes.slice(0, 4096).text());
  const box = open && /\bviewBox\s*=\s*["']([^"']*)["']/.exec(open[0]);
  const vb = box ? box[1].trim().split(/[\s,]+/).map(Number) : [];
  return vb.length === 4 && vb[2] > 0 ? { width: vb[2], height: vb[3] } : null;
}

// The render of `revision`, or with `partial` the growth so far; `sharp`: the render's SVG. A
// render asked for later wins over one still loading; a partial picture never replaces a render
// asked for after it, and shows only while the render grows.
async function loadPicture(revision, partial, sharp) {
  const ticket = partial || sharp ? page.pictureTicket : ++page.pictureTicket;
  const stale = () => ticket !== page.pictureTicket || (partial && page.status.state !== "running");
  let svg = Boolean(sharp);
  let r = await fetch(partial ? `/partial.png?n=${partial}`
                      : svg ? `/render.svg?revision=${revision}` : `/view.png?revision=${revision}`);
  if (!r.ok && !partial && !svg) { svg = true; r = await fetch(`/render.svg?revision=${revision}`); }
  if (!r.ok || stale()) return;
  // The bytes go to the <img> as they came (decoding them to text and back cost a third of the
  // time from the fetch to the image's address).
  const bytes = await r.blob();
  const size = svg ? await svgSize(bytes) : await pngSize(bytes);
  if (stale()) return;
  page.showingPartial = Boolean(partial);
  // The finished picture, published before the run ended: shown as a partial one until the
  // render's status says it is the render's (a run may still fail after it).
  let final = Boolean(partial) && page.status.final === partial;
  page.finalShown = final ? partial : 0;
  page.finalLoaded = false;
  page.finalAdopted = null;
  const first = page.pictureUrl === null;
  // A PNG is shown at the SVG's page size (strokes and seeds are drawn in its units).
  const picture = page.status && page.status.picture;
  if (svg && size) page.size = size;
  else if (size && picture && picture.width > 0) page.size = { width: picture.width, height: picture.height };
  else if (size) page.size = { width: page.size.width, height: page.size.width * size.height / size.width };
  page.shown = { revision, svg, pixels: svg ? Infinity : (size ? size.width : 0) };
  const url = URL.createObjectURL(new Blob([bytes], { type: svg ? "image/svg+xml" : "image/png" }));
  const img = $("picture");
  img.onload = () => { if (page.pictureUrl) URL.revokeObjectURL(page.pictureUrl); page.pictureUrl = url;
                       page.pictureBytes = bytes;
                       if (final && page.finalAdopted !== null) revision = page.finalAdopted, final = false, partial = null;
                       page.finalLoaded = final;
                       delete document.body.dataset.adopted;
                       document.body.dataset.picture = final ? "final" : partial ? "partial" : svg ? "svg" : "render";
                       if (final) document.body.dataset.final = String(partial);
                       else if (partial) document.body.dataset.partial = String(partial);
                       else document.body.dataset.shown = String(revision); };
  img.src = url;
  sizePicture();
  if (first) fit();
  drawOverlay();
  loadSharp();
}

// Zoomed in past the PNG's pixels: the render's SVG takes its place (once per revision).
function loadSharp() {
  const s = page.shown;
  if (!s || s.svg || page.showingPartial || s.revision === null || s.revision !== page.revision) return;
  if (page.view.scale * page.size.width * (window.devicePixelRatio || 1) <= s.pixels * 1.05) return;
  if (page.sharpAsked === s.revision) return;
  page.sharpAsked = s.revision;
  loadPicture(s.revision, null, true);
}

// The picture's room on the page, in device pixels: the server draws the PNG to fit it.
let viewTimer = null;
function reportView(delay = 200) {
  clearTimeout(viewTimer);
  viewTimer = setTimeout(() => {
    const v = $("view").getBoundingClientRect(), d = window.devicePixelRatio || 1;
    const clamp = (x) => Math.max(16, Math.min(8192, Math.round(x * d)));
    fetch(`/status.json?view=${clamp(v.width)}x${clamp(v.height)}`).catch(() => {});
  }, delay);
}

function paramRange(q) {
  if (q.range) return q.range.map(Number);
  const d = Number(q.default);
  if (d === 0) return [0, q.type === "int" || q.type === "long" ? 10 : 1];
  return d > 0 ? [0, 2 * d] : [2 * d, 0];
}

const HEX_COLOUR = /^#[0-9a-fA-F]{6}$/;
function unquoted(v) { return v.startsWith('"') && v.endsWith('"') ? JSON.parse(v) : v; }

function buildParams(status) {
  const params = status.params || [];
  const signature = JSON.stringify(params);
  if (signature === page.paramSignature) return;
  page.paramSignature = signature;
  const box = $("params");
  box.textContent = "";
  const current = (status.settings && status.settings.params) || {};
  for (const q of params) {
    const row = document.createElement("div");
    row.className = "row";
    row.dataset.param = q.name;
    const label = document.createElement("label");
    label.textContent = q.name;
    label.title = `${q.type} ${q.name} = ${q.default}` + (q.range ? ` in [${q.range[0]}, ${q.range[1]}]` : "");
    row.append(label);
    const value = current[q.name] !== undefined ? current[q.name] : q.default;
    if (["int", "long", "float", "double"].includes(q.type)) {
      const [lo, hi] = paramRange(q);
      const integer = q.type === "int" || q.type === "long";
      const slider = document.createElement("input");
      slider.type = "range"; slider.min = lo; slider.max = hi;
      slider.step = integer ? 1 : (hi - lo) / 200;
      slider.value = value; slider.name = q.name;
      const field = document.createElement("input");
      field.type = "number"; field.step = integer ? 1 : "any"; field.value = value;
      if (q.range) { field.min = lo; field.max = hi; }
      slider.addEventListener("input", () => {
        const v = integer ? String(Math.round(slider.value)) : String(Number(slider.value));
        field.value = v; sendSettings({ params: { [q.name]: v } });
      });
      field.addEventListener("change", () => { slider.value = field.value; sendSettings({ params: { [q.name]: field.value } }); });
      row.append(slider, field);
    } else if (q.type === "bool") {
      const box2 = document.createElement("input");
      box2.type = "checkbox"; box2.checked = value === "true" || value === "1";
      box2.addEventListener("change", () => sendSettings({ params: { [q.name]: box2.checked ? "true" : "false" } }));
      row.append(box2);
    } else {
      const text = document.createElement("input");
      text.type = "text";
      text.value = value.startsWith('"') && value.endsWith('"') ? JSON.parse(value) : value;
      text.addEventListener("change", () => sendSettings({ params: { [q.name]: text.value } }));
      row.append(text);
      // A colour (a string parameter whose default is #rrggbb) gets a colour picker too.
      if (HEX_COLOUR.test(unquoted(q.default))) {
        const picker = document.createElement("input");
        picker.type = "color";
        picker.value = HEX_COLOUR.test(text.value) ? text.value.toLowerCase() : unquoted(q.default).toLowerCase();
        picker.addEventListener("input", () => { text.value = picker.value; sendSettings({ params: { [q.name]: picker.value } }); });
        row.append(picker);
      }
    }
    box.append(row);
  }
}

// Controls follow the settings (changed by another tab, a tool, the command line) unless the
// user is on them.
function syncParams(values) {
  for (const row of document.querySelectorAll("#params .row")) {
    const v = values[row.dataset.param];
    if (v === undefined) continue;
    for (const input of row.querySelectorAll("input")) {
      if (input === document.activeElement) continue;
      if (input.type === "checkbox") input.checked = v === "true" || v === "1";
      else if (input.type === "color") { if (HEX_COLOUR.test(unquoted(v))) input.value = unquoted(v).toLowerCase(); }
      else input.value = v;
    }
  }
}

function syncSettings(s) {
  syncParams(s.params || {});
  if (document.activeElement !== $("rng") && s.rng_seed !== undefined) $("rng").value = s.rng_seed || "1";
  const panel = $("panel");
  if (s.panel !== undefined && document.activeElement !== panel) {
    if (s.panel && ![...panel.options].some((o) => o.value === s.panel)) panel.add(new Option(s.panel, s.panel));
    panel.value = s.panel || "";
  }
  page.seeds = (s.seeds || []).map((t) => t.split(",").map(Number));
  $("seedcount").textContent = page.seeds.length ? `${page.seeds.length} seed(s)` : "default seed";
  drawOverlay();
}

function fillRules(rules) {
  const body = $("rules").tBodies[0];
  body.textContent = "";
  for (const r of rules || []) {
    const tr = body.insertRow();
    if (r.successes === 0) { tr.className = "never"; tr.title = "this rule never fired"; }
    tr.insertCell().textContent = r.rule;
    for (const v of [r.line, r.successes, r.failures]) { const c = tr.insertCell(); c.className = "n"; c.textContent = v; }
  }
}

// --- each error with its source around it, the line highlighted, the column marked; its
// file:line opens the editor (POST /open: --editor or $VISUAL on the server).
function fillSources(diagnostics) {
  const box = $("sources");
  const shown = (diagnostics || []).filter((d) => d.source && d.source.lines.length);
  box.textContent = "";
  box.hidden = shown.length === 0;
  for (const d of shown) {
    const item = document.createElement("div");
    item.className = "source";
    const where = document.createElement("a");
    where.href = "#"; where.className = "open"; where.title = "open in the editor";
    where.textContent = `${d.file}:${d.line}:${d.column}`;
    where.addEventListener("click", (e) => {
      e.preventDefault();
      post("/open", { file: d.file, line: d.line, column: d.column })
        .then(() => showNote(`opened ${d.file.split("/").pop()}:${d.line} in the editor`))
        .catch(() => {});
    });
    const message = document.createElement("span");
    message.textContent = " " + d.message;
    item.append(where, message);
    const pre = document.createElement("pre");
    const width = String(d.source.first + d.source.lines.length - 1).length;
    d.source.lines.forEach((text, i) => {
      const number = d.source.first + i, line = document.createElement("span");
      line.className = number === d.line ? "line hit" : "line";
      line.textContent = `${String(number).padStart(width)} | ${text}\n`;
      pre.appendChild(line);
      if (number === d.line && d.column > 0) {
        const caret = document.createElement("span");
        caret.className = "caret";
        caret.textContent = `${" ".repeat(width)} | ${" ".repeat(d.column - 1)}^\n`;
        pre.appendChild(caret);
      }
    });
    item.appendChild(pre);
    box.appendChild(item);
  }
}

// --- earlier revisions (the server keeps the last good ones): click one to see it beside
function fillRevisions(status) {
  const grid = $("revgrid");
  const earlier = (status.revisions || []).filter((n) => n !== status.revision || status.state !== "ok");
  $("revisions").hidden = earlier.length === 0;
  const have = new Map([...grid.children].map((f) => [Number(f.dataset.revision), f]));
  for (const [n, f] of have) if (!earlier.includes(n)) f.remove();
  for (const n of earlier) {
    if (have.has(n)) continue;
    const figure = document.createElement("figure"), img = document.createElement("img");
    const caption = document.createElement("figcaption");
    figure.dataset.revision = String(n);
    img.alt = `revision ${n}`; img.src = `/revision.png?n=${n}`;
    caption.textContent = `rev. ${n}`;
    figure.append(img, caption);
    figure.addEventListener("click", () => showBeside(n));
    grid.insertBefore(figure, [...grid.children].find((f) => Number(f.dataset.revision) < n) || null);
  }
}
function showBeside(n) {
  $("besideimg").src = `/revision.png?n=${n}`;
  $("besidelabel").textContent = `revision ${n}`;
  $("beside").hidden = false;
  $("beside").dataset.revision = String(n);
  for (const f of $("revgrid").children) f.classList.toggle("current", Number(f.dataset.revision) === n);
  fit();
}
$("besideclose").addEventListener("click", () => {
  $("beside").hidden = true;
  for (const f of $("revgrid").children) f.classList.remove("current");
  fit();
});

// --- the variations sheet: the render with nine other rng seeds, made two at a time (the
// server runs two programs besides the live render); click one to take its seed.
let variationQueue = [];
function showVariations(first) {
  const grid = $("vargrid");
  grid.textContent = "";
  variationQueue = [];
  for (let seed = first; seed < first + 9; seed += 1) {
    const figure = document.createElement("figure"), img = document.createElement("img");
    const caption = document.createElement("figcaption");
    figure.dataset.seed = String(seed);
    img.alt = `rng seed ${seed}`;
    caption.textContent = `seed ${seed}`;
    figure.append(img, caption);
    figure.addEventListener("click", () => {
      for (const f of grid.children) f.classList.toggle("current", f === figure);
      sendSettings({ rng_seed: String(seed) });
    });
    grid.appendChild(figure);
    variationQueue.push({ img, seed, tries: 0 });
  }
  $("varmore").hidden = false;
  $("varmore").onclick = () => showVariations(first + 9);
  for (let i = 0; i < 2; i += 1) nextVariation();
}
function nextVariation() {
  const v = variationQueue.shift();
  if (!v) return;
  v.img.onload = () => { v.img.parentElement.dataset.loaded = "1"; nextVariation(); };
  // Busy (503: downloads running): again a little later.
  v.img.onerror = () => { if (++v.tries < 10) setTimeout(() => { variationQueue.unshift(v); nextVariation(); }, 1000); else nextVariation(); };
  v.img.src = `/variation.png?rng=${v.seed}&t=${Date.now()}`;
}
$("varshow").addEventListener("click", () => {
  const s = (page.status && page.status.settings) || {};
  showVariations(Number(s.rng_seed || 1) + 1);
});

// --- the growth library's fidelity report (--metrics "growth"): how the result keeps the
// reference's spacing, symbol mix and neighbourhoods (docs/stdlib/growth.md#fidelity-report).
function fillFidelity(g) {
  $("fidelity").hidden = !g;
  if (!g) return;
  const body = $("fidelitytable").tBodies[0];
  body.textContent = "";
  const pct = (v) => (typeof v === "number" ? (100 * v).toFixed(1) + "%" : "–");
  const num = (v, d = 2) => (typeof v === "number" ? v.toFixed(d) : "–");
  const row = (name, result, reference, off, label = name) => {
    const tr = body.insertRow();
    tr.insertCell().textContent = label;
    const r = tr.insertCell(); r.className = "n" + (off ? " off" : ""); r.textContent = result;
    const f = tr.insertCell(); f.className = "n"; f.textContent = reference;
    tr.dataset.key = name;
  };
  row("motifs", `${g.motifs}` + (g.restarts ? ` (${g.restarts} restarts)` : ""), "");
  row("NN median", num(g.nn_median, 3), "1", Math.abs((g.nn_median || 0) - 1) > 0.1);
  // Away from the panel's and the reference's edges, where an edge motif's neighbours are few.
  row("NN median inner", num(g.nn_median_inner, 3), num(g.nn_median_reference_inner, 3),
      Math.abs((g.nn_median_inner || 0) / (g.nn_median_reference_inner || 1) - 1) > 0.1);
  const same = g.same_symbol_neighbours || {};
  row("same-symbol pairs", pct(same.result), pct(same.reference),
      Math.abs((same.result || 0) - (same.reference || 0)) > 0.1);
  for (const [name, share] of Object.entries(g.symbols || {}))
    row(name, pct(share.result), pct(share.reference), Math.abs(share.result - share.reference) > 0.05, `“${name}” share`);
  const d = g.defects || {};
  row("defects", `${pct(d.share)} of ${d.interior || 0}`, "");
  row("largest hole", num(g.largest_hole), "", (g.largest_hole || 0) > 1.5);
  // The histogram: a pair of bars per bin, result in front.
  const h = g.nn_histogram || {}, svg = $("nnhistogram");
  svg.textContent = "";
  const bins = Math.max((h.result || []).length, (h.reference || []).length);
  const top = Math.max(1e-9, ...(h.result || []), ...(h.reference || []));
  const w = 210 / Math.max(1, bins);
  for (const [kind, dx] of [["reference", 0], ["result", w * 0.3]]) {
    (h[kind] || []).forEach((v, i) => {
      const r = document.createElementNS(SVGNS, "rect"), height = 56 * v / top;
      r.setAttribute("x", i * w + dx); r.setAttribute("width", w * 0.7);
      r.setAttribute("y", 58 - height); r.setAttribute("height", height);
      r.setAttribute("class", "bar-" + kind);
      svg.appendChild(r);
    });
  }
  // The reference's spacing: NN 1.
  const one = document.createElementNS(SVGNS, "line");
  for (const [k, v] of [["x1", w * 1 / (h.bin || 0.1)], ["x2", w * 1 / (h.bin || 0.1)], ["y1", 0], ["y2", 60]]) one.setAttribute(k, v);
  one.setAttribute("class", "nn-one");
  svg.appendChild(one);
}

// --- zoom and pan ---------------------------------------------------------------------------
function applyView() {
  $("canvas").style.transform = `translate(${page.view.x}px, ${page.view.y}px) scale(${page.view.scale})`;
  loadSharp();
}
function fit() {
  const v = $("view").getBoundingClientRect();
  const s = Math.min(v.width / page.size.width, v.height / page.size.height) * 0.97;
  page.view = { scale: s, x: (v.width - page.size.width * s) / 2, y: (v.height - page.size.height * s) / 2 };
  applyView();
}
function eventToPage(e) {
  const v = $("view").getBoundingClientRect();
  return [(e.clientX - v.left - page.view.x) / page.view.scale, (e.clientY - v.top - page.view.y) / page.view.scale];
}
$("view").addEventListener("wheel", (e) => {
  e.preventDefault();
  const v = $("view").getBoundingClientRect();
  const mx = e.clientX - v.left, my = e.clientY - v.top;
  const k = Math.exp(-e.deltaY * 0.0015);
  page.view.x = mx - (mx - page.view.x) * k;
  page.view.y = my - (my - page.view.y) * k;
  page.view.scale *= k;
  applyView();
}, { passive: false });
$("view").addEventListener("dblclick", fit);
$("zoomfit").addEventListener("click", fit);

let drag = null;
$("view").addEventListener("pointerdown", (e) => {
  if (e.button !== 0) return;
  e.preventDefault();  // no text selection or image drag while drawing

  $("view").setPointerCapture(e.pointerId);
  if (page.mode === "pan") drag = { kind: "pan", x: e.clientX, y: e.clientY, vx: page.view.x, vy: page.view.y };
  else if (page.mode === "seed") {
    page.seeds.push(toRegion(eventToPage(e)));
    drawOverlay();
    sendSettings({ seeds: page.seeds });
  } else {
    const scale = (layout() || { scale: 1 }).scale;
    drag = { kind: "stroke", stroke: { kind: page.mode, width: Number($("brush").value) / scale, points: [toRegion(eventToPage(e))] } };
    page.strokes.push(drag.stroke);
  }
});
$("view").addEventListener("pointermove", (e) => {
  if (!drag) return;
  if (drag.kind === "pan") {
    page.view.x = drag.vx + e.clientX - drag.x; page.view.y = drag.vy + e.clientY - drag.y; applyView();
  } else {
    const p = toRegion(eventToPage(e)), last = drag.stroke.points[drag.stroke.points.length - 1];
    const l = layout() || { scale: 1 };
    if (Math.hypot(p[0] - last[0], p[1] - last[1]) * l.scale * page.view.scale >= 3) { drag.stroke.points.push(p); drawOverlay(); }
  }
});
$("view").addEventListener("pointerup", () => {
  if (drag && drag.kind === "stroke") {
    if (drag.stroke.points.length < 2) page.strokes.pop();
    sendStrokes();
  }
  drag = null;
});

function sendStrokes() {
  if (!page.strokeTool) return;
  const body = { library: page.strokeTool.library, strokes: page.strokes };
  $("strokecount").textContent = page.strokes.length ? `${page.strokes.length} stroke(s)` : "no strokes";
  drawOverlay();
  post("/guides", body);
}

function drawOverlay() {
  const svg = $("overlay");
  svg.textContent = "";
  const l = layout();
  for (const s of page.strokes) {
    const line = document.createElementNS(SVGNS, "polyline");
    line.setAttribute("points", s.points.map((p) => toPage(p).join(",")).join(" "));
    const tool = page.strokeTool || { kinds: [], width_kinds: [] };
    const wide = tool.width_kinds.includes(s.kind);
    line.setAttribute("class", `stroke stroke-k${tool.kinds.indexOf(s.kind)}${wide ? " stroke-wide" : ""}`);
    line.setAttribute("stroke-width", wide && l ? s.width * l.scale : 2.5);
    svg.append(line);
  }
  for (const s of page.seeds) {
    const c = document.createElementNS(SVGNS, "circle");
    const p = toPage(s);
    c.setAttribute("cx", p[0]); c.setAttribute("cy", p[1]); c.setAttribute("r", 5);
    c.setAttribute("class", "seedmark");
    svg.append(c);
  }
}

function setMode(mode) {
  page.mode = mode;
  for (const o of document.querySelectorAll("#modes button")) o.classList.toggle("on", o.dataset.mode === mode);
  $("view").className = mode === "pan" || mode === "seed" ? mode : "draw";
}
$("modes").addEventListener("click", (e) => {
  const b = e.target.closest("button");
  if (b && b.dataset.mode) setMode(b.dataset.mode);
});

// --- controls -------------------------------------------------------------------------------
$("rng").addEventListener("change", () => sendSettings({ rng_seed: String($("rng").value) }));
$("shuffle").addEventListener("click", () => {
  const seed = String(Math.floor(Math.random() * 1e9));
  $("rng").value = seed;
  sendSettings({ rng_seed: seed });
});
$("panel").addEventListener("change", () => { page.seeds = []; sendSettings({ panel: $("panel").value, seeds: [] }); });
$("copycommand").addEventListener("click", async () => {
  try {
    await navigator.clipboard.writeText($("command").textContent);
    $("copied").textContent = "copied";
  } catch (e) {  // no clipboard (an address other than 127.0.0.1 over plain http): select it
    getSelection().selectAllChildren($("command"));
    $("copied").textContent = "selected: press Ctrl-C";
  }
  setTimeout(() => { $("copied").textContent = ""; }, 3000);
});
$("clearseeds").addEventListener("click", () => { page.seeds = []; drawOverlay(); sendSettings({ seeds: [] }); });
$("clearstrokes").addEventListener("click", () => { page.strokes = []; sendStrokes(); });

async function loadPanels() {
  const names = await (await fetch("/panels.json")).json();
  const select = $("panel");
  select.add(new Option("built-in panel", ""));
  for (const n of names) select.add(new Option(n, n));
}

// A dropped SVG becomes the panel.
const view = $("view");
view.addEventListener("dragover", (e) => { e.preventDefault(); view.classList.add("dragover"); });
view.addEventListener("dragleave", () => view.classList.remove("dragover"));
view.addEventListener("drop", async (e) => {
  e.preventDefault();
  view.classList.remove("dragover");
  const file = e.dataTransfer.files[0];
  if (!file) return;
  if (file.size > 4 * 1024 * 1024) { showNote("the panel is larger than 4 MiB"); return; }
  await post("/panel", await file.text(), "image/svg+xml");
  page.seeds = [];
});

// --- growth animation and debug frames ------------------------------------------------------
function showFrame(url) {
  const f = $("frame");
  f.src = url; f.hidden = false;
  $("picture").style.visibility = "hidden";
}
$("showrender").addEventListener("click", () => { $("frame").hidden = true; $("picture").style.visibility = "visible"; });
let playTimer = null;
$("play").addEventListener("click", async () => {
  clearInterval(playTimer);
  $("frameinfo").textContent = "rendering frames…";
  const iterations = (page.status.metrics && page.status.metrics.iterations) || 100;
  const every = Math.max(1, Math.ceil(iterations / 80));
  const r = await post("/frames", { every });
  page.frames = r.count;
  const pos = $("framepos");
  pos.max = r.count; pos.value = 1;
  let i = 1;
  const show = () => { pos.value = i; showFrame(`/frames/${i}.png?t=${Date.now()}`); $("frameinfo").textContent = `${i}/${r.count}`; };
  show();
  playTimer = setInterval(() => { if (i >= r.count) { clearInterval(playTimer); return; } i += 1; show(); }, 80);
});
$("framepos").addEventListener("input", () => {
  clearInterval(playTimer);
  const i = $("framepos").value;
  showFrame(`/frames/${i}.png`); $("frameinfo").textContent = `${i}/${page.frames}`;
});
function showDebug() { clearInterval(playTimer); showFrame(`/debug-frame.png?iteration=${$("debugit").value}`); }
$("debugshow").addEventListener("click", showDebug);
$("debugprev").addEventListener("click", () => { $("debugit").value = Math.max(1, Number($("debugit").value) - 1); showDebug(); });
$("debugnext").addEventListener("click", () => { $("debugit").value = Number($("debugit").value) + 1; showDebug(); });

// --- start ----------------------------------------------------------------------------------
loadPanels();
// --- the page state in the address: a link reproduces the view ------------------------------
// ?p.NAME=VALUE for each parameter set, rng=N, panel=NAME (one of the list), seed=X,Y each.
function stateQuery(s) {
  const q = new URLSearchParams();
  for (const [k, v] of Object.entries(s.params || {})) q.append("p." + k, v);
  if (s.rng_seed) q.set("rng", s.rng_seed);
  if (s.panel && [...$("panel").options].some((o) => o.value === s.panel && o.value !== "uploaded")) q.set("panel", s.panel);
  for (const seed of s.seeds || []) q.append("seed", seed);
  return q.toString();
}
function followAddress(settings) {
  const query = stateQuery(settings || {});
  if (query !== location.search.replace(/^\?/, "")) history.replaceState(null, "", query ? "?" + query : location.pathname);
}
function applyAddress() {
  const q = new URLSearchParams(location.search), change = {}, params = {};
  for (const [k, v] of q) if (k.startsWith("p.")) params[k.slice(2)] = v;
  if (Object.keys(params).length) change.params = params;
  if (q.has("rng")) change.rng_seed = q.get("rng");
  if (q.has("panel")) change.panel = q.get("panel");
  if (q.has("seed")) change.seeds = q.getAll("seed").map((t) => t.split(",").map(Number));
  if (Object.keys(change).length) post("/settings", change).catch(() => {});
}
applyAddress();

// --- one event stream per browser, shared by its tabs --------------------------------------
// A browser opens about six connections per host: with an event stream each, the seventh tab
// would never load. The tab holding the lock (Web Locks) keeps the one stream open and passes
// every status on (BroadcastChannel); when it closes, a waiting tab takes the lock and the
// stream over. Where a browser has neither (not a secure context: another --host), each tab
// has its own stream.
function followEvents() {
  const own = () => {
    const events = new EventSource("/events");
    events.onmessage = (e) => { update(JSON.parse(e.data)); if (page.channel) page.channel.postMessage(e.data); };
    return events;
  };
  if (!window.BroadcastChannel || !navigator.locks) { own(); return; }
  page.channel = new BroadcastChannel("acanthus-preview-events");
  page.channel.onmessage = (e) => { if (!page.leader) update(JSON.parse(e.data)); };
  // Until the leader's next event: the status now.
  fetch("/status.json").then((r) => r.json()).then((s) => { if (!page.status) update(s); }).catch(() => {});
  navigator.locks.request("acanthus-preview-events", () => new Promise(() => {
    page.leader = true;
    document.body.dataset.leader = "1";
    own();  // held until the tab closes
  }));
}
reportView(0);
followEvents();
window.addEventListener("resize", () => { applyView(); reportView(); });
