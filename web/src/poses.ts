// Decoding a frame's poses straight into three.js instance matrices.
//
// This is the page's per-frame hot path (N = 10,000 at 60 Hz), so it reads the packed bytes with
// typed-array views and writes the 16 floats of each matrix directly: no per-body objects.
import type { Poses, QuantisedPoses } from "./gen/foveal/v1/foveal_pb";

const SQRT1_2 = Math.SQRT1_2;

/** Write a column-major 4x4 rigid transform (unit quaternion x, y, z, w and position) at `o`. */
function writeMatrix(
  m: Float32Array,
  o: number,
  x: number,
  y: number,
  z: number,
  w: number,
  px: number,
  py: number,
  pz: number,
): void {
  const x2 = x + x, y2 = y + y, z2 = z + z;
  const xx = x * x2, xy = x * y2, xz = x * z2;
  const yy = y * y2, yz = y * z2, zz = z * z2;
  const wx = w * x2, wy = w * y2, wz = w * z2;
  m[o] = 1 - (yy + zz);
  m[o + 1] = xy + wz;
  m[o + 2] = xz - wy;
  m[o + 3] = 0;
  m[o + 4] = xy - wz;
  m[o + 5] = 1 - (xx + zz);
  m[o + 6] = yz + wx;
  m[o + 7] = 0;
  m[o + 8] = xz + wy;
  m[o + 9] = yz - wx;
  m[o + 10] = 1 - (xx + yy);
  m[o + 11] = 0;
  m[o + 12] = px;
  m[o + 13] = py;
  m[o + 14] = pz;
  m[o + 15] = 1;
}

/** A little-endian view of a byte field (protobuf-es hands out sub-arrays of the message). */
function view(b: Uint8Array): DataView {
  return new DataView(b.buffer, b.byteOffset, b.byteLength);
}

/**
 * Decode quantised poses (see `QuantisedPoses` in foveal.proto) into `matrices` (16 floats per
 * body), world coordinates. Returns the number of bodies written (at most what `matrices` holds).
 */
export function applyQuantisedPoses(p: QuantisedPoses, matrices: Float32Array): number {
  const n = Math.min(p.bodies, p.positions.length / 6, p.orientations.length / 4, matrices.length / 16) | 0;
  const pos = view(p.positions);
  const rot = view(p.orientations);
  const ox = p.origin?.x ?? 0, oy = p.origin?.y ?? 0, oz = p.origin?.z ?? 0;
  const s = p.extent / 65535;
  const k = (2 / 1023) * SQRT1_2;
  const c = new Float32Array(4);
  for (let i = 0; i < n; i++) {
    const px = ox + pos.getUint16(6 * i, true) * s;
    const py = oy + pos.getUint16(6 * i + 2, true) * s;
    const pz = oz + pos.getUint16(6 * i + 4, true) * s;
    const bits = rot.getUint32(4 * i, true);
    const largest = bits >>> 30;
    let shift = 20;
    let sum = 0;
    for (let j = 0; j < 4; j++) {
      if (j === largest) continue;
      const v = ((bits >>> shift) & 0x3ff) * k - SQRT1_2;
      c[j] = v;
      sum += v * v;
      shift -= 10;
    }
    c[largest] = Math.sqrt(Math.max(0, 1 - sum));
    writeMatrix(matrices, 16 * i, c[0], c[1], c[2], c[3], px, py, pz);
  }
  return n;
}

/** Decode f32 poses (see `Poses` in foveal.proto) into `matrices`; returns the bodies written. */
export function applyPoses(p: Poses, matrices: Float32Array): number {
  const n = Math.min(p.bodies, p.positions.length / 12, p.orientations.length / 16, matrices.length / 16) | 0;
  const pos = view(p.positions);
  const rot = view(p.orientations);
  const ox = p.origin?.x ?? 0, oy = p.origin?.y ?? 0, oz = p.origin?.z ?? 0;
  for (let i = 0; i < n; i++) {
    writeMatrix(
      matrices,
      16 * i,
      rot.getFloat32(16 * i, true),
      rot.getFloat32(16 * i + 4, true),
      rot.getFloat32(16 * i + 8, true),
      rot.getFloat32(16 * i + 12, true),
      ox + pos.getFloat32(12 * i, true),
      oy + pos.getFloat32(12 * i + 4, true),
      oz + pos.getFloat32(12 * i + 8, true),
    );
  }
  return n;
}

/** Call `f(a, b)` for every (u32, u32) pair packed in `bytes` (see `Collisions`). */
export function forEachPair(bytes: Uint8Array, f: (a: number, b: number) => void): void {
  const v = view(bytes);
  for (let o = 0; o + 8 <= bytes.length; o += 8) f(v.getUint32(o, true), v.getUint32(o + 4, true));
}

/** What an audit found of a deemed pair (`Collisions.deemed_truth`). */
export const enum DeemedTruth {
  NotAudited = 0,
  Touching = 1,
  Apart = 2,
}

/**
 * Call `f(a, b, truth)` for every deemed pair of a collision list with what the frame's audit
 * found of it (`NotAudited` for every pair of a frame without an audit).
 */
export function forEachDeemed(
  c: { deemed: Uint8Array; deemedTruth: Uint8Array },
  f: (a: number, b: number, truth: DeemedTruth) => void,
): void {
  const v = view(c.deemed), t = c.deemedTruth;
  for (let o = 0, k = 0; o + 8 <= c.deemed.length; o += 8, k++) {
    f(v.getUint32(o, true), v.getUint32(o + 4, true), (t[k] ?? 0) as DeemedTruth);
  }
}
