// The /psych page end to end in a real browser against the release server, without people: a
// simulated observer with a known F2 psychometric function (C = 4 degrees) goes through the
// setup, the calibration, the instructions, the practice and the blocks as a participant would,
// reads each trial's conditions from the page's test hook (window.foveal_psych) and answers by
// chance drawn from the function, by key and now and then by mouse button. One stimulus is made
// to stall the browser for 120 ms: its trial must be stored invalid and repeated at the end of its
// block. The stored CSV is then checked row by row against the observer's answers, and a design
// out of range must stop the page with the field named.
import assert from "node:assert/strict";
import { mkdtempSync, readFileSync, rmSync, writeFileSync, mkdirSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { after, before, describe, test } from "node:test";
import { freePort, launch, missing, startServer, waitFor, sleep } from "./harness.mjs";

const skip = missing() ?? false;

// A short design: 3 eccentricities x 2 directions x 3 gap levels, once each (18 trials), in two
// blocks, after 2 practice trials, 50 ms between stimuli.
const SHORT = {
  name: "short",
  title: "A short run of experiment 1",
  stimulus: { disc_diameter_deg: 1.0, duration_ms: 150, pair_axis: "horizontal" },
  fixation_cross_deg: 0.5,
  inter_stimulus_ms: 50,
  eccentricities_deg: [1, 4, 8],
  directions_deg: [0, 180],
  gaps: [
    { label: "touching", gap_deg: 0, weight: 1 },
    { label: "small", gap_deg: 0.1, weight: 1 },
    { label: "large", gap_deg: 0.4, weight: 1 },
  ],
  repetitions: 1,
  blocks: 2,
  practice_trials: 2,
  responses: { touching: { keys: ["f"], mouse_button: 0 }, apart: { keys: ["j"], mouse_button: 2 } },
  timing: { late_frame_factor: 1.5, max_repeats_per_block: 20 },
};

// The paper's experiment 4, short: a pair meeting in motion at 8 degrees a second along an axis
// drawn per trial, among 0 or 3 identical distractors, the cross hidden during the stimulus; at
// 0 and 4 degrees, touching or apart (8 trials, one block, no practice).
const MOVING = {
  ...SHORT,
  name: "moving",
  title: "A short run of experiment 4",
  stimulus: { disc_diameter_deg: 1.0, duration_ms: 250, pair_axis: "random", motion_speed_deg_s: 8 },
  eccentricities_deg: [0, 4],
  directions_deg: [0],
  gaps: [
    { label: "touching", gap_deg: 0, weight: 1 },
    { label: "large", gap_deg: 0.4, weight: 1 },
  ],
  blocks: 1,
  practice_trials: 0,
  distractors: { counts: [0, 3], colour: "white", speed_deg_s: 8, field_deg: 6 },
  hide_cross_during_stimulus: true,
};

// The simulated observer: F2 with C = 4 degrees, a Weibull of threshold 0.1 degrees and slope 2,
// 5% guesses and 2% lapses (foveal-psych's model).
const OBSERVER = { c: 4, alpha: 0.1, beta: 2, guess: 0.05, lapse: 0.02 };
function pApart(gap, ecc) {
  if (gap <= 0) return OBSERVER.guess;
  const x = (gap * Math.exp(-ecc / OBSERVER.c)) / OBSERVER.alpha;
  return OBSERVER.guess + (1 - OBSERVER.guess - OBSERVER.lapse) * (1 - Math.exp(-(x ** OBSERVER.beta)));
}

/** mulberry32: the observer's chance, seeded. */
function rng(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

const hook = (page) => page.evaluate(() => window.foveal_psych && JSON.parse(JSON.stringify(window.foveal_psych)));

/** Open `design`, enter `participant`, pass the calibration (`adjust`: press the arrows first)
 * and the instructions (`expect`, if given, must match them), and start the blocks. */
async function begin(page, url, design, participant, { adjust = false, expect = null } = {}) {
  await page.goto(`${url}psych?design=${design}`);
  assert.ok(await waitFor(async () => (await hook(page))?.state === "setup", 10_000), "the setup screen");
  await page.fill("#participant", participant);
  await page.click("#next");
  assert.ok(await waitFor(async () => (await hook(page)).state === "calibration", 5_000), "the calibration screen");
  if (adjust) {
    await page.keyboard.press("ArrowRight");
    await page.keyboard.press("ArrowLeft");
  }
  await page.keyboard.press("Enter");
  assert.ok(await waitFor(async () => (await hook(page)).state === "instructions", 5_000), "the instructions");
  if (expect) assert.match(await page.textContent("#screen"), expect);
  await page.keyboard.press(" ");
}

/** Until the page is done: past every break, `onTrial` with each trial waiting for an answer
 * (it answers); fails when the page stops or `seconds` pass. */
async function answerAll(page, seconds, onTrial) {
  let last = 0;
  const until = Date.now() + seconds * 1000;
  for (;;) {
    assert.ok(Date.now() < until, `the run did not finish within ${seconds} s`);
    const h = await hook(page);
    if (h.state === "error") assert.fail(`the page stopped: ${h.error}`);
    if (h.state === "done") return;
    if (h.state === "break") {
      await page.keyboard.press(" ");
      await waitFor(async () => (await hook(page)).state !== "break", 5_000, 10);
      continue;
    }
    if (h.state === "response" && h.trial && h.trial.id > last) {
      last = h.trial.id;
      await onTrial(h.trial);
      continue;
    }
    await sleep(10);
  }
}

/** A results CSV: its columns and its rows as objects by column. */
function readRows(path) {
  const text = readFileSync(path, "utf8");
  const [head, ...lines] = text.trimEnd().split("\n");
  const columns = head.split(",");
  return { text, head, lines, columns, rows: lines.map((l) => Object.fromEntries(l.split(",").map((v, i) => [columns[i], v]))) };
}

describe("/psych runs an experiment end to end", { skip }, () => {
  let server, browser, page, results, designs;
  const pageErrors = [];

  before(async () => {
    results = mkdtempSync(join(tmpdir(), "foveal-psych-results-"));
    designs = mkdtempSync(join(tmpdir(), "foveal-psych-designs-"));
    mkdirSync(designs, { recursive: true });
    writeFileSync(join(designs, "short.json"), JSON.stringify(SHORT, null, 2));
    writeFileSync(join(designs, "moving.json"), JSON.stringify(MOVING, null, 2));
    writeFileSync(join(designs, "broken.json"), JSON.stringify({ ...SHORT, name: "broken", gaps: [{ label: "touching", gap_deg: 0, weight: 99 }] }));
    server = await startServer(await freePort(), ["-n", "50", "--psych-results", results, "--psych-designs", designs]);
    browser = await launch();
    page = await browser.browser.newPage();
    page.on("pageerror", (e) => pageErrors.push(e.message));
  });

  after(async () => {
    await browser?.close();
    await server?.stop();
    for (const d of [results, designs]) if (d) rmSync(d, { recursive: true, force: true });
  });

  test("a simulated observer runs the short design; every trial is stored as it answered", { timeout: 180_000 }, async () => {
    // The card is matched: a few steps of the arrow keys, then Enter.
    await begin(page, server.url, "short", "sim01", { adjust: true });
    const chance = rng(7);
    const answers = [];
    let practiceSeen = 0;
    let stalled = false;
    await answerAll(page, 150, async (t) => {
      const apart = chance() < pApart(t.gap_deg, t.eccentricity_deg);
      if (t.practice) practiceSeen++;
      else answers.push({ ecc: t.eccentricity_deg, gap: t.gap_deg, label: t.gap_label, response: apart ? "apart" : "touching" });
      // Every fifth answer by mouse button (right: apart, left: touching), the others by key.
      if (answers.length % 5 === 4) await page.mouse.click(700, 700, { button: apart ? "right" : "left" });
      else await page.keyboard.press(apart ? "j" : "f");
      // Stall the third main trial's stimulus: its frames come late.
      if (!stalled && answers.length === 2) {
        await page.evaluate(() => window.foveal_psych.stallNextStimulus(120));
        stalled = true;
      }
    });
    assert.equal(practiceSeen, SHORT.practice_trials);
    assert.deepEqual(pageErrors, []);

    const final = await hook(page);
    assert.equal(final.results, "sim01_1.csv");
    const { text, head, lines, columns, rows } = readRows(join(results, "sim01_1.csv"));
    for (const c of ["participant", "eccentricity_deg", "gap_deg", "response", "valid", "invalid_reason", "repeat_of", "duration_ms", "frames", "frame_ms"]) {
      assert.ok(columns.includes(c), `column ${c} in ${head}`);
    }
    // One row per answer, in order, as answered.
    assert.equal(rows.length, answers.length, text);
    assert.equal(final.stored, rows.length);
    rows.forEach((r, i) => {
      assert.deepEqual(
        [Number(r.eccentricity_deg), Number(r.gap_deg), r.gap_label, r.response, r.participant, r.design],
        [answers[i].ecc, answers[i].gap, answers[i].label, answers[i].response, "sim01", "short"],
        `row ${i + 1}`,
      );
      assert.equal(Number(r.trial), i + 1);
      assert.ok(r.valid === "1" || r.valid === "0", `row ${i + 1} valid = ${r.valid}`);
      assert.equal(r.valid === "0", r.invalid_reason !== "", `row ${i + 1}: invalid exactly when a reason is given`);
      const frames = r.frame_ms.split(";").map(Number);
      assert.equal(frames.length, Number(r.frames) + 1, `row ${i + 1}: a timestamp per frame`);
      assert.equal(frames[frames.length - 1].toFixed(3), Number(r.duration_ms).toFixed(3), `row ${i + 1}: the duration is the frames'`);
      if (r.valid === "1") {
        assert.ok(Math.abs(Number(r.duration_ms) - 150) < Number(r.refresh_ms) / 2, `row ${i + 1}: a valid trial lasted ${r.duration_ms} ms`);
      }
    });
    // The stalled stimulus: stored invalid (a late frame), then repeated in its block.
    assert.equal(rows[2].valid, "0", `the stalled trial: ${lines[2]}`);
    assert.equal(rows[2].invalid_reason, "late_frame");
    const repeat = rows.find((r) => r.repeat_of === "3");
    assert.ok(repeat, "the stalled trial is repeated");
    assert.equal(repeat.block, rows[2].block);
    assert.deepEqual([repeat.eccentricity_deg, repeat.direction_deg, repeat.gap_label], [rows[2].eccentricity_deg, rows[2].direction_deg, rows[2].gap_label]);
    // Every invalid trial is repeated (the design allows 20 repeats a block), so the valid
    // trials are the design's 18, each cell once.
    const valid = rows.filter((r) => r.valid === "1");
    assert.equal(valid.length, 18, `valid trials (invalid: ${rows.filter((r) => r.valid === "0").map((r) => r.invalid_reason)})`);
    assert.equal(new Set(valid.map((r) => r.cell)).size, 18);
    console.log(`# ${rows.length} trials stored, ${rows.length - valid.length} invalid and repeated; refresh ${Number(rows[0].refresh_ms).toFixed(2)} ms`);

    const header = JSON.parse(readFileSync(join(results, "sim01_1.json"), "utf8"));
    assert.equal(header.design.name, "short");
    assert.equal(header.completed, true);
    assert.equal(header.trials_stored, rows.length);
    assert.equal(header.display.browser.px_per_cm_source, "calibration");
    assert.deepEqual(header.columns, columns);
  });

  test("a pair meeting in motion among distractors is stored with its level and its drawn axis", { timeout: 120_000 }, async () => {
    await begin(page, server.url, "moving", "sim02", { expect: /move towards each other/ });
    const seen = [];
    await answerAll(page, 100, async (t) => {
      seen.push(t);
      await page.keyboard.press(t.gap_deg > 0 ? "j" : "f");
    });
    assert.deepEqual(pageErrors, []);
    const { text, rows } = readRows(join(results, "sim02_1.csv"));
    assert.equal(rows.length, seen.length, text);
    rows.forEach((r, i) => {
      const t = seen[i];
      assert.equal(t.speed_deg_s, 8);
      assert.equal(t.cross_hidden, true);
      assert.equal(t.distractor_starts.length, t.distractors, `row ${i + 1}: one start per distractor`);
      assert.equal(Number(r.distractors), t.distractors, `row ${i + 1}`);
      assert.ok(t.axis_deg >= 0 && t.axis_deg < 360, `row ${i + 1}: axis ${t.axis_deg}`);
      assert.equal(r.axis_deg, t.axis_deg.toFixed(3), `row ${i + 1}: the axis drawn is stored`);
      if (r.valid === "1") assert.ok(Math.abs(Number(r.duration_ms) - 250) < Number(r.refresh_ms) / 2, `row ${i + 1}: ${r.duration_ms} ms`);
    });
    // Every cell (2 eccentricities x 2 gaps x 2 distractor levels) among the valid trials.
    const valid = rows.filter((r) => r.valid === "1");
    assert.equal(new Set(valid.map((r) => r.cell)).size, 8);
    assert.deepEqual(new Set(valid.map((r) => r.distractors)), new Set(["0", "3"]));
  });

  test("a design out of range stops the page with the field and its limit", async () => {
    await page.goto(`${server.url}psych?design=broken`);
    const h = await waitFor(async () => {
      const s = await hook(page);
      return s?.state === "error" && s;
    }, 10_000);
    assert.ok(h, "the page stopped");
    assert.match(h.error, /gaps\[0\]\.weight/);
    assert.match(h.error, /1\.\.=16/);
    assert.match(await page.textContent("#screen"), /gaps\[0\]\.weight/);
  });
});
