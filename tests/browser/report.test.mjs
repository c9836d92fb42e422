// The report's page in a real browser (Debian's chromium, driven by puppeteer-core):
//   node report.test.mjs COLLIDE2D_REPORT WORK_DIR
// runs `collide2d_report --pairs 10` with --json and --html, and checks that the page plots a point
// for every measurement of the JSON, that hovering one shows its method, time and error, that a
// contact's table shows its normal's errors, and that unticking a pair kind takes its points and
// its table away. Exits 77 (ctest: skipped), saying why,
// where no browser or no puppeteer-core is installed (scripts/deps.sh --test installs both).
import { execFileSync } from 'node:child_process';
import { mkdirSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

import { check, finish, launch } from './harness.mjs';

const [program, work] = process.argv.slice(2);

mkdirSync(work, { recursive: true });
const json = path.join(work, 'report.json'), html = path.join(work, 'report.html');
execFileSync(program, ['--pairs', '10', '--json', json, '--html', html], { stdio: 'ignore' });
const report = JSON.parse(readFileSync(json, 'utf8'));
const measured = [...report.distance, ...report.contact].filter((r) => r.nanoseconds > 0);

const browser = await launch();
try {
  const page = await browser.newPage();
  page.on('pageerror', (e) => check(false, `no script error (${e.message})`));
  await page.setViewport({ width: 1600, height: 900 });
  await page.goto(pathToFileURL(html).href);
  await page.waitForFunction('window.reportReady === true', { timeout: 30000 });
  const points = await page.$$eval('circle.point', (c) => c.length);
  check(points === measured.length, `a point for each measurement: ${points} of ${measured.length}`);

  // Hover the robust distance method's point.
  const robust = report.distance.find((r) => r.method === 'robust');
  const dot = await page.$('circle.point[data-kind="ellipse-ellipse distance"][data-method="robust"]');
  // Drawn last, so that no other method's point measured at about the same time and error covers it.
  await dot.evaluate((el) => el.parentNode.appendChild(el));
  await dot.hover();
  const tip = await page.$eval('#tip', (t) => (t.hidden ? '' : t.textContent));
  const expected = [`robust`, `${Number(robust.nanoseconds).toPrecision(3)} ns`,
                    `median error ${Number(robust.median_error).toPrecision(3)}`];
  check(expected.every((e) => tip.includes(e)), `hovering the robust method shows ${JSON.stringify(tip)}`);

  // A contact's table also holds its normal and point errors.
  const heads = await page.$eval('table[data-kind="circle-ellipse"]',
                                 (t) => [...t.tHead.rows[0].cells].map((c) => c.textContent));
  const ours = report.contact.find((r) => r.pair === 'circle-ellipse' && r.method === 'collide2d contact');
  const cells = await page.$eval('table[data-kind="circle-ellipse"]', (t) => [...t.tBodies[0].rows[0].cells].map((c) => c.textContent));
  check(heads.includes('normal (median / largest, rad)') &&
        cells[4] === `${Number(ours.median_normal_error).toPrecision(3)} / ${Number(ours.max_normal_error).toPrecision(3)}`,
        `the circle-ellipse table shows the normal's errors: ${JSON.stringify(heads)} ${JSON.stringify(cells)}`);

  // Untick rect-ellipse.
  await page.click('input[data-kind="rect-ellipse"]');
  const left = await page.$$eval('circle.point[data-kind="rect-ellipse"]', (c) => c.length);
  const hidden = await page.$eval('table[data-kind="rect-ellipse"]', (t) => t.hidden);
  const others = await page.$$eval('circle.point', (c) => c.length);
  const rect = measured.filter((r) => r.pair === 'rect-ellipse').length;
  check(left === 0 && hidden && others === measured.length - rect,
        `unticking rect-ellipse hides its ${rect} points and its table (${others} points left)`);
} finally {
  await browser.close();
}
finish();
