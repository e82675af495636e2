#!/usr/bin/env bash
# Yosys synthesis of the emitted units in hdl-out/ (or of the .v files given), each flow
# after a check that no latch is inferred and followed by `check -assert` (undriven or
# multiply driven nets, logic loops). Exits
# non-zero on any error. Logs and netlists go to $CARGO_TARGET_DIR/synth/ (default
# target/synth/).
#
#   scripts/synth.sh          each distinct module once: gpu_top.v (which holds
#                             command_parser, triangle_queue, cull_sort, divider,
#                             triangle_setup, edge_walk, span, pixel_bus and gpu_regs as its
#                             submodules), se.v, vector.v and texture_path.v (which holds
#                             texture_setup and texture_unit, and in it texture_coords,
#                             texture_address, texture_cache and texture_filter) elaborated:
#                             read, hierarchy, proc, flatten and `opt -fast` (memories kept
#                             as Yosys memories: mapping texture_coords' log ROMs to logic
#                             alone took 312 s of CPU). That is where the emitted Verilog can
#                             fail synthesis (syntax Yosys refuses, a latch, a multiply driven
#                             or undriven net, a logic loop), in 55 s of CPU for the four at
#                             stop 61, where synth_ecp5's coarse passes up to its gate mapping
#                             took 327 s; the coarse passes, the mapping and the place and
#                             route are the soak's (--all, and `edgepaint report`).
#                             Every other unit not listed in SUBMODULES (pixel_out.v, ept.v,
#                             se_cmd.v, blend.v) by generic `synth -flatten` and
#                             `synth_ecp5`. raster_top.v is gpu_top's scanline units with
#                             pixel_out behind them: its `synth_ecp5` took 176 s of CPU for
#                             no module the others leave out but its own glue (the test
#                             command)
#   scripts/synth.sh --all    every file in every flow, mapped to cells, also `synth_ice40`
#                             (scripts/soak.sh: 2,071 s on 2 cores at stop 37), and the
#                             variants in hdl-out/'s directories (raster_top's barycentric
#                             and SE back ends) by `synth_ecp5` only: the generic flow makes
#                             flip-flops of the SE engines' RAMs, and no iCE40 holds either
set -euo pipefail
cd "$(dirname "$0")/.."

if ! command -v yosys >/dev/null; then
    echo "synth: yosys is not on PATH: run scripts/setup-tools.sh" >&2
    exit 1
fi
# Units whose modules gpu_top.v holds (raster_top.v: all but its glue and pixel_out, which
# is synthesized alone), synthesized there; and the texture units, which texture_path.v holds
# (texture_setup, and texture_unit with its four).
SUBMODULES=(command_parser triangle_queue cull_sort divider triangle_setup edge_walk span pixel_bus gpu_regs raster_top
    texture_coords texture_address texture_cache texture_filter texture_unit texture_setup)
# Units the test command elaborates only (--all runs every flow, mapped to cells).
ELABORATE_ONLY=(gpu_top se vector texture_path)
flows=(generic ecp5)
all=0
if [[ ${1:-} == --all ]]; then
    all=1
    flows=(generic ice40 ecp5)
    shift
fi
shopt -s nullglob
files=("$@")
if [[ ${#files[@]} -eq 0 ]]; then
    for f in hdl-out/*.v; do
        unit=$(basename "$f" .v)
        if [[ $all == 1 || ! " ${SUBMODULES[*]} " =~ " $unit " ]]; then
            files+=("$f")
        fi
    done
    [[ $all == 1 ]] && files+=(hdl-out/*/*.v)
fi
if [[ ${#files[@]} -eq 0 ]]; then
    echo "synth: no Verilog in hdl-out/ (run 'cargo run --release' to emit it)" >&2
    exit 1
fi
out=${CARGO_TARGET_DIR:-target}/synth
mkdir -p "$out"

# One job per file and flow, $SYNTH_JOBS (default: the CPU count) at a time: raster_top
# and triangle_setup take minutes each.
synth_one() {
    local f=$1 flow=$2 out=$3 top name cmd log
    top=$(basename "$f" .v)
    # A variant's work files are named after its directory (raster_top-METHOD=2).
    name=$(basename "$(dirname "$f")")
    [[ $name == "$top"-* ]] || name=$top
    case $flow in
        generic) cmd="synth -flatten -top $top; check -assert; stat" ;;
        ice40) cmd="synth_ice40 -top $top -json $out/$name.ice40.json; check -assert; stat" ;;
        ecp5) cmd="synth_ecp5 -top $top -json $out/$name.ecp5.json; check -assert; stat" ;;
        elaborate) cmd="flatten; opt -fast; check -assert; stat" ;;
    esac
    log=$out/$name.$flow.log
    # No latches: a combinational output some path leaves unassigned (a `match` without a
    # default in a kernel) holds its value in one, which the flows map to a logic loop
    # that `check` does not flag (nextpnr's timing analysis stops on it).
    if yosys -q -l "$log" -p "read_verilog $f; hierarchy -top $top; proc; select -assert-none t:\$dlatch t:\$adlatch t:\$dlatchsr; $cmd" >/dev/null; then
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
    unit=$(basename "$f" .v)
    unit_flows=("${flows[@]}")
    if [[ $(basename "$(dirname "$f")") == "$unit"-* ]]; then
        unit_flows=(ecp5)
    elif [[ $all == 0 && " ${ELABORATE_ONLY[*]} " =~ " $unit " ]]; then
        unit_flows=(elaborate)
    fi
    for flow in "${unit_flows[@]}"; do
        printf '%s\0%s\0%s\0' "$f" "$flow" "$out"
    done
done | xargs -0 -n 3 -P "${SYNTH_JOBS:-$(nproc)}" bash -c 'synth_one "$@"' synth
