// Retrying while the server is away: waits that double from a base to a cap, each with random
// jitter (between half and all of the nominal wait), so that a page does not hammer a server that
// is down and many pages do not come back in lock step when it returns.

export class Backoff {
  private nominal: number;
  /** When the next attempt may be made (page clock, ms); 0: now. */
  private until = 0;

  constructor(private readonly baseMs = 500, private readonly capMs = 5000, private readonly random = Math.random) {
    this.nominal = baseMs;
  }

  /** The wait before the next attempt after a failure (ms), and the one after it doubled. */
  fail(now = performance.now()): number {
    const wait = this.nominal * (0.5 + 0.5 * this.random());
    this.nominal = Math.min(this.capMs, 2 * this.nominal);
    this.until = now + wait;
    return wait;
  }

  /** A success: the next failure waits the base again. */
  succeed(): void {
    this.nominal = this.baseMs;
    this.until = 0;
  }

  /** Whether an attempt may be made now (the wait after the last failure is over). */
  ready(now = performance.now()): boolean {
    return now >= this.until;
  }
}
