// Opens pages written by `locus view` in headless Chromium (Debian's, driven by playwright-core)
// and checks that each loads without console errors, that the scene holds as many objects as
// the page's embedded glTF has items, that clicking an object selects it, and that a
// screenshot of the view is not blank. Screenshots are saved next to the pages as artifacts.
// Usage: node viewer.mjs PAGE.html ...
import { readFile, writeFile } from 'node:fs/promises';
import { chromium } from 'playwright-core';
import { PNG } from 'pngjs';

/** The number of item nodes (extras with an index) in the page's embedded .glb. */
async function expectedItems(page) {
  const html = await readFile(page, 'utf8');
  const b64 = html.match(/<script id="locus-glb" type="application\/octet-stream">([^<]*)<\/script>/)[1];
  const glb = Buffer.from(b64, 'base64');
  const jsonLength = glb.readUInt32LE(12);
  const json = JSON.parse(glb.subarray(20, 20 + jsonLength).toString('utf8'));
  return json.nodes.filter((n) => n.extras && n.extras.index !== undefined).length;
}

const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
  args: ['--no-sandbox', '--disable-gpu', '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
    '--disable-quic', '--no-first-run', '--disable-background-networking',
    '--disable-component-update', '--disable-sync'],
});
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
  const expected = await expectedItems(file);
  const outputs = await page.locator('#outputs > li').count();
  // Click the middle of the view: the tutorials have geometry there.
  await page.mouse.click(300, 300);
  const selected = await page.evaluate(() => window.locusViewer.selected);
  const shot = await page.locator('#viewport canvas').screenshot();
  await writeFile(file.replace(/\.html$/, '.png'), shot);
  const png = PNG.sync.read(shot);
  let drawn = 0;
  for (let i = 0; i < png.data.length; i += 4) {
    const [r, g, b] = [png.data[i], png.data[i + 1], png.data[i + 2]];
    if (Math.abs(r - 0xf4) + Math.abs(g - 0xf4) + Math.abs(b - 0xf4) > 24) drawn += 1;
  }
  const share = drawn / (png.width * png.height);
  const problems = [...errors, ...state.errors];
  if (state.count !== expected) problems.push(`scene holds ${state.count} objects, the glTF ${expected} items`);
  if (outputs === 0) problems.push('the panel lists no outputs');
  if (share < 0.01) problems.push(`the screenshot is blank (${(share * 100).toFixed(2)} % drawn)`);
  console.log(`${file}: ${state.count} objects, ${outputs} outputs, ${(share * 100).toFixed(1)} % of the view drawn, clicked: ${selected ? `${selected.output} ${selected.path}[${selected.index}]` : 'nothing'}`);
  for (const p of problems) console.log(`  problem: ${p}`);
  if (problems.length) failed += 1;
  await page.close();
}
await browser.close();
if (failed) { console.log(`${failed} page(s) failed`); process.exit(1); }
