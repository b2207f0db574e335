// Builds ONE self-contained script, dist/foresight-viewer.js: an IIFE with three.js inside and
// its CSS injected from JavaScript (src/style.js), for the CLI to inline into its HTML page.
// FORESIGHT_VIEWER_OUT_DIR moves the output (CMake builds into its binary directory, so that two
// build trees never write the same file).
import { readFileSync } from 'node:fs';
import { defineConfig } from 'vite';

// three.js is MIT-licensed: its notice travels with every copy of the script (and so with every
// page the CLI writes), as a comment at the top of the minified bundle.
const threeLicense = readFileSync(new URL('./node_modules/three/LICENSE', import.meta.url), 'utf8').trim();
const threeNotice = {
    name: 'foresight-three-notice',
    generateBundle(_options, bundle) {
        for (const file of Object.values(bundle)) {
            if (file.type === 'chunk') file.code = `/*! three.js, bundled in this script.\n${threeLicense}\n*/\n${file.code}`;
        }
    },
};

export default defineConfig({
    plugins: [threeNotice],
    // Library mode leaves process.env.NODE_ENV in place; a page has no `process`.
    define: { 'process.env.NODE_ENV': JSON.stringify('production') },
    build: {
        lib: {
            entry: 'src/main.js',
            name: 'ForesightViewer',
            formats: ['iife'],
            fileName: () => 'foresight-viewer.js',
        },
        outDir: process.env.FORESIGHT_VIEWER_OUT_DIR || 'dist',
        emptyOutDir: true,
        target: 'es2020',
        minify: true,
        sourcemap: false,
        reportCompressedSize: false,
    },
});
