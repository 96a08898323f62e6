// The one client of the page: grpc-web to the server that served the page, binary format.
//
// A server with tokens (required beyond loopback) wants a bearer token on every call. The page
// takes it from its address, `http://HOST:PORT/#token=TOKEN` (a fragment never reaches the server
// or its logs), keeps it for the tab, and sends it as `authorization: Bearer TOKEN`. A viewer token
// is enough to watch; the mouse as gaze needs a gaze token and the controls an admin token (an
// admin token does everything).
import { createClient, type Client, type Interceptor } from "@connectrpc/connect";
import { createGrpcWebTransport } from "@connectrpc/connect-web";
import { Foveal } from "./gen/foveal/v1/foveal_pb";

export type FovealClient = Client<typeof Foveal>;

const TOKEN_KEY = "foveal.token";

/** The token from the address's fragment (remembered for the tab), or one remembered earlier. */
export function pageToken(): string | null {
  const fromHash = new URLSearchParams(window.location.hash.slice(1)).get("token");
  if (fromHash) {
    sessionStorage.setItem(TOKEN_KEY, fromHash);
    return fromHash;
  }
  return sessionStorage.getItem(TOKEN_KEY);
}

export function connect(baseUrl: string, token: string | null): FovealClient {
  const bearer: Interceptor = (next) => async (req) => {
    if (token) req.header.set("authorization", `Bearer ${token}`);
    return next(req);
  };
  return createClient(
    Foveal,
    createGrpcWebTransport({ baseUrl, useBinaryFormat: true, interceptors: [bearer] }),
  );
}
