// foveal viewer: the scene from GetScene, frames from WatchFrames (quantised poses and the
// collision list), the mouse as gaze through PushGaze, controls through Configure, and live plots.
// The loop's own controls (Pause, Resume, Step, Restart), picking a body (InspectBody), debug
// drawing, a colour-blind palette, a help overlay and a CSV of the last frames' metrics are a
// researcher's tools. It reconnects by itself, with jittered back-off, when the server goes away.
import { fromBinary, toBinary, type MessageInitShape } from "@bufbuild/protobuf";
import { Code, ConnectError } from "@connectrpc/connect";
import {
  Compare,
  FixationSource,
  FrameSchema,
  PairStatus,
  SceneConfigSchema,
  type BodyInspection,
  type Collisions,
  type Frame,
  type SceneConfig,
  type SceneDescription,
} from "./gen/foveal/v1/foveal_pb";
import { Backoff } from "./backoff";
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
import { FrameLog } from "./csv";
import { FirstContacts, starGap } from "./focus";
import { applyPoses, applyQuantisedPoses, DeemedTruth, forEachDeemed, forEachPair } from "./poses";
import { calls, connect, pageTokens } from "./rpc";
import { COLOURS, PALETTES, SceneView, usePalette, type PaletteName } from "./scene";
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

const tokens = pageTokens();
const client = connect(window.location.origin, tokens.token);
// A second token for the mouse alone (`#gaze=...`), for a viewer token that may not send gaze.
const gazeClient = tokens.gazeToken ? connect(window.location.origin, tokens.gazeToken) : client;
const view = new SceneView(el<HTMLCanvasElement>("scene"));
const overlay = new Overlay(el<HTMLCanvasElement>("overlay"));
/** The side by side's right view and overlay, made the first time the scene compares. */
let blind: { view: SceneView; overlay: Overlay; tally: Tally | null } | null = null;
const plots = new Plots(el("plots"), 360);
const gaze = new MouseGaze(gazeClient, el("scene"));
const log = new FrameLog();

let scene: SceneDescription | null = null;
let region: { rx: number; ry: number } | null = null;
let lastFrame: Frame | null = null;
/** The view holds its frame (a close-up, or a pause the server did not allow). */
let paused = false;
let restart: AbortController | null = null;
const arrivals: number[] = [];

/** The server's loop as the page last heard: paused, and its frame counter. */
const loop = { paused: false, frames: -1, note: "" };

/** Debug drawing and the palette, kept across visits. */
const draw = {
  links: false,
  priority: false,
  /** Thin out the bodies away from the fixation while drawing every body is too slow. */
  thin: localStorage.getItem("foveal.thin") !== "off",
  palette: (localStorage.getItem("foveal.palette") as PaletteName | null) ?? "standard",
};
if (!(draw.palette in PALETTES)) draw.palette = "standard";

/** The body picked for inspection and what the server said about it. */
const picked = {
  body: -1,
  inspection: null as BodyInspection | null,
  error: "",
};

/**
 * The side by side (SceneConfig.compare): whether the scene in force compares, with which collider,
 * and each side's true P per frame (the page's data the tests read: frame index, true P of the
 * gaze-steered side and of the gaze-blind side, and where the fixation was).
 */
const split = {
  on: false,
  collider: "off",
  frames: [] as { index: number; gaze: number; blind: number; x: number; y: number }[],
};

/** The collider names of the side-by-side control, in protocol enum order. */
const COMPARES: [string, Compare, string][] = [
  ["off", Compare.OFF, "off"],
  ["round-robin", Compare.ROUND_ROBIN, "round-robin, gaze-blind"],
  ["exact", Compare.EXACT, "exact"],
];

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

(window as unknown as { foveal: unknown }).foveal = {
  stats,
  view,
  gaze,
  focus,
  plots,
  split,
  loop,
  picked,
  draw,
  calls,
  pick: (body: number) => pickBody(body),
  lastFrame: () => lastFrame,
  tally: () => tally,
  colours: COLOURS,
  csv: (n?: number) => log.csv(n),
};

// ------------------------------------------------------------------------------------ layout

function layout(): void {
  const box = el("view-box");
  const aspect = scene?.camera?.aspect || 1.6;
  // Side by side, two views share the width; each keeps a line of caption under it.
  const sides = split.on ? 2 : 1;
  const caption = split.on ? 44 : 0;
  const w = Math.max(100, Math.min((box.clientWidth - 20 * (sides - 1)) / sides, (box.clientHeight - caption) * aspect));
  const h = w / aspect;
  const ids = split.on ? ["scene", "overlay", "scene-blind", "overlay-blind"] : ["scene", "overlay"];
  for (const id of ids) {
    const c = el<HTMLCanvasElement>(id);
    c.style.width = `${w}px`;
    c.style.height = `${h}px`;
  }
  for (const id of ["caption-gaze", "caption-blind"]) el(id).style.width = `${w}px`;
  view.resize(w, h);
  overlay.resize(Math.round(w), Math.round(h));
  if (split.on && blind) {
    blind.view.resize(w, h);
    blind.overlay.resize(Math.round(w), Math.round(h));
  }
}

/**
 * Show or hide the side by side for the scene in force (its `compare`): the right view is made
 * the first time, loaded with the scene, and follows the left view's camera.
 */
function useSplit(d: SceneDescription): void {
  const c = COMPARES.find(([, v]) => v === d.config?.compare);
  split.on = !!c && c[1] !== Compare.OFF;
  split.collider = c ? c[0] : "off";
  split.frames.length = 0;
  el("side-blind").hidden = !split.on;
  el("caption-gaze").hidden = !split.on;
  if (!split.on) return;
  if (!blind) {
    const v = new SceneView(el<HTMLCanvasElement>("scene-blind"));
    // The left view is the one orbited; the right one looks through its camera.
    v.controls.enabled = false;
    blind = { view: v, overlay: new Overlay(el<HTMLCanvasElement>("overlay-blind")), tally: null };
  }
  blind.view.load(d);
  blind.view.setFarStride(view.farStride);
}

/** The same poses on the right view, coloured by the gaze-blind collider's collision list. */
function showBlind(f: Frame, bodies: number): void {
  const c = f.comparison;
  if (!blind || !c) return;
  const v = blind.view;
  v.matrices().set(view.matrices().subarray(0, 16 * bodies));
  v.posesWritten(bodies);
  v.colour((set) => {
    blind!.tally = c.collisions ? markCollisions(c.collisions, set) : null;
  });
  v.setDetailRegion(view.detailRegion);
  v.commit();
}

/** Mean of a side's true P over the frames of the last `frames` frame indices (120: 2 s at 60 Hz). */
function recentMean(side: "gaze" | "blind", frames: number): number {
  const last = split.frames[split.frames.length - 1];
  const s = last ? split.frames.filter((f) => f.index > last.index - frames) : [];
  return s.length ? s.reduce((a, f) => a + f[side], 0) / s.length : NaN;
}

/** The captions under the two views: which collider each is and its true P. */
function drawCaptions(): void {
  if (!split.on) return;
  const last = split.frames[split.frames.length - 1];
  const fmt = (side: "gaze" | "blind") =>
    last ? `true P ${last[side].toFixed(3)} (mean of the last 2 s: ${recentMean(side, 120).toFixed(3)})` : "true P: waiting for frames…";
  const cfg = scene?.config;
  el("caption-gaze").innerHTML = `<b>${schedulerName(cfg?.scheduler)}</b>, steered by your gaze (the mouse)\n`;
  el("caption-gaze").append(fmt("gaze"));
  el("caption-blind").innerHTML = `<b>${split.collider === "exact" ? "exact" : "round-robin"}</b>, gaze-blind: the same frame, ${split.collider === "exact" ? "every pair resolved" : "the same budget"}\n`;
  el("caption-blind").append(fmt("blind"));
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
      if (e.rawMessage.includes("has the `gaze` role")) {
        return `${e.rawMessage}. This page was opened with a gaze token: it steers the fixation with the mouse but may not watch. Give it a viewer (or admin) token too: ${window.location.origin}/#token=VIEWER_TOKEN&gaze=GAZE_TOKEN`;
      }
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
  if (split.on) showBlind(f, bodies);
  // The legend names the audited colours only when the frame has them.
  const blindTally = split.on && blind ? blind.tally : null;
  const legend = el("legend");
  legend.classList.toggle("audited", !!tally?.audited || !!blindTally?.audited);
  legend.classList.toggle("sampled", (tally?.unaudited ?? 0) + (blindTally?.unaudited ?? 0) > 0);
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
    const p = f.profile;
    // Side by side, both true P come from the server's paired audit (the same pairs for both).
    const blindAudit = f.comparison?.metrics?.audit;
    const mainAudit = f.comparison?.mainAudit;
    if (split.on && mainAudit && blindAudit) {
      split.frames.push({
        index: Number(f.index),
        gaze: mainAudit.truePerceivedInaccuracy,
        blind: blindAudit.truePerceivedInaccuracy,
        x: fix?.x ?? NaN,
        y: fix?.y ?? NaN,
      });
      if (split.frames.length > 600) split.frames.shift();
    }
    plots.push({
      t: f.simTimeS,
      collisionMs: 1000 * m.collisionTimeS,
      geometric: m.geometricInaccuracy,
      perceived: m.perceivedInaccuracy,
      truePerceived: mainAudit ? mainAudit.truePerceivedInaccuracy : m.audit ? m.audit.truePerceivedInaccuracy : null,
      blindTruePerceived: blindAudit ? blindAudit.truePerceivedInaccuracy : null,
      budgetUse: use,
      deemedShare: candidates ? Number(m.deemedAtInterruption) / candidates : null,
      fps: arrivals.length,
      phasesMs: p
        ? [p.integrateS + p.renumberS, p.broadS, p.prioritiseS, p.narrowS, p.responseS, p.measureS].map((v) => 1000 * v)
        : [null, null, null, null, null, null],
    });
  }
  log.push(f);
}

/** What the P and budget plots cannot show under the configuration in force, said on the plot. */
function plotNotes(cfg: SceneConfig | undefined): { perceived: string; budget: string } {
  const budget = cfg?.budget?.kind.case;
  return {
    perceived:
      cfg?.audit || (cfg?.compare ?? Compare.OFF) !== Compare.OFF
        ? ""
        : "The true P needs the exact answer: tick \"audit\" (or turn the side by side on) to draw it. The solid line is the server's estimate.",
    budget:
      budget === "fractionOfExact"
        ? "Budget used is not drawn under a fraction-of-exact budget (the exact cost is not sent); the share deemed is."
        : budget === "interruptAtZero"
          ? "A zero budget does no sphere test: every candidate pair is deemed."
          : budget === "exact"
            ? "No budget: every pair is resolved, none deemed."
            : "",
  };
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
    if (c) tally = markCollisions(c, set);
    else tally = null;
    const ins = picked.inspection;
    if (picked.body >= 0 && ins) {
      for (const p of ins.pairs) set(p.other, pairColour(p.status));
    }
    if (picked.body >= 0) set(picked.body, COLOURS.picked);
  }, false, draw.priority ? priorityShade(f, bodies) : null);
  const links: { a: number; b: number; c: typeof COLOURS.real }[] = [];
  if (draw.links && c) {
    forEachPair(c.real, (a, b) => links.push({ a, b, c: COLOURS.real }));
    const audited = c.deemedTruth.length > 0;
    forEachDeemed(c, (a, b, t) => links.push({ a, b, c: deemedColour(t, audited) }));
  }
  if (picked.body >= 0 && picked.inspection) {
    for (const p of picked.inspection.pairs) links.push({ a: picked.body, b: p.other, c: pairColour(p.status) });
  }
  view.setLinks(links, links.length > 0);
  return bodies;
}

/** The colour of a deemed pair: by what the frame's audit found of it, when it was audited. */
function deemedColour(t: DeemedTruth, audited: boolean): typeof COLOURS.real {
  if (!audited) return COLOURS.deemed;
  return t === DeemedTruth.Apart ? COLOURS.deemed : t === DeemedTruth.Touching ? COLOURS.touching : COLOURS.unaudited;
}

/** The pairs of the last frame drawn, by colour (see markCollisions). */
interface Tally {
  real: number;
  /** Deemed, and apart by the audit: wrong guesses (or every deemed pair without an audit). */
  deemed: number;
  touching: number;
  unaudited: number;
  audited: boolean;
}
let tally: Tally | null = null;

/**
 * Colour a collision list's bodies. With an audit, a deemed pair is coloured by what it truly is:
 * apart (a wrong guess, drawn as deemed: its bodies bounce across a visible gap), touching (a right
 * guess, nothing shows) or, where a sampling audit passed it by, not audited. Right guesses go
 * first and wrong ones last, so that a body in any pair deemed across a gap shows it whatever else
 * it touches. Without an audit every deemed pair is drawn as deemed, as the frame reports it.
 */
function markCollisions(c: Collisions, set: (body: number, colour: typeof COLOURS.real) => void): Tally {
  const audited = c.deemedTruth.length > 0;
  const t: Tally = { real: 0, deemed: 0, touching: 0, unaudited: 0, audited };
  const pass = (want: (truth: DeemedTruth) => boolean) =>
    forEachDeemed(c, (a, b, truth) => {
      if (!want(truth)) return;
      const colour = deemedColour(truth, audited);
      if (!audited || truth === DeemedTruth.Apart) t.deemed++;
      else if (truth === DeemedTruth.Touching) t.touching++;
      else t.unaudited++;
      set(a, colour);
      set(b, colour);
    });
  if (audited) pass((truth) => truth === DeemedTruth.Touching);
  forEachPair(c.real, (a, b) => (t.real++, set(a, COLOURS.real), set(b, COLOURS.real)));
  if (audited) pass((truth) => truth === DeemedTruth.NotAudited);
  pass((truth) => !audited || truth === DeemedTruth.Apart);
  return t;
}

function pairColour(status: PairStatus): typeof COLOURS.real {
  return status === PairStatus.COLLIDING ? COLOURS.real : status === PairStatus.DEEMED ? COLOURS.deemed : COLOURS.separate;
}

let eccentricity = new Float32Array(0);
/**
 * Priority shading: each body's plain colour scaled by how near the fixation it is on the server's
 * screen, in units of the foveal region (full inside it, falling off outside): what the
 * schedulers' priority falls off with.
 */
function priorityShade(f: Frame, bodies: number): ((body: number) => number) | null {
  const fix = f.fixation;
  if (!fix || !region) return null;
  if (eccentricity.length < bodies) eccentricity = new Float32Array(bodies);
  view.eccentricities(fix.x, fix.y, region.rx, region.ry, eccentricity);
  return (i) => {
    const d = i < bodies ? eccentricity[i] : Infinity;
    return d <= 1 ? 1.6 : Math.max(0.2, Math.exp(-(d - 1) / 2));
  };
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

const reconnect = new Backoff();

async function session(): Promise<void> {
  const d = await client.getScene({});
  reconnect.succeed();
  scene = d;
  view.load(d);
  useSplit(d);
  const cfg = d.config;
  region = cfg?.display ? fovealRadius(cfg.display, cfg.eccentricityThresholdDeg) : null;
  fillControls(cfg);
  const truth = el("truth");
  truth.textContent = `truth: ${truthName(cfg?.truth)}`;
  truth.title = truthMeaning(cfg?.truth);
  plots.clear();
  plots.setNotes(plotNotes(cfg));
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
  for (;;) {
    try {
      await session();
    } catch (e) {
      stats.connected = false;
      stats.lastError = describe(e);
      el("truth").textContent = "";
      // Doubling from 0.5 s to 5 s with jitter: a page never floods a server that is down.
      const wait = reconnect.fail();
      const refused = e instanceof ConnectError && (e.code === Code.Unauthenticated || e.code === Code.PermissionDenied);
      const retry = `Retrying in ${(wait / 1000).toFixed(1)} s…`;
      setStatus(
        refused
          ? `foveal-server at ${window.location.host} refused the page: ${stats.lastError}. ${retry}`
          : `cannot reach foveal-server at ${window.location.host}: ${stats.lastError}. ${retry}`,
        "error",
      );
      await new Promise((r) => setTimeout(r, wait));
    }
  }
}

// ------------------------------------------------------------------------------------ controls

const schedulerSelect = el<HTMLSelectElement>("scheduler");
for (const [name] of SCHEDULERS) schedulerSelect.add(new Option(name, name));
const truthSelect = el<HTMLSelectElement>("truth-select");
for (const [name] of TRUTHS) truthSelect.add(new Option(name, name));

/**
 * Show the configuration in force, except in the control the user is editing (or in every control
 * with `force`: a refused value goes back to the one in force).
 */
function fillControls(cfg: SceneConfig | undefined, force = false): void {
  if (!cfg) return;
  const set = (id: string, v: string) => {
    const e = el<HTMLInputElement | HTMLSelectElement>(id);
    if (force || document.activeElement !== e) e.value = v;
  };
  set("scheduler", schedulerName(cfg.scheduler));
  set("truth-select", truthName(cfg.truth));
  set("budget", formatBudget(cfg.budget));
  set("bodies", String(cfg.bodies));
  set("measure-model", formatModel(cfg.measureModel));
  set("schedule-model", formatModel(cfg.scheduleModel));
  el<HTMLInputElement>("audit").checked = cfg.audit;
  set("compare", COMPARES.find(([, v]) => v === cfg.compare)?.[0] ?? "off");
  if (force || document.activeElement !== el("seed")) el<HTMLInputElement>("seed").placeholder = String(cfg.seed);
}

type ConfigChange = Exclude<MessageInitShape<typeof SceneConfigSchema>, SceneConfig>;

/**
 * Configure exactly the field named (`field`, a SceneConfig path) with the value `change` sets:
 * with an update mask, so that 0 is sent as 0 and refused or applied by the server, never
 * silently kept. A value the page or the server refuses goes back to the one in force, and the
 * reason is shown.
 */
async function configure(field: string, change: (c: ConfigChange) => void): Promise<void> {
  const out = el("config-error");
  const config: ConfigChange = {};
  const refused = (why: string) => {
    el("config-ok").textContent = "";
    out.textContent = `${why} (the control shows the value in force again)`;
    fillControls(scene?.config, true);
  };
  try {
    change(config);
  } catch (e) {
    refused(describe(e));
    return;
  }
  out.textContent = "applying…";
  try {
    const r = await client.configure({ config, updateMask: { paths: [field] } });
    out.textContent = "";
    el("config-ok").textContent = `applied from frame ${r.firstFrameIndex}`;
    restart?.abort(); // the session restarts on the new scene (GetScene, new mesh)
  } catch (e) {
    refused(describe(e));
  }
}

schedulerSelect.addEventListener("change", () =>
  configure("scheduler", (c) => {
    const s = SCHEDULERS.find(([n]) => n === schedulerSelect.value);
    if (!s) throw new Error(`unknown scheduler ${schedulerSelect.value}`);
    c.scheduler = s[1];
  }),
);
truthSelect.addEventListener("change", () =>
  configure("truth", (c) => {
    const t = TRUTHS.find(([n]) => n === truthSelect.value);
    if (!t) throw new Error(`unknown truth ${truthSelect.value}`);
    c.truth = t[1];
  }),
);
el("budget").addEventListener("change", (e) =>
  configure("budget", (c) => (c.budget = parseBudget((e.target as HTMLInputElement).value))),
);
el("bodies").addEventListener("change", (e) =>
  configure("bodies", (c) => {
    const text = (e.target as HTMLInputElement).value;
    const v = Number(text);
    // 0 and negatives go to the server, which says what it accepts.
    if (text.trim() === "" || !Number.isInteger(v)) throw new Error(`bodies N: "${text}" is not a whole number`);
    if (v < 0) throw new Error(`bodies N: ${v} is negative; the scene needs at least 1 body`);
    c.bodies = v;
  }),
);
el("measure-model").addEventListener("change", (e) =>
  configure("measure_model", (c) => (c.measureModel = parseModel((e.target as HTMLInputElement).value))),
);
el("schedule-model").addEventListener("change", (e) =>
  configure("schedule_model", (c) => (c.scheduleModel = parseModel((e.target as HTMLInputElement).value))),
);
el("audit").addEventListener("change", () => configure("audit", (c) => (c.audit = el<HTMLInputElement>("audit").checked)));
/** Turn the side by side on (with `name`'s collider) or off: a Configure of `compare` alone. */
function setCompare(name: string): Promise<void> {
  return configure("compare", (c) => {
    const v = COMPARES.find(([n]) => n === name);
    if (!v) throw new Error(`side by side: unknown collider ${name}`);
    c.compare = v[1];
  });
}
el<HTMLSelectElement>("compare").addEventListener("change", (e) => void setCompare((e.target as HTMLSelectElement).value));
el<HTMLInputElement>("mouse-gaze").addEventListener("change", (e) => (gaze.enabled = (e.target as HTMLInputElement).checked));

/** Hold the view's frame (a close-up; or a pause the server did not allow), or let it go. */
function setPaused(on: boolean): void {
  paused = on;
  showLoop();
}

function showLoop(): void {
  el("pause").textContent = loop.paused || paused ? "resume" : "pause";
  el("loop-note").textContent = loop.note;
}

/** Note the loop's state from a Pause, Resume or Step answer. */
function heard(s: { paused: boolean; frames: bigint }, note: string): void {
  loop.paused = s.paused;
  loop.frames = Number(s.frames);
  loop.note = note;
  showLoop();
}

function refusedControl(what: string, e: unknown): string {
  if (e instanceof ConnectError && (e.code === Code.PermissionDenied || e.code === Code.Unauthenticated)) {
    return `${what} needs an admin token (${e.rawMessage})`;
  }
  return `${what}: ${describe(e)}`;
}

/**
 * Pause or resume the server's simulation (admin). Without the right to, the view alone holds its
 * frame and says why.
 */
async function togglePause(): Promise<void> {
  if (paused && !loop.paused) {
    // The view alone was held (a close-up, or a refused pause): let it go.
    setPaused(false);
    return;
  }
  try {
    if (loop.paused) {
      heard(await client.resume({}), "");
      setPaused(false);
    } else {
      const s = await client.pause({});
      heard(s, `simulation paused after frame ${s.frames - 1n}: N or "step" advances one frame`);
    }
  } catch (e) {
    if (!loop.paused) {
      setPaused(true);
      loop.note = `${refusedControl("pausing the simulation", e)}: only the view is paused`;
    } else loop.note = refusedControl("resuming", e);
    showLoop();
  }
}

/** Advance a paused simulation by one frame (pausing it first if it runs). */
async function stepOnce(): Promise<void> {
  try {
    if (!loop.paused) heard(await client.pause({}), "");
    setPaused(false);
    const s = await client.step({ frames: 1 });
    heard(s, `simulation paused; stepped to frame ${s.frames - 1n}`);
    if (picked.body >= 0) void inspect();
  } catch (e) {
    loop.note = refusedControl("stepping", e);
    showLoop();
  }
}

/** Start the scene again, with the seed typed (or the one in force). */
async function restartScene(): Promise<void> {
  const text = el<HTMLInputElement>("seed").value.trim();
  let seed: bigint | undefined;
  if (text !== "") {
    try {
      seed = BigInt(text);
      if (seed < 0n || seed >= 1n << 64n) throw new Error("out of range");
    } catch {
      loop.note = `seed "${text}": use a whole number from 0 to 2^64 - 1 (empty: the seed in force)`;
      el<HTMLInputElement>("seed").value = "";
      showLoop();
      return;
    }
  }
  try {
    const r = await client.restart({ seed });
    loop.note = `restarted with seed ${r.applied?.seed} from frame ${r.firstFrameIndex}${loop.paused ? " (still paused)" : ""}`;
    el<HTMLInputElement>("seed").value = "";
    restart?.abort();
  } catch (e) {
    loop.note = refusedControl("restarting", e);
  }
  showLoop();
}

el("pause").addEventListener("click", () => void togglePause());
el("step").addEventListener("click", () => void stepOnce());
el("restart").addEventListener("click", () => void restartScene());
el("reset").addEventListener("click", () => view.resetView());
el("focus").addEventListener("click", () => setFocusArmed(!focus.armed));
el("help-button").addEventListener("click", () => toggleHelp());
el("help-close").addEventListener("click", () => toggleHelp(false));
window.addEventListener("keydown", (e) => {
  if (e.target instanceof HTMLInputElement || e.target instanceof HTMLSelectElement) return;
  if (e.key === "p" || e.key === " ") {
    void togglePause();
    e.preventDefault();
  } else if (e.key === "n" || e.key === ".") void stepOnce();
  else if (e.key === "r") view.resetView();
  else if (e.key === "f") setFocusArmed(!focus.armed);
  else if (e.key === "l") setDraw("links", !draw.links);
  else if (e.key === "e") setDraw("priority", !draw.priority);
  else if (e.key === "s") void setCompare(split.on ? "off" : "round-robin");
  else if (e.key === "c") setPalette(draw.palette === "standard" ? "colour-blind" : "standard");
  else if (e.key === "?" || e.key === "h") toggleHelp();
  else if (e.key === "Escape") {
    if (!el("help").hidden) toggleHelp(false);
    else pickBody(-1);
  }
});

// ------------------------------------------------------------------------------- help, drawing

function toggleHelp(on = el("help").hidden): void {
  el("help").hidden = !on;
}

/** Redraw the frame in view with the current colours (paused, nothing else would). */
function reshow(): void {
  if (lastFrame && !(view.focused && paused)) {
    show(lastFrame);
    view.commit();
  }
}

function setDraw(what: "links" | "priority", on: boolean): void {
  draw[what] = on;
  el<HTMLInputElement>(what === "links" ? "draw-links" : "draw-priority").checked = on;
  reshow();
}

function setThin(on: boolean): void {
  draw.thin = on;
  el<HTMLInputElement>("draw-thin").checked = on;
  localStorage.setItem("foveal.thin", on ? "on" : "off");
  lastThin = 0;
  if (!on) {
    view.setFarStride(1);
    blind?.view.setFarStride(1);
  }
}

function setPalette(name: PaletteName): void {
  draw.palette = name;
  usePalette(name);
  document.body.classList.toggle("colour-blind", name === "colour-blind");
  el<HTMLSelectElement>("palette").value = name;
  localStorage.setItem("foveal.palette", name);
  reshow();
}
el<HTMLInputElement>("draw-links").addEventListener("change", (e) => setDraw("links", (e.target as HTMLInputElement).checked));
el<HTMLInputElement>("draw-priority").addEventListener("change", (e) => setDraw("priority", (e.target as HTMLInputElement).checked));
el<HTMLInputElement>("draw-thin").addEventListener("change", (e) => setThin((e.target as HTMLInputElement).checked));
setThin(draw.thin);
el<HTMLSelectElement>("palette").addEventListener("change", (e) => setPalette((e.target as HTMLSelectElement).value as PaletteName));
setPalette(draw.palette);

el("csv").addEventListener("click", () => {
  const n = Number(el<HTMLInputElement>("csv-frames").value) || undefined;
  const text = log.csv(n);
  const a = document.createElement("a");
  a.href = URL.createObjectURL(new Blob([text], { type: "text/csv" }));
  a.download = `foveal-frames-${log.range(n)}.csv`;
  a.click();
  setTimeout(() => URL.revokeObjectURL(a.href), 1000);
});

// ------------------------------------------------------------------------------------ picking

/** Pick a body (-1: none) and ask the server for its pairs. */
function pickBody(body: number): void {
  picked.body = body;
  picked.inspection = null;
  picked.error = "";
  showPick();
  reshow();
  if (body >= 0) void inspect();
}

let inspecting = false;
async function inspect(): Promise<void> {
  if (picked.body < 0 || inspecting) return;
  const body = picked.body;
  inspecting = true;
  try {
    const r = await client.inspectBody({ body });
    if (picked.body === body) (picked.inspection = r), (picked.error = "");
  } catch (e) {
    if (picked.body === body) picked.error = describe(e);
  } finally {
    inspecting = false;
  }
  showPick();
  reshow();
}

const STATUS_NAMES: Record<number, string> = {
  [PairStatus.UNTESTED]: "untested",
  [PairStatus.ACTIVE]: "active",
  [PairStatus.COLLIDING]: "real collision",
  [PairStatus.SEPARATE]: "separate",
  [PairStatus.DEEMED]: "deemed (budget ran out)",
};

function showPick(): void {
  const box = el("pick");
  box.hidden = picked.body < 0;
  if (picked.body < 0) return;
  const ins = picked.inspection;
  const lines = [`body ${picked.body}${ins ? ` at frame ${ins.frameIndex}: ${ins.pairsTotal} candidate pair${ins.pairsTotal === 1 ? "" : "s"}` : ""}  (Esc: unpick)`];
  if (ins && lastFrame && ins.frameIndex !== lastFrame.index) {
    lines.push(`(the view shows frame ${lastFrame.index}${view.software ? ": this page draws every 6th frame; N steps to the latest" : ""})`);
  }
  if (picked.error) lines.push(picked.error);
  else if (!ins) lines.push("asking the server…");
  else {
    for (const p of ins.pairs) {
      lines.push(
        `  with ${String(p.other).padEnd(6)} ${(STATUS_NAMES[p.status] ?? "?").padEnd(24)} levels ${p.level}/${p.otherLevel}` +
          `${p.resolvedLevel ? ` resolved at ${p.resolvedLevel}` : ""}  priority ${p.priority > 0 ? p.priority.toPrecision(3) : "not ranked"}${p.foveal ? "  foveal" : ""}`,
      );
    }
    if (ins.pairs.length < ins.pairsTotal) lines.push(`  … and ${ins.pairsTotal - ins.pairs.length} more`);
  }
  el("pick-text").textContent = lines.join("\n");
}

// A click on the scene (a press and release without a drag, which orbits) picks the body under it.
{
  const canvas = el<HTMLCanvasElement>("scene");
  let down: { x: number; y: number } | null = null;
  canvas.addEventListener("pointerdown", (e) => (down = e.button === 0 ? { x: e.clientX, y: e.clientY } : null));
  canvas.addEventListener("pointerup", (e) => {
    if (!down || Math.hypot(e.clientX - down.x, e.clientY - down.y) > 4) return;
    down = null;
    const r = canvas.getBoundingClientRect();
    pickBody(view.pickAt((e.clientX - r.left) / r.width, (e.clientY - r.top) / r.height));
  });
}

// ------------------------------------------------------------------------------------ drawing

function text(id: string, s: string): void {
  el(id).textContent = s;
}

/** " ± se (1 in k)" for a figure summed over a sample of the deemed pairs, "" when exact. */
function sampled(stride: number, se: number): string {
  return stride > 1 ? ` ± ${se.toFixed(3)} (1 in ${stride})` : "";
}

/**
 * The readout's line on where the wrong guesses are: the deemed pairs an audit found apart, within
 * 5 degrees of the fixation and beyond, each as a share of the candidate pairs there (the frame's
 * own audit, or the side by side's paired one, scaled by its stride).
 */
function wrongGuesses(f: Frame | null): string[] {
  const m = f?.metrics;
  const a = m?.audit ?? f?.comparison?.mainAudit;
  if (!m || !a) return [];
  const near = Number(a.trueFovealFalsePositives), far = Number(a.trueFalsePositives) - near;
  const nearPairs = Number(m.fovealPairs), farPairs = Number(m.candidatePairs) - nearPairs;
  const pct = (k: number, n: number) => (n > 0 ? `${((100 * k) / n).toFixed(1)}%` : "-");
  return [`wrong guesses (deemed, truly apart): ${pct(near, nearPairs)} of ${nearPairs} pairs within 5°, ${pct(far, farPairs)} of ${farPairs} beyond`];
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
          ...(scene?.config?.budget?.kind.case === "sphereTests"
            ? [`a budget of ${scene.config.budget.kind.value} sphere tests: the same work on any machine, staged (not what a frame's time affords)`]
            : []),
          ...(m.budgetSpentBeforeNarrow
            ? ["the budget was spent before the narrow phase: every pair deemed (raise the budget)"]
            : []),
          ...wrongGuesses(f),
          ...thinned(),
          `Δ ${m.geometricInaccuracy.toFixed(3)}${sampled(m.metricsStride, m.geometricInaccuracySe)}  P ${m.perceivedInaccuracy.toFixed(3)}${sampled(m.metricsStride, m.perceivedInaccuracySe)}${m.audit ? `  true P ${m.audit.truePerceivedInaccuracy.toFixed(3)}  false positives ${m.audit.trueFalsePositives}` : ""}`,
          `fixation (${fix?.x.toFixed(3)}, ${fix?.y.toFixed(3)}) ${src}${gaze.held && gaze.enabled ? " (mouse off the scene: its last position held)" : ""}`,
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
// Thinning (SceneView.farStride): a draw that costs more than THIN_ABOVE_MS (the page then draws
// fewer than about 8 frames a second on the CPU, 20 with a GPU) doubles the stride of the bodies
// drawn away from the fixation, and one under a third of it halves the stride again; at most
// once a second, so that each stride's cost is measured before the next change.
const THIN_ABOVE_MS = view.software ? 60 : 25;
const MAX_FAR_STRIDE = 64;
let lastThin = 0;
function thin(t: number): void {
  if (!draw.thin || t - lastThin < 1000) return;
  lastThin = t;
  const k = view.farStride;
  let next = k;
  if (stats.drawMs > THIN_ABOVE_MS && k < MAX_FAR_STRIDE) next = 2 * k;
  else if (stats.drawMs < THIN_ABOVE_MS / 3 && k > 1) next = k / 2;
  if (next === k) return;
  view.setFarStride(next);
  blind?.view.setFarStride(next);
}

/** The readout's line on what is drawn, when not every body is. */
function thinned(): string[] {
  const { far, drawn } = view.farCounts;
  if (view.farStride === 1 || drawn === far) return [];
  return [`drawn: every body within the foveal region, ${drawn} of the ${far} beyond (1 in ${view.farStride}: drawing them all took this browser too long)`];
}

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
  thin(t);
  if (t - lastDraw >= Math.max(drawCost, MIN_DRAW_INTERVAL_MS)) {
    view.render();
    if (split.on && blind) {
      blind.view.followCamera(view);
      blind.view.render();
    }
    lastDraw = t;
    drewLastTick = true;
  }
  // The close-up's label while it holds its frame; resumed, the page is an orbited view.
  if (view.focused && paused && focus.found) {
    const c = focus.found;
    const ends = c.ends.map((p) => view.toScreen(p));
    overlay.label(focusLabel(c), c.gap / c.radius > 0.005 ? ends : [ends[0]]);
  } else overlay.draw(lastFrame?.fixation, region, gaze.enabled ? gaze.pointer : null);
  // The right view shows the same fixation (it measures P about it; its scheduler ignores it).
  if (split.on && blind) blind.overlay.draw(lastFrame?.fixation, region, null);
  if (t - lastPlot > 100) {
    lastPlot = t;
    if (!paused) plots.redraw();
    drawReadout();
    drawCaptions();
  }
}

// While the session is down the status is not polled (the session's own retries, backed off, find
// the server again); a failing poll backs off too.
const statusBackoff = new Backoff(1000, 5000);
async function pollStatus(): Promise<void> {
  if (!stats.connected || !statusBackoff.ready()) return;
  try {
    const s = await client.getStatus({});
    statusBackoff.succeed();
    if (s.paused !== loop.paused) loop.note = s.paused ? `simulation paused after frame ${s.frames - 1n}` : "";
    loop.paused = s.paused;
    loop.frames = Number(s.frames);
    showLoop();
    text("server", `server: ${s.paused ? "paused" : `${s.fps.toFixed(1)} fps`}  ${schedulerName(s.config?.scheduler)}  ${formatBudget(s.config?.budget)}  gaze ${s.gazeRateHz.toFixed(0)} Hz  ${s.subscribers} watching`);
    plots.setNotes(plotNotes(s.config));
  } catch {
    statusBackoff.fail();
    text("server", "server: unreachable");
  }
  // A picked body's pairs follow the running simulation, once a second.
  if (picked.body >= 0 && !loop.paused) void inspect();
}

layout();
requestAnimationFrame(animate);
setInterval(() => void pollStatus(), 1000);
void run();
