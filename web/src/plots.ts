// Live plots of the last seconds: T, Δ, P (estimate and, under audit, true), budget use, the
// step's phases, frame rate. A value a frame does not have (the true P without audit, the budget
// used under a budget the page cannot measure) is null, drawn as a gap, and the plot says in a
// note under its title what is missing and why, so that no plot is ever blank without a reason.
import uPlot from "uplot";

/** How many frames the plots keep (10 s at 60 Hz). */
const KEEP = 600;

interface Series {
  label: string;
  stroke: string;
  dash?: number[];
}

class Ring {
  readonly t: number[] = [];
  readonly ys: (number | null)[][];
  constructor(n: number) {
    this.ys = Array.from({ length: n }, () => []);
  }
  push(t: number, ys: (number | null)[]): void {
    this.t.push(t);
    // Gaps are null: uPlot skips them, where a NaN would poison the scale's range.
    ys.forEach((y, i) => this.ys[i].push(y === null || !Number.isFinite(y) ? null : y));
    if (this.t.length > KEEP) {
      this.t.shift();
      for (const y of this.ys) y.shift();
    }
  }
  clear(): void {
    this.t.length = 0;
    for (const y of this.ys) y.length = 0;
  }
}

class Chart {
  private plot: uPlot;
  readonly ring: Ring;
  private note: HTMLElement;
  constructor(parent: HTMLElement, readonly title: string, unit: string, readonly series: Series[], width: number) {
    this.ring = new Ring(series.length);
    const box = document.createElement("div");
    box.className = "chart";
    parent.appendChild(box);
    this.plot = new uPlot(
      {
        title,
        width,
        height: 84,
        legend: { show: true, live: false },
        cursor: { show: false },
        scales: { x: { time: false } },
        axes: [
          { stroke: "#9aa5b1", grid: { stroke: "#26303a" }, size: 30, label: "simulated time (s)", labelSize: 12, labelFont: "11px system-ui" },
          { stroke: "#9aa5b1", grid: { stroke: "#26303a" }, size: 52, label: unit, labelSize: 14 },
        ],
        series: [{ label: "t (s)" }, ...series.map((s) => ({ label: s.label, stroke: s.stroke, dash: s.dash, width: 1.5, spanGaps: false }))],
      },
      [[], ...series.map(() => [])],
      box,
    );
    this.note = document.createElement("p");
    this.note.className = "plot-note";
    box.appendChild(this.note);
  }
  /** Say under the plot what it cannot show (empty: nothing missing). */
  setNote(text: string): void {
    if (this.note.textContent !== text) this.note.textContent = text;
  }
  redraw(): void {
    this.plot.setData([this.ring.t, ...this.ring.ys] as uPlot.AlignedData);
  }
  /** Per series: how many of the kept frames have a value (for the page's tests). */
  counts(): { label: string; values: number }[] {
    return this.series.map((s, i) => ({ label: s.label, values: this.ring.ys[i].filter((y) => y !== null).length }));
  }
  get noteText(): string {
    return this.note.textContent ?? "";
  }
}

export interface PlotSample {
  t: number;
  collisionMs: number;
  geometric: number;
  perceived: number;
  truePerceived: number | null;
  /** The side by side's gaze-blind collider's true P on the same frame (null when off). */
  blindTruePerceived: number | null;
  budgetUse: number | null;
  deemedShare: number | null;
  fps: number;
  /** The step's phases, ms: integrate, broad, prioritise, narrow, response, measure. */
  phasesMs: (number | null)[];
}

/** The phases of PhaseProfile in the order of a step, with their plot colours. */
export const PHASES: [string, string][] = [
  ["integrate", "#74c0fc"],
  ["broad", "#ffd43b"],
  ["prioritise", "#b197fc"],
  ["narrow", "#ff8787"],
  ["response", "#63e6be"],
  ["measure", "#ced4da"],
];

export class Plots {
  private charts: Chart[];
  constructor(parent: HTMLElement, width: number) {
    this.charts = [
      new Chart(parent, "T, collision time", "ms", [{ label: "T", stroke: "#4dabf7" }], width),
      new Chart(parent, "Δ, geometric inaccuracy", "scene units", [{ label: "Δ", stroke: "#ffa94d" }], width),
      new Chart(parent, "P, perceived inaccuracy", "unitless", [
        { label: "P estimate", stroke: "#ff6b6b" },
        { label: "P true (audit)", stroke: "#e599f7", dash: [4, 3] },
        { label: "P true, gaze-blind", stroke: "#74c0fc", dash: [2, 2] },
      ], width),
      new Chart(parent, "budget", "%", [
        { label: "budget used", stroke: "#69db7c" },
        { label: "pairs deemed", stroke: "#ff4d4d" },
      ], width),
      new Chart(parent, "step phases", "ms", PHASES.map(([label, stroke]) => ({ label, stroke })), width),
      new Chart(parent, "frame rate", "fps", [{ label: "frames received", stroke: "#ced4da" }], width),
    ];
  }

  push(s: PlotSample): void {
    const [t, d, p, b, ph, f] = this.charts;
    t.ring.push(s.t, [s.collisionMs]);
    d.ring.push(s.t, [s.geometric]);
    p.ring.push(s.t, [s.perceived, s.truePerceived, s.blindTruePerceived]);
    b.ring.push(s.t, [s.budgetUse === null ? null : 100 * s.budgetUse, s.deemedShare === null ? null : 100 * s.deemedShare]);
    ph.ring.push(s.t, s.phasesMs);
    f.ring.push(s.t, [s.fps]);
  }

  /** What the P and budget plots cannot show under the settings in force ("" when nothing). */
  setNotes(notes: { perceived: string; budget: string }): void {
    this.charts[2].setNote(notes.perceived);
    this.charts[3].setNote(notes.budget);
  }

  clear(): void {
    for (const c of this.charts) c.ring.clear();
  }

  redraw(): void {
    for (const c of this.charts) c.redraw();
  }

  /** Each plot's title, its series' value counts and its note (the page's test hook). */
  summary(): { title: string; series: { label: string; values: number }[]; note: string }[] {
    return this.charts.map((c) => ({ title: c.title, series: c.counts(), note: c.noteText }));
  }
}
