// Opens a `woven share` page in headless Chromium (Debian's), from disk with the network off,
// waits for <model-viewer>'s load event and a few frames, and prints one JSON line: whether it
// loaded, the console errors and uncaught exceptions, the mean colour and coverage of
// model-viewer's own frame, and the mean colour of the poster (woven's render of the same view);
// with FRAME.png, model-viewer's frame is also written there, for the test to measure.
// Usage: node share_page_check.js PAGE/index.html CHROMIUM [FRAME.png]   (puppeteer-core drives it)
const fs = require('fs');
const path = require('path');
const puppeteer = require('puppeteer-core');

(async () => {
  const [page_, chromium, framePng] = process.argv.slice(2);
  const browser = await puppeteer.launch({
    executablePath: chromium,
    headless: true,
    args: ['--no-sandbox', '--enable-unsafe-swiftshader', '--use-angle=swiftshader', '--window-size=640,480'],
  });
  const result = { loaded: false, errors: [] };
  try {
    const page = await browser.newPage();
    await page.setViewport({ width: 640, height: 480 });
    await page.setOfflineMode(true);
    page.on('console', (m) => { if (m.type() === 'error') result.errors.push(m.text()); });
    page.on('pageerror', (e) => result.errors.push(String(e)));
    page.on('requestfailed', (r) => result.errors.push('request failed: ' + r.url().slice(0, 80)));
    await page.goto('file://' + path.resolve(page_), { waitUntil: 'load' });
    result.loaded = await page.evaluate(() => new Promise((resolve) => {
      const mv = document.getElementById('cloth');
      if (mv.loaded) return resolve(true);
      mv.addEventListener('load', () => resolve(true));
      mv.addEventListener('error', () => resolve(false));
      setTimeout(() => resolve(false), 60000);
    }));
    // Mean colour of an image drawn into a canvas, over its opaque pixels, and the opaque share.
    // The poster as a data URI: a file:// image would taint the canvas that measures it.
    const poster = 'data:image/png;base64,' + fs.readFileSync(path.join(path.dirname(page_), 'poster.png')).toString('base64');
    const stats = await page.evaluate(async (poster) => {
      const mean = async (url) => {
        const img = new Image();
        img.src = url;
        await img.decode();
        const c = document.createElement('canvas');
        c.width = img.naturalWidth; c.height = img.naturalHeight;
        const g = c.getContext('2d');
        g.drawImage(img, 0, 0);
        const d = g.getImageData(0, 0, c.width, c.height).data;
        let r = 0, gr = 0, b = 0, n = 0;
        for (let i = 0; i < d.length; i += 4) if (d[i + 3] > 127) { r += d[i]; gr += d[i + 1]; b += d[i + 2]; n++; }
        return { mean: n ? [r / n, gr / n, b / n] : [0, 0, 0], coverage: n / (d.length / 4) };
      };
      const mv = document.getElementById('cloth');
      mv.autoRotate = false;
      mv.resetTurntableRotation(0);
      mv.jumpCameraToGoal();
      await new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
      const frame = mv.toDataURL('image/png');
      return { frame: await mean(frame), poster: await mean(poster), png: frame };
    }, poster);
    if (framePng) fs.writeFileSync(framePng, Buffer.from(stats.png.split(',')[1], 'base64'));
    delete stats.png;
    Object.assign(result, stats);
  } catch (e) {
    result.errors.push('check: ' + String(e));
  }
  await browser.close();
  console.log(JSON.stringify(result));
})();
