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

// Labels are sized on screen, not in the scene: LABEL_PX tall at any zoom, so a label far
// from the camera stays readable and a near one does not cover the robot.
const RC_LABEL_PX = 24;
// A label stands this many label heights above its point, plus its row (stacked labels).
const RC_LABEL_LIFT = 0.1;

function rcLabelEntry(viewer, path) {
  const labels = (viewer.rcLabels ??= new Map());
  const node = viewer.scene_tree.find(rcSplitPath(path).concat(["<object>"]));
  const sprite = node && node.object;
  const map = sprite && sprite.material && sprite.material.map;
  if (!map || !map.image || !map.image.getContext) return null;
  let entry = labels.get(path);
  if (!entry || entry.sprite !== sprite) {
    // A new sprite (first label, or the robot was rebuilt): screen-sized from now on.
    entry = { sprite, text: null, row: 0, shown: 0, width: 0, aspect: 8 };
    labels.set(path, entry);
    sprite.material.sizeAttenuation = false;
    sprite.material.needsUpdate = true;
    sprite.center.set(0.5, -RC_LABEL_LIFT);
    rcSizeLabel(viewer, entry);
  }
  return entry;
}

// Redraw a "_text" sprite's canvas in place, only when its text changed.
function rcDrawLabel(viewer, path, text, row) {
  const entry = rcLabelEntry(viewer, path);
  if (!entry) return;
  if (row !== undefined) entry.row = row;
  if (text === entry.text) return;
  entry.text = text;
  const map = entry.sprite.material.map;
  const canvas = map.image;
  const font = "bold 40px sans-serif";
  let ctx = canvas.getContext("2d");
  ctx.font = font;
  const width = text ? ctx.measureText(text).width : 0;
  // meshcat draws "_text" on a 256×256 canvas; a label is a band as wide as its text (at
  // one font size, so every label reads alike), resized only when that width changes.
  const wanted = Math.max(128, Math.ceil((width + 24) / 64) * 64);
  if (canvas.width !== wanted || canvas.height !== 64) {
    canvas.width = wanted;
    canvas.height = 64;
    map.dispose();
    ctx = canvas.getContext("2d");
  }
  ctx.clearRect(0, 0, canvas.width, canvas.height);
  entry.width = text ? (width + 16) / canvas.width : 0; // a merged label takes no room
  if (entry.aspect !== canvas.width / canvas.height) {
    entry.aspect = canvas.width / canvas.height;
    rcSizeLabel(viewer, entry);
  }
  if (text) {
    ctx.font = font;
    ctx.fillStyle = "rgba(255, 255, 255, 0.8)";
    ctx.fillRect((canvas.width - width) / 2 - 8, 4, width + 16, canvas.height - 8);
    ctx.fillStyle = "#111111";
    ctx.textAlign = "center";
    ctx.textBaseline = "middle";
    ctx.fillText(text, canvas.width / 2, canvas.height / 2 + 2);
  }
  map.needsUpdate = true;
}

// With sizeAttenuation off, a sprite's world height h shows as h / (2 tan(fov / 2)) of
// the pane's height: undo the parents' scale so the band is RC_LABEL_PX pixels tall.
function rcSizeLabel(viewer, entry) {
  const camera = viewer.camera;
  // The pane's size as last set, not read from the DOM: reading it while the notebook's
  // DOM changes (every slider step) would force the browser to lay the page out again.
  const height = (viewer.rcPaneSize && viewer.rcPaneSize[1]) || 400;
  const parent = entry.sprite.parent;
  if (!camera || !camera.isPerspectiveCamera || !parent) return;
  parent.updateWorldMatrix(true, false);
  const m = parent.matrixWorld.elements;
  const scale = Math.hypot(m[4], m[5], m[6]) || 1;
  const tall = (2 * RC_LABEL_PX * Math.tan((camera.fov * Math.PI) / 360)) / height / scale;
  entry.sprite.scale.set((entry.aspect || 8) * tall, tall, 1);
}

function rcSizeLabels(viewer) {
  if (!viewer.rcLabels) return;
  for (const entry of viewer.rcLabels.values()) rcSizeLabel(viewer, entry);
}

// Labels must not cover each other on screen: from the kernel's rows (labels of close
// points already stacked), lift each label by whole rows until its box is clear of the
// boxes placed before it. Runs before each render, so it follows the camera.
function rcDeclutter(viewer) {
  if (!viewer.rcLabels || !viewer.rcLabels.size || !viewer.camera) return;
  const [width, height] = viewer.rcPaneSize || [1, 1];
  const boxes = [];
  for (const entry of viewer.rcLabels.values()) {
    const sprite = entry.sprite;
    if (!sprite.parent || !sprite.parent.visible || !entry.width) continue;
    const at = sprite.position.clone().setFromMatrixPosition(sprite.matrixWorld);
    at.project(viewer.camera);
    if (at.z > 1) continue; // behind the camera
    const x = ((at.x + 1) / 2) * width;
    const y = ((1 - at.y) / 2) * height;
    const half = (entry.width * entry.aspect * RC_LABEL_PX) / 2;
    let row = entry.row;
    const clear = (r) => {
      const bottom = y - (RC_LABEL_LIFT + r) * RC_LABEL_PX;
      return boxes.every(
        (b) => x + half <= b.left || x - half >= b.right || bottom <= b.top || bottom - RC_LABEL_PX >= b.bottom,
      );
    };
    while (row < entry.row + 12 && !clear(row)) row += 1;
    const bottom = y - (RC_LABEL_LIFT + row) * RC_LABEL_PX;
    boxes.push({ left: x - half, right: x + half, top: bottom - RC_LABEL_PX, bottom });
    if (row !== entry.shown) {
      entry.shown = row;
      sprite.center.set(0.5, -RC_LABEL_LIFT - row);
    }
  }
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

// The loaded animation, driven by the scene's control bar (meshcat's Animator).
function rcAnimation(viewer, action, value) {
  const animator = viewer.animator;
  if (action === "clear") {
    // Stopping the actions gives the objects back their own transforms; the scene sends
    // the current ones right after.
    animator.clear();
    return;
  }
  if (!animator.actions.length) return;
  if (action === "play") {
    animator.play();
  } else if (action === "pause") {
    animator.pause();
  } else if (action === "seek") {
    animator.pause();
    // A clip loaded paused is not active yet: activate it so seeking shows the frame.
    for (const clip of animator.actions) clip.play();
    animator.seek(value);
    animator.display_progress(value);
  } else if (action === "speed") {
    animator.mixer.timeScale = value;
  }
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
      const options = op.command.options;
      // meshcat's Animator keeps `playing` from the previous clip: a clip loaded paused
      // would then never advance, nor show its first frame.
      if (op.command.type === "set_animation" && options && !options.play) viewer.animator.pause();
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
      const rows = op.rows || [];
      op.paths.forEach((path, k) => rcDrawLabel(viewer, path, op.texts[k], rows[k]));
    } else if (op.op === "fit") {
      rcFit(viewer, op.radius);
    } else if (op.op === "animation") {
      rcAnimation(viewer, op.action, op.value);
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

// A viewer sized to its element (not the window), with a render loop that stops;
// `onFrame(viewer)` runs after each animation step (the widget reports playback time).
function rcCreateViewer(MeshCat, element, height, onFrame) {
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
  let disposed = false;
  // The page may give the pane another height than asked for (a pinned view is shorter).
  const sizeOf = () => [Math.max(element.clientWidth, 100), element.clientHeight || height || 400];
  const setSize = viewer.set_3d_pane_size.bind(viewer);
  viewer.set_3d_pane_size = (w, h) => {
    if (disposed) return;
    const [width, fallback] = sizeOf();
    viewer.rcPaneSize = [w === undefined ? width : w, h === undefined ? fallback : h];
    setSize(...viewer.rcPaneSize);
    rcSizeLabels(viewer);
  };
  const observer = new ResizeObserver(() => viewer.set_3d_pane_size());
  observer.observe(element);
  let frame = 0;
  const loop = () => {
    if (disposed) return;
    frame = requestAnimationFrame(loop);
    viewer.animator.update();
    if (onFrame) onFrame(viewer);
    if (viewer.needs_render) {
      viewer.controls.update();
      viewer.scene.updateMatrixWorld();
      rcDeclutter(viewer);
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
