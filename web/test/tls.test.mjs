// The viewer over https:// against a TLS foveal-server, in a browser that speaks only HTTP/1.1
// (chromium with HTTP/2 disabled, as behind many proxies): the server must offer http/1.1 beside
// h2 in ALPN, and grpc-web over HTTP/1.1 then carries the frames and the mouse as over plain HTTP.
import assert from "node:assert/strict";
import { execFileSync } from "node:child_process";
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { after, before, describe, test } from "node:test";
import { freePort, launch, missing, recordErrors, startServer, waitFor } from "./harness.mjs";

/** A CA and a certificate it signed for localhost, made with the openssl command; null without it. */
function certificates() {
  const dir = mkdtempSync(join(tmpdir(), "foveal-tls-"));
  const openssl = (...args) => execFileSync("openssl", args, { cwd: dir, stdio: "pipe" });
  try {
    const ec = ["-newkey", "ec", "-pkeyopt", "ec_paramgen_curve:P-256", "-nodes"];
    openssl("req", "-x509", ...ec, "-keyout", "ca.key", "-out", "ca.pem", "-days", "2", "-subj", "/CN=foveal test CA",
      "-addext", "basicConstraints=critical,CA:TRUE", "-addext", "keyUsage=critical,keyCertSign");
    openssl("req", ...ec, "-keyout", "server.key", "-out", "server.csr", "-subj", "/CN=localhost");
    writeFileSync(join(dir, "ext"), "subjectAltName=DNS:localhost,IP:127.0.0.1\nextendedKeyUsage=serverAuth\n");
    openssl("x509", "-req", "-in", "server.csr", "-CA", "ca.pem", "-CAkey", "ca.key", "-CAcreateserial",
      "-out", "server.pem", "-days", "2", "-extfile", "ext");
  } catch (e) {
    rmSync(dir, { recursive: true, force: true });
    if (process.env.FOVEAL_REQUIRE_BROWSER) throw new Error(`cannot make test certificates with openssl: ${e.message}`);
    console.log(`# skipping the TLS browser test: no openssl (${e.message})`);
    return null;
  }
  return { dir, cert: join(dir, "server.pem"), key: join(dir, "server.key"), ca: readFileSync(join(dir, "ca.pem")) };
}

const skip = missing() ?? false;

describe("viewer over https:// and HTTP/1.1", { skip }, () => {
  let tls, server, browser, page;
  const consoleErrors = [];

  before(async () => {
    tls = certificates();
    if (!tls) return;
    const port = await freePort();
    server = await startServer(port, ["-n", "200", "--budget", "1000tests"], tls);
    // The certificate's CA is not the system's: the browser is told to accept it, which is not
    // what this test is about. HTTP/2 off: only ALPN's http/1.1 can carry the page and calls.
    browser = await launch(["--disable-http2"], { ignoreHTTPSErrors: true });
    page = await browser.browser.newPage();
    recordErrors(page, consoleErrors);
    await page.goto(server.url);
  });

  after(async () => {
    await browser?.close();
    await server?.stop();
    if (tls) rmSync(tls.dir, { recursive: true, force: true });
  });

  test("loads over TLS and HTTP/1.1 and shows the server's frames", async (t) => {
    if (!tls) return t.skip("no openssl");
    const stats = () => page.evaluate(() => window.foveal.stats);
    const s = await waitFor(async () => {
      const s = await stats();
      return s.framesApplied >= 5 && s;
    }, 20_000);
    assert.ok(s, `frames applied: ${(await stats()).framesApplied}, last error: ${(await stats()).lastError}`);
    assert.equal(s.bodies, 200);
    assert.match(await page.textContent("#status"), /connected/);
    assert.ok(page.url().startsWith("https://localhost:"), page.url());
    // The protocol the page and its grpc-web calls actually used.
    const used = await page.evaluate(() => [
      ...new Set(
        [...performance.getEntriesByType("navigation"), ...performance.getEntriesByType("resource")].map(
          (e) => e.nextHopProtocol,
        ),
      ),
    ]);
    assert.deepEqual(used, ["http/1.1"]);
    assert.deepEqual(consoleErrors, []);
  });
});
