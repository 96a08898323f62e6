"""A stand-in for Pupil Capture's network API, for foveal's bridge tests.

Pupil Remote is a REP socket answering SUB_PORT (the port of the PUB socket) and t (the
Pupil clock); gaze datums are published as [topic, msgpack dict] on the PUB side. An XPUB
socket is used so that the datums are sent only once the bridge has subscribed (a plain PUB
drops messages sent before the subscription arrives).

Prints `READY <remote port>` on stdout once listening. Publishes the datums of DATUMS that
match the first subscription, answers Pupil Remote for --linger seconds more, then exits, as
a Pupil Capture that is closed does.
"""

import argparse
import sys
import time

import msgpack
import zmq


def gaze(topic, x, y, confidence, t, eyes):
    base = [{"topic": "pupil.%d.3d" % e, "id": e, "confidence": confidence,
             "timestamp": t, "norm_pos": [x, y]} for e in eyes]
    return {"topic": topic, "norm_pos": [x, y], "confidence": confidence,
            "timestamp": t, "base_data": base}


# Binocular, right eye (eye 0), a low-confidence left eye (eye 1), binocular again.
DATUMS = [
    gaze("gaze.3d.01.", 0.25, 0.75, 0.95, 100.00, [0, 1]),
    gaze("gaze.3d.0.", 0.50, 0.20, 0.90, 100.01, [0]),
    gaze("gaze.3d.1.", 0.60, 0.60, 0.30, 100.02, [1]),
    gaze("gaze.3d.01.", 0.40, 0.90, 0.99, 100.03, [0, 1]),
]


def surface_datum(name):
    entries = []
    for d in DATUMS:
        entry = dict(d)
        entry["topic"] = d["topic"] + "_on_surface"
        entry["norm_pos"] = [d["norm_pos"][0] / 2, d["norm_pos"][1] / 2]
        entry["on_surf"] = True
        entry["base_data"] = [d["topic"], d["timestamp"]]
        entries.append(entry)
    return {"topic": "surfaces." + name, "name": name, "timestamp": 100.03,
            "gaze_on_surfaces": entries}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--surface", default="screen")
    parser.add_argument("--linger", type=float, default=1.5)
    args = parser.parse_args()

    ctx = zmq.Context()
    remote = ctx.socket(zmq.REP)
    remote_port = remote.bind_to_random_port("tcp://127.0.0.1")
    pub = ctx.socket(zmq.XPUB)
    pub_port = pub.bind_to_random_port("tcp://127.0.0.1")
    print("READY %d" % remote_port, flush=True)

    poller = zmq.Poller()
    poller.register(remote, zmq.POLLIN)
    poller.register(pub, zmq.POLLIN)
    start = time.monotonic()
    published_at = None
    while True:
        now = time.monotonic()
        if published_at is not None and now - published_at > args.linger:
            break
        if published_at is None and now - start > 30:
            print("nobody subscribed within 30 s", file=sys.stderr)
            sys.exit(1)
        for sock, _ in poller.poll(100):
            if sock is remote:
                request = remote.recv().decode()
                if request == "SUB_PORT":
                    remote.send_string(str(pub_port))
                elif request == "t":
                    remote.send_string(repr(100.0 + time.monotonic() - start))
                else:
                    remote.send_string("Unknown command.")
            else:
                event = pub.recv()
                if event[:1] != b"\x01" or published_at is not None:
                    continue
                topic = event[1:].decode()
                if topic.startswith("surfaces."):
                    messages = [surface_datum(topic[len("surfaces."):])]
                else:
                    messages = DATUMS
                for datum in messages:
                    pub.send_multipart([datum["topic"].encode(),
                                        msgpack.packb(datum, use_bin_type=True)])
                published_at = time.monotonic()
    remote.close(linger=0)
    pub.close(linger=1000)
    ctx.term()


if __name__ == "__main__":
    main()
