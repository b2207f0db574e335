// The package in Chromium: a page served over http imports index.mjs (which embeds the wasm)
// and runs predictions; they must equal node's to the bit. Needs playwright-core (the viewer's,
// FORESIGHT_PLAYWRIGHT: a node_modules directory holding it) and Debian's chromium
// (FORESIGHT_CHROMIUM, default /usr/bin/chromium); skipped without them.
//
//   FORESIGHT_PLAYWRIGHT=../../viewer/node_modules node --test test/browser.test.mjs

import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createServer } from 'node:http';
import { existsSync, readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { extname, join, normalize, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

import { loadForesight } from '../index.mjs';

const root = fileURLToPath(new URL('..', import.meta.url));
const executablePath = process.env.FORESIGHT_CHROMIUM || '/usr/bin/chromium';
const modules = process.env.FORESIGHT_PLAYWRIGHT;
const missing = !modules ? 'FORESIGHT_PLAYWRIGHT not set'
    : !existsSync(join(modules, 'playwright-core')) ? `no playwright-core in ${modules}`
        : !existsSync(executablePath) ? `no browser at ${executablePath}` : false;

// The computation both sides run: a page gets it as text.
async function scenario(load) {
    const fs = await load();
    const world = fs.createWorld().addPlane({ normal: [0, 1, 0], distance: 0 })
        .addBox({ center: [0, 1.5, 10], halfExtents: [5, 1.5, 0.25] });
    const out = [];
    for (const method of ['exact', 'stepped', 'engine']) {
        const r = fs.predictProjectile([0, 1.6, 0], [0, 4, 12], 3, { world, settings: { method, radius: 0.05, friction: 0.4 } });
        out.push([r.position, r.velocity, r.bounces, Array.from(r.trajectory.position)]);
    }
    world.delete();
    out.push(fs.predictVehicleExact({ position: [0, 0, 0], velocity: [0, 0, 10], angularVelocity: [0, 0.5, 0] }, 2));
    out.push(fs.aimProjectile({ from: [0, 1.5, 0], speed: 25 }, { position: [30, 0, 40], velocity: [-3, 0, 1] }));
    try {
        fs.predictLinear({ position: [0, 0, 0], velocity: [1, 0, 0] }, -1);
    } catch (error) {
        out.push(`${error.name}: ${error.message}`);
    }
    return out;
}

test('the module loads in Chromium and computes what it computes in node', { skip: missing }, async () => {
    const server = createServer((request, response) => {
        const path = normalize(join(root, decodeURIComponent(new URL(request.url, 'http://x').pathname)));
        if (request.url === '/') {
            response.writeHead(200, { 'content-type': 'text/html' });
            response.end(`<!doctype html><script type="module">
                import { loadForesight } from '/index.mjs';
                const scenario = ${scenario.toString()};
                scenario(loadForesight).then((r) => { window.result = JSON.stringify(r); },
                    (e) => { window.result = 'failed: ' + e; });
            </script>`);
        } else if (path.startsWith(resolve(root)) && existsSync(path)) {
            response.writeHead(200, { 'content-type': extname(path) === '.mjs' ? 'text/javascript' : 'text/plain' });
            response.end(readFileSync(path));
        } else {
            response.writeHead(404);
            response.end();
        }
    });
    await new Promise((done) => server.listen(0, '127.0.0.1', done));
    const { chromium } = createRequire(join(resolve(modules), 'x.js'))('playwright-core');
    const browser = await chromium.launch({ executablePath, headless: true, args: ['--no-sandbox', '--disable-dev-shm-usage'] });
    try {
        const page = await browser.newPage();
        const errors = [];
        page.on('pageerror', (error) => errors.push(error.message));
        await page.goto(`http://127.0.0.1:${server.address().port}/`);
        await page.waitForFunction(() => window.result !== undefined, null, { timeout: 30000 });
        const inBrowser = await page.evaluate(() => window.result);
        assert.deepEqual(errors, []);
        assert.equal(inBrowser, JSON.stringify(await scenario(loadForesight)));
        assert.match(inBrowser, /ForesightError: predictLinear: time must be >= 0/);
    } finally {
        await browser.close();
        server.close();
    }
});
