// The page's HTML controls: legend, time slider with play button, tooltip, hint, error message.

function element(tag, className, parent, text) {
    const node = document.createElement(tag);
    if (className) node.className = className;
    if (text !== undefined) node.textContent = text;
    if (parent) parent.appendChild(node);
    return node;
}

const VARIANT_NAMES = { faithful: 'faithful (article)', exact: 'exact', engine: 'engine-matched' };
const hex = (color) => `#${color.toString(16).padStart(6, '0')}`;

/** entries: [{prediction, color}]; onToggle(index, visible) when a row is clicked. */
export function buildLegend(root, title, entries, keys, onToggle) {
    const legend = element('div', 'fv-panel fv-legend', root);
    element('h1', '', legend, title);
    entries.forEach(({ prediction, color }, index) => {
        const row = element('div', 'fv-row', legend);
        row.title = 'Click to hide or show';
        const swatch = element('span', 'fv-swatch', row);
        swatch.style.background = prediction.variant === 'faithful'
            ? `repeating-linear-gradient(90deg, ${color} 0 5px, transparent 5px 8px)` : color;
        element('span', 'fv-id', row, prediction.id);
        const method = prediction.engine ? `as ${prediction.engine} steps it` : prediction.method;
        element('span', 'fv-variant', row,
            `${VARIANT_NAMES[prediction.variant]} · ${prediction.model}${
                method !== prediction.model ? ` ${method}` : ''}`);
        let visible = true;
        row.addEventListener('click', () => {
            visible = !visible;
            row.classList.toggle('fv-hidden', !visible);
            onToggle(index, visible);
        });
    });
    if (entries.length === 0) element('div', 'fv-variant', legend, 'No predictions to draw.');
    const keyBox = element('div', 'fv-keys', legend);
    const key = (shape, color, text) => {
        const row = element('div', 'fv-key', keyBox);
        element('span', shape, row).style.background = color;
        element('span', '', row, text);
    };
    if (keys.bounce) key('fv-dot', '#dfe6f0', 'bounce / hit');
    if (keys.rest) key('fv-diamond', hex(keys.restColor), 'at rest');
    if (keys.vehicle) key('fv-swatch', 'rgba(200, 210, 230, 0.45)', 'vehicle pose every 0.25 s');
    if (keys.danger) key('fv-dot', 'rgba(255, 59, 59, 0.55)', 'danger zone (from its time on)');
    element('div', '', keyBox, `grid: ${keys.gridCell} m · axes: X red, Y green (up), Z blue`);
    return legend;
}

/** The time slider and play button; onTime(t) on user input, onPlay(playing) on the button. */
export function buildControls(root, maxTime, onTime, onPlay) {
    const bar = element('div', 'fv-panel fv-controls', root);
    const button = element('button', '', bar, 'Play');
    button.type = 'button';
    const slider = element('input', '', bar);
    Object.assign(slider, { type: 'range', min: '0', max: String(maxTime), step: 'any', value: '0' });
    slider.setAttribute('aria-label', 'time');
    const label = element('span', 'fv-time', bar);
    let playing = false;
    button.addEventListener('click', () => {
        playing = !playing;
        button.textContent = playing ? 'Pause' : 'Play';
        onPlay(playing);
    });
    slider.addEventListener('input', () => onTime(Number(slider.value)));
    if (maxTime <= 0) {
        button.disabled = true;
        slider.disabled = true;
    }
    return {
        show(t) {
            slider.value = String(t);
            label.textContent = `t = ${t.toFixed(3)} s / ${maxTime.toFixed(3)} s`;
        },
        stopped() {
            playing = false;
            button.textContent = 'Play';
        },
    };
}

export function buildHint(root) {
    element('div', 'fv-panel fv-hint', root,
        'drag: orbit · right-drag: pan · wheel: zoom · hover a path point for its state');
}

export function buildTooltip(root) {
    const tip = element('div', 'fv-panel fv-tooltip', root);
    const f = (v) => v.toFixed(3);
    const v3 = (v) => `(${f(v[0])}, ${f(v[1])}, ${f(v[2])})`;
    return {
        show(x, y, prediction, point) {
            tip.textContent = `${prediction.id} · ${point.event}\n`
                + `t = ${f(point.t)} s\n`
                + `position ${v3(point.position)} m\n`
                + `velocity ${v3(point.velocity)} m/s  |v| = ${f(Math.hypot(...point.velocity))}`;
            tip.style.display = 'block';
            const box = tip.getBoundingClientRect();
            tip.style.left = `${Math.min(x + 14, window.innerWidth - box.width - 4)}px`;
            tip.style.top = `${Math.min(y + 14, window.innerHeight - box.height - 4)}px`;
        },
        hide() {
            tip.style.display = 'none';
        },
    };
}

/** A full-page message in place of the viewer (a missing or malformed document, no WebGL). */
export function showMessage(heading, lines) {
    const cover = element('div', 'fv-message', document.body);
    cover.id = 'foresight-message';
    cover.setAttribute('role', 'alert');
    const box = element('div', 'fv-box', cover);
    element('h1', '', box, heading);
    if (lines.length === 1) element('p', '', box, lines[0]);
    else {
        const list = element('ul', '', box);
        for (const line of lines) element('li', '', list, line);
    }
    return cover;
}
