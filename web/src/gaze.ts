// The mouse as the gaze: pointer positions over the scene go to PushGaze in small batches at the
// pointer's rate, at most two requests in flight (a move never waits behind a repeat). While the pointer rests on the scene its
// position is re-sent every 100 ms, because the server treats gaze older than `gaze_max_age`
// (0.5 s by default) as stale and falls back to the screen centre: a resting eye still looks.
// When the pointer leaves the scene (to the controls, the plots) the last position over the scene
// is held and re-sent the same way, so the fixation stays where the viewer last looked instead of
// dropping to the centre; it stops while the tab is hidden or "mouse is the gaze" is off. A failed
// call (server away, a token that may not send gaze) backs off with jitter, 0.5 s doubling to 5 s,
// so a page never floods a server that is down.
import { create } from "@bufbuild/protobuf";
import { Backoff } from "./backoff";
import { GazeSampleSchema, type GazeSample } from "./gen/foveal/v1/foveal_pb";
import type { FovealClient } from "./rpc";

/** Batches leave at most this often (ms): a 60 Hz frame never waits for more than one. */
const FLUSH_MS = 8;
/** A resting pointer is re-sent this often (ms). */
const REPEAT_MS = 100;
/** Samples kept while a request is in flight; older ones are dropped (only the newest matters). */
const MAX_PENDING = 256;

export class MouseGaze {
  enabled = true;
  /** The pointer in normalised screen coordinates, or null before it first reaches the scene. */
  pointer: { x: number; y: number } | null = null;
  /** The pointer left the scene: `pointer` is its last position there, held. */
  held = false;
  /** Samples accepted by the server, and the last refusal or transport error. */
  accepted = 0;
  lastError = "";
  /** Round trip of the last PushGaze, ms, and when the last pointer event arrived (page clock). */
  lastRoundTripMs = 0;
  lastPointerAt = 0;
  private pending: GazeSample[] = [];
  private inFlight = 0;
  private lastSent = 0;
  private backoff = new Backoff();

  constructor(private client: FovealClient, private target: HTMLElement) {
    target.addEventListener("pointermove", (e) => this.move(e));
    target.addEventListener("pointerleave", () => (this.held = true));
    setInterval(() => this.tick(), FLUSH_MS);
  }

  private move(e: PointerEvent): void {
    const r = this.target.getBoundingClientRect();
    if (r.width <= 0 || r.height <= 0) return;
    this.pointer = { x: (e.clientX - r.left) / r.width, y: (e.clientY - r.top) / r.height };
    this.held = false;
    this.lastPointerAt = performance.now();
    this.sample();
  }

  private sample(): void {
    if (!this.enabled || !this.pointer || document.hidden) return;
    this.pending.push(
      create(GazeSampleSchema, {
        trackerTimeS: performance.now() / 1000,
        x: this.pointer.x,
        y: this.pointer.y,
        validity: 1,
      }),
    );
    if (this.pending.length > MAX_PENDING) this.pending.splice(0, this.pending.length - MAX_PENDING);
    void this.flush();
  }

  private tick(): void {
    if (this.enabled && this.pointer && this.inFlight === 0 && this.pending.length === 0 && performance.now() - this.lastSent > REPEAT_MS) {
      this.sample();
    } else {
      void this.flush();
    }
  }

  private async flush(): Promise<void> {
    // Two lanes: the server keeps the sample it received last, and a repeat of the resting pointer
    // that is still in flight must not hold back the move that follows it.
    if (this.inFlight >= 2 || this.pending.length === 0 || !this.backoff.ready()) return;
    const samples = this.pending;
    this.pending = [];
    this.inFlight++;
    this.lastSent = performance.now();
    try {
      const t0 = performance.now();
      const r = await this.client.pushGaze({ samples, source: "viewer:mouse" });
      this.lastRoundTripMs = performance.now() - t0;
      this.accepted += Number(r.accepted);
      this.lastError = r.rejections[0] ? `${r.rejections[0].field}: ${r.rejections[0].reason}` : "";
      this.backoff.succeed();
    } catch (e) {
      this.lastError = e instanceof Error ? e.message : String(e);
      this.backoff.fail();
    } finally {
      this.inFlight--;
    }
  }
}
