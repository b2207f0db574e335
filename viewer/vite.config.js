// Builds ONE self-contained script, dist/foresight-viewer.js: an IIFE with three.js inside and
// its CSS injected from JavaScript (src/style.js), for the CLI to inline into its HTML page.
// FORESIGHT_VIEWER_OUT_DIR moves the output (CMake builds into its binary directory, so that two
// build trees never write the same file).
import { defineConfig } from 'vite';

export default defineConfig({
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
