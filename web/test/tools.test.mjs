// The viewer's research tools and fixes in a real browser against a real foveal-server, read from
// the page's data (window.foveal), not its pixels: every plot has a line within 3 s of load at the
// server's defaults and says what it cannot show; pausing stops the server's frame counter and a
// step advances it by exactly one; picking a body shows its pairs; a refused value goes back to
// the one in force; the fixation holds while the pointer is over the controls; a token leaves the
// address bar and a gaze token alone is told it needs a viewer token; with the server gone the
// page backs off (its calls are counted) and comes back when the server does.
import assert from "node:assert/strict";
import { after, before, describe, test } from "node:test";
import { clientModule, freePort, launch, missing, recordErrors, sleep, startServer, waitFor } from "./harness.mjs";

const skip = missing() ?? false;

const foveal = (page, f, arg) => page.evaluate(f, arg);

describe("viewer at the server's default settings", { skip }, () => {
  let server, browser, page;

  before(async () => {
    server = await startServer(await freePort(), []);
    browser = await launch();
    page = await browser.browser.newPage();
  });

  after(async () => {
    await browser?.close();
    await server?.stop();
  });

  test("every plot has a line within 3 s of load, and says what it cannot show", async () => {
    const t0 = Date.now();
    await page.goto(server.url);
    const lines = (s) => s.every((c) => c.series.some((x) => x.values >= 2));
    const all = await waitFor(async () => {
      const s = await foveal(page, () => window.foveal?.plots.summary());
      return s && lines(s) && s;
    }, 3_000 - (Date.now() - t0), 50);
    const last = await foveal(page, () => window.foveal.plots.summary());
    assert.ok(all, `plots without a line 3 s after load: ${JSON.stringify(last.filter((c) => !c.series.some((x) => x.values >= 2)))}`);
    console.log(`# every plot had a line ${Date.now() - t0} ms after load`);
    // Without audit the true P has no values, and the P plot says why.
    const p = all.find((c) => c.title.startsWith("P,"));
    assert.equal(p.series.find((x) => x.label.startsWith("P true")).values, 0);
    assert.match(p.note, /tick "audit"/);
    // The plots hold gaps as null, never NaN.
    const nan = await foveal(page, () => JSON.stringify(window.foveal.plots.summary()).includes("NaN"));
    assert.equal(nan, false);
  });
});

describe("viewer's loop controls and picking (N = 400, 300 sphere tests)", { skip }, () => {
  let server, browser, page, rpc, pb;
  const consoleErrors = [];

  before(async () => {
    ({ nodeClient: rpc, ...pb } = await clientModule());
    server = await startServer(await freePort(), ["-n", "400", "--budget", "300tests"]);
    rpc = rpc(server.url);
    browser = await launch();
    page = await browser.browser.newPage();
    recordErrors(page, consoleErrors);
    await page.goto(server.url);
    const up = await waitFor(async () => (await foveal(page, () => window.foveal.stats.framesApplied)) > 5, 20_000);
    assert.ok(up, "no frames");
  });

  after(async () => {
    await browser?.close();
    await server?.stop();
  });

  test("pause stops the server's frame counter and step advances it by exactly one", async () => {
    await page.press("#scene", "p");
    const paused = await waitFor(async () => (await rpc.getStatus({})).paused, 5_000);
    assert.ok(paused, "the server did not pause");
    const a = (await rpc.getStatus({})).frames;
    await sleep(500);
    const b = (await rpc.getStatus({})).frames;
    assert.equal(b, a, "frames were simulated while paused");
    assert.equal(await page.textContent("#pause"), "resume");
    await page.click("#step");
    const stepped = await waitFor(async () => (await rpc.getStatus({})).frames !== a, 5_000);
    assert.ok(stepped, "the step did not advance the counter");
    await sleep(300);
    assert.equal((await rpc.getStatus({})).frames, a + 1n, "one step, one frame");
    // The page drew the stepped frame (it watches every 6th frame on software WebGL).
    const drawn = await waitFor(async () => (await foveal(page, () => window.foveal.stats.lastIndex)) === Number(a), 5_000);
    assert.ok(drawn, `the page shows frame ${await foveal(page, () => window.foveal.stats.lastIndex)}, not ${a}`);
    await page.press("#scene", "n");
    const again = await waitFor(async () => (await rpc.getStatus({})).frames === a + 2n, 5_000);
    assert.ok(again, "the key N did not step");
  });

  test("picking a body shows its pairs and their state", async () => {
    // A body of a deemed pair in the frame in view (the server is paused on it).
    const pair = await foveal(page, () => {
      const c = window.foveal.lastFrame()?.collisions;
      if (!c || c.deemed.length < 8) return null;
      const v = new DataView(c.deemed.buffer, c.deemed.byteOffset, c.deemed.byteLength);
      return [v.getUint32(0, true), v.getUint32(4, true)];
    });
    assert.ok(pair, "no deemed pair in the frame in view");
    const [a, b] = pair;
    await foveal(page, (a) => window.foveal.pick(a), a);
    const ins = await waitFor(() => foveal(page, () => window.foveal.picked.inspection && JSON.parse(JSON.stringify(window.foveal.picked.inspection, (k, v) => (typeof v === "bigint" ? Number(v) : v)))), 5_000);
    assert.ok(ins, `no inspection: ${await foveal(page, () => window.foveal.picked.error)}`);
    assert.equal(ins.body, a);
    const withB = ins.pairs.find((p) => p.other === b);
    assert.ok(withB, `pair (${a}, ${b}) not listed: ${JSON.stringify(ins.pairs)}`);
    assert.equal(withB.status, pb.PairStatus.DEEMED);
    const shown = await page.textContent("#pick-text");
    assert.match(shown, new RegExp(`body ${a} at frame \\d+: ${ins.pairsTotal} candidate pair`));
    for (const p of ins.pairs) assert.match(shown, new RegExp(`with ${p.other}\\s`));
    assert.match(shown, /deemed \(budget ran out\)/);
    assert.equal(await page.isVisible("#pick"), true);

    // A click on a body's centre picks a body (the nearest under the pointer).
    const box = await page.locator("#scene").boundingBox();
    const at = await foveal(page, (a) => window.foveal.view.bodyOnScreen(a), a);
    await page.mouse.click(box.x + at.x * box.width, box.y + at.y * box.height);
    const clicked = await waitFor(() => foveal(page, () => window.foveal.picked.inspection && Number(window.foveal.picked.inspection.body)), 5_000);
    assert.ok(clicked !== null && clicked >= 0, "the click picked nothing");
    await page.press("#scene", "Escape");
    assert.equal(await page.isVisible("#pick"), false);
  });

  test("resume runs the server again", async () => {
    await page.press("#scene", "p");
    const a = (await rpc.getStatus({})).frames;
    const running = await waitFor(async () => {
      const s = await rpc.getStatus({});
      return !s.paused && s.frames > a + 10n;
    }, 5_000);
    assert.ok(running, "the server did not resume");
    assert.equal(await page.textContent("#pause"), "pause");
  });

  test("a refused N goes back to the value in force and says why", async () => {
    await page.fill("#bodies", "0");
    await page.press("#bodies", "Enter");
    const shown = await waitFor(async () => {
      const t = await page.textContent("#config-error");
      return t.includes("must be") && t;
    }, 10_000);
    assert.ok(shown, `no refusal shown: "${await page.textContent("#config-error")}"`);
    assert.match(shown, /`scene\.bodies` = 0/);
    assert.equal(await page.inputValue("#bodies"), "400");
    assert.equal((await rpc.getStatus({})).config.bodies, 400);
  });

  test("the fixation holds while the pointer is over the controls", async () => {
    const box = await page.locator("#scene").boundingBox();
    await page.mouse.move(box.x + 0.3 * box.width, box.y + 0.4 * box.height);
    const there = (f) => f && f.source === pb.FixationSource.GAZE && Math.abs(f.x - 0.3) < 0.01 && Math.abs(f.y - 0.4) < 0.01;
    assert.ok(await waitFor(async () => there((await rpc.getStatus({})).lastFixation), 5_000), "the mouse never steered");
    await page.hover("#bodies");
    await sleep(1500); // three times the server's gaze age limit
    const f = (await rpc.getStatus({})).lastFixation;
    assert.ok(there(f), `the fixation moved to (${f.x}, ${f.y}), source ${f.source}`);
    assert.deepEqual(consoleErrors, []);
  });

  test("the colour-blind palette and the debug drawing switch from the keyboard", async () => {
    await page.press("#scene", "c");
    assert.equal(await foveal(page, () => window.foveal.draw.palette), "colour-blind");
    assert.equal(await page.inputValue("#palette"), "colour-blind");
    await page.press("#scene", "l");
    await page.press("#scene", "e");
    assert.deepEqual(await foveal(page, () => [window.foveal.draw.links, window.foveal.draw.priority]), [true, true]);
    await page.press("#scene", "?");
    assert.equal(await page.isVisible("#help"), true);
    assert.match(await page.textContent("#help"), /The mouse steers/);
    await page.press("#scene", "Escape");
    assert.equal(await page.isVisible("#help"), false);
    const csv = await foveal(page, () => window.foveal.csv(10));
    const rows = csv.trim().split("\n");
    assert.equal(rows.length, 11);
    assert.match(rows[0], /^frame,sim_time_s,collision_time_ms,/);
  });

  test("survives a server restart with back-off: its calls while the server is down are bounded", async () => {
    const port = Number(new URL(server.url).port);
    await server.stop();
    const down = await waitFor(async () => (await page.textContent("#status")).includes("cannot reach"), 10_000);
    assert.ok(down, `status says "${await page.textContent("#status")}"`);
    // The mouse rests on the scene: its gaze would be re-sent every 100 ms without back-off.
    const box = await page.locator("#scene").boundingBox();
    await page.mouse.move(box.x + 0.5 * box.width, box.y + 0.5 * box.height);
    const c0 = await foveal(page, () => window.foveal.calls.started);
    await sleep(10_000);
    const calls = (await foveal(page, () => window.foveal.calls.started)) - c0;
    console.log(`# calls in 10 s with the server down: ${calls}`);
    // Session and gaze each back off from 0.5 s doubling to 5 s: about 6 tries each in 10 s.
    assert.ok(calls <= 16, `${calls} calls in 10 s with the server down`);
    server = await startServer(port, ["-n", "300"]);
    const before = await foveal(page, () => window.foveal.stats.framesApplied);
    const up = await waitFor(async () => {
      const s = await foveal(page, () => window.foveal.stats);
      return s.connected && s.framesApplied > before + 5 && s;
    }, 20_000);
    assert.ok(up, "no frames after the server came back");
    assert.equal(up.bodies, 300);
  });
});

describe("viewer tokens in the address", { skip }, () => {
  const viewerToken = "viewer-token-0123456789";
  const gazeToken = "gaze-token-0123456789ab";
  let server, browser;

  before(async () => {
    server = await startServer(await freePort(), ["-n", "200", "--viewer-token", viewerToken, "--gaze-token", gazeToken]);
    browser = await launch();
  });

  after(async () => {
    await browser?.close();
    await server?.stop();
  });

  test("the token leaves the address bar once read; other parameters stay", async () => {
    const page = await browser.browser.newPage();
    await page.goto(`${server.url}#token=${viewerToken}&focus`);
    // Frames received, not applied: with #focus the view may hold the first contact at once.
    const watching = await waitFor(async () => (await foveal(page, () => window.foveal.stats.framesReceived)) > 3, 20_000);
    assert.ok(watching, `no frames with the viewer token: status "${await page.textContent("#status")}", ${JSON.stringify(await foveal(page, () => window.foveal.stats))}`);
    const url = page.url();
    assert.ok(!url.includes(viewerToken), url);
    assert.match(url, /#focus$/);
    assert.equal(await foveal(page, () => window.foveal.focus.armed || window.foveal.focus.found !== null), true, "#focus was read");
    await page.close();
  });

  test("a gaze token alone is told plainly it needs a viewer token too; with both it watches and steers", async () => {
    const page = await browser.browser.newPage();
    await page.goto(`${server.url}#token=${gazeToken}`);
    const told = await waitFor(async () => {
      const t = await page.textContent("#status");
      return t.includes("needs") && t;
    }, 20_000);
    assert.ok(told, `status says "${await page.textContent("#status")}"`);
    assert.match(told, /opened with a gaze token/);
    assert.match(told, /#token=VIEWER_TOKEN&gaze=GAZE_TOKEN/);
    await page.close();

    const both = await browser.browser.newPage();
    // A fresh tab: the remembered token of the other page is per tab.
    await both.goto(`${server.url}#token=${viewerToken}&gaze=${gazeToken}`);
    const watching = await waitFor(async () => (await foveal(both, () => window.foveal.stats.framesApplied)) > 3, 20_000);
    assert.ok(watching, "no frames with both tokens");
    const box = await both.locator("#scene").boundingBox();
    await both.mouse.move(box.x + 0.7 * box.width, box.y + 0.6 * box.height);
    const steered = await waitFor(async () => (await foveal(both, () => window.foveal.gaze.accepted)) > 0, 5_000);
    assert.ok(steered, `no gaze accepted: ${await foveal(both, () => window.foveal.gaze.lastError)}`);
    assert.ok(!both.url().includes(gazeToken));
    await both.close();
  });
});
