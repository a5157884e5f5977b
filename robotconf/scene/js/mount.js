// One scene on the page (appended to glue.js): the bar above the 3D pane, the viewer, its
// player and labels, wired to a `send` function (the widget's comm, or an exported page's
// own answers). Used by widget.js and by the HTML export alike.

const RC_STYLE = `
.robotconf-scene-root { font: 13px var(--jp-ui-font-family, sans-serif); }
.robotconf-scene-controls { display: flex; flex-wrap: wrap; align-items: center; gap: 4px;
  padding: 3px 2px; }
.robotconf-scene-controls[hidden] { display: none; }
.robotconf-scene-controls button, .robotconf-scene-controls select {
  font: inherit; padding: 2px 8px; border: 1px solid var(--jp-border-color1, #bbb);
  border-radius: 3px; background: var(--jp-layout-color1, #fff);
  color: var(--jp-ui-font-color1, #222); cursor: pointer; }
.robotconf-scene-controls button:disabled, .robotconf-scene-controls select:disabled,
.robotconf-scene-controls input:disabled { opacity: 0.45; cursor: default; }
.robotconf-scene-controls button.robotconf-scene-on {
  background: var(--jp-brand-color1, #1976d2); border-color: var(--jp-brand-color1, #1976d2);
  color: #fff; }
.robotconf-scene-play { min-width: 34px; }
.robotconf-scene-play svg { display: block; margin: 2px auto; }
.robotconf-scene-controls select.robotconf-scene-speed { width: 64px; padding: 2px 4px; }
.robotconf-scene-time { flex: 1 1 110px; min-width: 80px; max-width: 260px; }
.robotconf-scene-clock { min-width: 112px; font-variant-numeric: tabular-nums; }
.robotconf-scene-label-mode { display: inline-flex; align-items: center; gap: 0; margin: 0 4px; }
.robotconf-scene-label-mode button { border-radius: 0; margin-left: -1px; }
.robotconf-scene-label-mode button:first-of-type { border-radius: 3px 0 0 3px; }
.robotconf-scene-label-mode button:last-of-type { border-radius: 0 3px 3px 0; }
.robotconf-scene-caption { margin-right: 5px; }
.robotconf-scene { position: relative; width: 100%; overflow: hidden; }
.robotconf-scene-overlay { position: absolute; inset: 0; pointer-events: none;
  overflow: hidden; contain: strict; }
.robotconf-scene-leaders { position: absolute; left: 0; top: 0; width: 100%; height: 100%; }
.robotconf-scene-leader { stroke: #111; stroke-width: 1.2; stroke-dasharray: 4 2; }
.robotconf-scene-label { position: absolute; left: 0; top: 0; box-sizing: border-box;
  white-space: pre; font: ${RC_LABEL_FONT}; line-height: ${RC_LABEL_LINE}px;
  padding: ${RC_LABEL_PAD_Y}px ${RC_LABEL_PAD_X}px; color: #111;
  background: rgba(255, 255, 255, 0.85); border: 1px solid rgba(0, 0, 0, 0.35);
  border-radius: 3px; }
.robotconf-scene-label[hidden] { display: none; }
`;

function rcAddStyle() {
  if (document.getElementById("robotconf-scene-style")) return;
  const style = document.createElement("style");
  style.id = "robotconf-scene-style";
  style.textContent = RC_STYLE;
  document.head.appendChild(style);
}

// The page's parts of one scene, before the viewer code is there: the bar, the pane and
// a status line. `height` in pixels (undefined: fill the parent).
function rcScenePage(el, height, send) {
  rcAddStyle();
  const root = rcElement("div", "robotconf-scene-root");
  const bar = rcCreateBar((request) => send({ kind: "request", request }));
  const wrapper = rcElement("div", "robotconf-scene");
  if (height) {
    wrapper.style.height = `${height}px`;
  } else {
    // A page of its own (the HTML export): the bar on top, the pane takes the rest.
    root.style.cssText = "display: flex; flex-direction: column; height: 100%;";
    wrapper.style.cssText = "flex: 1; min-height: 0;";
  }
  const pane = rcElement("div", "robotconf-scene-pane");
  pane.style.cssText = "width: 100%; height: 100%;";
  const status = rcElement("div", "robotconf-scene-status", {}, "Loading the 3D viewer…");
  status.style.cssText = "position: absolute; left: 8px; top: 8px; font: 13px sans-serif;";
  wrapper.append(pane, status);
  root.append(bar.element, wrapper);
  el.appendChild(root);
  return { root, bar, wrapper, pane, status, height, send };
}

// Start the viewer in a page made by rcScenePage: returns {viewer, dispose}.
function rcStartViewer(MeshCat, page) {
  const report = (event) => page.send({ kind: "playback", ...event });
  const handle = rcCreateViewer(MeshCat, page.pane, page.height, report);
  page.status.remove();
  page.bar.follow(handle.viewer.rcPlayer);
  handle.viewer.rcOnOptions = (op) => page.bar.setOptions(op);
  return handle;
}
