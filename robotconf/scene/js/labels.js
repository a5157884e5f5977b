// Labels drawn by the page over the 3D pane (appended to glue.js).
//
// The kernel sends a text per label anchor (an invisible object at the labelled point,
// whose userData.clearance is the radius of the sphere drawn there). Before each render
// the page projects every anchor into the pane and writes its text in a small box just
// above that sphere, at one size at any zoom. A box never covers another box nor another
// labelled point: it moves up or down, or to a side, until it is clear, and a box that
// ends up more than RC_LABEL_NEAR pixels from its sphere gets a leader line to the point,
// so every label reads as its own point's. Long texts (merged labels such as
// "M4, M5, M6 (0.45, -0.15, 0.43)") wrap inside the pane: names on one line, the position
// on the next.

const RC_LABEL_FONT = "600 12px sans-serif";
const RC_LABEL_LINE = 15; // px per line of text
const RC_LABEL_PAD_X = 5; // px of padding left and right (plus a 1 px border)
const RC_LABEL_PAD_Y = 1; // px of padding above and below (plus a 1 px border)
const RC_LABEL_GAP = 3; // px between a point's sphere and the nearest edge of its label
const RC_LABEL_NEAR = 20; // px: a label farther than this from its sphere gets a leader line
const RC_LABEL_STEP = 4; // px between the positions tried around a point
const RC_LABEL_REACH = 160; // px: how far from its point a label may move
const RC_LABEL_MARK = 5; // px: at least half the side of the square kept clear at a point
const RC_LABEL_CELL = 48; // px: cell of the grid that finds nearby boxes

function rcCreateLabelLayer(viewer, element) {
  const layer = document.createElement("div");
  layer.className = "robotconf-scene-overlay";
  const svg = document.createElementNS("http://www.w3.org/2000/svg", "svg");
  svg.setAttribute("class", "robotconf-scene-leaders");
  layer.appendChild(svg);
  (element.parentElement || element).appendChild(layer);
  const context = document.createElement("canvas").getContext("2d");
  context.font = RC_LABEL_FONT;
  viewer.rcLabels = {
    layer,
    svg,
    entries: new Map(),
    wrapAt: 0,
    vector: null,
    measure: (text) => context.measureText(text).width,
  };
}

// The widest a label's text may be: 40 % of the pane, within 90 and 280 pixels.
function rcLabelWrapWidth(viewer) {
  const width = (viewer.rcPaneSize && viewer.rcPaneSize[0]) || 400;
  return Math.min(Math.max(0.4 * width, 90), 280) - 2 * (RC_LABEL_PAD_X + 1);
}

// Lines of `text` at most `wrapAt` pixels wide (as `measure` gives them), broken at
// spaces; a name list and its position "(x, y, z)" go on separate lines first.
function rcWrapLabel(text, wrapAt, measure) {
  if (!text) return [];
  if (measure(text) <= wrapAt) return [text];
  const open = text.indexOf(" (");
  const parts =
    open > 0 && text.endsWith(")") ? [text.slice(0, open), text.slice(open + 1)] : [text];
  const lines = [];
  for (const part of parts) {
    let line = "";
    for (const word of part.split(" ")) {
      const longer = line ? line + " " + word : word;
      if (line && measure(longer) > wrapAt) {
        lines.push(line);
        line = word;
      } else {
        line = longer;
      }
    }
    if (line) lines.push(line);
  }
  // A single word wider than the pane allows is cut where it must be.
  const out = [];
  for (let line of lines) {
    while (measure(line) > wrapAt && line.length > 1) {
      let cut = line.length - 1;
      while (cut > 1 && measure(line.slice(0, cut)) > wrapAt) cut -= 1;
      out.push(line.slice(0, cut));
      line = line.slice(cut);
    }
    out.push(line);
  }
  return out;
}

function rcSetLabels(viewer, paths, texts) {
  const labels = viewer.rcLabels;
  if (!labels) return;
  paths.forEach((path, k) => {
    let entry = labels.entries.get(path);
    if (!entry) {
      const el = document.createElement("div");
      el.className = "robotconf-scene-label";
      el.dataset.path = path;
      el.hidden = true;
      const leader = document.createElementNS("http://www.w3.org/2000/svg", "line");
      leader.setAttribute("class", "robotconf-scene-leader");
      leader.dataset.path = path;
      leader.style.display = "none";
      labels.layer.appendChild(el);
      labels.svg.appendChild(leader);
      entry = { path, parts: rcSplitPath(path).concat(["<object>"]), el, leader, text: null };
      entry.lines = [];
      entry.width = 0;
      entry.height = 0;
      entry.placed = "";
      entry.line = "";
      labels.entries.set(path, entry);
    }
    const text = String(texts[k] ?? "");
    if (text !== entry.text) {
      entry.text = text;
      rcShapeLabel(viewer, entry);
    }
  });
}

// Wrap and size one label's box (only when its text or the pane's width changes).
function rcShapeLabel(viewer, entry) {
  const labels = viewer.rcLabels;
  labels.wrapAt = rcLabelWrapWidth(viewer);
  entry.lines = rcWrapLabel(entry.text, labels.wrapAt, labels.measure);
  const widest = Math.max(0, ...entry.lines.map((line) => labels.measure(line)));
  entry.width = Math.ceil(widest) + 2 * (RC_LABEL_PAD_X + 1) + 2;
  entry.height = entry.lines.length * RC_LABEL_LINE + 2 * (RC_LABEL_PAD_Y + 1);
  entry.el.textContent = entry.lines.join("\n"); // text, never markup
  entry.el.style.width = entry.width + "px";
  entry.el.style.height = entry.height + "px";
}

function rcResizeLabels(viewer) {
  const labels = viewer.rcLabels;
  if (!labels || labels.wrapAt === rcLabelWrapWidth(viewer)) return;
  for (const entry of labels.entries.values()) rcShapeLabel(viewer, entry);
}

// The scene node at `parts`, without creating one (meshcat's find() creates what it misses).
function rcNode(viewer, parts) {
  let node = viewer.scene_tree;
  for (const part of parts) {
    node = node.children[part];
    if (!node) return null;
  }
  return node;
}

// After a delete, forget the labels whose anchors went with it.
function rcForgetLabels(viewer) {
  const labels = viewer.rcLabels;
  if (!labels) return;
  for (const [path, entry] of labels.entries) {
    if (!rcNode(viewer, entry.parts)) {
      entry.el.remove();
      entry.leader.remove();
      labels.entries.delete(path);
    }
  }
}

// Whether the object and every group above it are visible (a hidden layer, a "labels off").
function rcVisible(object) {
  for (let node = object; node; node = node.parent) if (!node.visible) return false;
  return true;
}

function rcHideLabel(entry) {
  if (!entry.el.hidden) entry.el.hidden = true;
  if (entry.leader.style.display !== "none") entry.leader.style.display = "none";
  entry.placed = "";
}

// Boxes on a coarse grid, so a label is checked only against the boxes near it.
function rcBoxGrid() {
  const cells = new Map();
  const keys = (box) => {
    const out = [];
    const i0 = Math.floor(box.left / RC_LABEL_CELL);
    const i1 = Math.floor(box.right / RC_LABEL_CELL);
    const j0 = Math.floor(box.top / RC_LABEL_CELL);
    const j1 = Math.floor(box.bottom / RC_LABEL_CELL);
    for (let i = i0; i <= i1; i++) for (let j = j0; j <= j1; j++) out.push(i + "," + j);
    return out;
  };
  return {
    add(box) {
      for (const key of keys(box)) {
        if (!cells.has(key)) cells.set(key, []);
        cells.get(key).push(box);
      }
    },
    clear(box, owner) {
      for (const key of keys(box)) {
        for (const other of cells.get(key) || []) {
          if (other.owner === owner) continue;
          const apart =
            box.right <= other.left || box.left >= other.right ||
            box.bottom <= other.top || box.top >= other.bottom;
          if (!apart) return false;
        }
      }
      return true;
    },
  };
}

// Where a label of `width` × `height` goes for a point at (x, y) whose sphere is `radius`
// pixels, in a pane of `paneWidth` × `paneHeight`: the first clear box (isClear) nearest
// the sphere, trying above, below, right and left at growing distances; inside the pane.
function rcPlaceLabel(x, y, radius, width, height, paneWidth, paneHeight, isClear) {
  const gap = radius + RC_LABEL_GAP;
  const inside = (left, top) => {
    left = Math.min(Math.max(left, 1), Math.max(1, paneWidth - width - 1));
    top = Math.min(Math.max(top, 1), Math.max(1, paneHeight - height - 1));
    return { left, top, right: left + width, bottom: top + height };
  };
  const first = inside(x - width / 2, y - gap - height);
  for (let off = 0; off <= RC_LABEL_REACH; off += RC_LABEL_STEP) {
    const tries = [
      [x - width / 2, y - gap - height - off],
      [x - width / 2, y + gap + off],
      [x + gap + off, y - height / 2],
      [x - gap - off - width, y - height / 2],
    ];
    for (const [left, top] of tries) {
      const box = inside(left, top);
      if (isClear(box)) return box;
    }
  }
  return first;
}

// How far the point (x, y) is from the box, and the box's point nearest to it.
function rcNearest(x, y, box) {
  const nx = Math.min(Math.max(x, box.left), box.right);
  const ny = Math.min(Math.max(y, box.top), box.bottom);
  return [Math.hypot(nx - x, ny - y), nx, ny];
}

function rcLayoutLabels(viewer) {
  const labels = viewer.rcLabels;
  const camera = viewer.camera;
  if (!labels || !labels.entries.size || !camera) return;
  const [width, height] = viewer.rcPaneSize || [1, 1];
  const vector = (labels.vector ??= camera.position.clone());
  const shown = [];
  for (const entry of labels.entries.values()) {
    const node = entry.text ? rcNode(viewer, entry.parts) : null;
    const anchor = node && node.object;
    if (!anchor || !rcVisible(anchor.parent)) {
      rcHideLabel(entry);
      continue;
    }
    // The sphere's radius on screen: its world radius over the depth, at the pane's scale.
    const m = anchor.matrixWorld.elements;
    const world = (anchor.userData.clearance || 0) * Math.hypot(m[0], m[1], m[2]);
    vector.setFromMatrixPosition(anchor.matrixWorld).applyMatrix4(camera.matrixWorldInverse);
    const depth = -vector.z;
    const focal = height / 2 / Math.tan((camera.fov * Math.PI) / 360);
    const radius = depth > 0 ? Math.min((world * focal) / depth, 80) : 0;
    vector.setFromMatrixPosition(anchor.matrixWorld).project(camera);
    const x = ((vector.x + 1) / 2) * width;
    const y = ((1 - vector.y) / 2) * height;
    if (vector.z > 1 || vector.z < -1 || x < 0 || x > width || y < 0 || y > height) {
      rcHideLabel(entry); // its point is not in the picture
      continue;
    }
    shown.push([entry, x, y, radius]);
  }
  const grid = rcBoxGrid();
  for (const [entry, x, y, radius] of shown) {
    const m = Math.max(RC_LABEL_MARK, 0.7 * radius);
    grid.add({ left: x - m, right: x + m, top: y - m, bottom: y + m, owner: entry });
  }
  for (const [entry, x, y, radius] of shown) {
    const box = rcPlaceLabel(x, y, radius, entry.width, entry.height, width, height, (b) =>
      grid.clear(b, entry),
    );
    grid.add({ ...box, owner: entry });
    const placed = `${Math.round(box.left)},${Math.round(box.top)}`;
    if (placed !== entry.placed) {
      entry.placed = placed;
      entry.el.style.transform = `translate(${Math.round(box.left)}px, ${Math.round(box.top)}px)`;
    }
    const point = `${x.toFixed(1)},${y.toFixed(1)},${radius.toFixed(1)}`;
    if (entry.el.dataset.point !== point) entry.el.dataset.point = point;
    if (entry.el.hidden) entry.el.hidden = false;
    const [distance, nx, ny] = rcNearest(x, y, box);
    if (distance > radius + RC_LABEL_NEAR) {
      const line = `${x.toFixed(1)},${y.toFixed(1)},${nx.toFixed(1)},${ny.toFixed(1)}`;
      if (line !== entry.line) {
        entry.line = line;
        const [x1, y1, x2, y2] = line.split(",");
        entry.leader.setAttribute("x1", x1);
        entry.leader.setAttribute("y1", y1);
        entry.leader.setAttribute("x2", x2);
        entry.leader.setAttribute("y2", y2);
      }
      if (entry.leader.style.display === "none") entry.leader.style.display = "";
    } else if (entry.leader.style.display !== "none") {
      entry.leader.style.display = "none";
    }
  }
}
