// robotconf 3D scene glue: loads meshcat's bundled viewer and applies robotconf's ops.
// Shared by the notebook widget and the self-contained HTML export.

// Import the UMD bundle as an ES module from a Blob URL: a <script> tag fails under a
// Content-Security-Policy without 'unsafe-inline', and with requirejs on the page the
// bundle registers as an AMD module instead of defining MeshCat.
function rcLoadMeshcat(source) {
  const text =
    "const module = { exports: {} }; const exports = module.exports;" +
    " const define = undefined;\n" + source + "\nexport default module.exports;\n";
  const url = URL.createObjectURL(new Blob([text], { type: "text/javascript" }));
  return import(url).then((mod) => {
    URL.revokeObjectURL(url);
    return mod.default;
  });
}

function rcSplitPath(path) {
  return path.split("/").filter((part) => part.length > 0);
}

// Redraw a "_text" sprite's canvas in place: labels change with q, objects do not.
function rcDrawLabel(viewer, path, text) {
  const node = viewer.scene_tree.find(rcSplitPath(path).concat(["<object>"]));
  const sprite = node && node.object;
  const map = sprite && sprite.material && sprite.material.map;
  if (!map || !map.image || !map.image.getContext) return;
  const canvas = map.image;
  // meshcat draws "_text" on a 256×256 canvas; a label is a wide band, so reshape it once.
  if (canvas.width !== 512 || canvas.height !== 64) {
    canvas.width = 512;
    canvas.height = 64;
    map.dispose();
  }
  const ctx = canvas.getContext("2d");
  ctx.clearRect(0, 0, canvas.width, canvas.height);
  let size = 40;
  ctx.font = "bold " + size + "px sans-serif";
  while (ctx.measureText(text).width > canvas.width - 16 && size > 10) {
    size -= 1;
    ctx.font = "bold " + size + "px sans-serif";
  }
  const width = ctx.measureText(text).width;
  ctx.fillStyle = "rgba(255, 255, 255, 0.8)";
  ctx.fillRect((canvas.width - width) / 2 - 8, 4, width + 16, canvas.height - 8);
  ctx.fillStyle = "#111111";
  ctx.textAlign = "center";
  ctx.textBaseline = "middle";
  ctx.fillText(text, canvas.width / 2, canvas.height / 2 + 2);
  map.needsUpdate = true;
}

function rcBuffer(view) {
  // Comm buffers arrive as DataView objects over a larger ArrayBuffer: honour byteOffset.
  if (view instanceof ArrayBuffer) return new Uint8Array(view);
  return new Uint8Array(view.buffer, view.byteOffset, view.byteLength);
}

function rcApply(viewer, ops, buffers) {
  for (const op of ops) {
    if (op.op === "command") {
      viewer.handle_command(op.command);
    } else if (op.op === "packed") {
      viewer.handle_command_bytearray(rcBuffer(buffers[op.buffers[0]]));
    } else if (op.op === "transforms") {
      const bytes = rcBuffer(buffers[op.buffers[0]]);
      // Copy: a Float32Array needs a 4-byte aligned offset, which a DataView may lack.
      const data = new Float32Array(bytes.slice().buffer);
      op.paths.forEach((path, k) => {
        viewer.set_transform(rcSplitPath(path), data.subarray(16 * k, 16 * k + 16));
      });
    } else if (op.op === "visible") {
      op.paths.forEach((path) => viewer.set_property(rcSplitPath(path), "visible", op.value));
    } else if (op.op === "labels") {
      op.paths.forEach((path, k) => rcDrawLabel(viewer, path, op.texts[k]));
    }
  }
  viewer.set_dirty();
}

// A viewer sized to its element (not the window), with a render loop that stops.
function rcCreateViewer(MeshCat, element, height) {
  const viewer = new MeshCat.Viewer(element, false);
  let disposed = false;
  const sizeOf = () => [Math.max(element.clientWidth, 100), height || element.clientHeight || 400];
  const setSize = viewer.set_3d_pane_size.bind(viewer);
  viewer.set_3d_pane_size = (w, h) => {
    if (disposed) return;
    const [width, fallback] = sizeOf();
    setSize(w === undefined ? width : w, h === undefined ? fallback : h);
  };
  const observer = new ResizeObserver(() => viewer.set_3d_pane_size());
  observer.observe(element);
  let frame = 0;
  const loop = () => {
    if (disposed) return;
    frame = requestAnimationFrame(loop);
    viewer.animator.update();
    if (viewer.needs_render) viewer.render();
  };
  viewer.animate = () => {}; // the capturer restarts meshcat's own loop; keep ours
  loop();
  viewer.set_3d_pane_size();
  const dispose = () => {
    if (disposed) return;
    disposed = true;
    cancelAnimationFrame(frame);
    observer.disconnect();
    try {
      viewer.gui.destroy();
    } catch (error) {
      /* already gone */
    }
    // Browsers keep about 16 live WebGL contexts: give this one back.
    viewer.renderer.dispose();
    viewer.renderer.forceContextLoss();
    element.innerHTML = "";
  };
  return { viewer, dispose };
}
