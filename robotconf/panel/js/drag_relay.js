// anywidget front end of robotconf.panel._drag_relay.DragRelay.
//
// ipywidgets sends a slider's new value only after the kernel has answered the previous
// one (one message in flight per widget), so a drag updates the robot once per kernel
// round trip. The relay listens to the sliders' models in the page and forwards every
// value the user drags to as a custom message, keeping up to MAX_IN_FLIGHT unanswered
// ones on the way: the kernel works on one value while the next travels. Values set by
// the kernel itself (undo, a preset) are not sent back.

const MAX_IN_FLIGHT = 3;
// An answer that never comes (a kernel interrupted mid-drag) must not block the relay.
const ANSWER_TIMEOUT_MS = 2000;

function initialize({ model }) {
  let inFlight = 0;
  let sequence = 0;
  let lastSent = 0;
  const waiting = new Map(); // model id -> latest value not sent yet
  let listening = [];

  const flush = () => {
    if (inFlight > 0 && performance.now() - lastSent > ANSWER_TIMEOUT_MS) inFlight = 0;
    for (const [id, value] of waiting) {
      if (inFlight >= MAX_IN_FLIGHT) return;
      waiting.delete(id);
      inFlight += 1;
      sequence += 1;
      lastSent = performance.now();
      model.send({ slider: id, value, seq: sequence });
    }
  };

  const onValue = (slider, value, options) => {
    // A user's move carries the view that made it; the kernel's own updates do not.
    if (!options || !options.updated_view) return;
    waiting.set(slider.model_id, value);
    flush();
  };

  const listen = async () => {
    for (const slider of listening) slider.off("change:value", onValue);
    listening = [];
    waiting.clear();
    const refs = model.get("sliders") || [];
    const manager = model.widget_manager;
    for (const ref of refs) {
      const id = String(ref).replace(/^IPY_MODEL_/, "");
      try {
        const slider = await manager.get_model(id);
        slider.on("change:value", onValue);
        listening.push(slider);
      } catch (error) {
        // A slider closed since the list was sent: the next list replaces it.
      }
    }
  };

  model.on("msg:custom", (message) => {
    if (message && message.ack !== undefined) {
      inFlight = Math.max(0, inFlight - 1);
      flush();
    }
  });
  model.on("change:sliders", listen);
  listen();
  return () => {
    for (const slider of listening) slider.off("change:value", onValue);
  };
}

function render({ el }) {
  el.style.display = "none";
}

export default { initialize, render };
