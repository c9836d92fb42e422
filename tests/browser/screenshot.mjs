// The README's picture of the replay page: node screenshot.mjs PAGE.html OUT.png
// (scripts/screenshot.sh makes the page and calls this). Opens the page in Debian's chromium, goes
// to a frame, zooms in on the middle of the arena and takes a picture of the view and its side panel.
import { launch } from './harness.mjs';

const [page_path, out] = process.argv.slice(2);
const browser = await launch();
try {
  const page = await browser.newPage();
  await page.setViewport({ width: 1280, height: 800 });
  await page.goto(new URL(page_path, `file://${process.cwd()}/`).href);
  await page.waitForFunction('window.replayReady === true', { timeout: 180000 });
  const error = await page.evaluate('window.replayError');
  if (error) throw new Error(error);
  await page.evaluate(() => {
    replayApi.setFrame(Math.min(180, replayApi.frames() - 1));
    replayPage.view.scale *= 2.5;
    replayApi.draw();
  });
  await page.screenshot({ path: out, clip: { x: 0, y: 0, width: 1280, height: 800 } });
} finally {
  await browser.close();
}
