// A Node client of the same server, for the browser tests to check what the server reports.
import { createClient } from "@connectrpc/connect";
import { createGrpcWebTransport } from "@connectrpc/connect-node";
import { Foveal, FixationSource, PairStatus, Scheduler, Truth } from "../src/gen/foveal/v1/foveal_pb";

export { FixationSource, PairStatus, Scheduler, Truth };

export function nodeClient(baseUrl: string) {
  return createClient(Foveal, createGrpcWebTransport({ baseUrl, httpVersion: "1.1", useBinaryFormat: true }));
}
