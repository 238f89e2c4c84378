// When the preview page in headless Chromium painted each revision, for bench/preview_edit.py.
// Usage: node paint_time.js URL CHROMIUM. Prints "ready REV" once the first picture is shown;
// then for each line "wait REV SINCE" on standard input prints "painted REV MS FIRST": MS the
// wall-clock time (ms since the epoch) of the first frame after the page's picture of revision
// REV or later loaded, or "painted REV none" after 120 s; FIRST the first frame painted after
// SINCE (ms since the epoch) with the growth so far (a partial picture) or the picture itself:
// the user's first look. A fifth word, the page's steps for that picture as JSON (ms since the
// epoch): "event" the status with the revision came, "fetch" and "fetched" the picture's request
// and its last byte, "loaded" the <img> decoded it.
"use strict";
const readline = require("readline");
const puppeteer = require("puppeteer-core");

const [url, chromium] = process.argv.slice(2);

(async () => {
  const browser = await puppeteer.launch({ executablePath: chromium, headless: "new",
                                           args: ["--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage"] });
  try {
    const page = await browser.newPage();
    await page.setViewport({ width: 1280, height: 760 });
    // The page sets data-shown when the new picture loaded; the frame after the next one is
    // the first with it on screen.
    await page.evaluateOnNewDocument(() => {
      window.paintedAt = {};
      window.partialsAt = [];
      window.eventAt = {};
      window.loadedAt = {};
      new MutationObserver((records) => {
        const now = Date.now();
        if (records.some((r) => r.attributeName === "data-revision")) {
          const r = Number(document.body.dataset.revision);
          if (!(r in window.eventAt)) window.eventAt[r] = now;
        }
        if (!records.some((r) => r.attributeName !== "data-revision")) return;
        const partial = records.some((r) => r.attributeName === "data-partial");
        const rev = Number(document.body.dataset.shown);
        if (!partial) window.loadedAt[rev] = now;
        requestAnimationFrame(() => requestAnimationFrame(() => {
          if (partial) window.partialsAt.push(Date.now());
          else window.paintedAt[rev] = Date.now();
        }));
      }).observe(document, { attributes: true, subtree: true, attributeFilter: ["data-shown", "data-partial", "data-revision"] });
    });
    await page.goto(url);
    await page.waitForFunction(() => Object.keys(window.paintedAt).length > 0, { timeout: 300000, polling: 50 });
    const first = await page.evaluate(() => Math.max(...Object.keys(window.paintedAt).map(Number)));
    console.log("ready " + first);
    const lines = readline.createInterface({ input: process.stdin });
    for await (const line of lines) {
      const m = line.match(/^wait (\d+) (\d+)$/);
      if (!m) continue;
      const rev = Number(m[1]), since = Number(m[2]);
      let ms = "none", first = "none", steps = {};
      try {
        await page.waitForFunction((r) => Object.keys(window.paintedAt).some((k) => Number(k) >= r),
                                   { timeout: 120000, polling: 10 }, rev);
        ms = await page.evaluate((r) => Math.min(...Object.entries(window.paintedAt)
          .filter(([k]) => Number(k) >= r).map(([, t]) => t)), rev);
        first = await page.evaluate((t, painted) => Math.min(painted, ...window.partialsAt.filter((p) => p >= t)),
                                    since, ms);
        steps = await page.evaluate((r) => {
          const shown = Object.keys(window.paintedAt).map(Number).filter((k) => k >= r).sort((a, b) => a - b)[0];
          const at = (t) => Math.round(performance.timeOrigin + t);
          const fetch = performance.getEntriesByType("resource")
            .filter((e) => e.name.includes(`/view.png?revision=${shown}`)).pop();
          return { event: window.eventAt[shown], loaded: window.loadedAt[shown],
                   fetch: fetch && at(fetch.startTime), fetched: fetch && at(fetch.responseEnd) };
        }, rev);
      } catch (e) { /* none */ }
      console.log(`painted ${rev} ${ms} ${first} ${JSON.stringify(steps)}`);
    }
  } finally {
    await browser.close();
  }
})().catch((e) => { console.error(e && e.stack ? e.stack : e); process.exit(1); });
