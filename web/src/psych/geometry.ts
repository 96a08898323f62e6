// Degrees of visual angle on a flat screen, exact: the eye sits at the viewing distance in front
// of the fixation cross, and the angle between two screen points is the angle between the eye's
// rays to them (not a small-angle approximation, which is 1.5% off at 10 degrees).
//
// Screen points are in centimetres from the fixation, x to the right and y up.

export type Point = readonly [number, number];

const RAD = Math.PI / 180;

/** The angle (degrees) between the eye's rays to `a` and `b`, the eye `distanceCm` away. */
export function angleDeg(a: Point, b: Point, distanceCm: number): number {
  const [ax, ay, az] = [a[0], a[1], distanceCm];
  const [bx, by, bz] = [b[0], b[1], distanceCm];
  const cx = ay * bz - az * by;
  const cy = az * bx - ax * bz;
  const cz = ax * by - ay * bx;
  return Math.atan2(Math.hypot(cx, cy, cz), ax * bx + ay * by + az * bz) / RAD;
}

/** The screen point at eccentricity `eccDeg` from the fixation in direction `dirDeg`. */
export function pointAt(eccDeg: number, dirDeg: number, distanceCm: number): Point {
  const r = distanceCm * Math.tan(eccDeg * RAD);
  return [r * Math.cos(dirDeg * RAD), r * Math.sin(dirDeg * RAD)];
}

/** The point `p + t u` (t >= 0) whose ray makes `deg` degrees with `p`'s: by bisection. */
export function along(p: Point, u: Point, deg: number, distanceCm: number): Point {
  if (deg <= 0) return p;
  const at = (t: number): Point => [p[0] + t * u[0], p[1] + t * u[1]];
  let hi = distanceCm * deg * RAD + 1e-6;
  while (angleDeg(p, at(hi), distanceCm) < deg) hi *= 2;
  let lo = 0;
  for (let i = 0; i < 80; i++) {
    const mid = (lo + hi) / 2;
    if (angleDeg(p, at(mid), distanceCm) < deg) lo = mid;
    else hi = mid;
  }
  return at((lo + hi) / 2);
}

export type Axis = "horizontal" | "vertical" | "radial" | "tangential" | "random";

/** The unit vector the two discs' centres lie along, at the point `p` between them; a `random`
 * axis is the angle drawn for the trial (`axisDeg`, counter-clockwise from the right). */
export function axisAt(axis: Axis, p: Point, axisDeg = 0): Point {
  const r = Math.hypot(p[0], p[1]);
  switch (axis) {
    case "random":
      return [Math.cos(axisDeg * RAD), Math.sin(axisDeg * RAD)];
    case "horizontal":
      return [1, 0];
    case "vertical":
      return [0, 1];
    case "radial":
      return r > 0 ? [p[0] / r, p[1] / r] : [1, 0];
    case "tangential":
      return r > 0 ? [-p[1] / r, p[0] / r] : [0, 1];
  }
}

/** Two discs on screen (centimetres from the fixation). */
export interface Layout {
  /** The point between the discs' facing edges. */
  contact: Point;
  centres: [Point, Point];
  radii: [number, number];
  /** The distance between the facing edges. */
  gapCm: number;
}

/**
 * Two discs of diameter `diameterDeg` whose facing edges are `gapDeg` apart (both angles as
 * seen from the eye), the point between them at (`eccDeg`, `dirDeg`), along `axis` (for a
 * `random` axis, at `axisDeg`). `awayDeg` moves each disc that much further out along the axis:
 * a moving pair at a moment other than its closest.
 */
export function layout(eccDeg: number, dirDeg: number, gapDeg: number, diameterDeg: number, axis: Axis, distanceCm: number, axisDeg = 0, awayDeg = 0): Layout {
  const p = pointAt(eccDeg, dirDeg, distanceCm);
  const u = axisAt(axis, p, axisDeg);
  const back: Point = [-u[0], -u[1]];
  const half = gapDeg / 2 + Math.max(0, awayDeg);
  const edges: [Point, Point] = [along(p, back, half, distanceCm), along(p, u, half, distanceCm)];
  const centres: [Point, Point] = [along(p, back, half + diameterDeg / 2, distanceCm), along(p, u, half + diameterDeg / 2, distanceCm)];
  const dist = (a: Point, b: Point) => Math.hypot(a[0] - b[0], a[1] - b[1]);
  const radii: [number, number] = [dist(centres[0], edges[0]), dist(centres[1], edges[1])];
  return { contact: p, centres, radii, gapCm: dist(edges[0], edges[1]) };
}

/**
 * How far out each disc of a moving pair is, `tMs` into a presentation of `durationMs` at
 * `speedDegS` (degrees per second): approaching for the first half, closest at the middle,
 * receding for the second (the paper's experiment 2).
 */
export function awayAt(tMs: number, durationMs: number, speedDegS: number): number {
  return (speedDegS * Math.abs(tMs - durationMs / 2)) / 1000;
}

/** CSS pixels per centimetre a display of these dimensions has, at this device pixel ratio. */
export function pxPerCmOfDisplay(widthPx: number, heightPx: number, diagonalIn: number, devicePixelRatio: number): number {
  return Math.hypot(widthPx, heightPx) / (diagonalIn * 2.54) / devicePixelRatio;
}

/** A credit card's width (ISO/IEC 7810 ID-1), the calibration's reference. */
export const CARD_WIDTH_CM = 8.56;
/** Its height. */
export const CARD_HEIGHT_CM = 5.398;
