// foveal viewer: the scene from GetScene, frames from WatchFrames (quantised poses and the
// collision list), the mouse as gaze through PushGaze, controls through Configure, and live plots.
// It reconnects by itself when the server goes away and comes back.
import { fromBinary, toBinary, type MessageInitShape } from "@bufbuild/protobuf";
import { Code, ConnectError } from "@connectrpc/connect";
import {
  FixationSource,
  FrameSchema,
  SceneConfigSchema,
  type Frame,
  type SceneConfig,
  type SceneDescription,
} from "./gen/foveal/v1/foveal_pb";
import {
  SCHEDULERS,
  TRUTHS,
  formatBudget,
  formatModel,
  parseBudget,
  parseModel,
  schedulerName,
  truthMeaning,
  truthName,
} from "./config";
import { MouseGaze } from "./gaze";
import { Overlay, fovealRadius } from "./overlay";
import { Plots } from "./plots";
import { FirstContacts, starGap } from "./focus";
import { applyPoses, applyQuantisedPoses, forEachPair } from "./poses";
import { connect, pageToken } from "./rpc";
import { COLOURS, SceneView } from "./scene";
import { starDims } from "./star";

function el<T extends HTMLElement>(id: string): T {
  const e = document.getElementById(id);
  if (!e) throw new Error(`page element #${id} is missing`);
  return e as T;
}

/** What the page measured, for the status panel and for the browser tests. */
const stats = {
  connected: false,
  lastError: "",
  framesReceived: 0,
  framesApplied: 0,
  lastIndex: -1,
  bodies: 0,
  /** Pose decode + instance matrix and colour update per applied frame, ms (last 300). */
  updateMs: [] as number[],
  /** Protobuf parse of a whole Frame message, ms, timed on every 10th frame (last 60). */
  parseMs: [] as number[],
  frameBytes: 0,
  /** Smoothed cost of drawing the scene once, ms. */
  drawMs: 0,
};

const token = pageToken();
const client = connect(window.location.origin, token);
const view = new SceneView(el<HTMLCanvasElement>("scene"));
const overlay = new Overlay(el<HTMLCanvasElement>("overlay"));
const plots = new Plots(el("plots"), 360);
const gaze = new MouseGaze(client, el("scene"));

let scene: SceneDescription | null = null;
let region: { rx: number; ry: number } | null = null;
let lastFrame: Frame | null = null;
let paused = false;
let restart: AbortController | null = null;
const arrivals: number[] = [];

/** A first contact the view stopped at (see "Focus on a first contact" below). */
interface FocusedContact {
  /** The two bodies, a < b. */
  pair: [number, number];
  frame: number;
  simTimeS: number;
  /** The truth in force ("shape", "leaf-spheres"). */
  truth: string;
  /** Star radius R, scene units. */
  radius: number;
  /** How far apart the drawn stars are at the frame's poses, scene units (<= 0: they touch). */
  gap: number;
  /** The two bodies' centres, world. */
  centres: [number[], number[]];
  /** On each star, the surface point nearest the other (where the gap is measured), world. */
  ends: [number[], number[]];
}
const focus = {
  /** Waiting for the next first contact to stop at (the F key, or `#focus` in the address). */
  armed: new URLSearchParams(window.location.hash.slice(1)).has("focus"),
  found: null as FocusedContact | null,
};

(window as unknown as { foveal: unknown }).foveal = { stats, view, gaze, focus };

// ------------------------------------------------------------------------------------ layout

function layout(): void {
  const box = el("view-box");
  const aspect = scene?.camera?.aspect || 1.6;
  const w = Math.max(100, Math.min(box.clientWidth, box.clientHeight * aspect));
  const h = w / aspect;
  for (const id of ["scene", "overlay"]) {
    const c = el<HTMLCanvasElement>(id);
    c.style.width = `${w}px`;
    c.style.height = `${h}px`;
  }
  view.resize(w, h);
  overlay.resize(Math.round(w), Math.round(h));
}
window.addEventListener("resize", layout);

// ------------------------------------------------------------------------------------ status

function setStatus(text: string, kind: "ok" | "error" | "info"): void {
  const s = el("status");
  s.textContent = text;
  s.className = kind;
}

function describe(e: unknown): string {
  if (e instanceof ConnectError) {
    if (e.code === Code.Unauthenticated) {
      return `${e.rawMessage} (this server wants a token: open ${window.location.origin}/#token=YOUR_TOKEN)`;
    }
    if (e.code === Code.PermissionDenied) {
      return `${e.rawMessage} (a gaze token sends the mouse, an admin token changes the scene)`;
    }
    return e.code === Code.Unknown ? e.rawMessage : `${Code[e.code]}: ${e.rawMessage}`;
  }
  return e instanceof Error ? e.message : String(e);
}

// ------------------------------------------------------------------------------------ frames

function onFrame(f: Frame): void {
  stats.framesReceived++;
  const now = performance.now();
  arrivals.push(now);
  while (arrivals.length && arrivals[0] < now - 1000) arrivals.shift();
  if (paused) return;

  const t0 = performance.now();
  const bodies = show(f);
  // The full tessellation where the viewer looks: every body reaching into the foveal region.
  const fix = f.fixation;
  view.setDetailRegion(fix && region ? { x: fix.x, y: fix.y, rx: region.rx, ry: region.ry } : null);
  view.commit();
  const t1 = performance.now();
  push(stats.updateMs, t1 - t0, 300);
  if (stats.framesReceived % 10 === 0) {
    const bytes = toBinary(FrameSchema, f);
    const p0 = performance.now();
    fromBinary(FrameSchema, bytes);
    push(stats.parseMs, performance.now() - p0, 60);
    stats.frameBytes = bytes.length;
  }
  stats.framesApplied++;
  stats.lastIndex = Number(f.index);
  stats.bodies = bodies;
  lastFrame = f;

  const m = f.metrics;
  if (m) {
    const budget = scene?.config?.budget?.kind;
    let use: number | null = null;
    if (budget?.case === "sphereTests" && budget.value > 0n) use = Number(m.sphereTests) / Number(budget.value);
    else if (budget?.case === "wallMs" && budget.value > 0) {
      // A wall-clock budget covers the whole frame, integration to metrics.
      const p = f.profile;
      const stepS = p ? p.renumberS + p.integrateS + p.broadS + p.prioritiseS + p.narrowS + p.responseS + p.measureS : m.collisionTimeS;
      use = (1000 * stepS) / budget.value;
    }
    else if (budget?.case === "exact") use = 0;
    const candidates = Number(m.candidatePairs);
    plots.push({
      t: f.simTimeS,
      collisionMs: 1000 * m.collisionTimeS,
      geometric: m.geometricInaccuracy,
      perceived: m.perceivedInaccuracy,
      truePerceived: m.audit ? m.audit.truePerceivedInaccuracy : null,
      budgetUse: use,
      deemedShare: candidates ? Number(m.deemedAtInterruption) / candidates : 0,
      fps: arrivals.length,
    });
  }
}

/** Draw a frame's poses and collision colours; returns the bodies written. */
function show(f: Frame): number {
  const matrices = view.matrices();
  let bodies = 0;
  if (f.quantisedPoses) bodies = applyQuantisedPoses(f.quantisedPoses, matrices);
  else if (f.poses) bodies = applyPoses(f.poses, matrices);
  view.posesWritten(bodies);
  const c = f.collisions;
  view.colour((set) => {
    if (!c) return;
    forEachPair(c.real, (a, b) => (set(a, COLOURS.real), set(b, COLOURS.real)));
    forEachPair(c.deemed, (a, b) => (set(a, COLOURS.deemed), set(b, COLOURS.deemed)));
  });
  return bodies;
}

// ------------------------------------------------------------------------ focus on a first contact

// While armed, a second stream watches every frame (the page's own stream may skip frames) with
// exact poses, and the first frame in which a pair turns green, a real collision that was not one
// in the frame before, is shown and held: the view pauses there, framed on that pair, and the
// page measures how far apart the two drawn stars are. The stream outlives a change of scene made
// from the page's controls, so that the new scene's first contacts are seen from its first frame;
// a contact in a scene the page has not loaded yet is held until it has.
const contacts = new FirstContacts();
let hunt: AbortController | null = null;
let pending: { f: Frame; pair: [number, number] } | null = null;

async function startHunt(): Promise<void> {
  hunt?.abort();
  pending = null;
  if (!focus.armed) return;
  const mine = new AbortController();
  hunt = mine;
  contacts.reset();
  try {
    const frames = client.watchFrames(
      { everyK: 1, includePoses: true, quantisedPoses: false, includeCollisions: true },
      { signal: mine.signal },
    );
    for await (const f of frames) {
      if (!focus.armed) break;
      const real: [number, number][] = [];
      if (f.collisions) forEachPair(f.collisions.real, (a, b) => real.push([a, b]));
      const fresh = contacts.next(Number(f.index), f.simTimeS, real);
      if (fresh.length) {
        pending = { f, pair: fresh[0] };
        focusPending();
        break;
      }
    }
  } catch {
    // A lost server: the session reports it, reconnects and starts the hunt again.
  } finally {
    mine.abort();
    if (hunt === mine) hunt = null;
  }
}

/** Show the contact found, once the page has loaded its scene (same number of bodies). */
function focusPending(): void {
  const p = pending;
  if (!p || !scene || p.f.poses?.bodies !== scene.config?.bodies) return;
  pending = null;
  const [a, b] = p.pair;
  const bodies = show(p.f);
  stats.bodies = bodies;
  lastFrame = p.f;
  const m = view.matrices();
  const dims = starDims(scene);
  if (a >= bodies || b >= bodies) return;
  const { gap, ends } = starGap(dims, { m, o: 16 * a }, { m, o: 16 * b });
  const centre = (i: number) => [m[16 * i + 12], m[16 * i + 13], m[16 * i + 14]];
  focus.found = {
    pair: [a, b],
    frame: Number(p.f.index),
    simTimeS: p.f.simTimeS,
    truth: truthName(scene.config?.truth),
    radius: dims.radius,
    gap,
    centres: [centre(a), centre(b)],
    ends,
  };
  focus.armed = false;
  view.focusOn(a, b, m.subarray(0, 16 * bodies), dims.radius);
  // The pair in its colour, every other body dimmed.
  view.colour((set) => (set(a, COLOURS.real), set(b, COLOURS.real)), true);
  setPaused(true);
}

/** What the overlay says about the pair in focus. */
function focusLabel(c: FocusedContact): string[] {
  const r = c.gap / c.radius;
  return [
    `first contact at t = ${c.simTimeS.toFixed(3)} s: bodies ${c.pair[0]} and ${c.pair[1]} (the others dimmed)`,
    `truth ${c.truth}: a real collision; the drawn stars ` +
      (r > 0.005 ? `are ${r.toFixed(2)}R apart` : r < -0.005 ? `touch (overlap ${(-r).toFixed(2)}R)` : "touch"),
  ];
}

function setFocusArmed(on: boolean): void {
  focus.armed = on;
  if (on) {
    focus.found = null;
    if (paused) setPaused(false);
    view.resetView();
    void startHunt();
  } else hunt?.abort();
}

function push(a: number[], v: number, keep: number): void {
  a.push(v);
  if (a.length > keep) a.shift();
}

function median(a: number[]): number {
  if (!a.length) return NaN;
  const s = [...a].sort((x, y) => x - y);
  return s[Math.floor(s.length / 2)];
}

// ------------------------------------------------------------------------------------ session

async function session(): Promise<void> {
  const d = await client.getScene({});
  scene = d;
  view.load(d);
  const cfg = d.config;
  region = cfg?.display ? fovealRadius(cfg.display, cfg.eccentricityThresholdDeg) : null;
  fillControls(cfg);
  const truth = el("truth");
  truth.textContent = `truth: ${truthName(cfg?.truth)}`;
  truth.title = truthMeaning(cfg?.truth);
  plots.clear();
  layout();
  stats.connected = true;
  stats.lastError = "";
  setStatus(`connected to ${window.location.host}: ${cfg?.bodies ?? 0} bodies${view.software ? " (software WebGL: every 6th frame, drawn at 10 fps)" : ""}`, "ok");
  restart = new AbortController();
  if (pending) focusPending();
  else if (focus.armed && !hunt) void startHunt();
  // Only the frames it can draw: with software WebGL (10 draws a second) every 6th of 60 Hz, so
  // that 10,000 bodies' poses at 60 Hz do not crowd the gaze out of the page's main thread.
  const frames = client.watchFrames(
    { everyK: view.software ? 6 : 1, includePoses: true, quantisedPoses: true, includeCollisions: true },
    { signal: restart.signal },
  );
  try {
    for await (const f of frames) onFrame(f);
  } catch (e) {
    if (restart.signal.aborted) return;
    throw e;
  }
  if (!restart.signal.aborted) throw new Error("the server ended the frame stream (shutting down?)");
}

async function run(): Promise<void> {
  let backoff = 500;
  for (;;) {
    try {
      await session();
      backoff = 500;
    } catch (e) {
      stats.connected = false;
      stats.lastError = describe(e);
      el("truth").textContent = "";
      const wait = backoff;
      const refused = e instanceof ConnectError && (e.code === Code.Unauthenticated || e.code === Code.PermissionDenied);
      const retry = `Retrying in ${(wait / 1000).toFixed(1)} s…`;
      setStatus(
        refused
          ? `foveal-server at ${window.location.host} refused the page: ${stats.lastError}. ${retry}`
          : `cannot reach foveal-server at ${window.location.host}: ${stats.lastError}. ${retry}`,
        "error",
      );
      await new Promise((r) => setTimeout(r, wait));
      backoff = Math.min(5000, backoff * 2);
    }
  }
}

// ------------------------------------------------------------------------------------ controls

const schedulerSelect = el<HTMLSelectElement>("scheduler");
for (const [name] of SCHEDULERS) schedulerSelect.add(new Option(name, name));
const truthSelect = el<HTMLSelectElement>("truth-select");
for (const [name] of TRUTHS) truthSelect.add(new Option(name, name));

/** Show the configuration in force, except in the control the user is editing. */
function fillControls(cfg: SceneConfig | undefined): void {
  if (!cfg) return;
  const set = (id: string, v: string) => {
    const e = el<HTMLInputElement | HTMLSelectElement>(id);
    if (document.activeElement !== e) e.value = v;
  };
  set("scheduler", schedulerName(cfg.scheduler));
  set("truth-select", truthName(cfg.truth));
  set("budget", formatBudget(cfg.budget));
  set("bodies", String(cfg.bodies));
  set("measure-model", formatModel(cfg.measureModel));
  set("schedule-model", formatModel(cfg.scheduleModel));
  el<HTMLInputElement>("audit").checked = cfg.audit;
}

type ConfigChange = Exclude<MessageInitShape<typeof SceneConfigSchema>, SceneConfig>;

async function configure(change: (c: ConfigChange) => void): Promise<void> {
  const out = el("config-error");
  const config: ConfigChange = { audit: el<HTMLInputElement>("audit").checked };
  try {
    change(config);
  } catch (e) {
    out.textContent = describe(e);
    return;
  }
  out.textContent = "applying…";
  try {
    const r = await client.configure({ config });
    out.textContent = "";
    el("config-ok").textContent = `applied from frame ${r.firstFrameIndex}`;
    restart?.abort(); // the session restarts on the new scene (GetScene, new mesh)
  } catch (e) {
    el("config-ok").textContent = "";
    out.textContent = describe(e);
  }
}

schedulerSelect.addEventListener("change", () =>
  configure((c) => {
    const s = SCHEDULERS.find(([n]) => n === schedulerSelect.value);
    if (!s) throw new Error(`unknown scheduler ${schedulerSelect.value}`);
    c.scheduler = s[1];
  }),
);
truthSelect.addEventListener("change", () =>
  configure((c) => {
    const t = TRUTHS.find(([n]) => n === truthSelect.value);
    if (!t) throw new Error(`unknown truth ${truthSelect.value}`);
    c.truth = t[1];
  }),
);
el("budget").addEventListener("change", (e) =>
  configure((c) => (c.budget = parseBudget((e.target as HTMLInputElement).value))),
);
el("bodies").addEventListener("change", (e) =>
  configure((c) => {
    const v = Number((e.target as HTMLInputElement).value);
    if (!Number.isInteger(v) || v < 0) throw new Error(`bodies: "${(e.target as HTMLInputElement).value}" is not a whole number`);
    c.bodies = v;
  }),
);
el("measure-model").addEventListener("change", (e) =>
  configure((c) => (c.measureModel = parseModel((e.target as HTMLInputElement).value))),
);
el("schedule-model").addEventListener("change", (e) =>
  configure((c) => (c.scheduleModel = parseModel((e.target as HTMLInputElement).value))),
);
el("audit").addEventListener("change", () => configure(() => {}));
el<HTMLInputElement>("mouse-gaze").addEventListener("change", (e) => (gaze.enabled = (e.target as HTMLInputElement).checked));

function setPaused(on: boolean): void {
  paused = on;
  el("pause").textContent = paused ? "resume" : "pause";
}
const togglePause = () => setPaused(!paused);
el("pause").addEventListener("click", togglePause);
el("reset").addEventListener("click", () => view.resetView());
el("focus").addEventListener("click", () => setFocusArmed(!focus.armed));
window.addEventListener("keydown", (e) => {
  if (e.target instanceof HTMLInputElement || e.target instanceof HTMLSelectElement) return;
  if (e.key === "p" || e.key === " ") {
    togglePause();
    e.preventDefault();
  } else if (e.key === "r") view.resetView();
  else if (e.key === "f") setFocusArmed(!focus.armed);
});

// ------------------------------------------------------------------------------------ drawing

function text(id: string, s: string): void {
  el(id).textContent = s;
}

/** " ± se (1 in k)" for a figure summed over a sample of the deemed pairs, "" when exact. */
function sampled(stride: number, se: number): string {
  return stride > 1 ? ` ± ${se.toFixed(3)} (1 in ${stride})` : "";
}

function drawReadout(): void {
  const f = lastFrame, m = f?.metrics, fix = f?.fixation;
  const src = fix ? ({ [FixationSource.GAZE]: "gaze", [FixationSource.FALLBACK_NO_GAZE]: "no gaze: centre", [FixationSource.FALLBACK_STALE]: "stale: centre" } as Record<number, string>)[fix.source] ?? "?" : "-";
  text(
    "readout",
    m
      ? [
          `frame ${f?.index}  bodies ${stats.bodies}  ${arrivals.length} fps`,
          `pairs ${m.candidatePairs}  real ${m.realCollisions}  deemed ${m.deemedAtInterruption}`,
          `T ${(1000 * m.collisionTimeS).toFixed(2)} ms  tests ${m.sphereTests}${m.budgetExhausted ? " (budget ran out)" : ""}`,
          ...(m.budgetSpentBeforeNarrow
            ? ["the budget was spent before the narrow phase: every pair deemed (raise the budget)"]
            : []),
          `Δ ${m.geometricInaccuracy.toFixed(3)}${sampled(m.metricsStride, m.geometricInaccuracySe)}  P ${m.perceivedInaccuracy.toFixed(3)}${sampled(m.metricsStride, m.perceivedInaccuracySe)}${m.audit ? `  true P ${m.audit.truePerceivedInaccuracy.toFixed(3)}  false positives ${m.audit.trueFalsePositives}` : ""}`,
          `fixation (${fix?.x.toFixed(3)}, ${fix?.y.toFixed(3)}) ${src}`,
          `decode+update ${median(stats.updateMs).toFixed(2)} ms  parse ${median(stats.parseMs).toFixed(2)} ms  ${(stats.frameBytes / 1024).toFixed(0)} KiB/frame`,
          `gaze sent ${gaze.accepted}${gaze.lastError ? `  (${gaze.lastError})` : ""}`,
        ].join("\n")
      : "waiting for frames…",
  );
  el("orbit-note").hidden = !view.orbited() || (view.focused && paused);
  el("focus").textContent = focus.armed ? "waiting for a first contact…" : "focus on a first contact";
}

// Drawing is paced by what it costs: where WebGL runs on the CPU (no GPU, as in headless
// browsers), presenting each drawn frame blocks the page's main thread for tens of milliseconds,
// and drawing at the display's rate would leave no time for input (the mouse is the gaze) or for
// the frame stream. There the scene is drawn at most 10 times a second (and at least twice its own
// cost apart); with a GPU neither limit bites.
// What a draw costs is measured as the delay it causes: the time from the draw to the next
// animation callback beyond one display period (presenting happens after the script returns).
const MIN_DRAW_INTERVAL_MS = view.software ? 100 : 0;
let lastPlot = 0;
let lastDraw = 0;
let drawCost = 0;
let lastTick = 0;
let drewLastTick = false;
function animate(t: number): void {
  requestAnimationFrame(animate);
  const gap = t - lastTick;
  if (drewLastTick && lastTick > 0) {
    const cost = Math.max(0, gap - 1000 / 60);
    drawCost = 0.7 * drawCost + 0.3 * 2 * cost;
    stats.drawMs = drawCost / 2;
  }
  lastTick = t;
  drewLastTick = false;
  if (t - lastDraw >= Math.max(drawCost, MIN_DRAW_INTERVAL_MS)) {
    view.render();
    lastDraw = t;
    drewLastTick = true;
  }
  // The close-up's label while it holds its frame; resumed, the page is an orbited view.
  if (view.focused && paused && focus.found) {
    const c = focus.found;
    const ends = c.ends.map((p) => view.toScreen(p));
    overlay.label(focusLabel(c), c.gap / c.radius > 0.005 ? ends : [ends[0]]);
  } else overlay.draw(lastFrame?.fixation, region, gaze.enabled ? gaze.pointer : null);
  if (t - lastPlot > 100) {
    lastPlot = t;
    if (!paused) plots.redraw();
    drawReadout();
  }
}

async function pollStatus(): Promise<void> {
  try {
    const s = await client.getStatus({});
    text("server", `server: ${s.fps.toFixed(1)} fps  ${schedulerName(s.config?.scheduler)}  ${formatBudget(s.config?.budget)}  gaze ${s.gazeRateHz.toFixed(0)} Hz  ${s.subscribers} watching`);
  } catch {
    text("server", "server: unreachable");
  }
}

layout();
requestAnimationFrame(animate);
setInterval(() => void pollStatus(), 1000);
void run();
