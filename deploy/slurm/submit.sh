#!/usr/bin/env bash
# Queue the study's array (study.sbatch) and its merge (merge.sbatch), the merge to start only
# once every array task has succeeded. Arguments go to the array's sbatch, for example
# `--array=0-63` for 64 shards. FOVEAL_BENCH (the foveal-bench binary) and FOVEAL_STUDY_DIR (where
# partials and results go; by default ./foveal-study) reach the jobs through the environment,
# which sbatch exports.
set -euo pipefail

here="$(cd "$(dirname "$0")" && pwd)"
export FOVEAL_STUDY_DIR="${FOVEAL_STUDY_DIR:-$PWD/foveal-study}"
array="$(sbatch --parsable "$@" "$here/study.sbatch")"
array="${array%%;*}"
merge="$(sbatch --parsable --dependency="afterok:$array" "$here/merge.sbatch")"
echo "study array $array, merge $merge: results in $FOVEAL_STUDY_DIR/results"
