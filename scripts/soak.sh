#!/usr/bin/env bash
# edgepaint's long checks, beyond the test command (scripts/test.sh): run before resolving
# any issue that touches RTL (README, "Soak", gives each step's time: hours in all on 2 cores);
# each step prints its time, and everything it writes goes under target/soak/.
#
#   1. tests        the whole suite with size classes 11 and 12 and rtl::custom compiled
#                   in (the features classes-11-12 and custom-formats, which the test
#                   command leaves out: raster_top's widths at each class, the class 11/12
#                   lockstep and the class-11 scene in Verilator, raster_top's lockstep at
#                   rtl::custom's formats and the CLI's emit and render at them), plus the
#                   tests marked #[ignore] for being long:
#                   the EPT at P = 1024 exhaustively (all 1,048,576 (XL, XR) pairs) in
#                   rust-hdl and Verilator, whole shipped scenes through raster_top in
#                   rust-hdl and Verilator in lockstep (every output every cycle), and
#                   100,000 random triangles through raster_top in Verilator against the model;
#                   then raster_top's custom-formats lockstep at a class-9 build
#   2. random soak  every random test with 10x the cases (EDGEPAINT_N = 10000) and another
#                   seed (EDGEPAINT_SEED, default 2: the test command runs seed 1)
#   3. synthesis    every file in hdl-out/, each unit alone too, in all three flows,
#                   mapped to cells, raster_top's barycentric and SE back ends (in
#                   hdl-out/'s directories) by synth_ecp5 only (the test command
#                   synthesizes each distinct module once, without iCE40, and only
#                   elaborates gpu_top, se, vector and texture_path); then
#                   Verilator lint of hdl-out/ and of every raster_top
#                   variant, classes 11 and 12 and rtl::custom too (scripts/lint.sh)
#   4. P&R          place and route of every unit of the default design on iCE40 and ECP5
#                   (`edgepaint report`): area and Fmax in target/soak/report/<unit>/report.md.
#                   nextpnr's router1 for the scanline units: triangle_setup and raster_top
#                   fit the LFE5U-45F now, where router2 diverged on both (stop 54: 2,069 and
#                   1,784 wires overused at iterations 74 and 46, and rising; router1 21 and
#                   31 minutes in all; Debian's nextpnr-ice40 0.4 fails an assertion in
#                   router2 on the divider); gpu_top takes router1, on which
#                   router2 diverged (router1 routed it in 68 minutes, with other work
#                   beside it), and only in the ECP5 flow (`--flow ecp5`: no iCE40 holds
#                   it, and the generic flow makes flip-flops of its RAMs; those two took
#                   an hour); the texture units, texture_setup and texture_path take
#                   router2, and blend router1, in the generic and ECP5 flows (their
#                   multipliers fit no iCE40 HX8K; 1 to 45 minutes each at stop 45). The textured raster_top
#                   (TEXTURE=1) only when named in PNR_UNITS, router1 in ECP5: on the
#                   LFE5U-85F (58% of its LUTs, 112 of its 156 multipliers) router2 diverged
#                   (over 13,000 wires overused after 10 iterations, twice; 35 minutes
#                   each); router1 has not yet been seen to finish it
#   5. mutate       scripts/mutate.sh: one operator of the emitted Verilog of edge_walk, span
#                   and triangle_setup changed at a time; the test command's tests must fail
#
# `scripts/soak.sh STEP...` runs only the steps named (tests, random, synth, pnr, mutate);
# `PNR_UNITS="unit ..." scripts/soak.sh pnr` routes only the units named.
set -euo pipefail
cd "$(dirname "$0")/.."

steps=("$@")
[[ ${#steps[@]} -gt 0 ]] || steps=(tests random synth pnr mutate)
want() { [[ " ${steps[*]} " =~ " $1 " ]]; }
step() {
    local name=$1
    shift
    printf '\n== soak: %s\n' "$name"
    local start=$SECONDS
    "$@"
    printf '== soak: %s passed in %d s\n' "$name" $((SECONDS - start))
}

scripts/setup-tools.sh
# shellcheck source=scripts/tools-env.sh
source scripts/tools-env.sh
mkdir -p target/soak

# Every build of the units: edgepaint's default features hold classes 11 and 12 and
# rtl::custom, and the testbenches' features add their tests.
features=(--features testbenches/classes-11-12,testbenches/custom-formats)
want tests && step "tests at every class, with the long ones (#[ignore])" \
    cargo test --workspace --locked "${features[@]}" -- --include-ignored
# rtl::custom below class 10 (issue 16: `edgepaint fit` gives a 320x240 workload class 9), in a
# target directory of its own so that the other steps' builds are left alone.
want tests && step "raster_top at a class-9 custom build (EDGEPAINT_CLASS=9)" \
    env EDGEPAINT_CLASS=9 EDGEPAINT_FORMATS='{"xy": "S10.3 half-up", "z": "S1.24 half-up", "color": "U8.2 half-up saturate", "inv_w": "U1.12 half-up", "ooa": "U1.20", "ooa_d": "S28.32", "dz": "S4.40", "z_acc": "S1.40", "dc": "S12.20", "c_acc": "S9.20"}' CARGO_TARGET_DIR=target/soak/class9 \
    cargo test --locked -p testbenches --features custom-formats --test tests raster_top_custom_formats_lockstep
want random && step "random tests, EDGEPAINT_N=10000, seed ${EDGEPAINT_SEED:-2}" \
    env EDGEPAINT_N=10000 EDGEPAINT_SEED="${EDGEPAINT_SEED:-2}" cargo test --workspace --locked "${features[@]}"
want synth && step "synthesis of every file in all flows" scripts/synth.sh --all
want synth && step "lint of every raster_top variant, classes 11 and 12 too" scripts/lint.sh
# The test profile's build of edgepaint: the one the tests made.
pnr() {
    local unit router flows scenes textured=()
    # The texture cache's hit rate on every shipped textured scene, beside the units that hold it.
    for f in scenes/textured/*.json; do textured+=(--scene "$f"); done
    local all=(ept se cull_sort divider edge_walk span pixel_out pixel_bus gpu_regs command_parser triangle_queue triangle_setup
        raster_top gpu_top texture_coords texture_address texture_cache texture_filter texture_unit texture_setup texture_path
        blend)
    # PNR_UNITS="a b ..." routes only those (a run cut short goes on where it stopped), and
    # may name the textured raster_top, which the default list leaves out (above).
    local units known=("${all[@]}" raster_top-TEXTURE=1)
    read -r -a units <<<"${PNR_UNITS:-${all[*]}}"
    for unit in "${units[@]}"; do
        [[ " ${known[*]} " == *" $unit "* ]] || { echo "soak: PNR_UNITS: no unit $unit (${known[*]})" >&2; return 1; }
        if [[ $unit == raster_top-TEXTURE=1 ]]; then
            # The textured raster_top (texture_path behind the scanline units): ECP5 only, as
            # raster_top fits no iCE40.
            cargo run --profile test --locked --quiet -- report --unit raster_top --param TEXTURE=1 --router router1 \
                --flow ecp5 "${textured[@]}" -o "target/soak/report/$unit"
            continue
        fi
        router=router1
        [[ $unit == texture_* ]] && router=router2
        flows=()
        [[ $unit == gpu_top ]] && flows=(--flow ecp5)
        # edge_walk since its rework for issue 17 (+38% LUT4) fills 87% of the iCE40 HX8K's
        # logic cells with pnr_wrapper's registers, and nextpnr-ice40 0.4 finds no legal
        # placement (stop 54): the generic and ECP5 flows only.
        [[ $unit == edge_walk ]] && flows=(--flow generic --flow ecp5)
        # The texture units hold multipliers (or, the cache, RAMs the generic flow makes
        # flip-flops of) no iCE40 HX8K has: the generic flow for gate equivalents and ECP5.
        [[ $unit == texture_* || $unit == blend ]] && flows=(--flow generic --flow ecp5)
        scenes=()
        [[ $unit == texture_cache || $unit == texture_unit || $unit == texture_path ]] && scenes=("${textured[@]}")
        cargo run --profile test --locked --quiet -- report --unit "$unit" --router $router "${flows[@]}" "${scenes[@]}" \
            -o "target/soak/report/$unit"
    done
}
want pnr && step "place and route of the default design" pnr
want mutate && step "mutations of the emitted Verilog of edge_walk, span and triangle_setup" scripts/mutate.sh
printf '\n== soak: all steps passed (%s)\n' "${steps[*]}"
