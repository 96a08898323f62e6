// The clients of the page: grpc-web to the server that served the page, binary format.
//
// A server with tokens (required beyond loopback) wants a bearer token on every call. The page
// takes it from its address, `http://HOST:PORT/#token=TOKEN` (a fragment never reaches the server
// or its logs), keeps it for the tab, and sends it as `authorization: Bearer TOKEN`; the token is
// then taken out of the address bar (history.replaceState), so that it is not left on the screen,
// in a screenshot or a copied link. A viewer token is enough to watch; the mouse as gaze needs a
// gaze token and the controls an admin token (an admin token does everything). A gaze token alone
// cannot watch: `#token=VIEWER_TOKEN&gaze=GAZE_TOKEN` gives the page one of each, the gaze token
// for the mouse only.
import { createClient, type Client, type Interceptor } from "@connectrpc/connect";
import { createGrpcWebTransport } from "@connectrpc/connect-web";
import { Foveal } from "./gen/foveal/v1/foveal_pb";

export type FovealClient = Client<typeof Foveal>;

const TOKEN_KEY = "foveal.token";
const GAZE_TOKEN_KEY = "foveal.gaze-token";

/** The page's tokens: the one it watches and controls with, and the one its mouse gaze uses. */
export interface PageTokens {
  token: string | null;
  gazeToken: string | null;
}

/**
 * The tokens from the address's fragment (remembered for the tab), or ones remembered earlier.
 * Tokens read from the fragment are taken out of the address bar; its other parameters stay.
 */
export function pageTokens(): PageTokens {
  const params = new URLSearchParams(window.location.hash.slice(1));
  const read = (name: string, key: string): string | null => {
    const v = params.get(name);
    if (v) sessionStorage.setItem(key, v);
    return v || sessionStorage.getItem(key);
  };
  const tokens = { token: read("token", TOKEN_KEY), gazeToken: read("gaze", GAZE_TOKEN_KEY) };
  if (params.has("token") || params.has("gaze")) {
    params.delete("token");
    params.delete("gaze");
    // `#focus` stays `#focus` (URLSearchParams would write `focus=`).
    const rest = [...params].map(([k, v]) => (v ? `${encodeURIComponent(k)}=${encodeURIComponent(v)}` : encodeURIComponent(k))).join("&");
    history.replaceState(history.state, "", `${window.location.pathname}${window.location.search}${rest ? `#${rest}` : ""}`);
  }
  return tokens;
}

/** Counts every call the page starts (the browser tests bound it while the server is down). */
export const calls = { started: 0 };

export function connect(baseUrl: string, token: string | null): FovealClient {
  const bearer: Interceptor = (next) => async (req) => {
    calls.started++;
    if (token) req.header.set("authorization", `Bearer ${token}`);
    return next(req);
  };
  return createClient(
    Foveal,
    createGrpcWebTransport({ baseUrl, useBinaryFormat: true, interceptors: [bearer] }),
  );
}
