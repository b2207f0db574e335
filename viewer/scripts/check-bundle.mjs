// Checks the built bundle can be inlined in the CLI's page: an HTML <script> element ends at the
// first "</script" (the writer escapes "</" as "<\/"), and "<!--" followed by "<script" would
// put the parser in the "double escaped" state, where even that end tag is not seen. It also
// checks that the bundle loads nothing from the network.
import { readFileSync, statSync } from 'node:fs';

const outDir = process.env.FORESIGHT_VIEWER_OUT_DIR;
const file = outDir ? `${outDir}/foresight-viewer.js` : new URL('../dist/foresight-viewer.js', import.meta.url);
const text = readFileSync(file, 'utf8');
const problems = [];
for (const [pattern, why] of [
    [/<!--/, 'an HTML comment opener confuses the <script> parser'],
    [/<script/i, 'a script start tag inside the script'],
    [/(?<![\w.])fetch\(|\.fetch\(/, 'a network fetch'], // not GLSL's texelFetch(
    [/XMLHttpRequest/, 'a network request'],
    [/(?<![\w.])import\(/, 'a dynamic import (the bundle must be one file)'],
]) {
    if (pattern.test(text)) problems.push(`contains ${pattern}: ${why}`);
}
try {
    new Function(text.replaceAll('</', '<\\/')); // still valid JavaScript once escaped as the page holds it
} catch (error) {
    problems.push(`does not parse once "</" is escaped: ${error.message}`);
}
if (problems.length) {
    console.error(`check-bundle: ${file} ${problems.join('; ')}`);
    process.exit(1);
}
console.log(`check-bundle: ${outDir ? file : 'dist/foresight-viewer.js'} is ${(statSync(file).size / 1024).toFixed(0)} KiB, fit to inline`);
