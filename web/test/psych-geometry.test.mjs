// The /psych page's visual angles, without a browser: discs placed at an eccentricity and gap in
// degrees subtend exactly those angles from the eye (no small-angle approximation), and the
// display flags give the paper's pixels per centimetre.
import assert from "node:assert/strict";
import { test } from "node:test";
import { bundle } from "./harness.mjs";

const g = await bundle("../src/psych/geometry.ts");

test("the gap, the discs and the eccentricity subtend the angles asked for", () => {
  for (const axis of ["horizontal", "vertical", "radial", "tangential"]) {
    for (const [ecc, dir, gap] of [[0, 0, 0.05], [2, 90, 0.05], [10, 45, 0.15], [30, 200, 1]]) {
      const l = g.layout(ecc, dir, gap, 1.0, axis, 70);
      const centre = g.pointAt(ecc, dir, 70);
      assert.ok(Math.abs(g.angleDeg([0, 0], l.contact, 70) - ecc) < 1e-9, `eccentricity ${ecc} ${axis}`);
      // The facing edges: each disc's centre moved by its radius towards the other.
      const edge = (i) => {
        const [c, o] = [l.centres[i], l.centres[1 - i]];
        const d = Math.hypot(o[0] - c[0], o[1] - c[1]);
        return [c[0] + ((o[0] - c[0]) * l.radii[i]) / d, c[1] + ((o[1] - c[1]) * l.radii[i]) / d];
      };
      assert.ok(Math.abs(g.angleDeg(edge(0), edge(1), 70) - gap) < 1e-7, `gap ${gap} at ${ecc} deg ${axis}: ${g.angleDeg(edge(0), edge(1), 70)}`);
      assert.ok(Math.abs(g.angleDeg(edge(0), centre, 70) - gap / 2) < 1e-7, "the point between the edges is the contact");
      for (const i of [0, 1]) {
        assert.ok(Math.abs(g.angleDeg(l.centres[i], edge(i), 70) - 0.5) < 1e-7, `disc ${i} radius ${axis}`);
      }
    }
  }
  // 10 degrees is 70 tan(10 deg) = 12.34 cm from the fixation, not 70 x 10 x pi / 180 = 12.22.
  assert.ok(Math.abs(Math.hypot(...g.pointAt(10, 0, 70)) - 12.343) < 1e-3);
});

test("the display flags give the paper's display: 22 inches of 1680x1050 at 35.5 px/cm", () => {
  assert.ok(Math.abs(g.pxPerCmOfDisplay(1680, 1050, 22, 1) - 35.45) < 0.01);
  assert.ok(Math.abs(g.pxPerCmOfDisplay(1680, 1050, 22, 2) - 17.73) < 0.01);
});

test("a moving pair approaches, is closest at the middle, and recedes along its drawn axis", () => {
  // 8 degrees a second over 250 ms: 1 degree out at the onset and the offset, 0 at 125 ms.
  assert.equal(g.awayAt(0, 250, 8), 1);
  assert.equal(g.awayAt(125, 250, 8), 0);
  assert.equal(g.awayAt(250, 250, 8), 1);
  assert.ok(Math.abs(g.awayAt(62.5, 250, 8) - 0.5) < 1e-12);
  for (const axisDeg of [0, 37.5, 90, 300]) {
    const near = g.layout(5, 90, 0.1, 1.0, "random", 70, axisDeg, 0);
    const far = g.layout(5, 90, 0.1, 1.0, "random", 70, axisDeg, 0.75);
    // The point between them stays put; the facing edges open by 2 x 0.75 degrees around it.
    assert.deepEqual(far.contact, near.contact);
    const edgeAngle = (l) => {
      const inner = (i) => {
        const [c, o] = [l.centres[i], l.centres[1 - i]];
        const d = Math.hypot(o[0] - c[0], o[1] - c[1]);
        return [c[0] + ((o[0] - c[0]) * l.radii[i]) / d, c[1] + ((o[1] - c[1]) * l.radii[i]) / d];
      };
      return g.angleDeg(inner(0), inner(1), 70);
    };
    assert.ok(Math.abs(edgeAngle(near) - 0.1) < 1e-7, `closest at ${axisDeg}`);
    assert.ok(Math.abs(edgeAngle(far) - 1.6) < 1e-6, `receding at ${axisDeg}: ${edgeAngle(far)}`);
    // Along the drawn axis: the centres' line points at axisDeg (or its opposite).
    const [a, b] = far.centres;
    const dir = (Math.atan2(b[1] - a[1], b[0] - a[0]) * 180) / Math.PI;
    const off = (((dir - axisDeg) % 180) + 180) % 180;
    assert.ok(off < 1e-6 || 180 - off < 1e-6, `axis ${axisDeg}: ${dir}`);
  }
});
