// Wrong guesses told from right ones, in a real browser against a real foveal-server, read from
// the page's data (window.foveal), not its pixels. With an audit every deemed pair comes with
// what it truly is, and the page draws the wrong guesses (deemed, truly apart: a bounce across a
// visible gap) in the deemed colour and the right ones (deemed, truly touching) in their own; the
// legend names both and the readout says how many wrong guesses lie within 5 degrees of the
// fixation and beyond. Without an audit every deemed pair is drawn as deemed.
//
// A sphere-test budget makes the frames the same whatever the machine's load.
import assert from "node:assert/strict";
import { describe, test } from "node:test";
import { missing, servedPage, waitFor } from "./harness.mjs";

const skip = missing() ?? false;

/** In the page: the last frame's deemed pairs with their truths and their bodies' colours. */
function inspect() {
  const f = window.foveal.lastFrame();
  const c = f?.collisions;
  if (!c) return null;
  const v = new DataView(c.deemed.buffer, c.deemed.byteOffset, c.deemed.byteLength);
  const deemed = [];
  for (let o = 0, k = 0; o + 8 <= c.deemed.length; o += 8, k++) {
    deemed.push({ a: v.getUint32(o, true), b: v.getUint32(o + 4, true), truth: c.deemedTruth[k] ?? -1 });
  }
  const view = window.foveal.view;
  const same = (body, colour) => {
    const [r, g, b] = view.colourOf(body);
    return Math.abs(r - colour.r) < 1e-6 && Math.abs(g - colour.g) < 1e-6 && Math.abs(b - colour.b) < 1e-6;
  };
  const K = window.foveal.colours;
  const counted = new Map();
  for (const p of deemed) for (const x of [p.a, p.b]) counted.set(x, (counted.get(x) ?? 0) + 1);
  const rv = new DataView(c.real.buffer, c.real.byteOffset, c.real.byteLength);
  for (let o = 0; o + 8 <= c.real.length; o += 8) for (const x of [rv.getUint32(o, true), rv.getUint32(o + 4, true)]) counted.set(x, (counted.get(x) ?? 0) + 1);
  return {
    truths: c.deemedTruth.length,
    deemed: deemed.length,
    falsePositives: Number(f.metrics.audit?.trueFalsePositives ?? -1),
    apart: deemed.filter((p) => p.truth === 2).length,
    touching: deemed.filter((p) => p.truth === 1).length,
    // Every body of a wrong guess is drawn in the deemed colour (wrong guesses are drawn last).
    apartDrawn: deemed.filter((p) => p.truth === 2).every((p) => same(p.a, K.deemed) && same(p.b, K.deemed)),
    // A body whose only pair is a right guess is drawn in the right guesses' colour.
    touchingAlone: deemed.filter((p) => p.truth === 1).flatMap((p) => [p.a, p.b]).filter((x) => counted.get(x) === 1),
    touchingDrawn: deemed
      .filter((p) => p.truth === 1)
      .flatMap((p) => [p.a, p.b])
      .filter((x) => counted.get(x) === 1)
      .every((x) => same(x, K.touching)),
    deemedDrawn: deemed.every((p) => same(p.a, K.deemed) && same(p.b, K.deemed)),
    notDeemed: deemed.filter((p) => !(same(p.a, K.deemed) && same(p.b, K.deemed))).slice(0, 3).map((p) => [p, view.colourOf(p.a), view.colourOf(p.b)]),
    deemedColour: [K.deemed.r, K.deemed.g, K.deemed.b],
    legendTouching: getComputedStyle(document.querySelector("#legend .sw.touching").parentElement).display !== "none",
    readout: document.getElementById("readout").textContent,
  };
}

describe("deemed pairs coloured by their truth (N = 5,000, 3,000 sphere tests)", { skip }, () => {
  const ctx = servedPage(["-n", "5000", "--budget", "3000tests", "--audit"]);

  test("with an audit, wrong guesses are drawn as deemed and right ones apart from them", async () => {
    const seen = await waitFor(async () => {
      const s = await ctx.page.evaluate(inspect);
      return s && s.deemed > 0 && s.touchingAlone.length > 0 && s.apart > 0 && s;
    }, 20_000, 100);
    assert.ok(seen, `no frame with both kinds of deemed pair: ${JSON.stringify(await ctx.page.evaluate(inspect))?.slice(0, 400)}`);
    console.log(`# ${seen.deemed} deemed: ${seen.apart} truly apart, ${seen.touching} truly touching`);
    assert.equal(seen.truths, seen.deemed, "one truth per deemed pair");
    assert.equal(seen.apart + seen.touching, seen.deemed, "a whole audit leaves no pair unaudited");
    assert.equal(seen.apart, seen.falsePositives, "the wrong guesses are the audit's false positives");
    assert.ok(seen.apartDrawn, "a wrong guess's body is not drawn in the deemed colour");
    assert.ok(seen.touchingDrawn, "a right guess's body is not drawn in its own colour");
    assert.ok(seen.legendTouching, "the legend does not name the right guesses");
    const readout = await waitFor(() => ctx.page.evaluate(() => /wrong guesses/.test(document.getElementById("readout").textContent) && document.getElementById("readout").textContent), 5_000, 100);
    assert.match(readout || seen.readout, /wrong guesses \(deemed, truly apart\): [\d.]+% of \d+ pairs within 5°, [\d.]+% of \d+ beyond/);
  });

  test("without an audit every deemed pair is drawn as deemed", async () => {
    await ctx.page.uncheck("#audit");
    const plain = await waitFor(async () => {
      const s = await ctx.page.evaluate(inspect);
      // A frame drawn on the scene the change reloaded (a reload clears the colours).
      return s && s.deemed > 0 && s.truths === 0 && s.deemedDrawn && s;
    }, 20_000, 100);
    const last = await ctx.page.evaluate(inspect);
    assert.ok(plain, `frames still carry truths, or deemed bodies are not drawn as deemed, with the audit off: ${JSON.stringify([last?.truths, last?.notDeemed])}`);
    assert.equal(plain.legendTouching, false, "the legend names right guesses the frame cannot tell");
    const readout = await waitFor(() => ctx.page.evaluate(() => {
      const t = document.getElementById("readout").textContent;
      return /frame \d+/.test(t) && !/wrong guesses/.test(t) && t;
    }), 5_000, 100);
    assert.ok(readout, "the readout still counts wrong guesses without an audit");
    assert.deepEqual(ctx.errors, []);
  });
});

describe("thinning the far bodies (N = 5,000)", { skip }, () => {
  const ctx = servedPage(["-n", "5000", "--budget", "3000tests"]);

  /** In the page: what the last split drew, and what it should have. */
  function drawn() {
    const v = window.foveal.view;
    return {
      stride: v.farStride,
      far: v.farCounts.far,
      farDrawn: v.farCounts.drawn,
      meshes: (v.mesh?.count ?? 0) + (v.peripheral?.count ?? 0),
      bodies: window.foveal.stats.bodies,
      drawMs: window.foveal.stats.drawMs,
      readout: document.getElementById("readout").textContent,
    };
  }

  test("one far body in k is drawn, every near one, and the readout says so", async () => {
    assert.ok(await waitFor(() => ctx.page.evaluate(() => window.foveal.stats.framesApplied > 3), 20_000), "no frames");
    const adaptive = await ctx.page.evaluate(drawn);
    console.log(`# drawing every body cost ${adaptive.drawMs.toFixed(0)} ms here; the page chose 1 in ${adaptive.stride}`);
    await ctx.page.evaluate(() => {
      window.foveal.draw.thin = false;
      window.foveal.view.setFarStride(4);
    });
    // The readout can say "1 in 4" before the next draw has thinned to it: wait for a draw
    // that has, by body index (of the far bodies, those whose index is a multiple of 4).
    const quarter = (d) => Math.abs(d.farDrawn - d.far / 4) <= d.far / 8 + 2;
    const thin = await waitFor(async () => {
      const d = await ctx.page.evaluate(drawn);
      return d.far > 0 && /drawn: every body within the foveal region, \d+ of the \d+ beyond \(1 in 4/.test(d.readout) && quarter(d) && d;
    }, 5_000, 100);
    assert.ok(thin, `no draw of one far body in 4 said so: ${JSON.stringify(await ctx.page.evaluate(drawn))}`);
    // Every body near the fixation is drawn: the meshes hold them and the far ones kept.
    assert.equal(thin.meshes, thin.bodies - thin.far + thin.farDrawn);

    // Unticked, every body is drawn again.
    await ctx.page.uncheck("#draw-thin");
    const all = await waitFor(async () => {
      const d = await ctx.page.evaluate(drawn);
      return d.stride === 1 && d.meshes === d.bodies && !/drawn: every body within/.test(d.readout) && d;
    }, 5_000, 100);
    assert.ok(all, `still thinned: ${JSON.stringify(await ctx.page.evaluate(drawn))}`);
  });
});
