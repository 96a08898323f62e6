// The one client of the page: grpc-web to the server that served the page, binary format.
import { createClient, type Client } from "@connectrpc/connect";
import { createGrpcWebTransport } from "@connectrpc/connect-web";
import { Foveal } from "./gen/foveal/v1/foveal_pb";

export type FovealClient = Client<typeof Foveal>;

export function connect(baseUrl: string): FovealClient {
  return createClient(Foveal, createGrpcWebTransport({ baseUrl, useBinaryFormat: true }));
}
