// What the browser tests share: Debian's chromium launched headless through puppeteer-core, or a skip
// that says which of the two is missing (exit 77, which ctest reports as skipped; scripts/deps.sh --test
// installs both), and a tally of checks.
import { existsSync } from 'node:fs';

const chromium = process.env.CHROMIUM || '/usr/bin/chromium';

export function skip(why) {
  console.log(`SKIPPED: ${why} (bash scripts/deps.sh --test installs it)`);
  process.exit(77);
}

export async function launch() {
  let puppeteer;
  try {
    puppeteer = (await import('puppeteer-core')).default;
  } catch {
    skip('puppeteer-core is not installed in tests/browser/node_modules');
  }
  if (!existsSync(chromium)) skip(`no browser at ${chromium}`);
  return puppeteer.launch({ executablePath: chromium, headless: true,
                            args: ['--no-sandbox', '--allow-file-access-from-files'] });
}

let failures = 0;

export function check(ok, what) {
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`);
  if (!ok) ++failures;
}

// Exits 1 after the checks where any failed.
export function finish() {
  if (failures > 0) {
    console.log(`${failures} check(s) failed`);
    process.exit(1);
  }
}
