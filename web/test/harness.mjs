// What the browser tests share: the server process, the Node client, and chromium.
//
// The tests need Debian's chromium and a built foveal-server. When either is missing they skip
// with the reason, unless FOVEAL_REQUIRE_BROWSER is set (as .ci/run sets it after installing
// them), in which case they fail.
import { spawn } from "node:child_process";
import { request as httpsRequest } from "node:https";
import { existsSync, mkdirSync, mkdtempSync, rmSync } from "node:fs";
import { createServer } from "node:net";
import { after, before } from "node:test";
import { tmpdir } from "node:os";
import { join, resolve } from "node:path";
import { fileURLToPath } from "node:url";
import { build } from "esbuild";

const here = fileURLToPath(new URL(".", import.meta.url));
export const repo = resolve(here, "../..");
export const CHROMIUM = process.env.FOVEAL_CHROMIUM ?? "/usr/bin/chromium";
export const SERVER =
  process.env.FOVEAL_SERVER_BIN ??
  join(process.env.CARGO_TARGET_DIR ?? join(repo, "target"), "release", "foveal-server");

/** Why the tests cannot run here, or null. Throws instead when they are required. */
export function missing() {
  const why = [];
  if (!existsSync(CHROMIUM)) why.push(`no chromium at ${CHROMIUM} (apt-get install -y chromium)`);
  if (!existsSync(SERVER)) why.push(`no server binary at ${SERVER} (cargo build --release -p foveal-server)`);
  if (why.length === 0) return null;
  const reason = why.join("; ");
  if (process.env.FOVEAL_REQUIRE_BROWSER) throw new Error(`FOVEAL_REQUIRE_BROWSER is set but ${reason}`);
  console.log(`# skipping the browser tests: ${reason}`);
  return reason;
}

/** The Node client module, bundled from TypeScript on the fly. */
export async function clientModule() {
  return bundle("client.ts");
}

/** A TypeScript module (path relative to test/), bundled for Node on the fly and imported. */
export async function bundle(entry) {
  // Inside web/, so that its imports resolve from web/node_modules.
  const dir = join(here, ".build");
  mkdirSync(dir, { recursive: true });
  const name = entry.replace(/^.*\//, "").replace(/\.ts$/, "");
  const out = join(dir, `${name}-${process.pid}.mjs`);
  await build({
    entryPoints: [join(here, entry)],
    bundle: true,
    platform: "node",
    format: "esm",
    outfile: out,
    packages: "external",
    logLevel: "warning",
    absWorkingDir: resolve(here, ".."),
  });
  const mod = await import(out);
  rmSync(out, { force: true });
  return mod;
}

export async function freePort() {
  return new Promise((ok, fail) => {
    const s = createServer();
    s.once("error", fail);
    s.listen(0, "127.0.0.1", () => {
      const { port } = s.address();
      s.close(() => ok(port));
    });
  });
}

// Servers still running when the test process exits (a failed or interrupted run) go with it.
const running = new Set();
process.on("exit", () => {
  for (const p of running) p.kill("SIGKILL");
});

/** GET `url` over TLS trusting only `ca` (PEM); resolves with the status code. */
function httpsStatus(url, ca) {
  return new Promise((ok, fail) => {
    const r = httpsRequest(url, { ca }, (res) => {
      res.resume();
      ok(res.statusCode);
    });
    r.once("error", fail);
    r.end();
  });
}

/**
 * Start foveal-server on `port` with `args`; resolves once it serves the page. With `tls`
 * (`{ cert, key, ca }`: file paths and the CA's PEM) it serves `https://localhost:PORT/`.
 */
export async function startServer(port, args, tls) {
  const tlsArgs = tls ? ["--tls-cert", tls.cert, "--tls-key", tls.key] : [];
  const proc = spawn(SERVER, ["--addr", `127.0.0.1:${port}`, "--log-level", "warn", ...tlsArgs, ...args], {
    stdio: ["ignore", "inherit", "inherit"],
  });
  running.add(proc);
  proc.once("exit", () => running.delete(proc));
  const failed = new Promise((_, fail) => proc.once("error", (e) => fail(new Error(`cannot start ${SERVER}: ${e.message}`))));
  failed.catch(() => {});
  const url = tls ? `https://localhost:${port}/` : `http://127.0.0.1:${port}/`;
  const until = Date.now() + 60_000;
  for (;;) {
    await Promise.race([failed, sleep(0)]);
    if (proc.exitCode !== null) throw new Error(`foveal-server exited with ${proc.exitCode}`);
    try {
      const status = tls ? await httpsStatus(url, tls.ca) : (await fetch(url)).status;
      if (status === 200) break;
    } catch {
      // not listening yet
    }
    if (Date.now() > until) {
      proc.kill("SIGKILL");
      throw new Error(`foveal-server did not serve ${url} within 60 s`);
    }
    await sleep(100);
  }
  return {
    url,
    proc,
    async stop() {
      if (proc.exitCode !== null) return;
      const exited = new Promise((ok) => proc.once("exit", ok));
      proc.kill("SIGTERM");
      const t = setTimeout(() => proc.kill("SIGKILL"), 10_000);
      await exited;
      clearTimeout(t);
    },
  };
}

export const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

/** Push every console error and uncaught exception of `page` onto `errors`. */
export function recordErrors(page, errors) {
  page.on("console", (m) => m.type() === "error" && errors.push(m.text()));
  page.on("pageerror", (e) => errors.push(String(e)));
}

/**
 * A describe block's server and page: its `before` starts foveal-server with `args` and opens
 * the viewer in a fresh browser (the page's console errors pushed onto `errors`), its `after`
 * closes both. Call inside `describe`; the fields are filled in when `before` has run.
 */
export function servedPage(args) {
  const ctx = { server: null, browser: null, page: null, errors: [] };
  before(async () => {
    ctx.server = await startServer(await freePort(), args);
    ctx.browser = await launch();
    ctx.page = await ctx.browser.browser.newPage();
    recordErrors(ctx.page, ctx.errors);
    await ctx.page.goto(ctx.server.url);
  });
  after(async () => {
    await ctx.browser?.close();
    await ctx.server?.stop();
  });
  return ctx;
}

/** Poll `f` until it returns a truthy value or `ms` pass; returns the value or null. */
export async function waitFor(f, ms, every = 20) {
  const until = Date.now() + ms;
  for (;;) {
    const v = await f();
    if (v) return v;
    if (Date.now() > until) return null;
    await sleep(every);
  }
}

/**
 * Debian's chromium, headless, software-rendered, with a fresh profile; `extraArgs` are added to
 * its command line and `options` to playwright's launch options.
 */
export async function launch(extraArgs = [], options = {}) {
  const { chromium } = await import("playwright-core");
  const profile = mkdtempSync(join(tmpdir(), "foveal-chromium-"));
  const browser = await chromium.launchPersistentContext(profile, {
    executablePath: CHROMIUM,
    headless: true,
    viewport: { width: 1400, height: 800 },
    args: [
      "--headless",
      "--no-sandbox",
      "--disable-gpu",
      "--disable-quic",
      "--no-first-run",
      "--disable-background-networking",
      "--disable-component-update",
      "--disable-sync",
      // WebGL on the CPU: without a GPU, chromium only offers SwiftShader when asked to.
      "--enable-unsafe-swiftshader",
      ...extraArgs,
    ],
    ...options,
  });
  return {
    browser,
    async close() {
      await browser.close();
      rmSync(profile, { recursive: true, force: true });
    },
  };
}

/** Summary statistics of a list of numbers. */
export function summary(a) {
  const s = [...a].sort((x, y) => x - y);
  const q = (p) => s[Math.min(s.length - 1, Math.floor(p * s.length))];
  return { n: s.length, p50: q(0.5), p95: q(0.95), max: s[s.length - 1] };
}
