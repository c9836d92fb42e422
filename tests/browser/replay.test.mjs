// The replay page in a real browser (Debian's chromium, driven by puppeteer-core):
//   node replay.test.mjs COLLIDE2D WORK_DIR
// runs a small scene whose events are known by construction (a bullet meeting a wall, two circles
// meeting, a box entering a sensor, a character walking a floor) with `collide2d run --html`, and
// checks that the page reports the run's frames, bodies and per-frame pair counts, draws the
// bullet's impact where the geometry puts it, draws the character where it walked, on the ground,
// with the floor's plane, names a clicked body, lists events by the bodies' user ids, and fits its layout to a
// window of 1280 x 800 and of 1920 x 1080. Then it loads the built-in scene's page (600 frames), checks
// its size, and prints the median time to draw a frame in a 1920 x 1080 window. Exits 77 (ctest: skipped),
// saying why, where no browser or no puppeteer-core is installed (scripts/deps.sh --test installs both).
import { execFileSync } from 'node:child_process';
import { mkdirSync, statSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

import { check, finish, launch } from './harness.mjs';

const [collide2d, work] = process.argv.slice(2);

// The scene: 20 x 10, 30 frames at 60 Hz. The bullet (radius 0.1) moves 5 a frame from x = 2 and
// meets the wall's face x = 9.5 in the step of update 1 (0-based) from x = 7, at t = (9.4 - 7) / 5,
// at (9.5, 5). The circles 2 apart close 4/60 a frame; the box reaches the sensor after 24 frames.
// The character (a circle of radius 0.4) stands the skin (0.01) over the floor's top, y = 0.5, and
// walks 1 a second to the left: after 30 frames it is at (15.5, 0.91).
const scene = {
  arena: { min: [0, 0], max: [20, 10] },
  frames: 30,
  dt: 1 / 60,
  fat_margin: 0.1,
  proximity_margin: 0.5,
  contacts: true,
  bodies: [
    { shape: 'circle', center: [2, 5], radius: 0.1, velocity: [300, 0], continuous: true, id: 7 },
    { shape: 'rect', center: [10, 5], half_extents: [0.5, 4], static: true, id: 9 },
    { shape: 'circle', center: [3, 2], radius: 0.5, velocity: [2, 0], id: 11 },
    { shape: 'circle', center: [5, 2], radius: 0.5, velocity: [-2, 0], id: 12 },
    { shape: 'circle', center: [15, 8], radius: 1.5, static: true, sensor: true, id: 20 },
    { shape: 'rect', center: [12, 8], half_extents: [0.3, 0.3], velocity: [3, 0], id: 21 },
    { shape: 'rect', center: [16, 0.25], half_extents: [3, 0.25], static: true, id: 30 },
  ],
  movers: [{ shape: 'circle', center: [16, 0.91], radius: 0.4, walk: [[0, -1]] }],
};

mkdirSync(work, { recursive: true });
const scenePath = path.join(work, 'scene.json');
const pagePath = path.join(work, 'scene.html');
writeFileSync(scenePath, JSON.stringify(scene));
const quiet = { encoding: 'utf8', stdio: ['ignore', 'pipe', 'ignore'] };  // no progress bar
const summary = execFileSync(collide2d, ['run', scenePath, '--html', pagePath], quiet);
const figure = (label) => Number(new RegExp(`^${label}\\s+([0-9.e+-]+)`, 'm').exec(summary)[1]);

const browser = await launch();
try {
  const page = await browser.newPage();
  await page.setViewport({ width: 1700, height: 1300 });
  page.on('pageerror', (e) => check(false, `no script error (${e.message})`));
  await page.goto(pathToFileURL(pagePath).href);
  await page.waitForFunction('window.replayReady === true', { timeout: 60000 });
  check(await page.evaluate('window.replayError === undefined'), 'the page reads the replay');

  const frames = await page.evaluate('replayApi.frames()');
  check(frames === figure('frames'), `frames: the page's ${frames}, the run's ${figure('frames')}`);
  const bodies = await page.evaluate('replayApi.bodies(0)');
  check(bodies === figure('bodies'), `bodies: the page's ${bodies}, the run's ${figure('bodies')}`);
  const counts = await page.evaluate(`Array.from({ length: ${frames} }, (_, f) => replayApi.counts(f))`);
  const stats = await page.evaluate(`replayPage.replay.frames.map((f) => f.stats)`);
  const mean = (key) => counts.reduce((s, c) => s + c[key], 0) / frames;
  const near = (a, b) => Math.abs(a - b) <= 1e-5 * Math.max(1, Math.abs(b));
  check(near(mean('candidates'), figure('candidate pairs per frame')),
        `candidate pairs per frame: the page's ${mean('candidates')}, the run's ${figure('candidate pairs per frame')}`);
  check(near(mean('overlapping'), figure('overlapping pairs per frame')),
        `overlapping pairs per frame: the page's ${mean('overlapping')}, the run's ${figure('overlapping pairs per frame')}`);
  check(counts.every((c, f) => c.candidates === stats[f].candidates && c.overlapping === stats[f].overlapping &&
                               c.proximity === stats[f].proximity && c.sensing === stats[f].sensing &&
                               c.contacts === stats[f].contacts && c.contacts === c.overlapping),
        'every frame: the pair lists the page rebuilt from changes have the lengths the World counted');
  check(mean('overlapping') > 0 && counts.some((c) => c.sensing > 0), 'the circles meet and the box enters the sensor');

  // The circle of user id 11 moves 2 a second from (3, 2): at the last frame, after 30 steps, (4, 2).
  const pose = await page.evaluate(`(() => {
    const frame = replayPage.replay.frames[${frames - 1}];
    const i = Array.from(frame.live).findIndex((e) => replayPage.replay.entries[e].bodyUser === 11n);
    return Array.from(frame.poses.subarray(3 * i, 3 * i + 2));
  })()`);
  check(Math.abs(pose[0] - 4) < 1e-5 && Math.abs(pose[1] - 2) < 1e-5, `body 11 ends at (4, 2): the page's (${pose})`);

  // The first impact: the frame, the point, and a red mark drawn there.
  const events = await page.evaluate('replayApi.events()');
  const first = events.find((v) => v.kind === 'impact');
  check(first !== undefined && first.frame === 1, `the first impact is at frame 1 (the page: ${first && first.frame})`);
  await page.evaluate('replayApi.setFrame(1)');
  const impact = (await page.evaluate('replayApi.impacts(1)'))[0];
  check(Math.abs(impact.point[0] - 9.5) < 1e-5 && Math.abs(impact.point[1] - 5) < 1e-5 &&
        Math.abs(impact.t - 0.48) < 1e-5, `the impact at (9.5, 5), t 0.48: the page's (${impact.point}), t ${impact.t}`);
  const [sx, sy] = await page.evaluate('replayApi.toScreen(9.5, 5)');
  const pixel = await page.evaluate(([x, y]) => Array.from(document.getElementById('view').getContext('2d')
    .getImageData(Math.round(x), Math.round(y), 1, 1).data), [sx, sy]);
  check(pixel[0] > 200 && pixel[1] < 60 && pixel[2] < 60, `the impact's mark is drawn at its point (pixel ${pixel})`);

  // The character at the last frame: where it walked, on the ground, the floor's plane under it,
  // and drawn in the ground's green.
  await page.evaluate(`replayApi.setFrame(${frames - 1})`);
  const mover = await page.evaluate(`replayPage.replay.frames[${frames - 1}].movers[0]`);
  check(Math.abs(mover.center[0] - 15.5) < 1e-5 && Math.abs(mover.center[1] - 0.91) < 1e-5 && mover.onGround,
        `the character ends at (15.5, 0.91) on the ground: the page's (${mover.center}), ${mover.onGround}`);
  check(mover.planes.length === 1 && Math.abs(mover.planes[0].normal[1] - 1) < 1e-6 &&
        Math.abs(mover.planes[0].separation - 0.01) < 1e-6,
        `its one plane is the floor's, facing up, the skin away: ${JSON.stringify(mover.planes)}`);
  const told = await page.$eval('#pair-counts', (d) => d.textContent);
  check(/movers 1, 1 on the ground/.test(told), `the frame's line counts it: ${told}`);
  const [mx, my] = await page.evaluate('replayApi.toScreen(15.5, 0.91)');
  const green = await page.evaluate(([x, y]) => Array.from(document.getElementById('view').getContext('2d')
    .getImageData(Math.round(x), Math.round(y), 1, 1).data), [mx, my]);
  check(green[1] > green[0] + 20 && green[1] > green[2] + 10, `the character is drawn green (pixel ${green})`);

  // A click on the wall names it.
  const [wx, wy] = await page.evaluate('replayApi.toScreen(10, 8)');
  const box = await (await page.$('#view')).boundingBox();
  await page.mouse.click(box.x + wx, box.y + wy);
  const details = await page.$eval('#details', (d) => d.textContent);
  check(/user id 9\b/.test(details) && /rect hx 0\.5 hy 4/.test(details) && /static/.test(details),
        `clicking the wall shows its details: ${JSON.stringify(details.split('\n').slice(0, 4))}`);

  // With the rectangles' layer off, the wall is neither drawn nor found.
  await page.click('#layer-kind2');
  await page.mouse.click(box.x + wx, box.y + wy);
  const hidden = await page.$eval('#details', (d) => d.textContent);
  check(hidden === 'No body there.', `with rects hidden, a click on the wall finds nothing: ${JSON.stringify(hidden)}`);

  // Events name bodies by their user ids: the bullet (7) meets the wall (9) at frame 1.
  const rows = await page.$$eval('#events div', (divs) => divs.map((d) => d.textContent));
  check(rows.some((r) => r.startsWith('frame 1: impact body 7 · body 9')),
        `the events list names the bodies by user id: ${JSON.stringify(rows.slice(0, 3))}`);

  // The layout fits the window: every control, the side panel and both plots lie within it, nothing
  // scrolls, and the view takes the room they leave.
  for (const [width, height] of [[1280, 800], [1920, 1080]]) {
    await page.setViewport({ width, height });
    // The page fits its canvases in its resize handler, which may run after setViewport returns.
    await page.waitForFunction(([w, h]) => {
      const view = document.getElementById('view');
      return view.width >= w - 400 && view.height >= h - 400;
    }, { timeout: 10000 }, [width, height]).catch(() => {});
    const layout = await page.evaluate(([w, h]) => {
      const shown = (el) => {
        const r = el.getBoundingClientRect();
        return r.left >= 0 && r.top >= 0 && r.right <= w && r.bottom <= h && r.width > 0 && r.height > 0;
      };
      const parts = [...document.querySelectorAll('header, aside, #controls > *, #plots canvas')];
      const view = document.getElementById('view');
      return {
        outside: parts.filter((el) => !shown(el)).map((el) => el.id || el.tagName),
        scroll: [document.documentElement.scrollWidth, document.documentElement.scrollHeight],
        view: [view.width, view.height],
      };
    }, [width, height]);
    check(layout.outside.length === 0 && layout.scroll[0] <= width && layout.scroll[1] <= height,
          `at ${width} x ${height} everything shows without scrolling (outside: ${layout.outside}; page ${layout.scroll})`);
    check(layout.view[0] >= width - 400 && layout.view[1] >= height - 400,
          `at ${width} x ${height} the view takes the room left: ${layout.view}`);
  }

  // The built-in scene's page: its size, and the time to draw a frame.
  const builtin = path.join(work, 'builtin.html');
  execFileSync(collide2d, ['run', '--html', builtin], quiet);
  const megabytes = statSync(builtin).size / 1e6;
  check(megabytes <= 25, `the built-in scene's page is ${megabytes.toFixed(1)} MB (at most 25)`);
  await page.goto(pathToFileURL(builtin).href);
  await page.waitForFunction('window.replayReady === true', { timeout: 180000 });
  check(await page.evaluate('replayApi.frames()') === 600, 'the built-in scene: 600 frames');
  const times = await page.evaluate(() => {
    const out = [];
    for (let f = 0; f < 600; f += 20) {
      const start = performance.now();
      replayApi.setFrame(f);
      out.push(performance.now() - start);
    }
    return out.sort((a, b) => a - b);
  });
  const size = await page.evaluate(() => `${canvas.width} x ${canvas.height}`);
  console.log(`median time to draw a frame of the built-in scene at ${size}: ${times[times.length >> 1].toFixed(1)} ms`);
} finally {
  await browser.close();
}
finish();
