// CTest viewer.page_in_chromium: the page `mink view` writes, opened for real in headless Chromium.
//
//   node viewer_test.mjs <mink> <scene.jsonl> <work dir>
//
// Writes the page of the scene, opens it from its file in Chromium (driven over the DevTools
// protocol through --remote-debugging-pipe, see cdp.mjs) and fails when the page's console shows an
// error or an exception, when the answer list does not hold one entry per query line with the
// answer's id and status, or when screenshots (decoded by png.mjs) show a blank picture, a shape
// missing at its projected centre, or a manifold point, witness point or normal missing where the
// answer puts it. Exit 0: passed; 1: failed; 77: skipped (no Chromium here). docs/viewer.md.
import { spawnSync } from 'node:child_process';
import {
  accessSync, constants, mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync,
} from 'node:fs';
import { delimiter, join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';

import { launchChromium } from './cdp.mjs';
import { decodePng } from './png.mjs';

const TIMEOUT_MS = 60000;  // the whole test, Chromium's start included
const WIDTH = 1000;
const HEIGHT = 700;
// The page's colours (viewer/viewer.js).
const COLOR = {
  a: [0xd8, 0x40, 0x2f],
  b: [0x2f, 0x6f, 0xd8],
  pointA: [0x7a, 0x12, 0x08],
  pointB: [0x0b, 0x2f, 0x73],
  normal: [0x13, 0xa3, 0x3a],
  manifold: [0xff, 0x9a, 0x00],
};

const [minkExe, scenePath, workDirArg] = process.argv.slice(2);
if (!workDirArg) {
  console.error('usage: node viewer_test.mjs <mink> <scene.jsonl> <work dir>');
  process.exit(2);
}
const started = Date.now();
const elapsed = () => `${((Date.now() - started) / 1000).toFixed(1)} s`;

// ---------------------------------------------------------------------------------------------
// Chromium: $MINK_CHROMIUM, else the first of the usual names on PATH.

function findChromium() {
  if (process.env.MINK_CHROMIUM) return process.env.MINK_CHROMIUM;
  const names = ['chromium', 'chromium-browser', 'google-chrome', 'google-chrome-stable'];
  for (const dir of (process.env.PATH || '/usr/bin:/bin').split(delimiter)) {
    for (const name of names) {
      try {
        accessSync(join(dir, name), constants.X_OK);
        return join(dir, name);
      } catch {
        // not here
      }
    }
  }
  return null;
}

const chromiumPath = findChromium();
if (!chromiumPath) {
  console.log('viewer test skipped: chromium not installed (apt-get install chromium; ' +
              'scripts/test installs it on Debian 12), or set MINK_CHROMIUM to its path');
  process.exit(77);
}

// ---------------------------------------------------------------------------------------------
// The page and the answers it must show.

const workDir = resolve(workDirArg);
mkdirSync(workDir, { recursive: true });
const pagePath = join(workDir, 'viewer_test.html');
const screenshotPath = (name) => join(workDir, `viewer_test_${name}.png`);

function run(args) {
  const result = spawnSync(minkExe, args, { encoding: 'utf8', maxBuffer: 64 << 20 });
  if (result.error) throw new Error(`cannot run ${minkExe}: ${result.error.message}`);
  if (result.status !== 0)
    throw new Error(`mink ${args.join(' ')} exited with ${result.status}:\n${result.stderr}`);
  return result.stdout;
}

const failures = [];
const fail = (message) => failures.push(message);
const check = (ok, message) => {
  if (!ok) fail(message);
  return ok;
};

const queries = readFileSync(scenePath, 'utf8').split('\n').filter((l) => l.trim() !== '')
  .map((l) => JSON.parse(l));
run(['view', scenePath, '-o', pagePath]);
const answers = run(['query', scenePath]).split('\n').filter((l) => l !== '')
  .map((l) => JSON.parse(l));
if (answers.length !== queries.length) {
  console.error(`mink query gave ${answers.length} answers to ${queries.length} queries`);
  process.exit(1);
}
// The scene must exercise what is checked below: a manifold, a separated pair, an error line.
if (!answers.some((a) => a.manifold && a.manifold.points.length > 0) ||
    !answers.some((a) => a.status === 'ok' && a.intersect === false) ||
    !answers.some((a) => a.status === 'error')) {
  console.error(`${scenePath} must hold a manifold, a separated pair and a malformed line`);
  process.exit(1);
}

// ---------------------------------------------------------------------------------------------
// Pixels.

const distance = (p, color) => Math.max(...color.map((c, k) => Math.abs(p[k] - c)));

function pixelsAround(image, [cx, cy], half) {
  const out = [];
  for (let y = Math.round(cy) - half; y <= Math.round(cy) + half; ++y)
    for (let x = Math.round(cx) - half; x <= Math.round(cx) + half; ++x)
      if (x >= 0 && y >= 0 && x < image.width && y < image.height) {
        const o = (y * image.width + x) * 4;
        out.push([image.rgba[o], image.rgba[o + 1], image.rgba[o + 2]]);
      }
  return out;
}

const near = (color, tolerance) => (p) => distance(p, color) <= tolerance;
const count = (pixels, predicate) => pixels.filter(predicate).length;
// A shape's own hue: the page draws a red-ish, b blue-ish (translucent, lit).
const hue = { a: (p) => p[0] - p[2] > 30, b: (p) => p[2] - p[0] > 30 };

// ---------------------------------------------------------------------------------------------
// The browser.

const profile = mkdtempSync(join(workDir, 'chromium-profile-'));
const browser = launchChromium(chromiumPath, [
  '--headless=new', '--no-sandbox', '--disable-gpu', '--use-angle=swiftshader',
  '--enable-unsafe-swiftshader', '--disable-dev-shm-usage', '--no-first-run',
  '--no-default-browser-check', '--disable-extensions', '--disable-background-networking',
  '--disable-component-update', '--mute-audio', '--hide-scrollbars', `--user-data-dir=${profile}`,
  `--window-size=${WIDTH},${HEIGHT}`, 'about:blank',
]);

let finished = false;
function finish(code, message) {
  if (finished) return;
  finished = true;
  if (message) console.log(message);
  browser.kill();
  try {
    rmSync(profile, { recursive: true, force: true });
  } catch {
    // best effort
  }
  process.exit(code);
}
const timer = setTimeout(() => {
  console.log(`--- chromium's output (end) ---\n${browser.log().slice(-4000)}`);
  finish(1, `FAILED: viewer test timed out after ${TIMEOUT_MS / 1000} s`);
}, TIMEOUT_MS);
process.on('SIGINT', () => finish(1, 'interrupted'));
process.on('SIGTERM', () => finish(1, 'terminated'));

const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

async function main() {
  // The page that Chromium opened with about:blank, attached in flat mode (one pipe, sessions).
  const { targetInfos } = await browser.send('Target.getTargets');
  let page = targetInfos.find((t) => t.type === 'page');
  if (!page) page = await browser.send('Target.createTarget', { url: 'about:blank' });
  const { sessionId } = await browser.send('Target.attachToTarget',
                                           { targetId: page.targetId, flatten: true });
  const send = (method, params) => browser.send(method, params, sessionId);

  const consoleErrors = [];
  const describe = (args) => (args || []).map((a) => a.value !== undefined ? String(a.value)
    : a.description || a.type).join(' ');
  browser.onEvent(({ method, params, sessionId: from }) => {
    if (from !== sessionId) return;
    const consoleError = params && (params.type === 'error' || params.type === 'assert');
    if (method === 'Runtime.consoleAPICalled' && consoleError)
      consoleErrors.push(`console.${params.type}: ${describe(params.args)}`);
    else if (method === 'Runtime.exceptionThrown') {
      const d = params.exceptionDetails;
      consoleErrors.push(`exception: ${d.exception ? d.exception.description : d.text}` +
                         ` (${d.url || 'page'}:${d.lineNumber + 1})`);
    } else if (method === 'Log.entryAdded' && params.entry.level === 'error') {
      consoleErrors.push(`log (${params.entry.source}): ${params.entry.text}`);
    }
  });
  await send('Runtime.enable');
  await send('Log.enable');
  await send('Page.enable');
  await send('Emulation.setDeviceMetricsOverride',
             { width: WIDTH, height: HEIGHT, deviceScaleFactor: 1, mobile: false });

  const evaluate = async (expression) => {
    const { result, exceptionDetails } =
      await send('Runtime.evaluate', { expression, returnByValue: true, awaitPromise: true });
    if (exceptionDetails)
      throw new Error(`evaluating ${expression.slice(0, 60)}...: ${exceptionDetails.exception
        ? exceptionDetails.exception.description : exceptionDetails.text}`);
    return result.value;
  };
  // Two animation frames: whatever was drawn has reached the screen.
  const settle = () =>
    evaluate('new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)))');
  const screenshot = async (name) => {
    const { data } = await send('Page.captureScreenshot', { format: 'png' });
    const png = Buffer.from(data, 'base64');
    writeFileSync(screenshotPath(name), png);
    const image = decodePng(png);
    check(image.width === WIDTH && image.height === HEIGHT,
          `screenshot ${name} is ${image.width}x${image.height}, not ${WIDTH}x${HEIGHT}`);
    return image;
  };

  const url = pathToFileURL(pagePath).href;
  const navigation = await send('Page.navigate', { url });
  if (navigation.errorText) throw new Error(`cannot open ${url}: ${navigation.errorText}`);
  // The page sets window.minkView once it has drawn its first picture.
  for (;;) {
    if (await evaluate('!!(window.minkView && window.minkView.ready)')) break;
    if (consoleErrors.length > 0) break;  // reported below; the page will not become ready
    await sleep(100);
  }
  console.log(`page ready after ${elapsed()}`);
  if (consoleErrors.length > 0) return consoleErrors.forEach((e) => fail(`page console: ${e}`));
  await settle();

  // ----- the answer list: one entry per query line, with the answer's id and status
  const view = await evaluate(`(() => {
    const v = window.minkView;
    const canvas = document.querySelector('#view canvas').getBoundingClientRect();
    return {
      items: v.items, errors: v.errors, mode: v.mode(), background: v.background,
      canvas: [canvas.left, canvas.top, canvas.width, canvas.height],
      summary: document.getElementById('summary').textContent,
      entries: [...document.querySelectorAll('#answers li')].map((li) => {
        const rows = [...li.querySelectorAll('tr')];
        const row = rows.find((tr) => tr.cells[0].textContent === 'status');
        return {
          error: li.classList.contains('error'),
          id: li.querySelector('.id').textContent,
          status: row ? row.cells[1].textContent : null,
          message: (li.querySelector('.message') || {}).textContent || null,
          manifold: rows.filter((tr) => /^ +[0-9]+$/.test(tr.cells[0].textContent)).length,
        };
      }),
    };
  })()`);
  const errorCount = answers.filter((a) => a.status === 'error').length;
  check(view.items === answers.length && view.errors === errorCount,
        `minkView counts ${view.items} queries, ${view.errors} errors; ` +
        `expected ${answers.length}, ${errorCount}`);
  check(view.summary.startsWith(`${answers.length} queries`),
        `summary "${view.summary}" does not start with "${answers.length} queries"`);
  check(view.entries.length === answers.length,
        `answer list has ${view.entries.length} entries for ${answers.length} query lines`);
  answers.forEach((a, i) => {
    const e = view.entries[i];
    if (!e) return;
    const what = `answer list entry ${i + 1}`;
    check(e.id === JSON.stringify(a.id), `${what}: id ${e.id}, expected ${JSON.stringify(a.id)}`);
    if (a.status === 'error') {
      check(e.error && e.message === `error: ${a.error}`,
            `${what}: expected an error entry "error: ${a.error}", got ${JSON.stringify(e)}`);
    } else {
      check(!e.error && e.status === a.status,
            `${what}: expected status ${a.status}, got ${JSON.stringify(e)}`);
      const points = a.manifold ? a.manifold.points.length : 0;
      check(e.manifold === points,
            `${what}: lists ${e.manifold} manifold points, expected ${points}`);
    }
  });
  check(view.mode === 'all', `the scene should open showing all queries, mode is ${view.mode}`);
  const background = [1, 3, 5].map((k) => parseInt(view.background.slice(k, k + 2), 16));

  // ----- all queries at once: the picture is not blank and every shape is where it should be
  const drawn = answers.map((a, i) => ({ a, q: queries[i], index: i }))
    .filter((x) => x.a.status !== 'error');
  const project = (points) =>
    evaluate(`${JSON.stringify(points)}.map((p) => window.minkView.project(p))`);
  const shapeChecks = async (image, items, label) => {
    for (const { q, index } of items) {
      const centres = await project([(q.pa && q.pa.t) || [0, 0, 0], (q.pb && q.pb.t) || [0, 0, 0]]);
      ['a', 'b'].forEach((which, k) => {
        const patch = pixelsAround(image, centres[k], 5);
        const off = count(patch, (p) => distance(p, background) > 12);
        const own = count(patch, hue[which]);
        check(off >= 0.8 * patch.length && own >= 0.3 * patch.length,
              `${label}: query ${index + 1} shape ${which} not drawn at its centre ` +
              `(${centres[k].map(Math.round)}): ${off}/${patch.length} pixels off the ` +
              'background, ' +
              `${own} of its colour`);
      });
    }
  };
  let image = await screenshot('all');
  {
    const [left, top, width, height] = view.canvas.map(Math.round);
    let off = 0;
    for (let y = top; y < top + height; ++y)
      for (let x = left; x < left + width; ++x) {
        const o = (y * image.width + x) * 4;
        if (distance([image.rgba[o], image.rgba[o + 1], image.rgba[o + 2]], background) > 12) ++off;
      }
    const fraction = off / (width * height);
    console.log(`all queries: ${(100 * fraction).toFixed(1)}% of the picture is not background`);
    check(fraction > 0.03, `the picture is blank: only ${(100 * fraction).toFixed(2)}% of it ` +
                           `differs from the background ${view.background}`);
    const corner = pixelsAround(image, [left + 4, top + 4], 2);
    check(count(corner, (p) => distance(p, background) <= 2) === corner.length,
          `the picture's corner is not the background colour ${view.background}`);
  }
  await shapeChecks(image, drawn, 'all queries');

  // ----- each drawable query alone (a click on its entry): shapes, witness points, normal,
  // manifold points, each where the answer puts it
  for (const { a, q, index } of drawn) {
    await evaluate(`document.querySelectorAll('#answers li')[${index}].click()`);
    await settle();
    const state = await evaluate(
      `[window.minkView.mode(), window.minkView.current(), window.minkView.scale(${index})]`);
    const label = `query ${index + 1} alone`;
    const shown = state[0] === 'one' && state[1] === index;
    if (!check(shown, `${label}: a click on its entry shows ${state}`))
      continue;
    const scale = state[2];
    image = await screenshot(`query${index + 1}`);
    await shapeChecks(image, [{ q, index }], label);
    const marks = [];
    if (a.manifold) {
      for (const p of a.manifold.points)
        marks.push(['manifold point', p.position, COLOR.manifold, 8]);
    } else {
      marks.push(['point_a', a.point_a, COLOR.pointA, 4], ['point_b', a.point_b, COLOR.pointB, 4]);
      // The normal's arrow head: from 0.33 to 0.45 of the scale along the normal from point_a.
      const at = a.point_a.map((x, k) => x + 0.36 * scale * a.normal[k]);
      marks.push(['normal arrow head', at, COLOR.normal, 3]);
    }
    const where = await project(marks.map((m) => m[1]));
    marks.forEach(([name, , color, least], k) => {
      const patch = pixelsAround(image, where[k], 4);
      const hits = count(patch, near(color, 40));
      check(hits >= least, `${label}: ${name} not drawn at (${where[k].map(Math.round)}): ` +
                           `${hits} of ${patch.length} pixels near its colour, expected ${least}+`);
    });
  }
  for (const e of consoleErrors) fail(`page console: ${e}`);
}

main().then(() => {
  clearTimeout(timer);
  if (failures.length > 0)
    finish(1, `FAILED (${elapsed()}), screenshots in ${workDir}:\n  ` + failures.join('\n  '));
  else
    finish(0, `viewer test passed in ${elapsed()} (${chromiumPath}; screenshots in ${workDir})`);
}, (error) => {
  clearTimeout(timer);
  console.log(`--- chromium's output (end) ---\n${browser.log().slice(-4000)}`);
  finish(1, `FAILED (${elapsed()}): ${error.stack || error}`);
});
