#!/usr/bin/env sh
# The one release build of the shipped binaries: run by docker/Dockerfile and by .ci/run, so CI
# builds exactly what the image ships.
set -eu
cargo build --release --locked -p foveal-server -p foveal-client --bins
