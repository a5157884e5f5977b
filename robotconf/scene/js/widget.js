// anywidget front end of robotconf.scene.Scene (appended to glue.js and the other parts).

// anywidget imports this module once per model, so page-wide state lives on globalThis:
// the viewer code arrives once per kernel through a hidden model (see loader.js).
function rcShared() {
  const shared = (globalThis.__robotconf_scene ??= {});
  if (!shared.ready) {
    shared.ready = new Promise((resolve) => {
      shared.resolve = resolve;
    });
  }
  return shared;
}

function rcTimeout(promise, ms) {
  return Promise.race([
    promise,
    new Promise((_, reject) => setTimeout(() => reject(new Error("timeout")), ms)),
  ]);
}

async function render({ model, el }) {
  let handle = null;
  let closed = false;
  const page = rcScenePage(el, model.get("height"), (message) => model.send(message));
  const view = Math.random().toString(36).slice(2);
  const pending = [];
  let replayed = false;
  const onMessage = (msg, buffers) => {
    if (msg.kind === "replay" && msg.view !== view) return;
    if (msg.kind !== "batch" && msg.kind !== "replay") return;
    // Batches sent before our replay are part of it: applying them too would load an
    // animation the replay then loads again.
    if (msg.kind === "replay") replayed = true;
    else if (!replayed) return;
    if (handle) rcApply(handle.viewer, msg.ops, buffers);
    else pending.push([msg, buffers]);
  };
  model.on("msg:custom", onMessage);
  // Views drop what was sent before they existed: ask the kernel for the scene log.
  model.send({ kind: "hello", view });

  try {
    const MeshCat = await rcTimeout(rcShared().ready, 20000);
    if (closed) return () => {};
    handle = rcStartViewer(MeshCat, page);
    el.dataset.robotconfScene = "ready";
    el.robotconfViewer = handle.viewer; // for the page's own tools and benchmarks
    for (const [msg, buffers] of pending.splice(0)) rcApply(handle.viewer, msg.ops, buffers);
  } catch (error) {
    page.status.textContent =
      "The 3D viewer did not load (" + error.message + "). Run the cell again; " +
      "scene.export_html(path) saves a copy that opens in any browser.";
    el.dataset.robotconfScene = "failed";
  }
  return () => {
    closed = true;
    model.off("msg:custom", onMessage);
    if (handle) handle.dispose();
  };
}

export default { render };
