// The live mode (live/, scripts/serve-live.mjs) in Debian's chromium: dragging the throw's
// velocity and the target redraws the trajectories with the WebAssembly module's numbers. The
// drawn line's vertices must equal, as floats, what the module computes in node for the velocity
// the page reports.
//
//   node test/live.test.mjs WASM_PACKAGE_DIR [SCREENSHOT.png]
import { existsSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { chromium } from 'playwright-core';

import { serveLive } from '../scripts/serve-live.mjs';

const [wasmPackage, screenshotPath] = process.argv.slice(2);
const executablePath = process.env.FORESIGHT_CHROMIUM || '/usr/bin/chromium';
if (!wasmPackage || !existsSync(join(wasmPackage, 'dist', 'foresight_core.mjs'))) {
    console.error('usage: node test/live.test.mjs WASM_PACKAGE_DIR [SCREENSHOT.png] (a built bindings/wasm package)');
    process.exit(2);
}
let failures = 0;
const fail = (text) => {
    ++failures;
    console.error(`FAIL live: ${text}`);
};

const { loadForesight } = await import(pathToFileURL(resolve(wasmPackage, 'index.mjs')).href);
const foresight = await loadForesight();
const world = foresight.createWorld()
    .addPlane({ normal: [0, 1, 0], distance: 0 })
    .addBox({ center: [0, 1.5, 10], halfExtents: [5, 1.5, 0.25] });
const HAND = [0, Math.fround(1.6), 0];
// The page's throw for a velocity, as the vertices it draws (float).
const expected = (velocity) => Array.from(new Float32Array(foresight.predictProjectile(HAND, velocity, 3,
    { world, settings: { restitution: 0.5, friction: 0.4, radius: 0.05 } }).trajectory.position));

function same(actual, wanted, what) {
    if (actual.length !== wanted.length) {
        fail(`${what}: ${actual.length / 3} points drawn, the module gives ${wanted.length / 3}`);
        return;
    }
    const i = actual.findIndex((v, k) => v !== wanted[k]);
    if (i >= 0) fail(`${what}: vertex value ${i} is ${actual[i]}, the module gives ${wanted[i]}`);
}

const { server, url } = await serveLive(wasmPackage);
const browser = await chromium.launch({
    executablePath,
    headless: true,
    args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist',
        '--enable-webgl', '--disable-dev-shm-usage'],
});
try {
    const page = await browser.newPage({ viewport: { width: 1200, height: 700 } });
    page.on('pageerror', (error) => fail(`page error: ${error.message}`));
    page.on('console', (message) => {
        if (message.type() === 'error') fail(`console error: ${message.text()}`);
    });
    await page.goto(url);
    await page.waitForFunction(() => window.foresightLive && window.foresightLive.ready, null, { timeout: 30000 });
    const hook = () => page.evaluate(() => JSON.parse(JSON.stringify(window.foresightLive)));

    const first = await hook();
    same(first.drawn, expected(first.velocity), 'the first throw');
    if (first.velocity[1] !== 4 || first.velocity[2] !== 12) fail(`the first throw is ${first.velocity}, not (0, 4, 12)`);

    // Drag the velocity: press in the view 3 m right of and 2 m above the hand (4 m/s per metre).
    const box = await page.locator('canvas').boundingBox();
    const { left, bottom, span } = first.view; // z from `left` across the width, y from `bottom` up
    const scale = box.width / span; // pixels per metre
    const at = (z, y) => [box.x + (z - left) * scale, box.y + box.height - (y - bottom) * scale];
    await page.mouse.move(...at(3, 1.6 + 2));
    await page.mouse.down();
    await page.mouse.move(...at(2.5, 1.6 + 2.5), { steps: 4 });
    await page.mouse.up();
    const dragged = await hook();
    const [, vy, vz] = dragged.velocity;
    if (!(Math.abs(vz - 10) < 0.2 && Math.abs(vy - 10) < 0.2)) { // a pixel is 30/1200 m: 0.1 m/s
        fail(`the drag set the velocity to (${vy}, ${vz}), not about (10, 10) m/s`);
    }
    same(dragged.drawn, expected(dragged.velocity), 'the dragged throw');
    if (dragged.drawn.length === first.drawn.length && dragged.drawn.every((v, k) => v === first.drawn[k])) {
        fail('the trajectory did not change with the velocity');
    }

    // The sliders and the hook do the same.
    await page.evaluate(() => window.foresightLive.setVelocity(6, 9));
    const set = await hook();
    same(set.drawn, expected([0, 6, 9]), 'the throw (0, 6, 9)');

    // Drag the target (right button): the aimed arc follows the module's low solution.
    await page.mouse.move(...at(18, 0));
    await page.mouse.down({ button: 'right' });
    await page.mouse.up({ button: 'right' });
    const aimed = await hook();
    if (Math.abs(aimed.target[2] - 18) > 0.1) fail(`the target is at z ${aimed.target[2]}, not about 18 m`);
    const low = foresight.aimProjectile({ from: HAND, speed: 15 }, { position: aimed.target })[0];
    if (!low || !aimed.aimed) {
        fail(`no aimed arc (the module: ${low ? 'a solution' : 'none'}, the page: ${aimed.aimed ? 'one' : 'none'})`);
    } else {
        same(aimed.aimed.positions, Array.from(foresight.predictProjectile(HAND, low.velocity, low.time).trajectory.position),
            'the aimed arc');
    }
    if (aimed.errors.length) fail(`errors: ${aimed.errors.join('; ')}`);
    if (screenshotPath) await page.screenshot({ path: screenshotPath });
} finally {
    await browser.close();
    server.close();
    world.delete();
}
if (failures) process.exit(1);
console.log('PASS live: the drawn trajectories are the module\'s, and follow the drags');
