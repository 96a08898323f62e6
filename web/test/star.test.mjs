// The star the viewer draws against the star the server tests (no browser needed): every point of
// the drawn surface lies within 0.005R of the exact core ball and cones, the drawing comes from
// GetScene's `star`, and an older server that sends none gets the canonical fractions.
import assert from "node:assert/strict";
import { before, describe, test } from "node:test";
import { bundle } from "./harness.mjs";

let star;
before(async () => {
  star = await bundle("../src/star.ts");
});

/** Points of a triangle on a barycentric grid of `k` steps, corners and edges included. */
function* samples(a, b, c, k) {
  for (let i = 0; i <= k; i++) {
    for (let j = 0; j <= k - i; j++) {
      const u = i / k, v = j / k, w = 1 - u - v;
      yield [0, 1, 2].map((d) => u * a[d] + v * b[d] + w * c[d]);
    }
  }
}

function* triangleCorners(g) {
  const p = g.attributes.position;
  const at = (i) => [p.getX(i), p.getY(i), p.getZ(i)];
  const n = g.index ? g.index.count : p.count;
  for (let t = 0; t < n; t += 3) {
    const i = g.index ? [g.index.getX(t), g.index.getX(t + 1), g.index.getX(t + 2)] : [t, t + 1, t + 2];
    yield i.map(at);
  }
}

const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const norm = (a) => Math.sqrt(dot(a, a));

/** How far inside its exact part (negative: outside) a sampled point of a drawn part is: least, most. */
function deviation(part, inside) {
  let lo = Infinity, hi = -Infinity;
  for (const [a, b, c] of triangleCorners(part)) {
    for (const p of samples(a, b, c, 8)) {
      const d = inside(p);
      lo = Math.min(lo, d);
      hi = Math.max(hi, d);
    }
  }
  return { lo, hi };
}

const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];

/** Where the ray from the centre along unit `u` crosses triangle abc: its distance, or null. */
function crossing(u, a, b, c) {
  const e1 = sub(b, a), e2 = sub(c, a);
  const p = cross(u, e2);
  const det = dot(e1, p);
  if (Math.abs(det) < 1e-15) return null;
  const s = [-a[0], -a[1], -a[2]];
  const v = dot(s, p) / det;
  if (v < 0 || v > 1) return null;
  const q = cross(s, e1);
  const w = dot(u, q) / det;
  if (w < 0 || v + w > 1) return null;
  const t = dot(e2, q) / det;
  return t > 0 ? t : null;
}

/** Signed distance from p to the solid cone of base radius b at the centre, apex at h along axis. */
function coneDistance(p, axis, b, h) {
  const a = dot(p, axis);
  const r = norm(p.map((x, d) => x - a * axis[d]));
  // In the half-plane (a, r): the base edge from (0, 0) to (0, b) and the slant from (0, b) to (h, 0).
  const base = r <= b ? Math.abs(a) : Math.hypot(a, r - b);
  const len = Math.hypot(h, b);
  const k = Math.min(1, Math.max(0, (a * h - (r - b) * b) / (len * len)));
  const slant = Math.hypot(a - k * h, r - b + k * b);
  const inside = a >= 0 && r <= b * (1 - a / h);
  return inside ? -Math.min(base, slant) : Math.min(base, slant);
}

describe("the drawn star", () => {
  for (const radius of [0.2, 1.5]) {
    test(`is within 0.005R of the exact star (R = ${radius})`, () => {
      const dims = { radius, coreRadius: 0.3 * radius, spikeBaseRadius: 0.25 * radius };
      const [core, ...spikes] = star.starParts(dims);
      assert.equal(spikes.length, 6);
      const tol = star.MAX_DEVIATION * radius;
      const eps = 1e-6 * radius;
      const report = [];

      const within = (what, d) => {
        assert.ok(d.lo >= -tol, `${what} stands ${-d.lo / radius}R out of the exact surface`);
        assert.ok(d.hi <= tol, `${what} dips ${d.hi / radius}R into the exact shape`);
        report.push(`${what} ${(-d.lo / radius).toFixed(4)}R out, ${(d.hi / radius).toFixed(4)}R in`);
      };
      within("core", deviation(core, (p) => dims.coreRadius - norm(p)));

      const axes = new Set();
      for (const spike of spikes) {
        // The apex is the vertex furthest out; the axis points at it.
        const p = spike.attributes.position;
        let apex = [0, 0, 0];
        for (let i = 0; i < p.count; i++) {
          const v = [p.getX(i), p.getY(i), p.getZ(i)];
          if (norm(v) > norm(apex)) apex = v;
        }
        assert.ok(Math.abs(norm(apex) - radius) < eps, `apex at ${norm(apex)}, not R`);
        const axis = apex.map((x) => Math.round(x / radius));
        axes.add(axis.join(","));
        // Inside the cone by this much, measured across the axis at the point's height.
        const cone = deviation(spike, (q) => {
          const along = dot(q, axis);
          const across = norm(q.map((x, d) => x - along * axis[d]));
          return dims.spikeBaseRadius * (1 - along / radius) - across;
        });
        within(`spike ${axis.join(",")}`, cone);
      }
      assert.equal(axes.size, 6, `spike axes: ${[...axes].join(" ")}`);

      const g = star.starGeometry(dims);
      console.log(`# R = ${radius}: ${star.triangles(g)} triangles, ${g.attributes.position.count} vertices per body; worst deviation: ${report.join(", ")}`);
    });
  }

  test("has no hole: along every direction from the centre its outer surface is the exact one's, within 0.005R", () => {
    const dims = { radius: 1, coreRadius: 0.3, spikeBaseRadius: 0.25 };
    const tris = star.starParts(dims).flatMap((part) => [...triangleCorners(part)]);
    const axes = [[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]];
    const tol = star.MAX_DEVIATION;
    const rays = 4000;
    for (let i = 0; i < rays; i++) {
      // Fibonacci directions, evenly over the sphere.
      const z = 1 - (2 * i + 1) / rays, rho = Math.sqrt(1 - z * z), phi = i * Math.PI * (3 - Math.sqrt(5));
      const u = [rho * Math.cos(phi), rho * Math.sin(phi), z];
      let out = 0;
      for (const [a, b, c] of tris) out = Math.max(out, crossing(u, a, b, c) ?? 0);
      assert.ok(out > 0, `nothing drawn along ${u}`);
      const q = u.map((x) => x * out);
      const parts = [norm(q) - dims.coreRadius, ...axes.map((e) => coneDistance(q, e, dims.spikeBaseRadius, dims.radius))];
      // On the surface of the union: outside (or within tol of) every part and on (within tol of) one.
      assert.ok(Math.min(...parts) <= tol, `along ${u} the star is drawn ${Math.min(...parts)}R too far out`);
      assert.ok(Math.min(...parts) >= -tol, `along ${u} the outer surface is ${-Math.min(...parts)}R inside: a hole`);
    }
  });

  test("the bound bites: the 20-face core and 6-sided spikes drawn before miss it", () => {
    const dims = { radius: 1, coreRadius: 0.3, spikeBaseRadius: 0.25 };
    const [core, spike] = star.starParts(dims, 0, 6);
    const ball = deviation(core, (p) => dims.coreRadius - norm(p));
    const cone = deviation(spike, (q) => dims.spikeBaseRadius * (1 - q[0]) - Math.hypot(q[1], q[2]));
    assert.ok(Math.max(-ball.lo, ball.hi) > star.MAX_DEVIATION, JSON.stringify(ball));
    assert.ok(Math.max(-cone.lo, cone.hi) > star.MAX_DEVIATION, JSON.stringify(cone));
  });

  test("the tessellation away from the fixation is within 0.035R of the exact star", () => {
    const dims = { radius: 1, coreRadius: 0.3, spikeBaseRadius: 0.25 };
    const [core, spike] = star.starParts(dims, star.PERIPHERAL_SPHERE_DETAIL, star.PERIPHERAL_CONE_SEGMENTS);
    const ball = deviation(core, (p) => dims.coreRadius - norm(p));
    const cone = deviation(spike, (q) => dims.spikeBaseRadius * (1 - q[0]) - Math.hypot(q[1], q[2]));
    for (const d of [ball, cone]) assert.ok(Math.max(-d.lo, d.hi) <= 0.035, JSON.stringify(d));
    console.log(`# away from the fixation: ${star.triangles(star.peripheralStarGeometry(dims))} triangles; core ${JSON.stringify(ball)}, spike ${JSON.stringify(cone)}`);
  });

  test("takes its dimensions from GetScene, or the canonical fractions from an older server", () => {
    const sent = { radius: 0.4, coreRadius: 0.1, spikeBaseRadius: 0.05 };
    assert.deepEqual(star.starDims({ config: { shapeRadius: 0.4 }, star: sent }), sent);
    const old = star.starDims({ config: { shapeRadius: 0.4 } });
    assert.equal(old.radius, 0.4);
    assert.ok(Math.abs(old.coreRadius - 0.12) < 1e-12 && Math.abs(old.spikeBaseRadius - 0.1) < 1e-12, JSON.stringify(old));
    assert.deepEqual(star.starDims({}), { radius: 0.2, coreRadius: 0.3 * 0.2, spikeBaseRadius: 0.25 * 0.2 });
  });
});
