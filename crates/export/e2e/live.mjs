// The live page of `locus view --serve` in headless Chromium: it loads without console errors
// and asks nothing of any origin but its server; after an orbit and a change to the graph file
// it reloads by itself, shows the new evaluation (its generation and object count) and keeps
// the camera it was left with.
// Usage: node live.mjs URL GRAPH.ron  (GRAPH.ron is the file the server watches; it holds a
// params.point node "p" whose point list is rewritten here)
import { readFile, writeFile } from 'node:fs/promises';
import { launchChromium } from './browser.mjs';

const [url, graph] = process.argv.slice(2);
/** How long a reload may take after the file changed (the server polls every 250 ms). */
const RELOAD_MS = 30000;

const browser = await launchChromium();
const errors = [];
const page = await browser.newPage({ viewport: { width: 900, height: 600 } });
const origin = new URL(url).origin;
page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
page.on('pageerror', (e) => errors.push(String(e)));
page.on('request', (r) => {
  const u = r.url();
  if (!u.startsWith(origin) && !u.startsWith('data:')) errors.push(`network request ${u}`);
});

const viewerState = () => page.evaluate(() => ({
  count: window.locusViewer.objectCount,
  generation: window.locusViewer.generation,
  camera: window.locusViewer.camera(),
  errors: window.locusViewer.errors,
}));

await page.goto(url);
await page.waitForSelector('body[data-ready="true"]', { timeout: 30000 });
const before = await viewerState();
const problems = [];
if (before.generation !== 1) problems.push(`first generation ${before.generation}, expected 1`);

// Orbit: drag across the canvas.
const canvas = await page.locator('#viewport canvas').boundingBox();
await page.mouse.move(canvas.x + canvas.width / 2, canvas.y + canvas.height / 2);
await page.mouse.down();
await page.mouse.move(canvas.x + canvas.width / 2 + 120, canvas.y + canvas.height / 2 + 40, { steps: 8 });
await page.mouse.up();
const orbited = (await viewerState()).camera;
const moved = orbited.position.some((v, i) => Math.abs(v - before.camera.position[i]) > 1e-6);
if (!moved) problems.push('the drag did not move the camera');

// One more point in the graph file: the page must reload with one more object.
const text = await readFile(graph, 'utf8');
const edited = text.replace(/"Pt": \[/, '"Pt": [(5, 5, 5), ');
if (edited === text) throw new Error(`${graph} has no "Pt": [ list to edit`);
const reloaded = page.waitForEvent('load', { timeout: RELOAD_MS });
await writeFile(graph, edited);
await reloaded;
await page.waitForSelector('body[data-ready="true"]', { timeout: 30000 });
const after = await viewerState();
if (after.count !== before.count + 1) problems.push(`after the change ${after.count} objects, expected ${before.count + 1}`);
const same = (a, b) => a.every((v, i) => Math.abs(v - b[i]) < 1e-9);
if (!same(after.camera.position, orbited.position) || !same(after.camera.target, orbited.target)) {
  problems.push(`the camera was not kept: ${JSON.stringify(orbited)} became ${JSON.stringify(after.camera)}`);
}
problems.push(...errors, ...after.errors);
await browser.close();
if (problems.length) {
  console.error(`live page ${url}: FAILED\n  ${problems.join('\n  ')}`);
  process.exit(1);
}
console.log(`live page ${url}: ok (generation ${before.generation} → ${after.generation}, ${before.count} → ${after.count} objects, camera kept)`);
