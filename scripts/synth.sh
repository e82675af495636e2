#!/usr/bin/env bash
# Yosys synthesis of every emitted unit in hdl-out/ (or of the .v files given): generic
# `synth -flatten`, `synth_ice40` and `synth_ecp5`, each followed by `check -assert`
# (undriven or multiply driven nets, logic loops). Exits non-zero on any error.
# Logs and netlists go to $CARGO_TARGET_DIR/synth/ (default target/synth/).
set -euo pipefail
cd "$(dirname "$0")/.."

if ! command -v yosys >/dev/null; then
    echo "synth: yosys is not on PATH: run scripts/setup-tools.sh" >&2
    exit 1
fi
shopt -s nullglob
files=("$@")
[[ ${#files[@]} -gt 0 ]] || files=(hdl-out/*.v)
if [[ ${#files[@]} -eq 0 ]]; then
    echo "synth: no Verilog in hdl-out/ (run 'cargo run --release' to emit it)" >&2
    exit 1
fi
out=${CARGO_TARGET_DIR:-target}/synth
mkdir -p "$out"

# One job per file and flow, $SYNTH_JOBS (default: the CPU count) at a time: raster_top
# and triangle_setup take minutes each.
synth_one() {
    local f=$1 flow=$2 out=$3 top cmd log
    top=$(basename "$f" .v)
    case $flow in
        generic) cmd="synth -flatten -top $top; check -assert; stat" ;;
        ice40) cmd="synth_ice40 -top $top -json $out/$top.ice40.json; check -assert; stat" ;;
        ecp5) cmd="synth_ecp5 -top $top -json $out/$top.ecp5.json; check -assert; stat" ;;
    esac
    log=$out/$top.$flow.log
    if yosys -q -l "$log" -p "read_verilog $f; $cmd" >/dev/null; then
        echo "synth: $f: $flow ok ($(grep -m1 -E 'Number of cells' "$log" | tr -s ' ' | sed 's/^ //'))"
    else
        echo "synth: $f: $flow FAILED (log: $log)" >&2
        tail -n 20 "$log" >&2
        return 1
    fi
}
export -f synth_one

# The largest files first, so the long jobs start early.
mapfile -t files < <(ls -S "${files[@]}")
for f in "${files[@]}"; do
    for flow in generic ice40 ecp5; do
        printf '%s\0%s\0%s\0' "$f" "$flow" "$out"
    done
done | xargs -0 -n 3 -P "${SYNTH_JOBS:-$(nproc)}" bash -c 'synth_one "$@"' synth
