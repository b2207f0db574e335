// Serves the viewer's live mode (live/index.html): the page, three.js from node_modules and the
// WebAssembly package (bindings/wasm, built: its dist/foresight_core.mjs must exist) under /wasm/.
// ES modules need http (a file: page may not import them).
//
//   node scripts/serve-live.mjs WASM_PACKAGE_DIR [PORT]   then open http://127.0.0.1:PORT/
//   (WASM_PACKAGE_DIR: build/bindings/wasm/package, or bindings/wasm after its build.sh)
import { createServer } from 'node:http';
import { existsSync, readFileSync, statSync } from 'node:fs';
import { extname, join, resolve, sep } from 'node:path';
import { fileURLToPath } from 'node:url';

const viewer = fileURLToPath(new URL('..', import.meta.url));
const types = { '.html': 'text/html', '.js': 'text/javascript', '.mjs': 'text/javascript', '.json': 'application/json' };

/**
 * Starts the server on 127.0.0.1.
 * @param {string} wasmPackage  the WebAssembly package's folder.
 * @param {number} [port=0]  0: any free port.
 * @returns {Promise<{server: import('node:http').Server, url: string}>}
 */
export async function serveLive(wasmPackage, port = 0) {
    const roots = [
        ['/wasm/', resolve(wasmPackage)],
        ['/node_modules/three/', join(viewer, 'node_modules', 'three')],
        ['/', join(viewer, 'live')],
    ];
    const server = createServer((request, response) => {
        const pathname = decodeURIComponent(new URL(request.url, 'http://host').pathname);
        const [prefix, root] = roots.find(([p]) => pathname.startsWith(p));
        let file = resolve(root, `.${sep}${pathname.slice(prefix.length)}`);
        if (file === root || (existsSync(file) && statSync(file).isDirectory())) file = join(file, 'index.html');
        if (!file.startsWith(root) || !existsSync(file)) {
            response.writeHead(404);
            response.end();
            return;
        }
        response.writeHead(200, { 'content-type': types[extname(file)] || 'application/octet-stream' });
        response.end(readFileSync(file));
    });
    await new Promise((done) => server.listen(port, '127.0.0.1', done));
    return { server, url: `http://127.0.0.1:${server.address().port}/` };
}

if (process.argv[1] && resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
    const [wasmPackage, port] = process.argv.slice(2);
    if (!wasmPackage || !existsSync(join(wasmPackage, 'dist', 'foresight_core.mjs'))) {
        console.error('usage: node scripts/serve-live.mjs WASM_PACKAGE_DIR [PORT] (a built bindings/wasm package)');
        process.exit(2);
    }
    const { url } = await serveLive(wasmPackage, Number(port || 8080));
    console.log(`foresight live mode: ${url}`);
}
