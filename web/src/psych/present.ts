// Presentation on requestAnimationFrame, timed by its frames.
//
// The stimulus is drawn in the callback of one frame and cleared in the callback of the first
// frame at least the intended duration (less half a refresh) after it, so it is on screen for a
// whole number of frames. Every callback's timestamp is kept: the measured duration is the
// clearing frame's timestamp minus the drawing frame's, and a trial is invalid when a frame
// interval during the stimulus exceeds `lateFactor` refresh periods (a dropped or late frame) or
// the measured duration misses the intended one by half a refresh or more. The timestamps are
// the browser's frame times, not the light leaving the screen: a photodiode is the only
// measure of that.

export interface Presentation {
  /** The drawing frame's timestamp (performance.now()'s clock). */
  onset: number;
  /** Every frame's timestamp from the drawing frame's to the clearing frame's, from the onset. */
  frames: number[];
  /** Clearing minus drawing frame. */
  durationMs: number;
  /** Frames the stimulus stayed on screen. */
  frameCount: number;
  /** Empty, `late_frame` or `duration`. */
  invalidReason: string;
}

/** Test hook: block the main thread this long in the stimulus's second frame (0: never). */
export const stall = { nextMs: 0 };

/**
 * Show the stimulus `draw` draws for `durationMs`, then `clear`. `draw` is called on the drawing
 * frame with 0 and on every later frame before the clearing one with its time from the onset
 * (ms), so a moving stimulus is drawn where it is at that frame.
 */
export function present(draw: (tMs: number) => void, clear: () => void, durationMs: number, refreshMs: number, lateFactor: number): Promise<Presentation> {
  return new Promise((resolve) => {
    const frames: number[] = [];
    let onset = -1;
    const stallMs = stall.nextMs;
    stall.nextMs = 0;
    const frame = (t: number) => {
      if (onset < 0) {
        draw(0);
        onset = t;
        frames.push(0);
        requestAnimationFrame(frame);
        return;
      }
      frames.push(t - onset);
      if (frames.length === 2 && stallMs > 0) {
        const until = performance.now() + stallMs;
        while (performance.now() < until) {
          // busy: the frame after this one comes late, as after a stall of the browser
        }
      }
      if (t - onset >= durationMs - refreshMs / 2) {
        clear();
        resolve(judge(onset, frames, durationMs, refreshMs, lateFactor));
        return;
      }
      draw(t - onset);
      requestAnimationFrame(frame);
    };
    requestAnimationFrame(frame);
  });
}

/** The presentation's timing verdict. */
export function judge(onset: number, frames: number[], durationMs: number, refreshMs: number, lateFactor: number): Presentation {
  const durationMsMeasured = frames[frames.length - 1];
  let invalidReason = "";
  for (let i = 1; i < frames.length; i++) {
    if (frames[i] - frames[i - 1] > lateFactor * refreshMs) {
      invalidReason = "late_frame";
      break;
    }
  }
  if (!invalidReason && Math.abs(durationMsMeasured - durationMs) >= refreshMs / 2) invalidReason = "duration";
  return { onset, frames, durationMs: durationMsMeasured, frameCount: frames.length - 1, invalidReason };
}

/** The refresh period: the median of `n` frame intervals. */
export function measureRefresh(n = 60): Promise<number> {
  return new Promise((resolve) => {
    const stamps: number[] = [];
    const frame = (t: number) => {
      stamps.push(t);
      if (stamps.length > n) {
        const d = stamps.slice(1).map((s, i) => s - stamps[i]).sort((a, b) => a - b);
        resolve(d[Math.floor(d.length / 2)]);
        return;
      }
      requestAnimationFrame(frame);
    };
    requestAnimationFrame(frame);
  });
}
