// The controls of robotconf.panel.form.Form, one class per kind of control, and the
// small helpers they share. The kernel's Python reads this file before form.js and
// joins the two into the widget's one module (anywidget loads a single module).

// A pause in typing this long sends a live field's text.
const TYPING_PAUSE_MS = 150;

function make(tag, className, parent) {
  const el = document.createElement(tag);
  if (className) el.className = className;
  if (parent) parent.appendChild(el);
  return el;
}

function showMessage(el, message) {
  const text = message && message.text ? message.text : "";
  el.textContent = text;
  el.className = "rc-message" + (message && message.tone ? " rc-" + message.tone : "");
  el.style.display = text ? "" : "none";
}

function numberText(value) {
  if (value === null || value === undefined) return "";
  if (typeof value === "number" && !Number.isFinite(value)) return String(value);
  return String(value);
}

// -- controls ---------------------------------------------------------------------------

class NumberView {
  constructor(spec, sender) {
    this.sender = sender;
    this.el = make("span", "rc-control rc-number");
    this.label = make("label", "rc-label", this.el);
    this.slider = make("input", "rc-slider", this.el);
    this.slider.type = "range";
    this.box = make("input", "rc-box", this.el);
    this.box.type = "text";
    this.box.setAttribute("inputmode", "decimal");
    this.box.spellcheck = false;
    this.widen = make("button", "rc-widen", this.el);
    this.widen.type = "button";
    this.widen.textContent = "↔";
    this.widen.title = "double the slider range";
    this.unit = make("span", "rc-unit", this.el);
    this.message = make("span", "rc-message", this.el);
    this.dragging = false;
    this.dirty = false; // the box holds text the student typed and did not send yet
    this.slider.addEventListener("pointerdown", () => (this.dragging = true));
    const release = () => {
      if (!this.dragging) return;
      this.dragging = false;
      this.render(this.spec); // the spec's value, now that the student let go
    };
    this.slider.addEventListener("pointerup", release);
    this.slider.addEventListener("pointercancel", release);
    this.slider.addEventListener("blur", release);
    this.slider.addEventListener("input", () => {
      const value = Number(this.slider.value);
      this.box.value = numberText(value);
      this.dirty = false;
      this.sender.send({ key: this.spec.key, event: "drag", value, rev: this.spec.rev }, true);
    });
    this.box.addEventListener("input", () => {
      this.dirty = true;
      if (!this.spec.live) return;
      // A field whose result shows as it is typed (a formula): tell the kernel after a
      // short pause in typing; it ignores text that is no number yet ("-", "1e").
      clearTimeout(this.typingTimer);
      this.typingTimer = setTimeout(() => {
        const text = this.box.value;
        this.sender.send({ key: this.spec.key, event: "typing", text, rev: this.spec.rev }, true);
      }, TYPING_PAUSE_MS);
    });
    this.box.addEventListener("keydown", (event) => this.onKey(event));
    this.box.addEventListener("change", () => this.typed());
    this.box.addEventListener("blur", () => {
      if (this.dirty) this.typed();
    });
    this.widen.addEventListener("click", () =>
      this.sender.send({ key: this.spec.key, event: "widen", rev: this.spec.rev }, false)
    );
    this.render(spec);
  }
  typed() {
    if (!this.dirty) return;
    this.dirty = false;
    const text = this.box.value;
    this.sender.send({ key: this.spec.key, event: "type", text, rev: this.spec.rev }, false);
  }
  onKey(event) {
    if (event.key === "Enter") {
      event.preventDefault();
      this.dirty = true;
      this.typed();
      return;
    }
    if (event.key !== "ArrowUp" && event.key !== "ArrowDown") return;
    event.preventDefault();
    const current = Number(this.box.value);
    if (!Number.isFinite(current)) return;
    const step = Number(this.spec.step) || 1;
    const sign = event.key === "ArrowUp" ? 1 : -1;
    // Onto the step's grid, as a slider notch would be, then one step further.
    const decimals = Math.max(0, -Math.floor(Math.log10(step)) + 2);
    const value = Number((Math.round(current / step) * step + sign * step).toFixed(decimals));
    this.box.value = numberText(value);
    this.dirty = false;
    this.sender.send({ key: this.spec.key, event: "drag", value, rev: this.spec.rev }, true);
  }
  render(spec) {
    this.spec = spec;
    this.el.className = "rc-control rc-number" + (spec.class ? " " + spec.class : "");
    this.el.dataset.key = spec.key;
    this.label.textContent = spec.label || "";
    this.label.style.display = spec.label ? "" : "none";
    if (spec.label_width) this.label.style.width = spec.label_width;
    const slider = spec.slider !== false;
    this.slider.style.display = slider ? "" : "none";
    this.widen.style.display = slider && spec.widen !== false ? "" : "none";
    this.slider.min = String(spec.min);
    this.slider.max = String(spec.max);
    this.slider.step = String(spec.step);
    for (const part of [this.slider, this.box, this.widen]) part.disabled = !!spec.disabled;
    const name = (spec.label || spec.key) + (spec.unit ? " [" + spec.unit + "]" : "");
    this.slider.setAttribute("aria-label", name);
    this.box.setAttribute("aria-label", name);
    if (spec.width) this.box.style.width = spec.width;
    this.box.title = spec.title || "";
    this.unit.textContent = spec.unit || "";
    this.unit.style.display = spec.unit ? "" : "none";
    showMessage(this.message, spec.message);
    this.box.classList.toggle("rc-refused", !!(spec.message && spec.message.tone === "error"));
    // The student's own value stays while they hold the control or their input to it
    // is on its way; the kernel's value shows once it has answered.
    const held = this.dragging || this.sender.busy(spec.key);
    if (!held && Number.isFinite(spec.value)) this.slider.value = String(spec.value);
    const typing = document.activeElement === this.box && this.dirty;
    if (!typing && !held) {
      this.box.value = spec.text !== undefined && spec.text !== null ? spec.text : numberText(spec.value);
    }
  }
}

class SelectView {
  constructor(spec, sender) {
    this.sender = sender;
    this.el = make("span", "rc-control rc-select");
    this.label = make("label", "rc-label", this.el);
    this.select = make("select", "", this.el);
    this.message = make("span", "rc-message", this.el);
    this.select.addEventListener("change", () => {
      const option = this.spec.options[this.select.selectedIndex];
      if (!option) return;
      this.sender.send({ key: this.spec.key, event: "choose", value: option[1], rev: this.spec.rev }, false);
    });
    this.render(spec);
  }
  render(spec) {
    const old = this.spec;
    this.spec = spec;
    this.el.className = "rc-control rc-select" + (spec.class ? " " + spec.class : "");
    this.el.dataset.key = spec.key;
    this.label.textContent = spec.label || "";
    this.label.style.display = spec.label ? "" : "none";
    if (!old || JSON.stringify(old.options) !== JSON.stringify(spec.options)) {
      this.select.textContent = "";
      for (const [text, value] of spec.options) {
        const option = make("option", "", this.select);
        option.textContent = text;
        option.value = JSON.stringify(value);
      }
    }
    const index = spec.options.findIndex((option) => option[1] === spec.value);
    this.select.selectedIndex = index;
    this.select.disabled = !!spec.disabled;
    this.select.title = spec.title || "";
    this.select.setAttribute("aria-label", spec.label || spec.key);
    if (spec.width) this.select.style.width = spec.width;
    showMessage(this.message, spec.message);
  }
}

class ToggleView {
  constructor(spec, sender) {
    this.sender = sender;
    this.el = make("span", "rc-control rc-toggle");
    this.buttons = [];
    this.render(spec);
  }
  render(spec) {
    const old = this.spec;
    this.spec = spec;
    this.el.className = "rc-control rc-toggle" + (spec.class ? " " + spec.class : "");
    this.el.dataset.key = spec.key;
    this.el.setAttribute("role", "radiogroup");
    if (!old || JSON.stringify(old.options) !== JSON.stringify(spec.options)) {
      this.el.textContent = "";
      if (spec.label) make("label", "rc-label", this.el).textContent = spec.label;
      this.buttons = spec.options.map(([text, value, title]) => {
        const button = make("button", "rc-choice", this.el);
        button.type = "button";
        button.textContent = text;
        if (title) button.title = title;
        button.addEventListener("click", () => {
          if (value === this.spec.value) return;
          this.sender.send({ key: this.spec.key, event: "choose", value, rev: this.spec.rev }, false);
        });
        return button;
      });
    }
    spec.options.forEach(([, value], i) => {
      const button = this.buttons[i];
      const chosen = value === spec.value;
      button.classList.toggle("rc-chosen", chosen);
      button.setAttribute("aria-pressed", chosen ? "true" : "false");
      button.disabled = !!spec.disabled;
    });
  }
}

class ButtonView {
  constructor(spec, sender) {
    this.sender = sender;
    this.el = make("button", "rc-control rc-button");
    this.el.type = "button";
    this.el.addEventListener("click", () =>
      this.sender.send({ key: this.spec.key, event: "click", rev: this.spec.rev }, false)
    );
    this.render(spec);
  }
  render(spec) {
    this.spec = spec;
    this.el.className =
      "rc-control rc-button" + (spec.style ? " rc-" + spec.style : "") + (spec.class ? " " + spec.class : "");
    this.el.dataset.key = spec.key;
    this.el.textContent = spec.label || "";
    this.el.title = spec.title || "";
    this.el.setAttribute("aria-label", spec.title || spec.label || spec.key);
    this.el.disabled = !!spec.disabled;
  }
}

class CheckView {
  constructor(spec, sender) {
    this.sender = sender;
    this.el = make("label", "rc-control rc-check");
    this.box = make("input", "", this.el);
    this.box.type = "checkbox";
    this.text = make("span", "", this.el);
    this.box.addEventListener("change", () =>
      this.sender.send({ key: this.spec.key, event: "check", value: this.box.checked, rev: this.spec.rev }, false)
    );
    this.render(spec);
  }
  render(spec) {
    this.spec = spec;
    this.el.className = "rc-control rc-check" + (spec.class ? " " + spec.class : "");
    this.el.dataset.key = spec.key;
    this.text.textContent = spec.label || "";
    this.box.checked = !!spec.value;
    this.box.disabled = !!spec.disabled;
    this.el.title = spec.title || "";
  }
}

class TextView {
  constructor(spec) {
    this.el = make("span", "rc-control rc-text");
    this.render(spec);
  }
  render(spec) {
    this.spec = spec;
    this.el.className =
      "rc-control rc-text" + (spec.tone ? " rc-" + spec.tone : "") + (spec.class ? " " + spec.class : "");
    if (spec.key) this.el.dataset.key = spec.key;
    // Text only: whatever it says (a module's name from a file) is never markup.
    this.el.textContent = spec.value || "";
    this.el.title = spec.title || "";
    this.el.style.display = spec.value ? "" : "none";
  }
}

class ImageView {
  constructor(spec) {
    this.el = make("img", "rc-control rc-image");
    this.render(spec);
  }
  render(spec) {
    this.spec = spec;
    // Only pictures the kernel drew (PNG data); nothing that could load from elsewhere.
    const src = typeof spec.src === "string" && spec.src.startsWith("data:image/png;base64,") ? spec.src : "";
    if (this.el.getAttribute("src") !== src) this.el.setAttribute("src", src);
    this.el.alt = spec.alt || "";
    if (spec.key) this.el.dataset.key = spec.key;
    this.el.style.width = spec.width || "";
    this.el.style.maxWidth = "100%";
  }
}

class FieldView {
  constructor(spec, sender) {
    this.sender = sender;
    this.el = make("label", "rc-control rc-field");
    this.label = make("span", "rc-label", this.el);
    this.input = make("input", "rc-box rc-text-box", this.el);
    this.input.type = "text";
    this.input.spellcheck = false;
    this.dirty = false;
    this.input.addEventListener("input", () => (this.dirty = true));
    const send = () => {
      if (!this.dirty) return;
      this.dirty = false;
      this.sender.send({ key: this.spec.key, event: "type", text: this.input.value, rev: this.spec.rev }, false);
    };
    this.input.addEventListener("change", send);
    this.input.addEventListener("keydown", (event) => {
      if (event.key === "Enter") send();
    });
    this.render(spec);
  }
  render(spec) {
    this.spec = spec;
    this.el.className = "rc-control rc-field" + (spec.class ? " " + spec.class : "");
    this.el.dataset.key = spec.key;
    this.label.textContent = spec.label || "";
    this.label.style.display = spec.label ? "" : "none";
    if (spec.width) this.input.style.width = spec.width;
    this.input.setAttribute("aria-label", spec.label || spec.key);
    const typing = document.activeElement === this.input && this.dirty;
    if (!typing && !this.sender.busy(spec.key)) this.input.value = spec.value || "";
  }
}

class LinkView {
  constructor(spec) {
    this.el = make("a", "rc-control rc-link");
    this.render(spec);
  }
  render(spec) {
    this.spec = spec;
    // A download the kernel made (a data: URI), nothing that loads from elsewhere.
    const href = typeof spec.href === "string" && spec.href.startsWith("data:") ? spec.href : "";
    if (this.el.getAttribute("href") !== href) this.el.setAttribute("href", href);
    this.el.setAttribute("download", spec.download || "download");
    this.el.target = "_blank";
    this.el.textContent = spec.label || "";
    this.el.className = "rc-control rc-link" + (spec.class ? " " + spec.class : "");
    if (spec.key) this.el.dataset.key = spec.key;
  }
}

const VIEWS = {
  number: NumberView,
  select: SelectView,
  toggle: ToggleView,
  button: ButtonView,
  check: CheckView,
  text: TextView,
  image: ImageView,
  field: FieldView,
  link: LinkView,
};
