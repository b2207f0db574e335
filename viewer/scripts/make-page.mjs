#!/usr/bin/env node
// make-page.mjs DOC.json OUT.html [TITLE]: writes the viewer page for a picture document, exactly
// as the CLI does (`foresight ... --html`). It is the reference for the C++ writer:
//
//   <!doctype html>
//   <html lang="en"><head><meta charset="utf-8"><meta name="viewport" content="width=device-width, initial-scale=1"><title>TITLE</title></head>
//   <body><script type="application/json" id="foresight-data">PICTURE DOCUMENT JSON</script>
//   <script>BUNDLE</script></body></html>
//
// with "</" written as "<\/" inside both scripts (so neither can end its element early; "<\/"
// means "</" in JSON strings and in JavaScript strings, regular expressions and comments), and
// TITLE HTML-escaped (& < > "). DOC.json is copied as it is (it may be deliberately malformed).
// The bundle is dist/foresight-viewer.js (`npm run build`), or $FORESIGHT_VIEWER_BUNDLE.
import { readFileSync, writeFileSync } from 'node:fs';

const [docPath, outPath, titleArgument] = process.argv.slice(2);
if (!docPath || !outPath) {
    console.error('usage: node scripts/make-page.mjs DOC.json OUT.html [TITLE]');
    process.exit(2);
}

function read(path, what) {
    try {
        return readFileSync(path, 'utf8');
    } catch (error) {
        console.error(`make-page: cannot read ${what} ${path}: ${error.message}`);
        process.exit(1);
    }
}

const documentText = read(docPath, 'the picture document');
const bundle = read(process.env.FORESIGHT_VIEWER_BUNDLE || new URL('../dist/foresight-viewer.js', import.meta.url),
    'the bundle (run `npm run build`)');
let title = titleArgument;
if (title === undefined) {
    try {
        title = JSON.parse(documentText).title;
    } catch {
        // A malformed document: the page still gets a title, and the viewer says what is wrong.
    }
}
if (typeof title !== 'string' || title === '') title = 'foresight';

const escapeScript = (text) => text.replaceAll('</', '<\\/');
const escapeHtml = (text) => text.replaceAll('&', '&amp;').replaceAll('<', '&lt;').replaceAll('>', '&gt;')
    .replaceAll('"', '&quot;');

const page = '<!doctype html>\n'
    + '<html lang="en"><head><meta charset="utf-8">'
    + '<meta name="viewport" content="width=device-width, initial-scale=1">'
    + `<title>${escapeHtml(title)}</title></head>\n`
    + `<body><script type="application/json" id="foresight-data">${escapeScript(documentText.trim())}</script>\n`
    + `<script>${escapeScript(bundle.trim())}</script></body></html>\n`;
writeFileSync(outPath, page);
console.log(`make-page: wrote ${outPath} (${(page.length / 1024).toFixed(0)} KiB)`);
