// The /psych page: the paper's experiment 1 (or any design the server holds) run in the browser.
// Setup (an opaque participant id and a session label), a calibration against a credit card,
// instructions, practice with feedback, then the blocks with breaks; each main trial is posted to
// the server as it ends. `window.foveal_psych` is the test hook: the state, the trial waiting for
// an answer, and what has been stored (web/test/psych.test.mjs answers through it).

import { Api, type DesignAnswer, Refused, pageToken } from "./api";
import { type Cell, type Design, blocks, practice } from "./design";
import { CARD_HEIGHT_CM, CARD_WIDTH_CM, type Layout, type Point, awayAt, layout, pointAt, pxPerCmOfDisplay } from "./geometry";
import { type Presentation, measureRefresh, present, stall } from "./present";

type State = "loading" | "setup" | "calibration" | "instructions" | "refresh" | "iti" | "stimulus" | "response" | "feedback" | "break" | "done" | "error";

interface HookTrial {
  /** Increases with every presentation (practice included). */
  id: number;
  practice: boolean;
  block: number;
  eccentricity_deg: number;
  direction_deg: number;
  gap_label: string;
  gap_deg: number;
  /** Distractors shown, and where each was at the onset (cm from the fixation, y up). */
  distractors: number;
  distractor_starts: Point[];
  /** The pair's axis drawn for the trial (degrees), where the design draws it. */
  axis_deg: number | null;
  /** Speed of each disc (degrees per second; 0: stationary). */
  speed_deg_s: number;
  /** Whether the fixation cross is hidden during the stimulus. */
  cross_hidden: boolean;
}

const hook = {
  state: "loading" as State,
  trial: null as HookTrial | null,
  /** Main trials posted and acknowledged. */
  stored: 0,
  /** Main trials marked invalid. */
  invalid: 0,
  results: null as string | null,
  error: null as string | null,
  refreshMs: 0,
  /** Block the main thread this long during the next stimulus (tests the late-frame check). */
  stallNextStimulus(ms: number) {
    stall.nextMs = ms;
  },
};
(window as unknown as { foveal_psych: typeof hook }).foveal_psych = hook;

const canvas = document.getElementById("stimulus") as HTMLCanvasElement;
const ctx = canvas.getContext("2d", { alpha: false }) as CanvasRenderingContext2D;
const screen = document.getElementById("screen") as HTMLDivElement;
const api = new Api(pageToken());
const designName = new URLSearchParams(window.location.search).get("design") ?? "experiment1";
const PLAIN = /^[A-Za-z0-9_-]{1,32}$/;

let design: Design;
let info: DesignAnswer;
let pxPerCm = 0;
let pxPerCmSource: "calibration" | "display-flags" = "display-flags";
let crossVisible = false;

function setState(s: State) {
  hook.state = s;
}

function fail(message: string) {
  setState("error");
  hook.error = message;
  document.body.classList.remove("running");
  show(`<h1>The experiment stopped</h1><p class="error"></p><p class="small">Nothing stored so far is lost. Reload the page to start a new session.</p>`);
  (screen.querySelector(".error") as HTMLElement).textContent = message;
}

function show(html: string) {
  screen.innerHTML = `<div class="panel">${html}</div>`;
  screen.hidden = false;
}

function hide() {
  screen.hidden = true;
  screen.innerHTML = "";
}

/** Resolves at the next press of one of `keys` (or a click on `button`, if given). */
function waitKey(keys: string[], button?: HTMLElement | null): Promise<void> {
  return new Promise((resolve) => {
    const onKey = (e: KeyboardEvent) => {
      if (keys.includes(e.key)) {
        e.preventDefault();
        done();
      }
    };
    const done = () => {
      window.removeEventListener("keydown", onKey);
      button?.removeEventListener("click", done);
      resolve();
    };
    window.addEventListener("keydown", onKey);
    button?.addEventListener("click", done);
  });
}

// --- drawing -------------------------------------------------------------------------------

function resize() {
  const dpr = window.devicePixelRatio || 1;
  canvas.width = Math.round(window.innerWidth * dpr);
  canvas.height = Math.round(window.innerHeight * dpr);
  redraw(null);
}

/** Distractor discs at one moment: centres (cm from the fixation), their radius and colour. */
interface Dots {
  centres: Point[];
  radiusCm: number;
  colour: string;
}

/**
 * The screen cleared to black, the fixation cross (unless `hideCross`), `stim`'s discs and the
 * distractors, if given.
 */
function redraw(stim: Layout | null, dots: Dots | null = null, hideCross = false) {
  const dpr = window.devicePixelRatio || 1;
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  ctx.fillStyle = "#000";
  ctx.fillRect(0, 0, canvas.width, canvas.height);
  if (!crossVisible || !design) return;
  // Device pixels, origin at the fixation, y up.
  const s = pxPerCm * dpr;
  ctx.setTransform(s, 0, 0, -s, canvas.width / 2, canvas.height / 2);
  if (!hideCross) {
    const arm = Math.tan(((design.fixation_cross_deg / 2) * Math.PI) / 180) * info.display.viewing_distance_cm;
    ctx.strokeStyle = "#fff";
    ctx.lineWidth = (2 * dpr) / s;
    ctx.beginPath();
    ctx.moveTo(-arm, 0);
    ctx.lineTo(arm, 0);
    ctx.moveTo(0, -arm);
    ctx.lineTo(0, arm);
    ctx.stroke();
  }
  if (dots) {
    ctx.fillStyle = dots.colour;
    for (const c of dots.centres) {
      ctx.beginPath();
      ctx.arc(c[0], c[1], dots.radiusCm, 0, 2 * Math.PI);
      ctx.fill();
    }
  }
  if (!stim) return;
  ctx.fillStyle = "#fff";
  for (const i of [0, 1]) {
    ctx.beginPath();
    ctx.arc(stim.centres[i][0], stim.centres[i][1], stim.radii[i], 0, 2 * Math.PI);
    ctx.fill();
  }
}

/** The pair of `c` with its axis at `axisDeg` (a `random` axis's draw), `awayDeg` out of its closest. */
function layoutOf(c: Cell, axisDeg = 0, awayDeg = 0): Layout {
  return layout(c.eccentricityDeg, c.directionDeg, c.gap.gap_deg, design.stimulus.disc_diameter_deg, design.stimulus.pair_axis, info.display.viewing_distance_cm, axisDeg, awayDeg);
}

/** Each disc's speed, degrees per second (0: stationary). */
function speedDegS(): number {
  return design.stimulus.motion_speed_deg_s ?? 0;
}

/**
 * `n` distractors for one trial: starting uniformly within the design's field about the
 * fixation, each moving in a straight line in its own random direction at the design's speed
 * (converted at the fixation's scale: a degree there is `distance x tan 1°` of screen). Returns
 * their starts and their position at `tMs`.
 */
function distractors(n: number): { starts: Point[]; at: (tMs: number) => Dots | null } {
  const dz = design.distractors;
  if (!dz || n === 0) return { starts: [], at: () => null };
  const d = info.display.viewing_distance_cm;
  const cmPerDeg = d * Math.tan(Math.PI / 180);
  const starts: Point[] = [];
  const velocities: Point[] = [];
  for (let i = 0; i < n; i++) {
    starts.push(pointAt(dz.field_deg * Math.sqrt(Math.random()), 360 * Math.random(), d));
    const a = 2 * Math.PI * Math.random();
    velocities.push([dz.speed_deg_s * cmPerDeg * Math.cos(a), dz.speed_deg_s * cmPerDeg * Math.sin(a)]);
  }
  const radiusCm = d * Math.tan(((design.stimulus.disc_diameter_deg / 2) * Math.PI) / 180);
  const colour = dz.colour === "red" ? "#f00" : "#fff";
  return {
    starts,
    at: (tMs) => ({
      centres: starts.map((p, i) => [p[0] + (velocities[i][0] * tMs) / 1000, p[1] + (velocities[i][1] * tMs) / 1000] as Point),
      radiusCm,
      colour,
    }),
  };
}

/** Why the design's stimuli do not fit this window, or null. */
function offScreen(): string | null {
  const half = [window.innerWidth / 2 / pxPerCm, window.innerHeight / 2 / pxPerCm];
  const widest = Math.max(...design.gaps.map((g) => g.gap_deg));
  // A moving pair is furthest apart at the onset and the offset; a random axis may point anywhere.
  const away = awayAt(0, design.stimulus.duration_ms, speedDegS());
  const axes = design.stimulus.pair_axis === "random" ? [0, 45, 90, 135] : [0];
  for (const e of design.eccentricities_deg)
    for (const d of design.directions_deg)
      for (const axisDeg of axes) {
      const l = layout(e, d, widest, design.stimulus.disc_diameter_deg, design.stimulus.pair_axis, info.display.viewing_distance_cm, axisDeg, away);
      for (const axis of [0, 1]) {
        const reach = Math.max(...[0, 1].map((i) => Math.abs(l.centres[i][axis]) + l.radii[i]));
        if (reach > half[axis]) {
          return `At ${e} degrees in direction ${d} the discs reach ${reach.toFixed(1)} cm from the fixation cross ${axis === 0 ? "sideways" : "up or down"}, but this window leaves ${half[axis].toFixed(1)} cm: make the window full screen (F11), run the server with a shorter --viewing-distance-cm and sit that close, or use a design with smaller eccentricities.`;
        }
      }
    }
  return null;
}

// --- screens ---------------------------------------------------------------------------------

async function setup(): Promise<{ participant: string; session: string }> {
  setState("setup");
  const d = info.display;
  show(`<h1>${escapeHtml(design.title)}</h1>
    <p>Design <b>${escapeHtml(design.name)}</b>: ${info.trials} trials in ${design.blocks} blocks, after ${design.practice_trials} practice trials.</p>
    <label>Participant id <input id="participant" type="text" autocomplete="off" spellcheck="false" placeholder="e.g. P07"></label>
    <label>Session <input id="session" type="text" value="1" autocomplete="off"></label>
    <p class="small">An opaque code (letters, digits, - and _), never a name: the results file is named after it.</p>
    <p class="small">Display (the server's flags): ${d.width_px}x${d.height_px} px, ${d.diagonal_in} inch diagonal, viewed from ${d.viewing_distance_cm} cm. foveal-server ${escapeHtml(info.version)}.</p>
    <p class="error" id="setup-error"></p>
    <button id="next" type="button">Next</button>`);
  const participant = screen.querySelector("#participant") as HTMLInputElement;
  const session = screen.querySelector("#session") as HTMLInputElement;
  const error = screen.querySelector("#setup-error") as HTMLElement;
  participant.focus();
  for (;;) {
    await waitKey(["Enter"], screen.querySelector("#next"));
    const p = participant.value.trim();
    const s = session.value.trim();
    if (!PLAIN.test(p)) error.textContent = "The participant id must be 1 to 32 letters, digits, - or _.";
    else if (!PLAIN.test(s)) error.textContent = "The session must be 1 to 32 letters, digits, - or _.";
    else return { participant: p, session: s };
  }
}

async function calibrate() {
  setState("calibration");
  const dpr = window.devicePixelRatio || 1;
  const fromFlags = pxPerCmOfDisplay(info.display.width_px, info.display.height_px, info.display.diagonal_in, dpr);
  let width = Math.round(CARD_WIDTH_CM * fromFlags);
  show(`<h1>Calibration</h1>
    <p>Hold a credit card (or any ID-1 card, 85.60 mm wide) flat against the screen and make the grey card as wide as it: <kbd>&larr;</kbd> <kbd>&rarr;</kbd> (<kbd>Shift</kbd> for bigger steps) or the slider.</p>
    <div id="card"></div>
    <input id="card-width" type="range" min="100" max="1500" step="1" style="width: 100%">
    <p id="card-note" class="small"></p>
    <button id="accept" type="button">This is the card's size (Enter)</button>
    <button id="skip" type="button">Skip: trust the display flags</button>`);
  const card = screen.querySelector("#card") as HTMLElement;
  const slider = screen.querySelector("#card-width") as HTMLInputElement;
  const note = screen.querySelector("#card-note") as HTMLElement;
  const update = () => {
    width = Math.max(100, Math.min(1500, width));
    card.style.width = `${width}px`;
    card.style.height = `${(width * CARD_HEIGHT_CM) / CARD_WIDTH_CM}px`;
    slider.value = String(width);
    const perCm = width / CARD_WIDTH_CM;
    const diagonal = Math.hypot(window.screen.width, window.screen.height) / perCm / 2.54;
    note.textContent = `${perCm.toFixed(2)} CSS px per cm (the display flags say ${fromFlags.toFixed(2)}); a screen of ${window.screen.width}x${window.screen.height} CSS px would then be ${diagonal.toFixed(1)} inches across.`;
  };
  update();
  slider.addEventListener("input", () => {
    width = Number(slider.value);
    update();
  });
  const onKey = (e: KeyboardEvent) => {
    const step = e.shiftKey ? 10 : 1;
    if (e.key === "ArrowLeft") width -= step;
    else if (e.key === "ArrowRight") width += step;
    else return;
    e.preventDefault();
    update();
  };
  window.addEventListener("keydown", onKey);
  const skipped = await new Promise<boolean>((resolve) => {
    screen.querySelector("#skip")?.addEventListener("click", () => resolve(true));
    void waitKey(["Enter"], screen.querySelector("#accept")).then(() => resolve(false));
  });
  window.removeEventListener("keydown", onKey);
  if (skipped) {
    pxPerCm = fromFlags;
    pxPerCmSource = "display-flags";
  } else {
    pxPerCm = width / CARD_WIDTH_CM;
    pxPerCmSource = "calibration";
  }
}

/** What the participant will see, in one sentence for the instructions. */
function stimulusSentence(): string {
  const dz = design.distractors;
  const others = dz ? ` Other ${dz.colour === "red" ? "red" : "white"} discs will move about the screen at the same time: ignore them.` : "";
  if (speedDegS() > 0) return `Two white discs will move towards each other briefly somewhere around it, meet or nearly meet, and move apart again.${others} Judge the moment they are closest.`;
  return `Two white discs will flash briefly somewhere around it.${others}`;
}

async function instructions() {
  setState("instructions");
  const key = (k: string[]) => k.map((x) => `<kbd>${escapeHtml(x)}</kbd>`).join(" or ");
  const mouse = (b: number | null) => (b === null ? "" : ` or the ${["left", "middle", "right", "back", "forward"][b]} mouse button`);
  const r = design.responses;
  show(`<h1>Instructions</h1>
    <p>Keep your eyes on the ${design.hide_cross_during_stimulus ? "middle of the screen (the cross there disappears while the discs are shown)" : "cross in the middle of the screen"} the whole time. ${stimulusSentence()}</p>
    <p>If the discs <b>touch</b>, press ${key(r.touching.keys)}${mouse(r.touching.mouse_button)}.<br>
    If there is a <b>gap</b> between them, press ${key(r.apart.keys)}${mouse(r.apart.mouse_button)}.</p>
    <p>Answer as well as you can; guess when unsure. First ${design.practice_trials} practice trials, which tell you whether you were right; then ${design.blocks} blocks with a break after each.</p>
    <p>Sit ${info.display.viewing_distance_cm} cm from the screen. Press <kbd>space</kbd> to start (the page goes full screen).</p>
    <button id="start" type="button">Start</button>`);
  await waitKey([" "], screen.querySelector("#start"));
  try {
    if (!document.fullscreenElement) {
      await document.documentElement.requestFullscreen();
      // The window takes its new size over the next frames; the fit check needs it.
      await sleep(300);
    }
  } catch {
    // A browser that refuses full screen runs in the window; the fit check below decides.
  }
}

// --- trials ----------------------------------------------------------------------------------

interface Answered {
  response: "apart" | "touching";
  source: "key" | "mouse";
  at: number;
}

/** The next answer by key or mouse button. */
function answer(): Promise<Answered> {
  return new Promise((resolve) => {
    const r = design.responses;
    const onKey = (e: KeyboardEvent) => {
      const response = r.touching.keys.includes(e.key) ? "touching" : r.apart.keys.includes(e.key) ? "apart" : null;
      if (!response || e.repeat) return;
      e.preventDefault();
      done({ response, source: "key", at: e.timeStamp });
    };
    const onMouse = (e: MouseEvent) => {
      const response = r.touching.mouse_button === e.button ? "touching" : r.apart.mouse_button === e.button ? "apart" : null;
      if (!response) return;
      e.preventDefault();
      done({ response, source: "mouse", at: e.timeStamp });
    };
    const done = (a: Answered) => {
      window.removeEventListener("keydown", onKey);
      window.removeEventListener("mousedown", onMouse);
      resolve(a);
    };
    window.addEventListener("keydown", onKey);
    window.addEventListener("mousedown", onMouse);
  });
}

const sleep = (ms: number) => new Promise((r) => setTimeout(r, ms));
let presentations = 0;

/** One presentation and its answer. */
async function run(cell: Cell, block: number, isPractice: boolean, refreshMs: number): Promise<{ shown: Presentation; answered: Answered; stim: Layout; axisDeg: number | null }> {
  setState("iti");
  await sleep(design.inter_stimulus_ms);
  const axisDeg = design.stimulus.pair_axis === "random" ? 360 * Math.random() : null;
  // The pair at its closest (what the gap is measured on), and at any moment of the motion.
  const stim = layoutOf(cell, axisDeg ?? 0);
  const speed = speedDegS();
  const duration = design.stimulus.duration_ms;
  const pairAt = (tMs: number) => (speed > 0 ? layoutOf(cell, axisDeg ?? 0, awayAt(tMs, duration, speed)) : stim);
  const dots = distractors(cell.distractors);
  const hideCross = design.hide_cross_during_stimulus === true;
  hook.trial = {
    id: ++presentations,
    practice: isPractice,
    block,
    eccentricity_deg: cell.eccentricityDeg,
    direction_deg: cell.directionDeg,
    gap_label: cell.gap.label,
    gap_deg: cell.gap.gap_deg,
    distractors: cell.distractors,
    distractor_starts: dots.starts,
    axis_deg: axisDeg,
    speed_deg_s: speed,
    cross_hidden: hideCross,
  };
  // Listening from before the onset: an answer during the stimulus counts.
  const answered = answer();
  setState("stimulus");
  const shown = await present((t) => redraw(pairAt(t), dots.at(t), hideCross), () => redraw(null), duration, refreshMs, design.timing.late_frame_factor);
  setState("response");
  return { shown, answered: await answered, stim, axisDeg };
}

async function experiment() {
  const { participant, session } = await setup();
  await calibrate();
  await instructions();
  const misfit = offScreen();
  if (misfit) return fail(misfit);
  document.body.classList.add("running");
  hide();
  crossVisible = true;
  redraw(null);
  setState("refresh");
  let refreshMs = await measureRefresh();
  hook.refreshMs = refreshMs;
  const started = await api.startSession({
    participant,
    session,
    design: design.name,
    display: {
      px_per_cm: pxPerCm,
      px_per_cm_source: pxPerCmSource,
      viewing_distance_cm: info.display.viewing_distance_cm,
      window_width_px: window.innerWidth,
      window_height_px: window.innerHeight,
      device_pixel_ratio: window.devicePixelRatio || 1,
      refresh_ms: refreshMs,
    },
  });
  hook.results = started.results;
  const t0 = performance.now();

  // Practice: feedback, nothing stored.
  for (const cell of practice(design)) {
    const { answered } = await run(cell, 1, true, refreshMs);
    const right = (answered.response === "apart") === cell.gap.gap_deg > 0;
    setState("feedback");
    const fb = document.createElement("div");
    fb.id = "feedback";
    fb.textContent = right ? "correct" : "wrong";
    document.body.append(fb);
    await sleep(700);
    fb.remove();
  }

  // The main blocks, each trial stored as it ends, in order.
  let stored: Promise<void> = Promise.resolve();
  let storeError: unknown = null;
  let number = 0;
  const lists = blocks(design);
  for (let b = 0; b < lists.length; b++) {
    setState("break");
    document.body.classList.remove("running");
    crossVisible = false;
    redraw(null);
    const first = b === 0;
    show(`<h1>${first ? "Practice done" : `Block ${b} of ${lists.length} done`}</h1>
      <p>${first ? "" : "Take a break. "}Press <kbd>space</kbd> to start block ${b + 1} of ${lists.length} (${lists[b].length} trials).</p>`);
    await waitKey([" "]);
    hide();
    document.body.classList.add("running");
    crossVisible = true;
    redraw(null);
    refreshMs = await measureRefresh(30);
    hook.refreshMs = refreshMs;
    const queue: { cell: Cell; repeatOf: number | null }[] = lists[b].map((cell) => ({ cell, repeatOf: null }));
    let repeats = 0;
    for (let i = 0; i < queue.length; i++) {
      if (storeError) throw storeError;
      const { cell, repeatOf } = queue[i];
      const { shown, answered, stim, axisDeg } = await run(cell, b + 1, false, refreshMs);
      number++;
      const valid = shown.invalidReason === "";
      if (!valid) {
        hook.invalid++;
        if (repeats < design.timing.max_repeats_per_block) {
          repeats++;
          queue.push({ cell, repeatOf: number });
        }
      }
      const dpr = window.devicePixelRatio || 1;
      const record = {
        trial: number,
        block: b + 1,
        cell: cell.index,
        eccentricity_deg: cell.eccentricityDeg,
        direction_deg: cell.directionDeg,
        gap_label: cell.gap.label,
        gap_deg: cell.gap.gap_deg,
        response: answered.response,
        response_source: answered.source,
        rt_ms: Math.max(0, answered.at - shown.onset),
        valid,
        invalid_reason: shown.invalidReason,
        repeat_of: repeatOf,
        duration_ms: shown.durationMs,
        intended_ms: design.stimulus.duration_ms,
        frames: shown.frameCount,
        refresh_ms: refreshMs,
        onset_ms: Math.max(0, shown.onset - t0),
        gap_px: stim.gapCm * pxPerCm * dpr,
        x_px: stim.contact[0] * pxPerCm,
        y_px: stim.contact[1] * pxPerCm,
        frame_ms: shown.frames,
        distractors: cell.distractors,
        ...(axisDeg === null ? {} : { axis_deg: axisDeg }),
      };
      stored = stored.then(() =>
        api.storeTrial(started.session, record).then(
          () => {
            hook.stored++;
          },
          (e) => {
            storeError = e;
          },
        ),
      );
    }
  }
  await stored;
  if (storeError) throw storeError;
  const end = await api.finish(started.session, true);
  crossVisible = false;
  redraw(null);
  document.body.classList.remove("running");
  if (document.fullscreenElement) await document.exitFullscreen().catch(() => {});
  setState("done");
  show(`<h1>Thank you</h1><p>${end.trials_stored} trials are stored in <b>${escapeHtml(started.results)}</b> in the server's results directory.</p>`);
}

function escapeHtml(s: string): string {
  return s.replace(/[&<>"']/g, (c) => `&#${c.charCodeAt(0)};`);
}

async function main() {
  window.addEventListener("resize", resize);
  window.addEventListener("contextmenu", (e) => e.preventDefault());
  resize();
  try {
    info = await api.design(designName);
    design = info.design;
  } catch (e) {
    const hint = e instanceof Refused && e.status === 401 ? ` Open the page as ${window.location.origin}/psych#token=TOKEN with a gaze (or admin) token.` : "";
    return fail(`${e instanceof Error ? e.message : String(e)}${hint}`);
  }
  try {
    await experiment();
  } catch (e) {
    fail(e instanceof Error ? e.message : String(e));
  }
}

void main();
