#!/usr/bin/env bash
# Verilator lint of every emitted unit in hdl-out/, of raster_top at size classes 11 and
# 12, with units left out (CULL_SORT=0, PIXEL_OUT=0, both) and at the formats of
# rtl::custom (crates/rtl/custom-formats.json; all emitted under target/lint/), or of the
# .v files given, with -Wall.
# Exits non-zero if any file has a warning or an error.
#
# Waived, and why:
#   -Wno-WIDTH         rust-hdl writes every literal and index as 32 bits (`xl[32'h5]`,
#                      `x << 32'h4`), so operand widths never match; the dual-simulation
#                      tests compare the Verilog with rust-hdl's own simulator instead.
#   -Wno-DECLFILENAME  rust-hdl writes a unit's sub-modules (`ept$root`, `ept$root$pe`, …)
#                      into the unit's one file, so only the top module matches the name.
#   scripts/lint-waivers.vlt  per-signal waivers, each with its reason there.
set -euo pipefail
cd "$(dirname "$0")/.."

if ! command -v verilator >/dev/null; then
    echo "lint: verilator is not on PATH: run scripts/setup-tools.sh, then 'source scripts/tools-env.sh'" >&2
    exit 1
fi
# edgepaint as the test profile builds it (optimised, and the build `cargo test` already
# made): no second build for the variants emitted below.
edgepaint() { cargo run --profile test --quiet -- "$@"; }
shopt -s nullglob
files=("$@")
if [[ ${#files[@]} -eq 0 ]]; then
    files=(hdl-out/*.v)
    if [[ ${#files[@]} -eq 0 ]]; then
        echo "lint: no Verilog in hdl-out/ (run 'cargo run --release' to emit it)" >&2
        exit 1
    fi
    # raster_top at the larger size classes too (screens up to 2048 and 4096).
    for n in 11 12; do
        edgepaint emit --unit raster_top --param N=$n -o "target/lint/raster_top-N$n" >/dev/null
        files+=("target/lint/raster_top-N$n/raster_top.v")
    done
    # raster_top with units left out.
    for units in "CULL_SORT=0" "PIXEL_OUT=0" "CULL_SORT=0 PIXEL_OUT=0"; do
        dir="target/lint/raster_top-${units// /-}"
        # shellcheck disable=SC2046 # one --param per word of $units
        edgepaint emit --unit raster_top $(printf -- '--param %s ' $units) -o "$dir" >/dev/null
        files+=("$dir/raster_top.v")
    done
    # raster_top at formats other than its class's defaults (24-bit depth, ...).
    edgepaint emit --unit raster_top --formats crates/rtl/custom-formats.json \
        -o target/lint/raster_top-custom >/dev/null
    files+=("target/lint/raster_top-custom/raster_top.v")
fi

failed=0
for f in "${files[@]}"; do
    top=$(basename "$f" .v)
    if verilator --lint-only -Wall -Wno-WIDTH -Wno-DECLFILENAME --top-module "$top" scripts/lint-waivers.vlt "$f"; then
        echo "lint: $f: clean"
    else
        echo "lint: $f: FAILED" >&2
        failed=1
    fi
done
exit $failed
