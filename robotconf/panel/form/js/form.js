// anywidget front end of robotconf.panel.form.Form: rows of controls drawn from the
// kernel's spec, and what the student does sent back as events.
//
// The kernel holds the truth; this page only shows the spec and reports input. Two rules
// keep the two from fighting:
// - Nothing the kernel sets is ever sent back: an event leaves only on a user's input
//   (a drag, a key, a click), never when a value, range or step changes from the spec.
// - While the student holds a control (a slider being dragged, a box being typed in),
//   its value on screen is theirs; the spec's value is shown once they let go.
// A drag sends each position at once, keeping up to MAX_IN_FLIGHT unanswered events on
// the way (the kernel answers each), so the kernel works on one position while the next
// travels; positions that pile up meanwhile are merged, the newest winning. Every event
// carries the control's `rev`, so an event made before a unit switch or a row change is
// recognised as stale by the kernel.

const MAX_IN_FLIGHT = 3;
// An answer that never comes (an interrupted kernel) must not block the form.
const ANSWER_TIMEOUT_MS = 2000;

// make, showMessage and the control views (VIEWS) come from controls.js, read first.

class Sender {
  constructor(model, answered) {
    this.model = model;
    this.answered = answered;
    this.inFlight = 0;
    this.sequence = 0;
    this.lastSent = 0;
    this.waiting = new Map(); // key -> latest drag event not sent yet
    this.unanswered = new Map(); // seq -> key of an event the kernel has not answered
    model.on("msg:custom", (message) => {
      if (message && message.ack !== undefined) {
        const key = this.unanswered.get(message.ack);
        this.unanswered.delete(message.ack);
        this.inFlight = Math.max(0, this.inFlight - 1);
        this.flush();
        // The kernel has handled the event (its new spec, if any, came first): a control
        // whose input changed nothing shows the kernel's value again.
        if (key !== undefined) this.answered(key);
      }
    });
  }
  send(event, merge) {
    if (merge) {
      this.waiting.set(event.key, event);
    } else {
      // A click or a typed value goes after every drag position sent before it.
      this.waiting.delete(event.key);
      this.flush(true);
      this.post(event);
      return;
    }
    this.flush();
  }
  post(event) {
    this.inFlight += 1;
    this.sequence += 1;
    this.lastSent = performance.now();
    this.unanswered.set(this.sequence, event.key);
    this.model.send(Object.assign({}, event, { seq: this.sequence }));
  }
  // Whether the student's input to `key` is still on its way (the kernel's spec lags).
  busy(key) {
    if (this.waiting.has(key)) return true;
    for (const pending of this.unanswered.values()) if (pending === key) return true;
    return false;
  }
  flush(all) {
    if (this.inFlight > 0 && performance.now() - this.lastSent > ANSWER_TIMEOUT_MS) {
      this.inFlight = 0;
      this.unanswered.clear();
    }
    for (const [key, event] of this.waiting) {
      if (!all && this.inFlight >= MAX_IN_FLIGHT) return;
      this.waiting.delete(key);
      this.post(event);
    }
  }
}

// -- the form ---------------------------------------------------------------------------

const NAVIGATION_KEYS = new Set([
  "ArrowLeft",
  "ArrowRight",
  "ArrowUp",
  "ArrowDown",
  "Home",
  "End",
  "PageUp",
  "PageDown",
]);

// A control without a key of its own (a label, a note) is named by its row, its line and
// its place in the line: named by row and place alone, two lines of one row would share a
// name, and the second line would take the first one's element away.
function controlKey(spec, row, line, index) {
  return spec.key || row.key + "#" + line + "." + index;
}

function shapeOf(rows) {
  return JSON.stringify(
    (rows || []).map((row) => [
      row.key,
      row.class || "",
      (row.lines || []).map((line, n) => line.map((c, i) => [controlKey(c, row, n, i), c.type])),
    ])
  );
}

function render({ model, el }) {
  const sender = new Sender(model, (key) => refresh(key));
  const root = make("div", "rc-form", el);
  // JupyterLab's notebook takes arrow keys for its own shortcuts (a range input is not
  // ":read-write", so command mode claims them): keep them for the form's controls.
  root.addEventListener("keydown", (event) => {
    if (NAVIGATION_KEYS.has(event.key)) event.stopPropagation();
  });
  let views = new Map();
  let rowMessages = new Map();
  let shape = null;

  const specOf = () => JSON.parse(model.get("_spec_json") || "{}");
  const draw = () => {
    const spec = specOf();
    const rows = spec.rows || [];
    root.className = "rc-form" + (spec.class ? " " + spec.class : "");
    const newShape = shapeOf(rows);
    if (newShape !== shape) {
      // Rows or controls came or went: lay the form out again, keeping each control's
      // element (a control the student holds keeps its state).
      shape = newShape;
      const kept = new Map();
      root.textContent = "";
      rowMessages = new Map();
      for (const row of rows) {
        const rowEl = make("div", "rc-row" + (row.class ? " " + row.class : ""), root);
        rowEl.dataset.key = row.key;
        if (row.box) rowEl.classList.add("rc-boxed");
        (row.lines || []).forEach((line, n) => {
          const lineEl = make("div", "rc-line", rowEl);
          line.forEach((control, i) => {
            const key = controlKey(control, row, n, i);
            let view = views.get(key);
            if (!view || view.constructor !== VIEWS[control.type]) {
              view = new VIEWS[control.type](control, sender);
            } else {
              view.render(control);
            }
            view.shown = JSON.stringify(control);
            kept.set(key, view);
            lineEl.appendChild(view.el);
          });
        });
        const message = make("div", "rc-row-message", rowEl);
        rowMessages.set(row.key, message);
        showMessage(message, row.message);
        message.classList.add("rc-row-message");
        message.shown = JSON.stringify(row.message || null);
      }
      views = kept;
      return;
    }
    for (const row of rows) {
      // A q step changes one or two controls of a form of dozens: drawing only what
      // changed keeps the page's style and layout work (most of a drag's cost in the
      // browser) to those.
      (row.lines || []).forEach((line, n) =>
        line.forEach((control, i) => {
          const view = views.get(controlKey(control, row, n, i));
          if (!view) return;
          const text = JSON.stringify(control);
          if (text === view.shown) return;
          view.render(control);
          view.shown = text;
        })
      );
      const message = rowMessages.get(row.key);
      const text = JSON.stringify(row.message || null);
      if (message && text !== message.shown) {
        showMessage(message, row.message);
        message.classList.add("rc-row-message");
        message.shown = text;
      }
    }
  };
  // The kernel answered an event of `key`: that control shows the kernel's value again
  // (its spec may be the same as before, when the input changed nothing).
  const refresh = (key) => {
    const view = views.get(key);
    if (view && view.spec) view.render(view.spec);
  };
  model.on("change:_spec_json", draw);
  draw();
  return () => model.off("change:_spec_json", draw);
}

export default { render };
