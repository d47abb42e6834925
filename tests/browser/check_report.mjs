// Opens a beverloo report (index.html) in Debian's headless Chromium through playwright-core,
// served from localhost, at a phone and a desktop width. Fails (exit 1, one line per problem)
// on: a console error or page error, a request that fails or answers >= 400, an <img> that does
// not decode, a link to a file the report does not have, a page wider than the phone's screen.
// Keeps a full-page screenshot per width in ARTEFACT_DIR.
// Usage: node check_report.mjs REPORT_DIR ARTEFACT_DIR
import http from "node:http";
import fs from "node:fs";
import path from "node:path";
import { chromium } from "playwright-core";

const [reportDir, artefactDir] = process.argv.slice(2);
const types = {".html": "text/html", ".svg": "image/svg+xml", ".png": "image/png", ".csv": "text/csv",
               ".md": "text/markdown", ".dat": "text/plain", ".gp": "text/plain"};
const server = http.createServer((req, res) => {
  const rel = decodeURIComponent(new URL(req.url, "http://x").pathname).replace(/^\/+/, "") || "index.html";
  const file = path.resolve(reportDir, rel);
  if (!file.startsWith(path.resolve(reportDir)) || !fs.existsSync(file) || !fs.statSync(file).isFile()) {
    res.writeHead(404); res.end(); return;
  }
  res.writeHead(200, {"Content-Type": types[path.extname(file)] || "application/octet-stream"});
  fs.createReadStream(file).pipe(res);
});
await new Promise(r => server.listen(0, "127.0.0.1", r));
const base = `http://127.0.0.1:${server.address().port}/`;

const problems = [];
const browser = await chromium.launch({
  executablePath: "/usr/bin/chromium",
  args: ["--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run", "--disable-background-networking",
         "--disable-component-update", "--disable-sync"],
});
const widths = [["phone", 390, 844], ["desktop", 1280, 900]];
let figures = 0, links = 0;
for (const [name, width, height] of widths) {
  const page = await browser.newPage({viewport: {width, height}});
  page.on("console", m => { if (m.type() === "error") problems.push(`${name}: console error: ${m.text()}`); });
  page.on("pageerror", e => problems.push(`${name}: page error: ${e.message}`));
  page.on("requestfailed", r => problems.push(`${name}: request failed: ${r.url()} (${r.failure()?.errorText})`));
  page.on("response", r => { if (r.status() >= 400) problems.push(`${name}: ${r.status()} for ${r.url()}`); });
  await page.goto(base + "index.html", {waitUntil: "load"});
  const imgs = await page.$$eval("img", els => els.map(e => ({src: e.getAttribute("src"), ok: e.complete && e.naturalWidth > 0,
                                                             shown: e.getBoundingClientRect().width})));
  for (const i of imgs) {
    if (!i.ok) problems.push(`${name}: figure ${i.src} does not load or decode`);
    if (i.shown > width) problems.push(`${name}: figure ${i.src} is ${i.shown} px wide on a ${width} px screen`);
  }
  figures = imgs.length;
  const hrefs = await page.$$eval("a[href]", els => els.map(e => e.getAttribute("href")));
  links = hrefs.length;
  for (const h of hrefs) {
    if (/^[a-z]+:/i.test(h) || h.startsWith("#")) continue;  // the report links only its own files
    const r = await page.request.get(base + h);
    if (r.status() !== 200) problems.push(`${name}: link ${h} answers ${r.status()}`);
  }
  const overflow = await page.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
  if (overflow > 1) problems.push(`${name}: the page is ${overflow} px wider than the ${width} px screen`);
  await page.screenshot({path: path.join(artefactDir, `report-${name}.png`), fullPage: true});
  await page.close();
}
await browser.close();
server.close();
if (figures === 0) problems.push("the report shows no figure");
for (const p of problems) console.log("FAIL " + p);
if (problems.length) process.exit(1);
console.log(`ok  ${figures} figures and ${links} links load at ${widths.map(w => w[1]).join(" and ")} px, no console errors`);
