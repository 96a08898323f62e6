#!/usr/bin/env sh
# The one release build of the shipped binaries: run by docker/Dockerfile and by .ci/run, so CI
# builds exactly what the image ships. foveal-bench is in the image so that a cluster runs the
# study's shards and their merge from it (deploy/).
set -eu
cargo build --release --locked -p foveal-server -p foveal-client -p foveal-bench --bins
