// Opens pages written by `locus view` in headless Chromium (Debian's, driven by playwright-core)
// and checks that each loads without console errors, that the scene holds as many objects as
// the page's embedded glTF has items, that the panel lists the glTF's outputs, that clicking an
// object reports its output, path and index, and that a screenshot of the view is not blank.
// Screenshots are saved next to the pages as artifacts.
// Usage: node viewer.mjs PAGE.html ...
import { readFile, writeFile } from 'node:fs/promises';
import { launchChromium } from './browser.mjs';
import { PNG } from 'pngjs';

/** The JSON chunk of the page's embedded .glb. */
async function embeddedGltf(page) {
  const html = await readFile(page, 'utf8');
  const b64 = html.match(/<script id="locus-glb" type="application\/octet-stream">([^<]*)<\/script>/)[1];
  const glb = Buffer.from(b64, 'base64');
  const jsonLength = glb.readUInt32LE(12);
  const json = JSON.parse(glb.subarray(20, 20 + jsonLength).toString('utf8'));
  return json;
}

/** The item nodes of a glTF (nodes whose extras have an index), and its output names. */
function expectations(json) {
  const items = json.nodes.filter((n) => n.extras && n.extras.index !== undefined).map((n) => n.extras);
  const root = json.nodes[json.scenes[json.scene].nodes[0]];
  const outputs = (root.children ?? []).map((i) => json.nodes[i].name);
  return { items, outputs, rootName: root.name };
}

const same = (a, b) => a && b && a.output === b.output && a.path === b.path && a.index === b.index;
const address = (a) => `${a.output} ${a.path}[${a.index}]`;

/** The most objects clicked on a page before giving up on hitting the one aimed at. */
const MAX_CLICKS = 20;

const browser = await launchChromium();
let failed = 0;
for (const file of process.argv.slice(2)) {
  const errors = [];
  const page = await browser.newPage({ viewport: { width: 900, height: 600 } });
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  page.on('pageerror', (e) => errors.push(String(e)));
  page.on('request', (r) => { if (!r.url().startsWith('file:') && !r.url().startsWith('data:')) errors.push(`network request ${r.url()}`); });
  await page.goto(`file://${file}`);
  await page.waitForSelector('body[data-ready="true"]', { timeout: 30000 });
  const state = await page.evaluate(() => ({ count: window.locusViewer.objectCount, errors: window.locusViewer.errors }));
  const gltf = expectations(await embeddedGltf(file));
  const expected = gltf.items.length;
  const outputs = await page.locator('#outputs > li').count();
  const listed = await page.$$eval('#outputs > li > label', (ls) => ls.map((l) => l.textContent.trim()));
  const problems = [];
  // Click objects where the viewer says they are on screen; a click may hit another object in
  // front, so aim at up to MAX_CLICKS of them until one reports the item aimed at. Whatever a
  // click selects must be an item of the glTF, and the selection box must name it.
  const probes = await page.evaluate(() => window.locusViewer.probes());
  let selected = null;
  for (const probe of probes.slice(0, MAX_CLICKS)) {
    await page.mouse.click(probe.x, probe.y);
    const got = await page.evaluate(() => window.locusViewer.selected);
    if (!got) continue;
    if (!gltf.items.some((i) => same(i, got))) problems.push(`a click selected ${address(got)}, which is not an item of the glTF`);
    const text = await page.locator('#selection').textContent();
    if (!text.includes(address(got))) problems.push(`the selection box says "${text}", not ${address(got)}`);
    if (same(got, probe)) { selected = got; break; }
  }
  if (!selected) problems.push(`no click on ${Math.min(probes.length, MAX_CLICKS)} objects in view reported the object clicked`);
  const shot = await page.locator('#viewport canvas').screenshot();
  await writeFile(file.replace(/\.html$/, '.png'), shot);
  const png = PNG.sync.read(shot);
  let drawn = 0;
  for (let i = 0; i < png.data.length; i += 4) {
    const [r, g, b] = [png.data[i], png.data[i + 1], png.data[i + 2]];
    if (Math.abs(r - 0xf4) + Math.abs(g - 0xf4) + Math.abs(b - 0xf4) > 24) drawn += 1;
  }
  const share = drawn / (png.width * png.height);
  problems.unshift(...errors, ...state.errors);
  if (state.count !== expected) problems.push(`scene holds ${state.count} objects, the glTF ${expected} items`);
  if (gltf.rootName !== 'locus-root') problems.push(`the glTF's root node is named ${gltf.rootName}, not locus-root`);
  if (outputs === 0) problems.push('the panel lists no outputs');
  if (JSON.stringify(listed) !== JSON.stringify(gltf.outputs)) {
    problems.push(`the panel lists ${JSON.stringify(listed)}, the glTF has outputs ${JSON.stringify(gltf.outputs)}`);
  }
  if (share < 0.01) problems.push(`the screenshot is blank (${(share * 100).toFixed(2)} % drawn)`);
  console.log(`${file}: ${state.count} objects, ${outputs} outputs, ${(share * 100).toFixed(1)} % of the view drawn, clicked: ${selected ? address(selected) : 'nothing'}`);
  for (const p of problems) console.log(`  problem: ${p}`);
  if (problems.length) failed += 1;
  await page.close();
}
await browser.close();
if (failed) { console.log(`${failed} page(s) failed`); process.exit(1); }
