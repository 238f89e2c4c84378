// When the preview page in headless Chromium painted each revision, for bench/preview_edit.py.
// Usage: node paint_time.js URL CHROMIUM. Prints "ready REV" once the first picture is shown;
// then for each line "wait REV SINCE" on standard input prints "painted REV MS FIRST": MS the
// wall-clock time (ms since the epoch) of the first frame after the page's picture of revision
// REV or later loaded, or "painted REV none" after 120 s; FIRST the first frame painted after
// SINCE (ms since the epoch) with the growth so far (a partial picture) or the picture itself:
// the user's first look. The finished picture may come before its run ends (marked final) and
// counts as painted for REV when the page takes it as REV's picture. A fifth word, the page's steps for that picture as JSON (ms since the
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
      window.finalAt = {};
      window.finalLoadedAt = {};
      new MutationObserver((records) => {
        const now = Date.now();
        const changed = (name) => records.some((r) => r.attributeName === name);
        if (changed("data-revision")) {
          const r = Number(document.body.dataset.revision);
          if (!(r in window.eventAt)) window.eventAt[r] = now;
        }
        // The finished picture, shown before its run ended (data-final, the partial picture the
        // server marked final): painted then. It is revision R's picture only once the page
        // adopts it as R's (data-adopted, when R's status named it): R's paint is the final's.
        if (changed("data-final")) {
          const n = Number(document.body.dataset.final);
          window.finalLoadedAt[n] = now;
          requestAnimationFrame(() => requestAnimationFrame(() => {
            window.finalAt[n] = Date.now();
            window.partialsAt.push(window.finalAt[n]);
          }));
        }
        if (changed("data-partial"))
          requestAnimationFrame(() => requestAnimationFrame(() => window.partialsAt.push(Date.now())));
        if (!changed("data-shown")) return;
        const rev = Number(document.body.dataset.shown);
        const adopted = document.body.dataset.adopted;
        window.loadedAt[rev] = adopted ? window.finalLoadedAt[adopted] : now;
        requestAnimationFrame(() => requestAnimationFrame(() => {
          window.paintedAt[rev] = (adopted && window.finalAt[adopted]) || Date.now();
        }));
      }).observe(document, { attributes: true, subtree: true,
                             attributeFilter: ["data-shown", "data-partial", "data-final", "data-revision"] });
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
          // (an adopted final picture was fetched as /partial.png?n=N)
          const adopted = window.eventAt[shown] && document.body.dataset.adopted;
          const fetch = performance.getEntriesByType("resource")
            .filter((e) => e.name.includes(`/view.png?revision=${shown}`) ||
                           (adopted && e.name.includes(`/partial.png?n=${adopted}`))).pop();
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
