// The results endpoint (docs/PROTOCOL.md, "Psychophysics results"): the design, a session, and
// each trial posted as it ends, in order, retried while the network fails, so that a closed tab
// loses at most the trial in flight.

import type { Design } from "./design";

export interface ServerDisplay {
  width_px: number;
  height_px: number;
  diagonal_in: number;
  viewing_distance_cm: number;
}

export interface DesignAnswer {
  design: Design;
  trials: number;
  display: ServerDisplay;
  version: string;
}

/** A refusal from the server: its status, message and the field at fault. */
export class Refused extends Error {
  constructor(
    readonly status: number,
    message: string,
    readonly field: string | null,
  ) {
    super(message);
  }
}

const TOKEN_KEY = "foveal-psych-token";

/** The token from `#token=...` (then taken out of the address bar) or from this tab's storage. */
export function pageToken(): string | null {
  const params = new URLSearchParams(window.location.hash.slice(1));
  const t = params.get("token");
  if (t) {
    sessionStorage.setItem(TOKEN_KEY, t);
    params.delete("token");
    const rest = params.toString();
    history.replaceState(history.state, "", `${window.location.pathname}${window.location.search}${rest ? `#${rest}` : ""}`);
  }
  return t || sessionStorage.getItem(TOKEN_KEY);
}

export class Api {
  constructor(private readonly token: string | null) {}

  private async call<T>(method: string, path: string, body?: unknown): Promise<T> {
    const headers: Record<string, string> = {};
    if (this.token) headers.authorization = `Bearer ${this.token}`;
    if (body !== undefined) headers["content-type"] = "application/json";
    const r = await fetch(`/psych/api/${path}`, { method, headers, body: body === undefined ? undefined : JSON.stringify(body) });
    const answer = await r.json().catch(() => ({ error: `HTTP ${r.status}` }));
    if (!r.ok) throw new Refused(r.status, answer.error ?? `HTTP ${r.status}`, answer.field ?? null);
    return answer as T;
  }

  design(name: string): Promise<DesignAnswer> {
    return this.call("GET", `design?name=${encodeURIComponent(name)}`);
  }

  startSession(request: unknown): Promise<{ session: string; results: string }> {
    return this.call("POST", "sessions", request);
  }

  /**
   * Store trial `trial.trial` of `session`, retrying a failed network (not a refusal) with a
   * growing pause; a 409 saying the trial is already stored (a retry after a lost answer) is a
   * success.
   */
  async storeTrial(session: string, trial: { trial: number }): Promise<void> {
    for (let attempt = 0; ; attempt++) {
      try {
        await this.call("POST", `sessions/${session}/trials`, trial);
        return;
      } catch (e) {
        if (e instanceof Refused) {
          if (e.status === 409 && e.field === "trial" && e.message.includes("already stored") && attempt > 0) return;
          throw e;
        }
        if (attempt >= 8) throw e;
        await new Promise((r) => setTimeout(r, 250 * 2 ** Math.min(attempt, 4)));
      }
    }
  }

  finish(session: string, completed: boolean): Promise<{ trials_stored: number }> {
    return this.call("POST", `sessions/${session}/finish`, { completed });
  }
}
