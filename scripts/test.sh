#!/usr/bin/env bash
# Sets everything up and runs the whole test suite (what CI runs); then the same suite under
# ASan + UBSan (scripts/sanitize.sh) and bounded fuzzing of the readers (scripts/fuzz.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
(cd build && ctest --output-on-failure -j"$(nproc)")
bash scripts/sanitize.sh
bash scripts/fuzz.sh
