// The page's CSS, injected from JavaScript so that the bundle is a single script.
const css = `
html, body { margin: 0; height: 100%; overflow: hidden; background: #1b2029; }
body { font: 13px/1.4 system-ui, -apple-system, "Segoe UI", Roboto, "DejaVu Sans", sans-serif;
       color: #e8ecf2; }
#fv-root { position: fixed; inset: 0; }
#fv-root canvas { display: block; width: 100%; height: 100%; outline: none; }
.fv-panel { position: absolute; background: rgba(20, 24, 32, 0.86); border: 1px solid #3a4456;
            border-radius: 6px; box-shadow: 0 2px 10px rgba(0, 0, 0, 0.35); }
.fv-legend { top: 12px; left: 12px; padding: 10px 12px; max-width: min(520px, 60%);
             max-height: calc(100% - 110px); overflow-y: auto; }
.fv-legend h1 { font-size: 15px; margin: 0 0 8px; font-weight: 600; }
.fv-legend .fv-row { display: flex; align-items: center; gap: 8px; padding: 2px 0;
                     cursor: pointer; user-select: none; white-space: nowrap; }
.fv-legend .fv-row.fv-hidden { opacity: 0.4; }
.fv-legend .fv-swatch { width: 22px; height: 4px; border-radius: 2px; flex: none; }
.fv-legend .fv-swatch.fv-dashed { background-size: 8px 4px !important; }
.fv-legend .fv-id { font-weight: 600; }
.fv-legend .fv-variant { color: #aab4c4; }
.fv-legend .fv-keys { margin-top: 8px; padding-top: 6px; border-top: 1px solid #3a4456;
                      color: #aab4c4; font-size: 12px; }
.fv-legend .fv-key { display: flex; align-items: center; gap: 8px; }
.fv-legend .fv-dot { width: 10px; height: 10px; border-radius: 50%; flex: none; }
.fv-legend .fv-diamond { width: 9px; height: 9px; transform: rotate(45deg); flex: none;
                         margin: 0 1px; }
.fv-controls { left: 50%; bottom: 14px; transform: translateX(-50%); display: flex;
               align-items: center; gap: 10px; padding: 8px 12px; width: min(720px, 90%);
               box-sizing: border-box; }
.fv-controls button { font: inherit; color: #e8ecf2; background: #2e3747; border: 1px solid #4a566c;
                      border-radius: 4px; padding: 3px 0; width: 64px; cursor: pointer; }
.fv-controls button:hover { background: #3a4559; }
.fv-controls input[type=range] { flex: 1; min-width: 80px; accent-color: #4fa3ff; }
.fv-controls .fv-time { font-variant-numeric: tabular-nums; min-width: 150px; text-align: right; }
.fv-hint { right: 12px; top: 12px; padding: 6px 10px; color: #aab4c4; font-size: 12px; }
.fv-tooltip { position: absolute; pointer-events: none; padding: 6px 9px; font-size: 12px;
              font-variant-numeric: tabular-nums; white-space: pre; display: none; z-index: 2; }
.fv-message { position: fixed; inset: 0; display: flex; align-items: center; justify-content: center;
              background: #1b2029; z-index: 3; }
.fv-message .fv-box { max-width: 640px; padding: 20px 24px; background: #2a1d21;
                      border: 1px solid #a34a55; border-radius: 8px; }
.fv-message h1 { font-size: 17px; margin: 0 0 10px; color: #ff9aa5; }
.fv-message ul { margin: 8px 0 0; padding-left: 20px; }
.fv-message li { font-family: ui-monospace, "DejaVu Sans Mono", monospace; font-size: 12px; }
`;

export function injectStyle() {
    const style = document.createElement('style');
    style.id = 'foresight-viewer-style';
    style.textContent = css;
    document.head.appendChild(style);
}
