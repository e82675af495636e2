#!/usr/bin/env bash
# Verilator lint of every emitted unit in hdl-out/ (the default design, and in its
# directories raster_top's barycentric and SE back ends), of raster_top at size classes 11 and
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
# made): no second build for the variants emitted below. $EDGEPAINT, when set, is that
# binary, built (scripts/test.sh runs the lint beside the tests, without a second cargo);
# $LINT_SKIP names variants below it does not hold (the test command's is built without
# classes 11 and 12: "N11 N12").
if [[ -z ${EDGEPAINT:-} ]]; then
    cargo build --profile test --quiet --bin edgepaint
    EDGEPAINT=${CARGO_TARGET_DIR:-target}/debug/edgepaint
fi
export EDGEPAINT
# Emissions and lints run $LINT_JOBS (default: the CPU count) at a time.
jobs=${LINT_JOBS:-$(nproc)}
shopt -s nullglob
files=("$@")
if [[ ${#files[@]} -eq 0 ]]; then
    files=(hdl-out/*.v hdl-out/*/*.v)
    if [[ ${#files[@]} -eq 0 ]]; then
        echo "lint: no Verilog in hdl-out/ (run 'cargo run --release' to emit it)" >&2
        exit 1
    fi
    # Other builds, each a directory under target/lint/ named unit-variant and the
    # arguments that emit it: raster_top at the larger size classes (screens up to 2048 and
    # 4096), with units left out, at formats other than its class's defaults (24-bit depth,
    # ...), with its barycentric method at one lane (hdl-out/ holds it at four, and the SE
    # back end); the vector unit and pixel_out with several lanes, and pixel_out blending.
    variants=(
        "raster_top-N11" "--param N=11"
        "raster_top-N12" "--param N=12"
        "raster_top-CULL_SORT=0" "--param CULL_SORT=0"
        "raster_top-PIXEL_OUT=0" "--param PIXEL_OUT=0"
        "raster_top-CULL_SORT=0-PIXEL_OUT=0" "--param CULL_SORT=0 --param PIXEL_OUT=0"
        "raster_top-METHOD=1" "--param METHOD=1"
        "raster_top-custom" "--formats crates/rtl/custom-formats.json"
        "vector-LANES=4" "--param LANES=4"
        "pixel_out-LANES=4" "--param LANES=4"
        "pixel_out-BLEND=1" "--param BLEND=1"
    )
    emit=()
    for ((i = 0; i < ${#variants[@]}; i += 2)); do
        if [[ " ${LINT_SKIP:-} " =~ " ${variants[i]#raster_top-} " ]]; then
            echo "lint: ${variants[i]} skipped (LINT_SKIP)"
            continue
        fi
        files+=("target/lint/${variants[i]}/${variants[i]%%-*}.v")
        emit+=("target/lint/${variants[i]}" "${variants[i]%%-*} ${variants[i + 1]}")
    done
    printf '%s\0' "${emit[@]}" | xargs -0 -n 2 -P "$jobs" bash -c '
        # shellcheck disable=SC2086 # the arguments are words
        "$EDGEPAINT" emit --unit $2 -o "$1" >/dev/null || { echo "lint: emitting $1 failed" >&2; exit 255; }' emit
fi

# gpu_top holds these units (raster_top's without pixel_out): their waivers apply to its
# file too, rewritten to name it (Verilator's -file takes one pattern, no alternatives).
waivers=${CARGO_TARGET_DIR:-target}/lint/waivers
mkdir -p "$waivers"
sed -E 's#-file "\*(command_parser|divider|edge_walk|gpu_regs|pixel_bus|raster_top|span|triangle_setup)\.v"#-file "*gpu_top.v"#' \
    scripts/lint-waivers.vlt >"$waivers/gpu_top.vlt"
export waivers

lint_one() {
    local f=$1 top vlt=scripts/lint-waivers.vlt
    top=$(basename "$f" .v)
    [[ $top == gpu_top ]] && vlt=$waivers/gpu_top.vlt
    if verilator --lint-only -Wall -Wno-WIDTH -Wno-DECLFILENAME --top-module "$top" "$vlt" "$f"; then
        echo "lint: $f: clean"
    else
        echo "lint: $f: FAILED" >&2
        return 1
    fi
}
export -f lint_one
printf '%s\0' "${files[@]}" | xargs -0 -n 1 -P "$jobs" bash -c 'lint_one "$1"' lint
