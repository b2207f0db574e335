#!/usr/bin/env node
// viewer.test.mjs PAGE.html [SCREENSHOT.png] [--expect-message]
//
// Opens a foresight viewer page in Debian's chromium (playwright-core; no browser download) and
// checks it against the picture document embedded in it:
// - no console errors, no page errors, nothing loaded from the network;
// - window.foresightViewer.ready, and its counts equal those computed here from the document;
// - projectiles: setTime(t_k) puts positionOf(id) on path point k (1e-6 m), and between two
//   points of free flight on the parabola p + v dt + g dt^2 / 2; vehicles and samples: on their
//   samples and on the straight line between two; after its end time an object stays at its end;
// - hovering a path point shows its time in the tooltip;
// - the WebGL canvas is not blank (many distinct colours); optionally saves a screenshot.
// A page whose document is not JSON (or with --expect-message, one that breaks the contract)
// must show the viewer's message instead, with no exception.
// Exit status 0 when every check passes, 1 otherwise. FORESIGHT_CHROMIUM overrides the browser.
import { existsSync, readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { chromium } from 'playwright-core';

const args = process.argv.slice(2);
const expectMessageFlag = args.includes('--expect-message');
const [pagePath, screenshotPath] = args.filter((a) => !a.startsWith('--'));
if (!pagePath) {
    console.error('usage: node test/viewer.test.mjs PAGE.html [SCREENSHOT.png] [--expect-message]');
    process.exit(2);
}
const executablePath = process.env.FORESIGHT_CHROMIUM || '/usr/bin/chromium';
const POSITION_TOLERANCE = 1e-6; // [m] the viewer computes in doubles: rounding is ~1e-15 m
const failures = [];
const fail = (message) => failures.push(message);
const name = pagePath;

function finish() {
    if (failures.length) {
        console.error(`FAIL ${name}`);
        for (const message of failures) console.error(`  - ${message}`);
        process.exit(1);
    }
    console.log(`ok   ${name}`);
    process.exit(0);
}

// The embedded document, read here independently of the viewer.
const html = readFileSync(pagePath, 'utf8');
const match = html.match(/<script type="application\/json" id="foresight-data">([\s\S]*?)<\/script>/);
let doc = null;
if (match) {
    try {
        doc = JSON.parse(match[1].replaceAll('<\\/', '</'));
    } catch {
        doc = null;
    }
}
const expectMessage = expectMessageFlag || doc === null;

if (!existsSync(executablePath)) {
    console.error(`FAIL ${name}: no browser at ${executablePath} (run scripts/install-deps.sh, `
        + 'which installs Debian\'s chromium, or set FORESIGHT_CHROMIUM)');
    process.exit(1);
}

const browser = await chromium.launch({
    executablePath,
    headless: true,
    args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
        '--ignore-gpu-blocklist', '--enable-webgl', '--disable-dev-shm-usage'],
});
try {
    const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
    page.on('console', (message) => {
        if (message.type() === 'error') fail(`console error: ${message.text()}`);
    });
    page.on('pageerror', (error) => fail(`page error (uncaught exception): ${error.message}`));
    page.on('request', (request) => {
        const url = request.url();
        if (!url.startsWith('file:') && !url.startsWith('data:') && !url.startsWith('blob:')) {
            fail(`the page loaded ${url}: it must open with no network`);
        }
    });
    await page.goto(pathToFileURL(resolve(pagePath)).href);
    try {
        await page.waitForFunction(() => window.foresightViewer && window.foresightViewer.ready === true,
            null, { timeout: 30000 });
    } catch {
        fail('window.foresightViewer.ready did not become true within 30 s');
        finish();
    }
    const state = await page.evaluate(() => {
        const hook = window.foresightViewer;
        const message = document.getElementById('foresight-message');
        return { failed: hook.failed, errors: hook.errors, counts: hook.counts, timeRange: hook.timeRange,
            message: message ? message.innerText : null };
    });

    if (expectMessage) {
        if (!state.failed) fail('the document is malformed, but the viewer did not report failure');
        if (!state.message || state.message.trim().length < 20) {
            fail('the document is malformed, but the page shows no message');
        } else {
            console.log(`     message shown: ${state.message.replace(/\s+/g, ' ').slice(0, 160)}`);
        }
        if (state.errors.length === 0) fail('foresightViewer.errors is empty for a malformed document');
    } else {
        if (state.failed) fail(`the viewer refused the document: ${state.errors.join('; ')}`);
        if (state.errors.length) fail(`foresightViewer.errors: ${state.errors.join('; ')}`);
        if (!state.failed) await checkScene(page, state);
    }
    if (screenshotPath) {
        if (!expectMessage && !state.failed) {
            await page.evaluate((t) => window.foresightViewer.setTime(t), state.timeRange[1] * 0.3);
        }
        await page.mouse.move(0, 0);
        await page.screenshot({ path: screenshotPath });
        console.log(`     screenshot: ${screenshotPath}`);
    }
} finally {
    await browser.close();
}
finish();

function expectedCounts(picture) {
    const drawn = (picture.predictions ?? []).filter((p) => p.model !== 'orientation'
        && Array.isArray(p.path) && p.path.length > 0);
    const events = drawn.flatMap((p) => p.path.map((point) => point.event));
    return {
        paths: drawn.length,
        bounceMarkers: events.filter((e) => e === 'bounce' || e === 'hit').length,
        restMarkers: events.filter((e) => e === 'rest').length,
        vehicles: drawn.filter((p) => p.model === 'vehicle').length,
        dangerZones: (picture.danger_zones ?? []).length,
        meshes: (picture.world?.meshes ?? []).length,
    };
}

function distance(a, b) {
    return Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

async function checkScene(page, state) {
    const expected = expectedCounts(doc);
    for (const [key, value] of Object.entries(expected)) {
        if (state.counts[key] !== value) fail(`counts.${key} is ${state.counts[key]}, the document has ${value}`);
    }
    console.log(`     counts ${JSON.stringify(state.counts)}`);
    const drawn = doc.predictions.filter((p) => p.model !== 'orientation' && p.path?.length);
    const ends = drawn.map((p) => Math.max(p.time ?? 0, p.path[p.path.length - 1].t));
    const maxTime = Math.max(0, ...ends, ...(doc.danger_zones ?? []).map((z) => z.time ?? 0));
    if (state.timeRange[0] !== 0 || Math.abs(state.timeRange[1] - maxTime) > 1e-9) {
        fail(`timeRange is ${JSON.stringify(state.timeRange)}, expected [0, ${maxTime}]`);
    }

    // Expected positions: at the path's points, and between two points by the contract's rule.
    const gravity = doc.gravity ?? [0, -9.81, 0];
    const probes = []; // {id, t, position, what}
    const seen = new Set();
    for (const prediction of drawn) {
        if (seen.has(prediction.id)) continue; // positionOf(id) answers for the first
        seen.add(prediction.id);
        const path = prediction.path;
        const unique = path.map((_, k) => k).filter((k) => (k === 0 || path[k - 1].t < path[k].t)
            && (k === path.length - 1 || path[k + 1].t > path[k].t));
        const special = unique.filter((k) => path[k].event !== 'step' && path[k].event !== 'sample');
        const even = [0.2, 0.4, 0.6, 0.8].map((f) => unique[Math.floor(f * (unique.length - 1))]);
        for (const k of new Set([...special, ...even])) {
            if (k === undefined) continue;
            probes.push({ id: prediction.id, t: path[k].t, position: path[k].position,
                what: `path point ${k} (${path[k].event})` });
        }
        let between = 0;
        for (let k = 0; k + 1 < path.length && between < 4; ++k) {
            const a = path[k];
            const b = path[k + 1];
            const span = b.t - a.t;
            if (!(span > 0) || k % 3 !== 1) continue;
            const dt = span * 0.37;
            let position;
            if (prediction.model === 'projectile') {
                const flight = (time) => a.position.map((x, i) => x + a.velocity[i] * time
                    + 0.5 * gravity[i] * time * time);
                // Free flight only: the parabola from a must meet b.
                if (a.event === 'rest' || distance(flight(span), b.position) > 1e-9) continue;
                position = flight(dt);
            } else {
                position = a.position.map((x, i) => x + (b.position[i] - x) * (dt / span));
            }
            probes.push({ id: prediction.id, t: a.t + dt, position,
                what: prediction.model === 'projectile' ? `the parabola after point ${k}`
                    : `between samples ${k} and ${k + 1}` });
            ++between;
        }
        const end = Math.max(prediction.time ?? 0, path[path.length - 1].t);
        if (end < maxTime) {
            probes.push({ id: prediction.id, t: maxTime, position: path[path.length - 1].position,
                what: 'its end, after its end time' });
        }
    }
    const answers = await page.evaluate((list) => list.map(({ id, t }) => {
        window.foresightViewer.setTime(t);
        return window.foresightViewer.positionOf(id);
    }), probes.map(({ id, t }) => ({ id, t })));
    let worst = 0;
    probes.forEach((probe, i) => {
        const got = answers[i];
        if (!Array.isArray(got) || got.length !== 3) {
            fail(`positionOf(${probe.id}) at t = ${probe.t} returned ${JSON.stringify(got)}`);
            return;
        }
        const error = distance(got, probe.position);
        worst = Math.max(worst, error);
        if (!(error <= POSITION_TOLERANCE)) {
            fail(`${probe.id} at t = ${probe.t} (${probe.what}): at ${JSON.stringify(got)}, expected `
                + `${JSON.stringify(probe.position)} (${error.toExponential(2)} m off)`);
        }
    });
    console.log(`     ${probes.length} positions checked, worst ${worst.toExponential(2)} m`);

    // Hover a path point: the tooltip shows its time.
    const target = drawn.find((p) => p.path.length >= 3);
    if (target) {
        const k = Math.floor(target.path.length / 2);
        await page.evaluate(() => window.foresightViewer.setTime(0));
        const [x, y] = await page.evaluate((p) => window.foresightViewer.screenOf(p), target.path[k].position);
        await page.mouse.move(x + 1, y + 1);
        const tip = await page.evaluate(() => {
            const node = document.querySelector('.fv-tooltip');
            return node && node.style.display !== 'none' ? node.textContent : '';
        });
        if (!tip.includes('t = ')) {
            fail(`hovering ${target.id}'s point ${k} at (${x.toFixed(0)}, ${y.toFixed(0)}) shows no tooltip`);
        } else {
            console.log(`     hover: ${tip.split('\n').slice(0, 2).join(' · ')}`);
        }
        await page.mouse.move(0, 0);
    }

    // The picture: read the WebGL canvas (the renderer keeps its drawing buffer) and count colours.
    const picture = await page.evaluate(() => {
        const canvas = document.querySelector('#fv-root canvas');
        const copy = document.createElement('canvas');
        copy.width = canvas.width;
        copy.height = canvas.height;
        const context = copy.getContext('2d');
        context.drawImage(canvas, 0, 0);
        const data = context.getImageData(0, 0, copy.width, copy.height).data;
        const colours = new Set();
        const background = `${data[0]},${data[1]},${data[2]}`;
        let other = 0;
        for (let i = 0; i < data.length; i += 4) {
            const key = `${data[i]},${data[i + 1]},${data[i + 2]}`;
            colours.add(key);
            if (key !== background) ++other;
        }
        return { colours: colours.size, covered: other / (data.length / 4), size: [copy.width, copy.height] };
    });
    if (picture.colours < 100 || picture.covered < 0.05) {
        fail(`the canvas looks blank: ${picture.colours} distinct colours, `
            + `${(picture.covered * 100).toFixed(1)}% of pixels differ from the corner`);
    }
    console.log(`     canvas ${picture.size.join('x')}: ${picture.colours} colours, `
        + `${(picture.covered * 100).toFixed(0)}% drawn`);
}
