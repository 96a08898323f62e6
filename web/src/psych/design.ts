// An experiment's design as the server sends it (the server has checked it against its limits;
// see server/src/psych/design.rs), and the trial lists drawn from it.

import type { Axis } from "./geometry";

export interface GapLevel {
  label: string;
  gap_deg: number;
  weight: number;
}

export interface Answer {
  keys: string[];
  mouse_button: number | null;
}

export interface Distractors {
  counts: number[];
  colour: "red" | "white";
  speed_deg_s: number;
  field_deg: number;
}

export interface Design {
  name: string;
  title: string;
  stimulus: { disc_diameter_deg: number; duration_ms: number; pair_axis: Axis; motion_speed_deg_s?: number | null };
  fixation_cross_deg: number;
  inter_stimulus_ms: number;
  eccentricities_deg: number[];
  directions_deg: number[];
  gaps: GapLevel[];
  repetitions: number;
  blocks: number;
  practice_trials: number;
  responses: { touching: Answer; apart: Answer };
  timing: { late_frame_factor: number; max_repeats_per_block: number };
  distractors?: Distractors | null;
  hide_cross_during_stimulus?: boolean;
}

/** One condition: an eccentricity, a direction, a gap level and a distractor level. */
export interface Cell {
  /** As the server numbers cells: ((e * directions + d) * gap levels + g) * distractor levels + l. */
  index: number;
  eccentricityDeg: number;
  directionDeg: number;
  gap: GapLevel;
  /** Distractors shown (0 without). */
  distractors: number;
}

/** Every cell of the design, in the server's numbering. */
export function cells(d: Design): Cell[] {
  const out: Cell[] = [];
  const levels = d.distractors?.counts ?? [0];
  d.eccentricities_deg.forEach((e, ei) =>
    d.directions_deg.forEach((dir, di) =>
      d.gaps.forEach((gap, gi) =>
        levels.forEach((count, li) => {
          const index = ((ei * d.directions_deg.length + di) * d.gaps.length + gi) * levels.length + li;
          out.push({ index, eccentricityDeg: e, directionDeg: dir, gap, distractors: count });
        }),
      ),
    ),
  );
  return out;
}

/** Fisher-Yates, in place. */
export function shuffle<T>(a: T[], random: () => number = Math.random): T[] {
  for (let i = a.length - 1; i > 0; i--) {
    const j = Math.floor(random() * (i + 1));
    [a[i], a[j]] = [a[j], a[i]];
  }
  return a;
}

/** The main trials: every cell, its gap's weight times the repetitions, shuffled, in blocks. */
export function blocks(d: Design, random: () => number = Math.random): Cell[][] {
  const all: Cell[] = [];
  for (const c of cells(d)) for (let k = 0; k < c.gap.weight * d.repetitions; k++) all.push(c);
  shuffle(all, random);
  const out: Cell[][] = [];
  for (let b = 0; b < d.blocks; b++) {
    out.push(all.slice(Math.round((b * all.length) / d.blocks), Math.round(((b + 1) * all.length) / d.blocks)));
  }
  return out;
}

/** Practice trials: drawn from the cells as the main trials weigh them. */
export function practice(d: Design, random: () => number = Math.random): Cell[] {
  const weighted: Cell[] = [];
  for (const c of cells(d)) for (let k = 0; k < c.gap.weight; k++) weighted.push(c);
  return Array.from({ length: d.practice_trials }, () => weighted[Math.floor(random() * weighted.length)]);
}
