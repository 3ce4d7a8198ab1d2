// Every golden case rendered in the page by the WebAssembly renderer on Chromium's WebGL2 and
// compared with the desktop's golden image (golden_images/; the cases are read from
// tests/golden/CMakeLists.txt, one list for both). Chromium is Debian's (/usr/bin/chromium),
// headless, on SwiftShader (its CPU WebGL2); puppeteer-core drives it and downloads nothing.
//
// The limits are not the desktop's (one level, a few pixels beyond it): SwiftShader is another
// rasteriser and texture unit than llvmpipe, and two kinds of difference are expected, measured
// 2026-12-02 over the 18 cases the page renders (Chromium 156, SwiftShader):
//   - a pixel on a triangle's edge that one rasteriser covers and the other leaves to the next
//     triangle or the background (their tie rules differ): a whole surface colour apart, up to
//     183 levels, on isolated pixels, at most 0.110 % of a case's (universe/weight);
//   - filtered reads of 8-bit textures (mipmapped albedo textures, the field map): SwiftShader's
//     filter weights are coarser; up to 3 levels, a mean of at most 0.76 levels (default).
// So a case passes when at most 0.25 % of its pixels (41 of 128x128) are more than 4 levels off
// and the mean difference is at most 1 level. A wrong image fails both: the negative control at
// the end (the default scene's probe 2 mm aside and 0.5 mm higher, its pseudo-shadow moved and
// lighter) must be refused, or the comparison could not tell.
//   node web/tests/golden_in_browser.mjs PAGE_DIR [OUT_DIR]
// PAGE_DIR is web/build_page.sh's output. Writes OUT_DIR/<case>.png: the desktop golden, the
// page's render and their difference (x10) side by side, and OUT_DIR/page.png, a screenshot of
// the page showing the default scene; prints one line per case. Exit 0
// when every case passes or is skipped for a reason the line gives (a scene with a mesh file:
// assimp has no WebAssembly build); 1 otherwise.
import fs from 'node:fs';
import http from 'node:http';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { PNG } from 'pngjs';
import puppeteer from 'puppeteer-core';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const [pageDir, outDir = path.join(root, 'build/web_golden_out')] = process.argv.slice(2);
if (!pageDir || !fs.existsSync(path.join(pageDir, 'pseudoshadow.wasm'))) {
  console.error('usage: node web/tests/golden_in_browser.mjs PAGE_DIR [OUT_DIR]  (PAGE_DIR from web/build_page.sh)');
  process.exit(2);
}
const browserPath = process.env.PSEUDOSHADOW_CHROMIUM || '/usr/bin/chromium';

// The golden cases: "name|failpercent|hardfail|reason[|extra render arguments]" lines of
// PS_GOLDEN_CASES, the hard limits given as ${PS_GOLDEN_HARDFAIL_N} (N levels).
function goldenCases() {
  const text = fs.readFileSync(path.join(root, 'tests/golden/CMakeLists.txt'), 'utf8');
  const list = text.slice(text.indexOf('set(PS_GOLDEN_CASES'));
  const cases = [];
  for (const m of list.matchAll(/^\s*"([^"|]+)\|([\d.]+)\|\$\{PS_GOLDEN_HARDFAIL_(\d+)\}\|([^|"]*)(?:\|([^"]*))?"/gm)) {
    const [, name, failPercent, hardLevels, reason, extra = ''] = m;
    const [scene, variant] = name.split('@');
    const overrides = ['render.size=[128,128]', 'render.frames=2'];
    const args = extra.trim().split(/\s+/).filter(Boolean);
    for (let i = 0; i < args.length; i += 2) {
      if (args[i] !== '--probe') throw new Error(`golden case ${name}: no page equivalent for ${args[i]}`);
      overrides.push(`probe.position=[${args[i + 1]}]`);
    }
    const file = (variant ? `${scene}_${variant}` : scene).replace('/', '_');
    cases.push({ name, scene: `/share/pseudoshadow/scenes/${scene}.toml`, overrides, golden: path.join(root, 'golden_images', `${file}.png`),
                 failPercent: Number(failPercent), hardLevels: Number(hardLevels), reason });
  }
  if (cases.length === 0) throw new Error('no golden cases found in tests/golden/CMakeLists.txt');
  return cases;
}

const kLevelsOff = 4;        // a pixel "off" differs by more than this many levels in a channel
const kOffPercent = 0.25;    // the share of pixels off a case allows
const kMeanLevels = 1.0;     // the mean difference (largest channel per pixel) a case allows

function serve(dir) {
  const types = { '.html': 'text/html', '.js': 'text/javascript', '.wasm': 'application/wasm', '.data': 'application/octet-stream' };
  const server = http.createServer((req, res) => {
    const file = path.join(dir, path.normalize(decodeURIComponent(new URL(req.url, 'http://x').pathname)));
    if (!file.startsWith(dir) || !fs.existsSync(file) || fs.statSync(file).isDirectory()) {
      res.writeHead(404).end();
      return;
    }
    res.writeHead(200, { 'Content-Type': types[path.extname(file)] || 'application/octet-stream' });
    fs.createReadStream(file).pipe(res);
  });
  return new Promise((resolve) => server.listen(0, '127.0.0.1', () => resolve(server)));
}

// Levels per channel (RGB) between two RGBA images of one size.
function compare(a, b) {
  let maxLevels = 0, off = 0, sum = 0;
  const n = a.width * a.height;
  const diff = Buffer.alloc(n * 4);
  for (let p = 0; p < n; ++p) {
    let worst = 0;
    for (let c = 0; c < 3; ++c) {
      const d = Math.abs(a.data[p * 4 + c] - b.data[p * 4 + c]);
      worst = Math.max(worst, d);
      diff[p * 4 + c] = Math.min(255, d * 10);
    }
    diff[p * 4 + 3] = 255;
    maxLevels = Math.max(maxLevels, worst);
    if (worst > kLevelsOff) ++off;
    sum += worst;
  }
  const offPercent = (100 * off) / n, meanLevels = sum / n;
  return { maxLevels, offPercent, meanLevels, passed: offPercent <= kOffPercent && meanLevels <= kMeanLevels, diff };
}

function sideBySide(images, width, height) {
  const png = new PNG({ width: width * images.length + 4 * (images.length - 1), height });
  png.data.fill(255);
  images.forEach((data, k) => {
    for (let y = 0; y < height; ++y)
      data.copy(png.data, (y * png.width + k * (width + 4)) * 4, y * width * 4, (y + 1) * width * 4);
  });
  return PNG.sync.write(png);
}

const server = await serve(path.resolve(pageDir));
const browser = await puppeteer.launch({
  executablePath: browserPath,
  headless: true,
  args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--force-color-profile=srgb'],
});
let failed = 0;
try {
  const page = await browser.newPage();
  const consoleLines = [];
  page.on('console', (m) => consoleLines.push(m.text()));
  await page.goto(`http://127.0.0.1:${server.address().port}/index.html?test`);
  const version = await page.evaluate(() => window.pseudoshadow.ready);
  const browserVersion = await browser.version();
  console.log(`page: ${browserVersion}, ${version}`);
  fs.mkdirSync(outDir, { recursive: true });
  const render = (c) => page.evaluate((scene, overrides) => {
    try {
      const im = window.pseudoshadow.render(scene, overrides);
      return { width: im.width, height: im.height, rgba: Array.from(im.rgba) };
    } catch (e) {
      return { error: e.message };
    }
  }, c.scene, c.overrides);
  // One case: the render against its golden; the comparison, or null when it did not render.
  const runCase = async (c) => {
    const t0 = Date.now();
    const got = await render(c);
    const ms = Date.now() - t0;
    if (got.error) {
      if (/'mesh_file'|no mesh files/.test(got.error)) {
        console.log(`skip ${c.name}: a mesh file, and assimp has no WebAssembly build (${got.error})`);
        return { skipped: true };
      }
      console.log(`FAIL ${c.name}: ${got.error}`);
      return null;
    }
    const golden = PNG.sync.read(fs.readFileSync(c.golden), { colorType: 6 });  // as RGBA
    const mine = { width: got.width, height: got.height, data: Buffer.from(got.rgba) };
    if (mine.width !== golden.width || mine.height !== golden.height) {
      console.log(`FAIL ${c.name}: ${mine.width}x${mine.height}, the golden is ${golden.width}x${golden.height}`);
      return null;
    }
    const r = compare(golden, mine);
    fs.writeFileSync(path.join(outDir, `${c.name.replace(/[/@]/g, '_')}.png`),
                     sideBySide([golden.data, mine.data, r.diff], golden.width, golden.height));
    r.line = `${c.name}: ${r.offPercent.toFixed(3)} % of pixels more than ${kLevelsOff} levels off (limit ${kOffPercent} %), ` +
             `mean ${r.meanLevels.toFixed(3)} levels (limit ${kMeanLevels}), largest ${r.maxLevels}; ${ms} ms`;
    return r;
  };
  const cases = goldenCases();
  let passed = 0, skipped = 0;
  for (const c of cases) {
    const r = await runCase(c);
    if (r && r.skipped) {
      ++skipped;
      continue;
    }
    if (r) console.log(`${r.passed ? 'ok  ' : 'FAIL'} ${r.line}`);
    if (r && r.passed) ++passed;
    else ++failed;
  }
  console.log(`golden_in_browser: ${passed} of ${cases.length} cases within the limits, ${skipped} skipped (reasons above)`);
  // The negative control: a wrong image must be refused.
  const base = cases.find((c) => c.name === 'default');
  const control = { ...base, name: 'control (default, probe moved)', overrides: [...base.overrides, 'probe.position=[2,0,7.5]'] };
  const r = await runCase(control);
  if (!r || r.skipped || r.passed) {
    console.log(`FAIL ${r && r.line ? r.line : control.name}: a wrong image was not refused`);
    ++failed;
  } else {
    console.log(`ok   refused as it should be: ${r.line}`);
  }
  // The page as a person sees it: the default scene at 256x256 on its canvas.
  await page.evaluate(() => {
    window.pseudoshadow.show(window.pseudoshadow.render('/share/pseudoshadow/scenes/default.toml', ['render.size=[256,256]']));
  });
  await page.screenshot({ path: path.join(outDir, 'page.png') });
  console.log(`golden_in_browser: the side-by-side images (golden, page, difference x10) and page.png are in ${outDir}`);
  if (failed > 0 && consoleLines.length > 0) console.log(`the page's console:\n  ${consoleLines.slice(-20).join('\n  ')}`);
} finally {
  await browser.close();
  server.close();
}
console.log(failed === 0 ? 'golden_in_browser: passed' : `golden_in_browser: ${failed} failed`);
process.exit(failed === 0 ? 0 : 1);
