#!/usr/bin/env bash
# Sets everything up and runs the demo: simulate, calibrate, detect, correct; writes out/demo.
# Builds the CLI alone (the demo needs nothing else); scripts/test.sh builds everything.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh projsurf
./build/projsurf demo --out out/demo
