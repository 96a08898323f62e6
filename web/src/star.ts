// The body shape as the server tests it under the `shape` truth, drawn from GetScene's `star`
// closely enough that what the page shows touching is what collides.
import * as THREE from "three";
import { mergeGeometries, mergeVertices } from "three/examples/jsm/utils/BufferGeometryUtils.js";
import type { SceneDescription } from "./gen/foveal/v1/foveal_pb";

/** The star's dimensions, scene units (GetScene's `star`). */
export interface StarDims {
  /** Bounding radius R: the spike apexes are this far from the centre. */
  radius: number;
  /** Radius of the core ball. */
  coreRadius: number;
  /** Radius of each spike's base disc, centred at the body's centre. */
  spikeBaseRadius: number;
}

/** Core ball radius over R, the canonical star's (DESIGN.md), for servers that send no `star`. */
export const CORE_FRACTION = 0.3;
/** Spike base radius over R, likewise. */
export const SPIKE_BASE_FRACTION = 0.25;

/**
 * Tessellation: fine enough that every point of the drawn surface is within 0.005R of the exact
 * one, and no finer, since every body of the instanced mesh pays for every triangle (on a CPU
 * rasteriser the draw time grows with them). Each part straddles its exact surface: its vertices
 * are pushed out just so far that the flat faces between them dip as far inside as the vertices
 * stand outside, which halves the worst deviation of the inscribed part with the same triangles.
 * - Core ball, radius r: an icosahedron subdivided `SPHERE_DETAIL` times. Inscribed (vertices on
 *   the sphere), a face is furthest inside at its circumcentre, by r(1 - c) where c r is the
 *   distance of its plane from the centre; the smallest c over the faces of detail 2 is 0.9717
 *   (measured at build time below), so the inscribed ball would be off by 0.028r = 0.0085R
 *   (r = 0.3R). With the vertices on the sphere of radius 2r/(1 + c) the worst deviation is
 *   r(1 - c)/(1 + c) = 0.0144r = 0.0043R, either way.
 * - Spikes, base radius b = 0.25R: cones whose cross-section at every height is a regular n-gon.
 *   Inscribed in the exact circle of radius r it is at most r(1 - cos(pi/n)) inside it (n = 12:
 *   0.034r); with its vertices at radius 2r/(1 + cos(pi/n)) it is within
 *   r(1 - cos(pi/n))/(1 + cos(pi/n)) = 0.0173r of it, at most 0.0043R at the base.
 * So the drawn star is within 0.0043R of the tested one where the viewer looks (bodies away from
 * the fixation are drawn coarser, see PERIPHERAL_SPHERE_DETAIL) (the 20-face core and 6-sided cones drawn
 * before were up to 0.062R and 0.033R inside it). Leaving out the core's faces hidden inside the
 * spikes (visibleCore), a body costs 120 + 6 * 12 = 192 triangles instead of 56; on a CPU
 * rasteriser (SwiftShader) a draw of 10,000 bodies takes about twice as long as before, with a GPU
 * neither count matters. test/star.test.mjs measures the deviation on the geometry itself, and that
 * the faces left out leave no hole.
 */
export const SPHERE_DETAIL = 2;
/** Radial segments of each spike (see SPHERE_DETAIL). */
export const CONE_SEGMENTS = 12;
/** The bound the tessellation keeps to, as a fraction of R. */
export const MAX_DEVIATION = 0.005;

/** The star the server describes, or the canonical one of its shape radius (an older server). */
export function starDims(d: SceneDescription): StarDims {
  const s = d.star;
  if (s && s.radius > 0 && s.coreRadius > 0 && s.spikeBaseRadius > 0) {
    return { radius: s.radius, coreRadius: s.coreRadius, spikeBaseRadius: s.spikeBaseRadius };
  }
  const radius = d.config?.shapeRadius || 0.2;
  return { radius, coreRadius: CORE_FRACTION * radius, spikeBaseRadius: SPIKE_BASE_FRACTION * radius };
}

/** Rotations taking +y to +x, -x, +y, -y, +z, -z. */
const AXES: [number, number, number][] = [
  [0, 0, -Math.PI / 2], [0, 0, Math.PI / 2], [0, 0, 0], [0, 0, Math.PI], [Math.PI / 2, 0, 0], [-Math.PI / 2, 0, 0],
];

/**
 * The smallest distance of a face's plane from the centre of an icosphere of radius 1 and this
 * detail (three.js subdivides unevenly: the faces next to the icosahedron's vertices are largest).
 */
function innermostFace(detail: number): number {
  const p = new THREE.IcosahedronGeometry(1, detail).attributes.position;
  const a = new THREE.Vector3(), b = new THREE.Vector3(), c = new THREE.Vector3(), n = new THREE.Vector3();
  let least = 1;
  for (let i = 0; i < p.count; i += 3) {
    a.fromBufferAttribute(p, i);
    b.fromBufferAttribute(p, i + 1);
    c.fromBufferAttribute(p, i + 2);
    n.crossVectors(b.sub(a), c.sub(a)).normalize();
    least = Math.min(least, Math.abs(n.dot(a)));
  }
  return least;
}

/**
 * The parts, body frame, indexed, with smooth normals: the core ball, then the six spikes
 * (cones along +x, -x, +y, -y, +z, -z, base disc centred at the origin, apex at R), tessellated
 * as described at SPHERE_DETAIL.
 */
export function starParts(s: StarDims, detail = SPHERE_DETAIL, segments = CONE_SEGMENTS): THREE.BufferGeometry[] {
  const base = (2 * s.spikeBaseRadius) / (1 + Math.cos(Math.PI / segments));
  const parts = [visibleCore(s, detail, base * Math.cos(Math.PI / segments))];
  // A base disc inside the core is hidden: leave it out unless the spikes are wider than the core.
  const openEnded = base <= s.coreRadius;
  for (const [rx, ry, rz] of AXES) {
    const cone = new THREE.ConeGeometry(base, s.radius, segments, 1, openEnded);
    cone.deleteAttribute("uv");
    cone.translate(0, s.radius / 2, 0);
    cone.applyMatrix4(new THREE.Matrix4().makeRotationFromEuler(new THREE.Euler(rx, ry, rz)));
    parts.push(cone);
  }
  return parts;
}

/**
 * The core ball without the faces the spikes hide. Each spike covers the ball out to 40 degrees
 * from its axis (where the cone leaves the ball), 70% of the ball's surface in all; drawing the
 * faces there would cost every body triangles no one can see. A face is left out when its three
 * corners lie within one drawn cone: a cone and a flat face are convex, so the whole face is then
 * inside it. `inner` is the radius of the circle inscribed in the drawn cone's base polygon; the
 * drawn cone contains that circle's cone.
 */
function visibleCore(s: StarDims, detail: number, inner: number): THREE.BufferGeometry {
  const ball = new THREE.IcosahedronGeometry((2 * s.coreRadius) / (1 + innermostFace(detail)), detail);
  const pos = ball.attributes.position.array;
  const nor = ball.attributes.normal.array;
  const within = (i: number, axis: number, sign: number) => {
    const along = sign * pos[3 * i + axis];
    const across = Math.hypot(pos[3 * i + ((axis + 1) % 3)], pos[3 * i + ((axis + 2) % 3)]);
    return along >= 0 && across < inner * (1 - along / s.radius);
  };
  const hidden = (t: number) =>
    [0, 1, 2].some((axis) => [1, -1].some((sign) => [t, t + 1, t + 2].every((i) => within(i, axis, sign))));
  const keptPos: number[] = [];
  const keptNor: number[] = [];
  for (let t = 0; t < pos.length / 3; t += 3) {
    if (hidden(t)) continue;
    keptPos.push(...pos.slice(3 * t, 3 * t + 9));
    keptNor.push(...nor.slice(3 * t, 3 * t + 9));
  }
  const core = new THREE.BufferGeometry();
  core.setAttribute("position", new THREE.Float32BufferAttribute(keptPos, 3));
  core.setAttribute("normal", new THREE.Float32BufferAttribute(keptNor, 3));
  // Polyhedra come unindexed; sharing the vertices keeps the vertex work per body down.
  return mergeVertices(core);
}

/** One geometry for the instanced mesh: the parts merged once. */
export function starGeometry(s: StarDims): THREE.BufferGeometry {
  const merged = mergeGeometries(starParts(s));
  if (!merged) throw new Error("star geometry: parts do not merge");
  return merged;
}

/**
 * Tessellation of the bodies drawn away from the fixation (see SceneView): the icosahedron itself
 * for the core and six-sided spikes, straddling their surfaces as above, within
 * r(1 - c)/(1 + c) = 0.114r = 0.034R of the core (c = 0.795 for the icosahedron's faces) and
 * 0.072b = 0.018R of a spike: about a third of the triangles of the full tessellation.
 */
export const PERIPHERAL_SPHERE_DETAIL = 0;
/** Radial segments of each spike away from the fixation. */
export const PERIPHERAL_CONE_SEGMENTS = 6;

/** The star as drawn away from the fixation: the coarser tessellation, merged. */
export function peripheralStarGeometry(s: StarDims): THREE.BufferGeometry {
  const merged = mergeGeometries(starParts(s, PERIPHERAL_SPHERE_DETAIL, PERIPHERAL_CONE_SEGMENTS));
  if (!merged) throw new Error("star geometry: parts do not merge");
  return merged;
}

/** Triangles of a geometry (indexed or not). */
export function triangles(g: THREE.BufferGeometry): number {
  return (g.index ? g.index.count : g.attributes.position.count) / 3;
}
