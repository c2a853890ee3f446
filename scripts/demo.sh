#!/usr/bin/env bash
# Sets everything up and runs the demo: simulate, calibrate, detect, correct; writes out/demo.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
./build/projsurf demo --out out/demo
