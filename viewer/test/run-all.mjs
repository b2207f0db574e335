#!/usr/bin/env node
// npm test: builds a page for every example document with scripts/make-page.mjs (into
// test/out/, or $FORESIGHT_VIEWER_TEST_OUT) and runs viewer.test.mjs on it. Documents expected to
// be refused are listed here. The bundle is dist/foresight-viewer.js or $FORESIGHT_VIEWER_BUNDLE.
import { mkdirSync } from 'node:fs';
import { spawnSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';

const here = fileURLToPath(new URL('.', import.meta.url));
const out = process.env.FORESIGHT_VIEWER_TEST_OUT || `${here}out`;
mkdirSync(out, { recursive: true });
const examples = [
    { name: 'projectile', screenshot: true },
    { name: 'vehicle', screenshot: true },
    { name: 'malformed', refused: true }, // not JSON
    { name: 'invalid', refused: true },   // JSON, but it breaks the contract
];
let failed = 0;
for (const { name, screenshot, refused } of examples) {
    const page = `${out}/${name}.html`;
    const run = (args) => spawnSync(process.execPath, args, { stdio: 'inherit' }).status === 0;
    const ok = run([`${here}../scripts/make-page.mjs`, `${here}${name}.json`, page])
        && run([`${here}viewer.test.mjs`, page, ...(screenshot ? [`${out}/${name}.png`] : []),
            ...(refused ? ['--expect-message'] : [])]);
    if (!ok) ++failed;
}
console.log(failed ? `${failed} of ${examples.length} viewer tests FAILED` : `all ${examples.length} viewer tests passed`);
process.exit(failed ? 1 : 0);
