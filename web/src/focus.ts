// Focus on a first contact: the page stops the view at the first frame in which a pair turns
// green (a real collision that was not one in the frame before) and measures how far apart the
// two drawn stars are there, so that the viewer can see what the truth in force calls colliding.
//
// The gap is measured on the exact star GetScene describes (core ball and six cones), at the poses
// the frame carried: the least signed distance from a point of one star's surface to the other
// star, over a grid of surface points refined by local search, both ways round. Positive: the
// stars are that far apart; zero or negative: they touch (the deepest surface point of one inside
// the other, a measure of the overlap).
import type { StarDims } from "./star";

/** A body's pose as the page holds it: a column-major rigid 4x4 matrix at offset `o` of `m`. */
export interface Pose {
  m: Float32Array | number[];
  o: number;
}

/** A point on a part of the star: the part (0 core, 1-6 spikes +x, -x, +y, -y, +z, -z) and two parameters. */
interface SurfacePoint {
  part: number;
  u: number;
  v: number;
}

/** The body-frame point of a surface parameterisation: core (polar u, azimuth v), spike (height u in [0, 1], angle v). */
function surface(s: StarDims, p: SurfacePoint, out: number[]): void {
  if (p.part === 0) {
    const st = Math.sin(p.u);
    out[0] = s.coreRadius * st * Math.cos(p.v);
    out[1] = s.coreRadius * st * Math.sin(p.v);
    out[2] = s.coreRadius * Math.cos(p.u);
    return;
  }
  const axis = (p.part - 1) >> 1;
  const sign = (p.part - 1) & 1 ? -1 : 1;
  const h = Math.min(1, Math.max(0, p.u));
  const r = s.spikeBaseRadius * (1 - h);
  out[axis] = sign * h * s.radius;
  out[(axis + 1) % 3] = r * Math.cos(p.v);
  out[(axis + 2) % 3] = r * Math.sin(p.v);
}

/** Signed distance from a body-frame point to a spike along `axis`, `sign` (negative inside). */
function spikeDistance(s: StarDims, q: number[], axis: number, sign: number): number {
  const x = sign * q[axis];
  const u = q[(axis + 1) % 3], w = q[(axis + 2) % 3];
  const y = Math.sqrt(u * u + w * w);
  const h = s.radius, b = s.spikeBaseRadius;
  // In the (along, across) half-plane the spike is the triangle (0, 0), (0, b), (h, 0): its
  // boundary there is the base segment x = 0 and the slant from (0, b) to (h, 0).
  const over = Math.max(0, y - b);
  const base = Math.sqrt(x * x + over * over);
  const t = Math.min(1, Math.max(0, (x * h - (y - b) * b) / (h * h + b * b)));
  const sx = x - t * h, sy = y - b + t * b;
  const slant = Math.sqrt(sx * sx + sy * sy);
  const inside = x >= 0 && y <= b * (1 - x / h);
  return inside ? -Math.min(base, slant) : Math.min(base, slant);
}

/** Signed distance from a body-frame point to the star (exact outside it, negative inside). */
export function starDistance(s: StarDims, q: number[]): number {
  let d = Math.sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]) - s.coreRadius;
  for (let axis = 0; axis < 3; axis++) {
    d = Math.min(d, spikeDistance(s, q, axis, 1), spikeDistance(s, q, axis, -1));
  }
  return d;
}

/** World point of body-frame `q` under pose `a`. */
function toWorld(a: Pose, q: number[], out: number[]): void {
  const m = a.m, o = a.o;
  for (let i = 0; i < 3; i++) out[i] = m[o + i] * q[0] + m[o + 4 + i] * q[1] + m[o + 8 + i] * q[2] + m[o + 12 + i];
}

/** Body-frame point of world `p` under pose `a` (the rotation's transpose). */
function toBody(a: Pose, p: number[], out: number[]): void {
  const m = a.m, o = a.o;
  const dx = p[0] - m[o + 12], dy = p[1] - m[o + 13], dz = p[2] - m[o + 14];
  for (let i = 0; i < 3; i++) out[i] = m[o + 4 * i] * dx + m[o + 4 * i + 1] * dy + m[o + 4 * i + 2] * dz;
}

/** The starting grid: core points and spike points from base rim to apex. */
function grid(): SurfacePoint[] {
  const pts: SurfacePoint[] = [];
  for (let i = 0; i <= 12; i++) for (let j = 0; j < 24; j++) pts.push({ part: 0, u: (Math.PI * i) / 12, v: (2 * Math.PI * j) / 24 });
  for (let part = 1; part <= 6; part++) {
    for (let i = 0; i < 32; i++) for (let j = 0; j < 24; j++) pts.push({ part, u: i / 32, v: (2 * Math.PI * j) / 24 });
    pts.push({ part, u: 1, v: 0 });
  }
  return pts;
}
const GRID = grid();

/** The least signed distance from a surface point of star `a` to star `b`, and where. */
function oneWay(s: StarDims, a: Pose, b: Pose): { d: number; at: number[] } {
  const q = [0, 0, 0], w = [0, 0, 0], r = [0, 0, 0];
  const f = (p: SurfacePoint) => {
    surface(s, p, q);
    toWorld(a, q, w);
    toBody(b, w, r);
    return starDistance(s, r);
  };
  let best = GRID[0], bestD = Infinity;
  for (const p of GRID) {
    const d = f(p);
    if (d < bestD) (bestD = d), (best = p);
  }
  // Local search from the best grid point: a compass search on its two parameters.
  let cur = { ...best };
  let du = cur.part === 0 ? Math.PI / 12 : 1 / 32, dv = (2 * Math.PI) / 24;
  for (let k = 0; k < 40; k++) {
    let moved = false;
    for (const [eu, ev] of [[1, 0], [-1, 0], [0, 1], [0, -1]]) {
      const next = { part: cur.part, u: cur.u + eu * du, v: cur.v + ev * dv };
      if (next.part !== 0) next.u = Math.min(1, Math.max(0, next.u));
      const d = f(next);
      if (d < bestD) (bestD = d), (cur = next), (moved = true);
    }
    if (!moved) (du /= 2), (dv /= 2);
  }
  surface(s, cur, q);
  toWorld(a, q, w);
  return { d: bestD, at: [...w] };
}

/**
 * How far apart two stars of dimensions `s` at poses `a` and `b` are (scene units; zero or
 * negative when they touch), and on each star the surface point nearest the other (world; when
 * they touch, the point reaching deepest into the other).
 */
export function starGap(s: StarDims, a: Pose, b: Pose): { gap: number; ends: [number[], number[]] } {
  const ab = oneWay(s, a, b);
  const ba = oneWay(s, b, a);
  return { gap: Math.min(ab.d, ba.d), ends: [ab.at, ba.at] };
}

/**
 * First contacts in a stream of frames: the real pairs of a frame that were not real in the frame
 * before it. A frame that does not directly follow the previous one seen (a dropped frame, a new
 * scene) has no known "before", so it yields none.
 */
export class FirstContacts {
  private last = -1;
  private lastTime = -1;
  private before = new Set<string>();

  reset(): void {
    this.last = -1;
    this.lastTime = -1;
    this.before.clear();
  }

  /** The pairs (a < b) of this frame that are real now and were not in the frame before. */
  next(index: number, simTimeS: number, real: [number, number][]): [number, number][] {
    const known = this.last >= 0 && index === this.last + 1 && simTimeS > this.lastTime;
    const now = new Set<string>();
    const fresh: [number, number][] = [];
    for (const [x, y] of real) {
      const a = Math.min(x, y), b = Math.max(x, y);
      const key = `${a},${b}`;
      now.add(key);
      if (known && !this.before.has(key)) fresh.push([a, b]);
    }
    this.before = now;
    this.last = index;
    this.lastTime = simTimeS;
    return fresh;
  }
}
