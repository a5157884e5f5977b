// Hidden model that carries meshcat's viewer code to the page once per kernel.
// (appended to glue.js)
function rcShared() {
  const shared = (globalThis.__robotconf_scene ??= {});
  if (!shared.ready) {
    shared.ready = new Promise((resolve) => {
      shared.resolve = resolve;
    });
  }
  return shared;
}

function initialize({ model }) {
  const shared = rcShared();
  if (shared.loading) return;
  // Start the import but do not await it: initialize must return quickly.
  shared.loading = rcLoadMeshcat(model.get("source")).then(
    (MeshCat) => shared.resolve(MeshCat),
    (error) => console.error("robotconf: the meshcat viewer failed to load", error),
  );
}

export default { initialize };
