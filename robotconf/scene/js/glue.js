// robotconf 3D scene glue: loads meshcat's bundled viewer and applies robotconf's ops.
// Shared by the notebook widget and the self-contained HTML export (with labels.js,
// player.js, bar.js and mount.js).

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

// Fit: the camera keeps its direction and moves to where a sphere of `radius` about the
// orbit centre just fills the narrower side of the pane.
function rcFit(viewer, radius) {
  const camera = viewer.camera;
  if (!camera || !camera.isPerspectiveCamera || !(radius > 0)) return;
  const half = (camera.fov * Math.PI) / 360;
  const across = Math.atan(Math.tan(half) * (camera.aspect || 1));
  const distance = (1.05 * radius) / Math.sin(Math.min(half, across));
  if (camera.position.length() < 1e-12) camera.position.set(0.9, 0.6, 0.9);
  camera.position.setLength(distance);
  viewer.controls.target.set(0, 0, 0);
  viewer.controls.update();
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
      if (op.command.type === "delete") rcForgetLabels(viewer);
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
      rcSetLabels(viewer, op.paths, op.texts);
    } else if (op.op === "fit") {
      rcFit(viewer, op.radius);
    } else if (op.op === "playback") {
      if (viewer.rcPlayer) viewer.rcPlayer.command(op);
    } else if (op.op === "options") {
      if (viewer.rcOnOptions) viewer.rcOnOptions(op);
    }
  }
  viewer.set_dirty();
}

// Whether WebGL runs on the CPU (no GPU, or a GPU the browser refuses). Asked once per
// page, on a throw-away context.
function rcSoftwareWebGL() {
  const shared = (globalThis.__robotconf_scene ??= {});
  if (shared.software === undefined) {
    let name = "";
    try {
      const gl = document.createElement("canvas").getContext("webgl");
      const info = gl && gl.getExtension("WEBGL_debug_renderer_info");
      name = info ? String(gl.getParameter(info.UNMASKED_RENDERER_WEBGL)) : "";
      const lose = gl && gl.getExtension("WEBGL_lose_context");
      if (lose) lose.loseContext();
    } catch (error) {
      name = "";
    }
    shared.software = /swiftshader|llvmpipe|softpipe|software|basic render/i.test(name);
  }
  return shared.software;
}

// A viewer sized to its element (not the window), with a render loop that stops, the
// page's player (player.js) and the labels' layer over the canvas (labels.js).
function rcCreateViewer(MeshCat, element, height, report) {
  // Smoothing the edges (multisampling) costs a software renderer about a third of each
  // frame, which a slider drag on a laptop without a GPU feels; a GPU does it for free.
  const smooth = !rcSoftwareWebGL();
  const renderer = new MeshCat.THREE.WebGLRenderer({ antialias: smooth, alpha: true });
  renderer.domElement.dataset.antialias = String(smooth);
  element.appendChild(renderer.domElement);
  const viewer = new MeshCat.Viewer(element, false, renderer);
  // Soft shadow maps re-render the scene once per shadow-casting light on every frame;
  // on a laptop without a GPU (software WebGL) that halves the frame rate of a drag,
  // and a kinematics picture needs no shadows.
  viewer.renderer.shadowMap.enabled = false;
  // The scene's bar plays animations (player.js): meshcat's own "Animations" menu would
  // be a second player that the bar and the kernel know nothing about.
  const animations = viewer.animator.folder.domElement.parentElement;
  if (animations) animations.style.display = "none";
  viewer.rcPlayer = rcCreatePlayer(viewer, report);
  rcCreateLabelLayer(viewer, element);
  let disposed = false;
  // The page may give the pane another height than asked for (a pinned view is shorter).
  const sizeOf = () => [Math.max(element.clientWidth, 100), element.clientHeight || height || 400];
  const setSize = viewer.set_3d_pane_size.bind(viewer);
  viewer.set_3d_pane_size = (w, h) => {
    if (disposed) return;
    const [width, fallback] = sizeOf();
    viewer.rcPaneSize = [w === undefined ? width : w, h === undefined ? fallback : h];
    setSize(...viewer.rcPaneSize);
    rcResizeLabels(viewer);
  };
  const observer = new ResizeObserver(() => viewer.set_3d_pane_size());
  observer.observe(element);
  let frame = 0;
  const loop = (now) => {
    if (disposed) return;
    frame = requestAnimationFrame(loop);
    viewer.rcPlayer.tick(now === undefined ? performance.now() : now);
    if (viewer.needs_render) {
      viewer.controls.update();
      viewer.scene.updateMatrixWorld();
      rcLayoutLabels(viewer);
      viewer.render();
    }
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
