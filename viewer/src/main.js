// The foresight viewer: reads the picture document embedded in the page
// (<script type="application/json" id="foresight-data">, docs/viewer-format.md) and draws it.
// window.foresightViewer is the test hook (viewer/README.md).
import { readPictureDocument } from './document.js';
import { injectStyle } from './style.js';
import { showMessage } from './ui.js';
import { createViewer } from './viewer.js';

const hook = {
    ready: false,
    failed: false,
    message: '',
    counts: { paths: 0, bounceMarkers: 0, restMarkers: 0, vehicles: 0, dangerZones: 0, meshes: 0 },
    timeRange: [0, 0],
    errors: [],
    setTime: () => 0,
    positionOf: () => null,
};
window.foresightViewer = hook;
window.addEventListener('error', (event) => hook.errors.push(String(event.message)));

function fail(heading, lines) {
    hook.failed = true;
    hook.message = [heading, ...lines].join('\n');
    hook.errors.push(...lines);
    document.title = `${document.title || 'foresight'}: ${heading.toLowerCase()}`;
    showMessage(heading, lines);
    // A warning, not an error: the page did what it should with a bad document.
    console.warn(`foresight viewer: ${hook.message}`);
    hook.ready = true;
}

function start() {
    try {
        injectStyle();
        const { document: picture, problems } = readPictureDocument(document);
        if (problems) {
            fail('This picture document cannot be shown', problems);
            return;
        }
        createViewer(picture, hook);
    } catch (error) {
        document.getElementById('fv-root')?.remove();
        fail('The viewer could not start', [error && error.message ? error.message : String(error)]);
    }
}

if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', start);
else start();
