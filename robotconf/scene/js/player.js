// The page's player of a loaded animation (appended to glue.js).
//
// The page owns the clock: once the kernel loads a motion (meshcat's set_animation builds
// one keyframe action per item, then a "load" op says where to start), each frame moves
// the time on by the frame's duration times the speed and shows the motion there, until
// the end. The bar shows the time as it goes; only a student's drag of its slider seeks.
// The kernel hears of changes only (a student's play, pause, seek or speed, and the end),
// never of each frame, and a kernel command is never reported back.

// A frame longer than this (ms) advances the motion by this much only.
const RC_LONGEST_FRAME_MS = 250;

function rcCreatePlayer(viewer, report) {
  const state = { id: 0, loaded: false, duration: 0, time: 0, speed: 1, playing: false };
  let last = 0;
  const listeners = [];

  const notify = () => {
    for (const listener of listeners) listener(state);
  };
  const send = (event) => {
    if (!report || !state.loaded) return;
    report({
      event,
      time: state.time,
      playing: state.playing,
      speed: state.speed,
      animation: state.id,
    });
  };
  // Show the motion at state.time: every action at that time, the mixer not advanced.
  const show = () => {
    const animator = viewer.animator;
    for (const action of animator.actions) action.time = state.time;
    animator.mixer.update(0);
    viewer.set_dirty();
  };
  const clamp = (t) => Math.min(Math.max(Number(t) || 0, 0), state.duration);

  const player = {
    state,
    onChange(listener) {
      listeners.push(listener);
      listener(state);
    },
    // A command of the kernel (an op): applied, not reported.
    command(op) {
      if (op.action === "load") {
        const animator = viewer.animator;
        // Loaded paused by meshcat: make every action part of the mixer, at our time.
        for (const action of animator.actions) action.play();
        Object.assign(state, {
          id: op.id,
          loaded: true,
          duration: Math.max(0, op.duration),
          speed: op.speed > 0 ? op.speed : 1,
        });
        state.time = clamp(op.time);
        state.playing = Boolean(op.playing) && state.time < state.duration;
        last = performance.now();
        show();
      } else if (op.action === "clear") {
        // The objects keep the frame shown; the kernel sends their transforms next.
        viewer.animator.clear();
        Object.assign(state, { loaded: false, playing: false, time: 0, duration: 0 });
      } else if (!state.loaded) {
        return;
      } else if (op.action === "play") {
        this.play(false);
      } else if (op.action === "pause") {
        this.pause(false);
      } else if (op.action === "seek") {
        this.seek(op.time, false);
      } else if (op.action === "speed") {
        this.setSpeed(op.value, false);
      }
      notify();
    },
    play(byStudent = true) {
      if (!state.loaded || state.playing) return;
      if (state.time >= state.duration) state.time = 0; // an ended motion plays again
      state.playing = true;
      last = performance.now();
      show();
      notify();
      if (byStudent) send("play");
    },
    pause(byStudent = true) {
      if (!state.loaded || !state.playing) return;
      state.playing = false;
      notify();
      if (byStudent) send("pause");
    },
    seek(t, byStudent = true) {
      if (!state.loaded) return;
      state.playing = false;
      state.time = clamp(t);
      show();
      notify();
      if (byStudent) send("seek");
    },
    setSpeed(speed, byStudent = true) {
      if (!(speed > 0) || speed === state.speed) return;
      state.speed = speed;
      notify();
      if (byStudent && state.loaded) send("speed");
    },
    // One animation frame at `now` (performance.now() milliseconds).
    tick(now) {
      if (!state.playing) {
        last = now;
        return;
      }
      // A stalled page (the first render, a tab in the background) resumes where it was
      // instead of skipping part of the motion.
      const elapsed = Math.min(Math.max(0, now - last), RC_LONGEST_FRAME_MS) / 1000;
      last = now;
      state.time = Math.min(state.time + elapsed * state.speed, state.duration);
      if (state.time >= state.duration) state.playing = false;
      show();
      notify();
      if (!state.playing) send("end");
    },
  };
  return player;
}
