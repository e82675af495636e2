#!/usr/bin/env bash
# Place and route of every unit of the default design (hdl-out/), and the area/speed report:
# `edgepaint report` synthesizes each unit (Yosys generic, iCE40, ECP5), wraps it between
# registers (rtl::emit::pnr_wrapper) and runs nextpnr-ice40 (iCE40 HX8K) and nextpnr-ecp5
# (LFE5U-25F), then writes report.md and report.json into target/report/ (or -o DIR).
# Too slow for every CI run (the EPT at P = 1024 takes about 7 minutes); the test command
# runs lint.sh and synth.sh instead. Extra arguments go to `edgepaint report`, e.g.
#   scripts/pnr.sh --unit ept --param P=64 --param P=1024
set -euo pipefail
cd "$(dirname "$0")/.."
for tool in yosys nextpnr-ice40 nextpnr-ecp5; do
    if ! command -v "$tool" >/dev/null; then
        echo "pnr: $tool is not on PATH: run scripts/setup-tools.sh, then 'source scripts/tools-env.sh'" >&2
        exit 1
    fi
done
exec cargo run --release --quiet -- report "$@"
