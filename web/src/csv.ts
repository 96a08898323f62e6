// The last frames' metrics, kept for a CSV download: one row per frame received, the columns the
// protocol's FrameMetrics and PhaseProfile carry, with their units in the header.
import { FixationSource, type Frame } from "./gen/foveal/v1/foveal_pb";

/** Frames kept (10 s at 60 Hz). */
export const KEEP_FRAMES = 600;

const COLUMNS = [
  "frame",
  "sim_time_s",
  "collision_time_ms",
  "geometric_inaccuracy_units",
  "perceived_inaccuracy",
  "perceived_inaccuracy_se",
  "true_perceived_inaccuracy",
  "true_false_positives",
  "candidate_pairs",
  "real_collisions",
  "deemed_at_interruption",
  "sphere_tests",
  "budget_exhausted",
  "metrics_stride",
  "integrate_ms",
  "broad_ms",
  "prioritise_ms",
  "narrow_ms",
  "response_ms",
  "measure_ms",
  "renumber_ms",
  "fixation_x",
  "fixation_y",
  "fixation_source",
];

const SOURCES: Record<number, string> = {
  [FixationSource.GAZE]: "gaze",
  [FixationSource.FALLBACK_NO_GAZE]: "fallback_no_gaze",
  [FixationSource.FALLBACK_STALE]: "fallback_stale",
  [FixationSource.FALLBACK_TRACK_LOST]: "fallback_track_lost",
};

export class FrameLog {
  private rows: string[] = [];
  private indices: number[] = [];

  push(f: Frame): void {
    const m = f.metrics, p = f.profile, x = f.fixation;
    if (!m) return;
    const ms = (s: number | undefined) => (s === undefined ? "" : String(1000 * s));
    const row = [
      String(f.index),
      String(f.simTimeS),
      ms(m.collisionTimeS),
      String(m.geometricInaccuracy),
      String(m.perceivedInaccuracy),
      String(m.perceivedInaccuracySe),
      m.audit ? String(m.audit.truePerceivedInaccuracy) : "",
      m.audit ? String(m.audit.trueFalsePositives) : "",
      String(m.candidatePairs),
      String(m.realCollisions),
      String(m.deemedAtInterruption),
      String(m.sphereTests),
      m.budgetExhausted ? "1" : "0",
      String(m.metricsStride),
      ms(p?.integrateS),
      ms(p?.broadS),
      ms(p?.prioritiseS),
      ms(p?.narrowS),
      ms(p?.responseS),
      ms(p?.measureS),
      ms(p?.renumberS),
      x ? String(x.x) : "",
      x ? String(x.y) : "",
      x ? (SOURCES[x.source] ?? "unspecified") : "",
    ];
    this.rows.push(row.join(","));
    this.indices.push(Number(f.index));
    if (this.rows.length > KEEP_FRAMES) {
      this.rows.shift();
      this.indices.shift();
    }
  }

  clear(): void {
    this.rows.length = 0;
    this.indices.length = 0;
  }

  /** The last `n` frames (all kept by default) as CSV, a header line first. */
  csv(n = KEEP_FRAMES): string {
    const rows = this.rows.slice(-Math.max(1, Math.min(n, KEEP_FRAMES)));
    return [COLUMNS.join(","), ...rows].join("\n") + "\n";
  }

  /** "first-last" frame indices of the last `n` frames, for the file's name. */
  range(n = KEEP_FRAMES): string {
    const i = this.indices.slice(-Math.max(1, Math.min(n, KEEP_FRAMES)));
    return i.length ? `${i[0]}-${i[i.length - 1]}` : "none";
  }
}
