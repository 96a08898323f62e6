// The side by side in a real browser against a real foveal-server, read from the page's data
// (window.foveal.split), not its pixels: the control turns it on through Configure, the right view
// appears with its caption, and once the mouse has rested on one spot for 2 s the gaze-steered
// side's true P is lower than the gaze-blind side's on the same frames. The P plot then has a line
// for each side's true P.
//
// Under a sphere-test budget both sides do the same work on every frame whatever the machine's
// load (a browser drawing with software WebGL shares the two cores of a test machine); under the
// default wall-clock budget how much each side gets done depends on that load.
import assert from "node:assert/strict";
import { mkdirSync } from "node:fs";
import { join } from "node:path";
import { describe, test } from "node:test";
import { missing, repo, servedPage, sleep, waitFor } from "./harness.mjs";

const skip = missing() ?? false;

describe("side by side (N = 2,000, 3,000 sphere tests)", { skip }, () => {
  const ctx = servedPage(["-n", "2000", "--budget", "3000tests"]);

  test("turned on from the page, the gaze side's true P is lower after the mouse rests 2 s", async () => {
    assert.ok(await waitFor(() => ctx.page.evaluate(() => window.foveal.stats.framesApplied > 5), 20_000), "no frames");
    await ctx.page.selectOption("#compare", "round-robin");
    const on = await waitFor(() => ctx.page.evaluate(() => window.foveal.split.on && window.foveal.split.frames.length > 5), 30_000, 100);
    assert.ok(on, `the side by side did not start: ${await ctx.page.textContent("#config-error")}`);
    assert.equal(await ctx.page.isVisible("#scene-blind"), true);
    assert.match(await ctx.page.textContent("#caption-blind"), /round-robin, gaze-blind/);

    // Rest the mouse on the left view, away from the centre, and let 2 s of frames pass.
    const box = await ctx.page.locator("#scene").boundingBox();
    const [x, y] = [0.3, 0.4];
    await ctx.page.mouse.move(box.x + x * box.width, box.y + y * box.height);
    const settled = await waitFor(
      () =>
        ctx.page.evaluate(
          ([x, y]) => {
            const f = window.foveal.split.frames;
            const last = f[f.length - 1];
            return last && Math.abs(last.x - x) < 0.01 && Math.abs(last.y - y) < 0.01 && last.index;
          },
          [x, y],
        ),
      5_000,
      50,
    );
    assert.ok(settled, "the fixation did not reach the mouse");
    await sleep(2_000);
    const rested = await ctx.page.evaluate(
      ([x, y, from]) => window.foveal.split.frames.filter((f) => f.index > from && Math.abs(f.x - x) < 0.01 && Math.abs(f.y - y) < 0.01),
      [x, y, settled],
    );
    assert.ok(rested.length >= 10, `only ${rested.length} frames at the resting mouse in 2 s`);
    const mean = (k) => rested.reduce((a, f) => a + f[k], 0) / rested.length;
    const gaze = mean("gaze"), blind = mean("blind");
    console.log(`# ${rested.length} frames at rest: true P gaze-steered ${gaze.toFixed(3)}, gaze-blind ${blind.toFixed(3)}`);
    assert.ok(gaze < blind, `true P gaze-steered ${gaze} is not below gaze-blind ${blind}`);
    // The caption under each view says its true P.
    assert.match(await ctx.page.textContent("#caption-gaze"), /true P \d/);
    assert.match(await ctx.page.textContent("#caption-blind"), /true P \d/);
    // The P plot draws both true P.
    const p = (await ctx.page.evaluate(() => window.foveal.plots.summary())).find((c) => c.title.startsWith("P,"));
    for (const label of ["P true (audit)", "P true, gaze-blind"]) {
      assert.ok(p.series.find((s) => s.label === label).values >= 2, `${label} has no line`);
    }
    assert.deepEqual(ctx.errors, []);
  });
});

// With FOVEAL_SCREENSHOT set: the README's pictures of the side by side, at the server's default
// scene and budget started with `--compare round-robin`, and with `--demo`, the mouse resting off
// centre and every body drawn (no thinning).
for (const [name, args] of [
  ["side-by-side.png", ["--compare", "round-robin"]],
  ["demo.png", ["--demo"]],
]) {
  describe(`side by side for the README's picture (${args.join(" ")})`, { skip: skip || !process.env.FOVEAL_SCREENSHOT }, () => {
    const ctx = servedPage(args);

    test(`docs/figures/${name}`, async () => {
      assert.ok(await waitFor(() => ctx.page.evaluate(() => window.foveal.split.frames.length > 5), 20_000, 100), "no compared frames");
      await ctx.page.uncheck("#draw-thin");
      const box = await ctx.page.locator("#scene").boundingBox();
      await ctx.page.mouse.move(box.x + 0.3 * box.width, box.y + 0.4 * box.height);
      await sleep(4_000);
      const f = await ctx.page.evaluate(() => window.foveal.split.frames.slice(-60));
      const mean = (k) => f.reduce((a, x) => a + x[k], 0) / f.length;
      console.log(`# picture: last ${f.length} frames, true P gaze-steered ${mean("gaze").toFixed(1)}, gaze-blind ${mean("blind").toFixed(1)}`);
      const dir = join(repo, "docs", "figures");
      mkdirSync(dir, { recursive: true });
      await ctx.page.screenshot({ path: join(dir, name) });
    });
  });
}
