// Live plots of the last seconds: T, Δ, P (estimate and, under audit, true), budget use, frame rate.
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
  readonly ys: number[][];
  constructor(n: number) {
    this.ys = Array.from({ length: n }, () => []);
  }
  push(t: number, ys: (number | null)[]): void {
    this.t.push(t);
    ys.forEach((y, i) => this.ys[i].push(y ?? NaN));
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
  constructor(parent: HTMLElement, title: string, unit: string, series: Series[], width: number) {
    this.ring = new Ring(series.length);
    this.plot = new uPlot(
      {
        title,
        width,
        height: 110,
        legend: { show: true, live: false },
        cursor: { show: false },
        scales: { x: { time: false } },
        axes: [
          { stroke: "#9aa5b1", grid: { stroke: "#26303a" }, size: 28 },
          { stroke: "#9aa5b1", grid: { stroke: "#26303a" }, size: 52, label: unit, labelSize: 14 },
        ],
        series: [{ label: "t (s)" }, ...series.map((s) => ({ label: s.label, stroke: s.stroke, dash: s.dash, width: 1.5, spanGaps: false }))],
      },
      [[], ...series.map(() => [])],
      parent,
    );
  }
  redraw(): void {
    this.plot.setData([this.ring.t, ...this.ring.ys] as uPlot.AlignedData);
  }
}

export interface PlotSample {
  t: number;
  collisionMs: number;
  geometric: number;
  perceived: number;
  truePerceived: number | null;
  budgetUse: number | null;
  deemedShare: number;
  fps: number;
}

export class Plots {
  private charts: Chart[];
  constructor(parent: HTMLElement, width: number) {
    this.charts = [
      new Chart(parent, "T, collision time", "ms", [{ label: "T", stroke: "#4dabf7" }], width),
      new Chart(parent, "Δ, geometric inaccuracy", "units", [{ label: "Δ", stroke: "#ffa94d" }], width),
      new Chart(parent, "P, perceived inaccuracy", "", [
        { label: "P estimate", stroke: "#ff6b6b" },
        { label: "P true (audit)", stroke: "#e599f7", dash: [4, 3] },
      ], width),
      new Chart(parent, "budget", "%", [
        { label: "budget used", stroke: "#69db7c" },
        { label: "pairs deemed", stroke: "#ff4d4d" },
      ], width),
      new Chart(parent, "frame rate", "fps", [{ label: "frames received", stroke: "#ced4da" }], width),
    ];
  }

  push(s: PlotSample): void {
    const [t, d, p, b, f] = this.charts;
    t.ring.push(s.t, [s.collisionMs]);
    d.ring.push(s.t, [s.geometric]);
    p.ring.push(s.t, [s.perceived, s.truePerceived]);
    b.ring.push(s.t, [s.budgetUse === null ? null : 100 * s.budgetUse, 100 * s.deemedShare]);
    f.ring.push(s.t, [s.fps]);
  }

  clear(): void {
    for (const c of this.charts) c.ring.clear();
  }

  redraw(): void {
    for (const c of this.charts) c.redraw();
  }
}
