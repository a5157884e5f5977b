// The scene's bar above the pane (appended to glue.js): play/pause, speed, time, fit,
// labels mode, frames and trace, drawn by the page.
//
// Classes and ARIA labels (browser tests find the controls by them; keep them stable):
//   .robotconf-scene-controls   the bar (role=toolbar, aria-label "3D view controls")
//   .robotconf-scene-play       play/pause button; aria-label "play" or "pause" (its action)
//   .robotconf-scene-speed      <select>, aria-label "playback speed"; values 0.25 … 4
//   .robotconf-scene-time       <input type=range>, aria-label "animation time" (seconds)
//   .robotconf-scene-clock      "t = 1.25 / 3.00 s"
//   .robotconf-scene-fit        button "fit", aria-label "fit the view"
//   .robotconf-scene-label-mode radio group, aria-label "labels"; buttons role=radio with
//                               data-mode "off" | "names" | "positions" and aria-checked
//   .robotconf-scene-frames     toggle button "frames", aria-pressed
//   .robotconf-scene-trace      toggle button "trace", aria-pressed
// The player's controls follow the page's player; the view options show the kernel's
// values (an "options" op), so a click shows once the kernel took it.

const RC_SPEEDS = [0.25, 0.5, 1, 2, 4];
const RC_LABEL_MODES = [
  ["off", "off"],
  ["names", "names"],
  ["positions", "names + positions"],
];
// JupyterLab's notebook takes these keys for its own shortcuts when focus is on a control
// that is not a text field (a range input or a button): keep them for the bar.
const RC_BAR_KEYS = new Set([
  "ArrowLeft",
  "ArrowRight",
  "ArrowUp",
  "ArrowDown",
  "Home",
  "End",
  "PageUp",
  "PageDown",
  "Enter",
  " ",
]);
// A slider drag reports where it is at most this often (ms), and once at its end.
const RC_SEEK_REPORT_MS = 200;

function rcElement(tag, className, attributes = {}, text = "") {
  const element = document.createElement(tag);
  if (className) element.className = className;
  for (const [name, value] of Object.entries(attributes)) element.setAttribute(name, value);
  if (text) element.textContent = text;
  return element;
}

// ▶ and ⏸ drawn as shapes: not every system font has a pause glyph.
function rcIcon(kind) {
  const svg = document.createElementNS("http://www.w3.org/2000/svg", "svg");
  svg.setAttribute("viewBox", "0 0 16 16");
  svg.setAttribute("width", "12");
  svg.setAttribute("height", "12");
  svg.setAttribute("aria-hidden", "true");
  const shapes =
    kind === "play"
      ? [["polygon", { points: "3,1 14,8 3,15" }]]
      : [["rect", { x: "3", y: "2", width: "3.5", height: "12" }],
         ["rect", { x: "9.5", y: "2", width: "3.5", height: "12" }]];
  for (const [tag, attributes] of shapes) {
    const shape = document.createElementNS("http://www.w3.org/2000/svg", tag);
    for (const [name, value] of Object.entries(attributes)) shape.setAttribute(name, value);
    shape.setAttribute("fill", "currentColor");
    svg.appendChild(shape);
  }
  return svg;
}

function rcFormatSpeed(speed) {
  return `${Number(speed.toPrecision(3))}×`;
}

// The bar; `request(r)` sends a view-option request to the kernel. Returns the element
// and `follow(player)` / `setOptions(op)`.
function rcCreateBar(request) {
  const bar = rcElement("div", "robotconf-scene-controls", {
    role: "toolbar",
    "aria-label": "3D view controls",
  });
  const play = rcElement("button", "robotconf-scene-play", {
    type: "button",
    "aria-label": "play",
    title: "play the animation",
  });
  play.append(rcIcon("play"));
  const speed = rcElement("select", "robotconf-scene-speed", {
    "aria-label": "playback speed",
    title: "playback speed",
  });
  const time = rcElement("input", "robotconf-scene-time", {
    type: "range",
    min: "0",
    max: "1",
    step: "0.001",
    value: "0",
    "aria-label": "animation time",
    title: "drag to show the motion at another time",
  });
  const clock = rcElement("span", "robotconf-scene-clock", {}, "no animation");
  const fit = rcElement("button", "robotconf-scene-fit", {
    type: "button",
    "aria-label": "fit the view",
    title: "centre the robot and zoom until it fills the pane",
  }, "fit");
  const modes = rcElement("span", "robotconf-scene-label-mode", {
    role: "radiogroup",
    "aria-label": "labels",
  });
  modes.append(rcElement("span", "robotconf-scene-caption", {}, "labels"));
  const modeButtons = RC_LABEL_MODES.map(([mode, text]) => {
    const button = rcElement("button", "", {
      type: "button",
      role: "radio",
      "data-mode": mode,
      "aria-checked": "false",
    }, text);
    button.addEventListener("click", () => request({ kind: "labels", mode }));
    modes.append(button);
    return button;
  });
  const toggle = (className, text, title) =>
    rcElement("button", className, { type: "button", "aria-pressed": "false", title }, text);
  const frames = toggle("robotconf-scene-frames", "frames", "x, y, z axes of every frame");
  const trace = toggle("robotconf-scene-trace", "trace", "the end-effector's path in an animation");
  bar.append(play, speed, time, clock, fit, modes, frames, trace);

  bar.addEventListener("keydown", (event) => {
    if (RC_BAR_KEYS.has(event.key)) event.stopPropagation();
  });
  fit.addEventListener("click", () => request({ kind: "fit" }));
  frames.addEventListener("click", () =>
    request({ kind: "frames", value: frames.getAttribute("aria-pressed") !== "true" }),
  );
  trace.addEventListener("click", () =>
    request({ kind: "trace", value: trace.getAttribute("aria-pressed") !== "true" }),
  );

  const setSpeeds = (current) => {
    const values = [...new Set([...RC_SPEEDS, current])].sort((a, b) => a - b);
    const key = values.join(",");
    if (speed.dataset.values !== key) {
      speed.dataset.values = key;
      speed.replaceChildren(
        ...values.map((value) => rcElement("option", "", { value: String(value) }, rcFormatSpeed(value))),
      );
    }
    if (Number(speed.value) !== current) speed.value = String(current);
  };
  setSpeeds(1);

  let player = null;
  let dragging = false;
  let lastSeek = 0;
  const show = (state) => {
    const off = !state.loaded;
    for (const control of [play, speed, time]) control.disabled = off;
    const action = state.playing ? "pause" : "play";
    if (play.getAttribute("aria-label") !== action) {
      play.setAttribute("aria-label", action);
      play.title = `${action} the animation`;
      play.replaceChildren(rcIcon(action));
    }
    setSpeeds(state.speed);
    if (off) {
      clock.textContent = "no animation";
      return;
    }
    const top = String(state.duration || 1);
    if (time.max !== top) {
      time.max = top;
      time.step = String(Math.max(state.duration / 1000, 1e-4));
    }
    if (!dragging) time.value = String(state.time);
    const text = `t = ${state.time.toFixed(2)} / ${state.duration.toFixed(2)} s`;
    if (clock.textContent !== text) clock.textContent = text;
    time.setAttribute("aria-valuetext", `${state.time.toFixed(2)} s of ${state.duration.toFixed(2)} s`);
  };

  play.addEventListener("click", () => {
    if (!player) return;
    if (player.state.playing) player.pause();
    else player.play();
  });
  speed.addEventListener("change", () => {
    if (player) player.setSpeed(Number(speed.value));
  });
  // Only the student moves the slider's value this way ("input" never fires when the
  // player sets it), so following the clock can never seek.
  time.addEventListener("input", () => {
    if (!player) return;
    dragging = true;
    const now = performance.now();
    const report = now - lastSeek >= RC_SEEK_REPORT_MS;
    if (report) lastSeek = now;
    player.seek(Number(time.value), report);
  });
  time.addEventListener("change", () => {
    dragging = false;
    if (player) player.seek(Number(time.value), true);
  });

  return {
    element: bar,
    follow(next) {
      player = next;
      player.onChange(show);
    },
    setOptions(op) {
      bar.hidden = op.controls === false;
      for (const button of modeButtons) {
        const on = button.dataset.mode === op.labels;
        button.setAttribute("aria-checked", String(on));
        button.classList.toggle("robotconf-scene-on", on);
      }
      for (const [button, on] of [[frames, op.frames], [trace, op.trace]]) {
        button.setAttribute("aria-pressed", String(Boolean(on)));
        button.classList.toggle("robotconf-scene-on", Boolean(on));
      }
    },
  };
}
