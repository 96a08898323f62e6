"""A Lab Streaming Layer outlet of type Gaze (pylsl, which bundles liblsl), for foveal's bridge
tests.

Prints `READY` once the outlet exists, waits for one inlet to connect, pushes SAMPLES (one
with NaN gaze; the last two as a chunk, so the second has a deduced time stamp), then closes
the outlet, which ends the inlet's stream feed.

With --restart the outlet then comes back (a new outlet, same source id) after a second, waits
for the inlet to reconnect, pushes AFTER_RESTART and closes again. With --chunks it pushes
CHUNKS instead: chunks of five samples at 100 Hz stamped when pushed, the second pushed early so
that by its stamp it begins before the first ends.

The channels are x, y, pupil size; with --swap the layout is y, pupil size, x (to test the
channel options).
"""

import argparse
import math
import sys
import time

import pylsl

# (x, y, pupil) and the LSL time stamp; the chunk's time stamp is that of its last sample.
SAMPLES = [((0.10, 0.20, 3.0), 1000.00), ((0.30, 0.40, 3.1), 1000.01),
           ((math.nan, math.nan, 0.0), 1000.02)]
CHUNK = [(0.50, 0.60, 3.2), (0.70, 0.80, 3.3)]
CHUNK_TIME = 1000.04
AFTER_RESTART = [((0.15, 0.25, 3.0), 1000.05), ((0.35, 0.45, 3.0), 1000.06)]
# (first x, stamp of the chunk's newest sample): the second chunk's stamp is 30 ms early.
CHUNKS = [(0.10, 1000.04), (0.60, 1000.06)]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--name", required=True)
    parser.add_argument("--format", choices=["float32", "double64"], default="float32")
    parser.add_argument("--swap", action="store_true")
    parser.add_argument("--restart", action="store_true")
    parser.add_argument("--chunks", action="store_true")
    args = parser.parse_args()

    def layout(values):
        x, y, p = values
        return [y, p, x] if args.swap else [x, y, p]

    fmt = pylsl.cf_float32 if args.format == "float32" else pylsl.cf_double64

    def open_outlet():
        info = pylsl.StreamInfo(args.name, "Gaze", 3, 100.0, fmt, "foveal-test-" + args.name)
        outlet = pylsl.StreamOutlet(info)
        return outlet

    def await_inlet(outlet):
        if not outlet.wait_for_consumers(30):
            print("no inlet connected within 30 s", file=sys.stderr)
            sys.exit(1)

    outlet = open_outlet()
    print("READY", flush=True)
    await_inlet(outlet)
    if args.chunks:
        for x, t in CHUNKS:
            outlet.push_chunk([layout((x + 0.01 * k, 0.5, 3.0)) for k in range(5)], t)
    else:
        for values, t in SAMPLES:
            outlet.push_sample(layout(values), t)
        outlet.push_chunk([layout(v) for v in CHUNK], CHUNK_TIME)
    time.sleep(0.5)
    del outlet
    if args.restart:
        time.sleep(1.0)
        outlet = open_outlet()
        await_inlet(outlet)
        for values, t in AFTER_RESTART:
            outlet.push_sample(layout(values), t)
        time.sleep(0.5)
        del outlet


if __name__ == "__main__":
    main()
