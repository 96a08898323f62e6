// The viewer's close-up of a first contact (the F key, or `#focus` in the address), in a real
// browser against a real foveal-server, under each truth: the page stops at a frame in which a
// pair turns green, that pair is a real collision there and was not in the frame before (checked
// on the server's own frame stream), the camera is framed on it, and the drawn stars touch under
// the shape truth and are visibly apart under the leaf-sphere truth (measured by the page on the
// frame's poses, and checked here from the server's poses against dense samples of the two stars).
//
// FOVEAL_SCREENSHOT=1 also writes the close-ups to docs/figures/contact-<truth>.png (README).
import assert from "node:assert/strict";
import { mkdirSync } from "node:fs";
import { join } from "node:path";
import { after, before, describe, test } from "node:test";
import { bundle, clientModule, freePort, launch, missing, repo, sleep, startServer, waitFor } from "./harness.mjs";

const skip = missing() ?? false;

/** The scene of the README's pictures: few bodies, a fixed seed, exact frames. */
const SCENE = { bodies: 40, seed: 1 };

// ------------------------------------------------------------------ an independent star judge

const R = 0.2, CORE = 0.3 * R, BASE = 0.25 * R; // the canonical star (DESIGN.md "Shape")

/** Whether body-frame point (x, y, z) lies in the star (closed). */
function inStar(x, y, z) {
  if (x * x + y * y + z * z <= CORE * CORE) return true;
  for (const [along, u, v] of [[x, y, z], [y, z, x], [z, x, y]]) {
    const across = Math.sqrt(u * u + v * v);
    if (across <= BASE * (1 - Math.abs(along) / R)) return true;
  }
  return false;
}

/** Distance from 2D point (px, py) to segment (ax, ay)-(bx, by). */
function segment(px, py, ax, ay, bx, by) {
  const dx = bx - ax, dy = by - ay;
  const t = Math.max(0, Math.min(1, ((px - ax) * dx + (py - ay) * dy) / (dx * dx + dy * dy)));
  const ex = px - ax - t * dx, ey = py - ay - t * dy;
  return Math.sqrt(ex * ex + ey * ey);
}

/** Distance from body-frame point (x, y, z) to the star (0 inside): the least over its parts. */
function toStar(x, y, z) {
  if (inStar(x, y, z)) return 0;
  let d = Math.sqrt(x * x + y * y + z * z) - CORE;
  for (const [along, u, v] of [[x, y, z], [-x, y, z], [y, z, x], [-y, z, x], [z, x, y], [-z, x, y]]) {
    // A cone is its axial half-plane's triangle (0, 0), (0, BASE), (R, 0) turned about its axis.
    const across = Math.sqrt(u * u + v * v);
    d = Math.min(d, segment(along, across, 0, 0, 0, BASE), segment(along, across, 0, BASE, R, 0), segment(along, across, R, 0, 0, 0));
  }
  return d;
}

/** Body-frame points on the star: the core's sphere and the six cones' sides, spaced under 0.02R. */
function starSurface() {
  const pts = [];
  const k = 4000;
  for (let i = 0; i < k; i++) {
    const z = 1 - (2 * (i + 0.5)) / k, r = Math.sqrt(1 - z * z), phi = i * Math.PI * (3 - Math.sqrt(5));
    pts.push([CORE * r * Math.cos(phi), CORE * r * Math.sin(phi), CORE * z]);
  }
  for (let axis = 0; axis < 3; axis++) {
    for (const sign of [1, -1]) {
      for (let i = 0; i <= 100; i++) {
        const h = i / 100, rad = BASE * (1 - h);
        const rings = i === 100 ? 1 : 96;
        for (let j = 0; j < rings; j++) {
          const a = (2 * Math.PI * j) / rings;
          const p = [0, 0, 0];
          p[axis] = sign * h * R;
          p[(axis + 1) % 3] = rad * Math.cos(a);
          p[(axis + 2) % 3] = rad * Math.sin(a);
          pts.push(p);
        }
      }
    }
  }
  return pts;
}
const SURFACE = starSurface();

/** Rotate v by the unit quaternion (x, y, z, w). */
function rotate([x, y, z, w], v) {
  const tx = 2 * (y * v[2] - z * v[1]), ty = 2 * (z * v[0] - x * v[2]), tz = 2 * (x * v[1] - y * v[0]);
  return [v[0] + w * tx + (y * tz - z * ty), v[1] + w * ty + (z * tx - x * tz), v[2] + w * tz + (x * ty - y * tx)];
}

/** The 3x3 rotation matrix (row-major) of a unit quaternion. */
function rotation(q) {
  const c = [[1, 0, 0], [0, 1, 0], [0, 0, 1]].map((e) => rotate(q, e));
  return [c[0][0], c[1][0], c[2][0], c[0][1], c[1][1], c[2][1], c[0][2], c[1][2], c[2][2]];
}

/**
 * Two stars at poses {p: centre, q: quaternion}: whether a surface sample of either lies in the
 * other (they overlap), and the least distance from a sample of either to the other star (an
 * upper bound on their gap, within the samples' spacing of it: about 0.01R).
 */
function judge(a, b) {
  let overlap = false, gap = Infinity;
  for (const [s, o] of [[a, b], [b, a]]) {
    // Body frame of s to body frame of o: o's rotation transposed times (s's rotation v + s.p - o.p).
    const S = rotation(s.q), O = rotation(o.q);
    const t = [0, 1, 2].map((i) => s.p[i] - o.p[i]);
    for (const v of SURFACE) {
      const w0 = S[0] * v[0] + S[1] * v[1] + S[2] * v[2] + t[0];
      const w1 = S[3] * v[0] + S[4] * v[1] + S[5] * v[2] + t[1];
      const w2 = S[6] * v[0] + S[7] * v[1] + S[8] * v[2] + t[2];
      const d = toStar(O[0] * w0 + O[3] * w1 + O[6] * w2, O[1] * w0 + O[4] * w1 + O[7] * w2, O[2] * w0 + O[5] * w1 + O[8] * w2);
      if (d === 0) overlap = true;
      if (d < gap) gap = d;
    }
  }
  return { overlap, gap };
}

/** A rigid column-major matrix from a centre and a unit quaternion (as the page holds poses). */
function matrix({ p, q }) {
  const col = (v) => rotate(q, v);
  return [...col([1, 0, 0]), 0, ...col([0, 1, 0]), 0, ...col([0, 0, 1]), 0, ...p, 1];
}

describe("the page's star gap", () => {
  let focus, dims;
  before(async () => {
    focus = await bundle("../src/focus.ts");
    dims = { radius: R, coreRadius: CORE, spikeBaseRadius: BASE };
  });

  test("agrees with dense samples of the two stars, apart and touching", () => {
    // Seeded poses at centre distances from 0.5R to 2R: cores, spikes and tips against each other.
    let seed = 7;
    const rand = () => ((seed = (Math.imul(seed, 1664525) + 1013904223) >>> 0) / 2 ** 32);
    const quat = () => {
      const q = [rand() - 0.5, rand() - 0.5, rand() - 0.5, rand() - 0.5];
      const n = Math.hypot(...q);
      return q.map((x) => x / n);
    };
    let apart = 0, touching = 0;
    for (let k = 0; k < 40; k++) {
      const d = R * (0.5 + 1.5 * rand());
      const dir = rotate(quat(), [1, 0, 0]);
      const a = { p: [0.3, -0.1, 0.2], q: quat() };
      const b = { p: a.p.map((x, i) => x + d * dir[i]), q: quat() };
      const { gap } = focus.starGap(dims, { m: matrix(a), o: 0 }, { m: matrix(b), o: 0 });
      const j = judge(a, b);
      if (j.overlap) {
        touching++;
        assert.ok(gap <= 0.02 * R, `pose ${k}: the samples overlap, the page says ${(gap / R).toFixed(4)}R apart`);
      } else {
        apart++;
        assert.ok(
          Math.abs(gap - j.gap) <= 0.03 * R,
          `pose ${k}: the page says ${(gap / R).toFixed(4)}R, the samples ${(j.gap / R).toFixed(4)}R`,
        );
      }
    }
    assert.ok(apart >= 5 && touching >= 5, `${apart} poses apart, ${touching} touching`);
  });
});

// ------------------------------------------------------------------------------ in the browser

/** Poses of body i in a Frame's f32 `poses`: centre and quaternion (x, y, z, w). */
function pose(poses, i) {
  const p = new DataView(poses.positions.buffer, poses.positions.byteOffset, poses.positions.byteLength);
  const q = new DataView(poses.orientations.buffer, poses.orientations.byteOffset, poses.orientations.byteLength);
  const o = poses.origin ?? { x: 0, y: 0, z: 0 };
  return {
    p: [o.x + p.getFloat32(12 * i, true), o.y + p.getFloat32(12 * i + 4, true), o.z + p.getFloat32(12 * i + 8, true)],
    q: [0, 1, 2, 3].map((k) => q.getFloat32(16 * i + 4 * k, true)),
  };
}

/** The real pairs of a frame, as "a,b" with a < b. */
function realPairs(f) {
  const b = f.collisions.real;
  const v = new DataView(b.buffer, b.byteOffset, b.byteLength);
  const out = new Set();
  for (let o = 0; o + 8 <= b.length; o += 8) {
    const x = v.getUint32(o, true), y = v.getUint32(o + 4, true);
    out.add(`${Math.min(x, y)},${Math.max(x, y)}`);
  }
  return out;
}

for (const truth of ["leaf-spheres", "shape"]) {
  describe(`the viewer's close-up of a first contact under --truth ${truth}`, { skip }, () => {
    let server, browser, page, watching, watcher;
    /** The server's frames by index: sim time, real pairs, poses (the last 1,200). */
    const frames = new Map();

    before(async () => {
      const { nodeClient } = await clientModule();
      // One body (no pairs) until the page asks for the scene, so that the first contact the page
      // stops at is one of the scene's first, whatever the time the page takes to load.
      server = await startServer(await freePort(), [
        "-n", "1", "--seed", String(SCENE.seed), "--budget", "exact", "--truth", truth,
      ]);
      const rpc = nodeClient(server.url);
      watching = new AbortController();
      watcher = (async () => {
        try {
          const stream = rpc.watchFrames(
            { everyK: 1, includePoses: true, quantisedPoses: false, includeCollisions: true },
            { signal: watching.signal },
          );
          for await (const f of stream) {
            frames.set(Number(f.index), { simTimeS: f.simTimeS, real: realPairs(f), poses: f.poses });
            frames.delete(Number(f.index) - 1200);
          }
        } catch (e) {
          if (!watching.signal.aborted) throw e;
        }
      })();
      browser = await launch();
      page = await browser.browser.newPage();
      await page.setViewportSize({ width: 1200, height: 760 });
      await page.goto(`${server.url}#focus`);
    });

    after(async () => {
      watching?.abort();
      await watcher;
      await browser?.close();
      await server?.stop();
    });

    test("stops at a pair turning green, frames it, and the stars touch only under the shape truth", async () => {
      const connected = await waitFor(() => page.evaluate(() => window.foveal.stats.connected), 30_000, 100);
      assert.ok(connected, "the page never connected");
      assert.equal(await page.evaluate(() => window.foveal.focus.armed), true, "#focus did not arm the page");
      await page.fill("#bodies", String(SCENE.bodies));
      await page.press("#bodies", "Enter");

      const found = await waitFor(() => page.evaluate(() => window.foveal.focus.found), 90_000, 100);
      assert.ok(found, `no first contact in 90 s (status "${await page.textContent("#status")}")`);
      const [a, b] = found.pair;
      console.log(
        `# ${truth}: bodies ${a} and ${b} at frame ${found.frame} (t = ${found.simTimeS.toFixed(3)} s), ` +
          `page gap ${(found.gap / found.radius).toFixed(4)}R`,
      );
      assert.equal(found.truth, truth);
      assert.equal(found.radius, R);

      // A real collision in that frame and not in the frame before, on the server's own stream.
      const here = await waitFor(() => frames.get(found.frame), 10_000);
      const prev = frames.get(found.frame - 1);
      assert.ok(here && prev, `the server's stream lacks frame ${found.frame} or the one before`);
      assert.ok(prev.simTimeS < here.simTimeS, "the frame before is of another scene");
      assert.ok(here.real.has(`${a},${b}`), `bodies ${a} and ${b} are not a real pair in frame ${found.frame}`);
      assert.ok(!prev.real.has(`${a},${b}`), `bodies ${a} and ${b} were already a real pair in the frame before`);

      // The page held the server's poses, and the camera looks at the pair's midpoint.
      const pa = pose(here.poses, a), pb = pose(here.poses, b);
      for (const [mine, theirs] of [[found.centres[0], pa.p], [found.centres[1], pb.p]]) {
        assert.ok(Math.hypot(...mine.map((x, i) => x - theirs[i])) < 1e-5, `page centre ${mine}, server ${theirs}`);
      }
      const view = await page.evaluate(([p, q]) => {
        const v = window.foveal.view;
        const ndc = (c) => {
          const w = v.camera.position.clone().set(c[0], c[1], c[2]).project(v.camera);
          return [w.x, w.y, w.z];
        };
        return { target: v.controls.target.toArray(), focused: v.focused, a: ndc(p), b: ndc(q) };
      }, [pa.p, pb.p]);
      assert.ok(view.focused, "the view is not framed on the pair");
      const mid = pa.p.map((x, i) => (x + pb.p[i]) / 2);
      assert.ok(Math.hypot(...view.target.map((x, i) => x - mid[i])) < 1e-4, `orbit target ${view.target}, midpoint ${mid}`);
      for (const c of [view.a, view.b]) {
        assert.ok(Math.abs(c[0]) < 0.8 && Math.abs(c[1]) < 0.8 && Math.abs(c[2]) < 1, `a centre projects to ${c}`);
      }

      // What the page measured, against dense samples of the two stars at the server's poses.
      const j = judge(pa, pb);
      console.log(`# ${truth}: samples ${j.overlap ? "overlap" : `${(j.gap / R).toFixed(4)}R apart`}`);
      if (truth === "shape") {
        assert.ok(j.overlap || j.gap <= 0.02 * R, `the samples are ${(j.gap / R).toFixed(4)}R apart`);
        assert.ok(found.gap <= 0.005 * R, `the page says the stars are ${(found.gap / R).toFixed(4)}R apart`);
      } else {
        assert.ok(!j.overlap, "the samples of the two stars overlap");
        assert.ok(found.gap >= 0.05 * R, `the page says the stars are ${(found.gap / R).toFixed(4)}R apart`);
        assert.ok(Math.abs(found.gap - j.gap) <= 0.03 * R, `page ${found.gap}, samples ${j.gap}`);
      }

      // The view holds that frame while frames keep arriving.
      const s0 = await page.evaluate(() => ({ ...window.foveal.stats }));
      await sleep(1500);
      const s1 = await page.evaluate(() => ({ ...window.foveal.stats }));
      assert.ok(s1.framesReceived > s0.framesReceived, "no frames arrive while paused");
      assert.equal(s1.framesApplied, s0.framesApplied, "the view moved on");
      assert.match(await page.textContent("#pause"), /resume/);

      if (process.env.FOVEAL_SCREENSHOT) {
        // Drawn at full resolution: give software WebGL a few draws at its pace.
        await sleep(Math.min(8000, 500 + 4 * (await page.evaluate(() => window.foveal.stats.drawMs))));
        mkdirSync(join(repo, "docs", "figures"), { recursive: true });
        await page.locator("#stack").screenshot({ path: join(repo, "docs", "figures", `contact-${truth}.png`) });
      }

      // R goes back to the server's camera.
      await page.locator("#scene").focus();
      await page.keyboard.press("r");
      assert.equal(await page.evaluate(() => window.foveal.view.focused), false);
    });
  });
}
