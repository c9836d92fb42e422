// The testbed page in a real browser (Debian's chromium, driven by puppeteer-core):
//   node testbed.test.mjs TESTBED_HTML COLLIDE2D
// drags shape B into shape A for a few pairs of kinds and checks that what the page shows (the
// overlap, the separation and normal, the drag's time of impact) is what `collide2d query` prints for
// the query line the page shows, to the digits the page shows. Exits 77 (ctest: skipped), saying why,
// where there is no browser, no puppeteer-core, or no testbed page (a build configured with
// -DCOLLIDE2D_BUILD_TESTBED=ON makes it; scripts/deps.sh --test installs all three's tools).
import { execFileSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import { pathToFileURL } from 'node:url';

import { check, finish, launch, skip } from './harness.mjs';

const [testbed, collide2d] = process.argv.slice(2);
if (!existsSync(testbed)) skip(`no testbed page at ${testbed}: configure with -DCOLLIDE2D_BUILD_TESTBED=ON`);

// What the command prints for a line, as numbers.
function query(mode, line) {
  const args = mode ? ['query', mode] : ['query'];
  return execFileSync(collide2d, args, { input: line + '\n', encoding: 'utf8' }).trim().split(' ').map(Number);
}
const shown = (x) => Number(x).toPrecision(6);
const shownPoint = (x, y) => `(${shown(x)}, ${shown(y)})`;

const browser = await launch();
try {
  const page = await browser.newPage();
  page.on('pageerror', (e) => check(false, `no script error (${e.message})`));
  await page.setViewport({ width: 1400, height: 800 });
  await page.goto(pathToFileURL(testbed).href);
  await page.waitForFunction('window.testbedReady === true', { timeout: 60000 });
  const view = await (await page.$('#view')).boundingBox();
  const row = async (table, key) =>
    page.$eval(`#${table} tr[data-key="${key}"] td:last-child`, (td) => td.textContent).catch(() => null);

  for (const [a, b] of [['rect', 'ellipse'], ['polygon', 'capsule'], ['circle', 'ellipse'], ['ellipse', 'ellipse']]) {
    await page.evaluate(([ka, kb]) => {
      testbed.setKind('a', ka);
      testbed.setKind('b', kb);
      Object.assign(testbed.shapes.a, { x: -1.5, y: 0, angle: 0.3 });
      Object.assign(testbed.shapes.b, { x: 3.6, y: 0.5, angle: -0.4 });
      testbed.setKind('b', kb);
    }, [a, b]);
    // Drag B by its centre towards A until they overlap.
    const [bx, by] = await page.evaluate('testbed.toScreen(testbed.shapes.b.x, testbed.shapes.b.y)');
    await page.mouse.move(view.x + bx, view.y + by);
    await page.mouse.down();
    await page.mouse.move(view.x + bx - 160, view.y + by - 10, { steps: 6 });
    await page.mouse.up();
    const line = await page.$eval('#line', (e) => e.textContent);
    const d = query(null, line), c = query('--contact', line);
    const overlap = await row('results', 'overlap');
    check(overlap === (d[0] === 1 ? 'yes' : 'no') && d[0] === 1,
          `${a}–${b} dragged together: the page's overlap "${overlap}", the command's ${d[0]}`);
    const separation = await row('results', 'separation'), normal = await row('results', 'normal (A to B)');
    check(separation === shown(c[0]) && normal === shownPoint(c[1], c[2]),
          `${a}–${b}: separation ${separation} and normal ${normal} as the command's ${shown(c[0])} ${shownPoint(c[1], c[2])}`);
    const toiLine = await page.$eval('#toi-line', (e) => e.textContent);
    const t = query('--toi', toiLine);
    const hit = await row('toi', 'hit'), time = await row('toi', 't');
    check(hit === (t[0] === 1 ? 'yes' : 'no') && time === shown(t[1]) && t[1] > 0 && t[1] < 1,
          `${a}–${b}: the drag's time of impact ${hit} ${time} as the command's ${t[0]} ${shown(t[1])}`);
  }
} finally {
  await browser.close();
}
finish();
