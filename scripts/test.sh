#!/usr/bin/env bash
# edgepaint's one test command (README, "Test"); CI's .ci/run calls exactly this.
# On a fresh Debian 12 machine it installs the pinned hardware tools, then builds and
# tests everything: formatting, lints, every Rust test (models, reference, every RTL unit
# against its model in rust-hdl's simulator and in Verilator, raster_top frames in
# Verilator, the CLI as a process), then Verilator lint of every emitted file and Yosys
# synthesis of each distinct module. One optimised build (the test profile) serves the
# tests, the lint's extra variants and the CLI tests. Each step prints its time; the long
# checks are in scripts/soak.sh. Synthesis and lint run beside the tests, so that no core
# stands idle in the tests' tails (clippy beside the build was slower: both keep two cores busy).
set -euo pipefail
cd "$(dirname "$0")/.."

start=$SECONDS
last=$SECONDS
step() {
    printf '\n== %s (after %d s)\n' "$*" $((SECONDS - start))
    last=$SECONDS
}
took() {
    printf '== took %d s\n' $((SECONDS - last))
}

step "tools"
scripts/setup-tools.sh
# shellcheck source=scripts/tools-env.sh
source scripts/tools-env.sh
took

step "format"
cargo fmt --all -- --check
# The rtl crate's units are modules declared inside its size-class macro (crates/rtl/src/lib.rs),
# which cargo fmt does not reach: rustfmt checks them by name.
find crates/rtl/src -name '*.rs' -print0 | xargs -0 rustfmt --edition 2021 --check
took

step "the tests' build, with clippy's lints (-D warnings)"
# shellcheck source=scripts/test-build-env.sh
source scripts/test-build-env.sh
cargo test --workspace --locked "${features[@]}" --no-run
took

# Beside the tests, on the core their tails leave idle: Yosys synthesis of hdl-out/ (each
# distinct module once; it needs only hdl-out/) and Verilator lint of hdl-out/ and of
# raster_top's other builds (emitted by the test build's edgepaint). Their output is shown
# once the tests are done.
step "tests, with synthesis and lint beside them"
out=${CARGO_TARGET_DIR:-target}
scripts/synth.sh >"$out/synth-step.log" 2>&1 &
synth=$!
# The test build's edgepaint holds no class 11 or 12 and no rtl::custom: those variants are
# the soak's lint, as are raster_top without cull_sort alone and without pixel_out alone (each
# 26 s of CPU; both left out is linted here; the tests run raster_top without pixel_out, the
# soak the other two).
EDGEPAINT=$out/debug/edgepaint LINT_SKIP="N11 N12 CULL_SORT=0 PIXEL_OUT=0 custom" scripts/lint.sh >"$out/lint-step.log" 2>&1 &
lint=$!
# Four test threads on the two cores: one test's Verilator build or rust-hdl simulation beside
# another's. At two, a third of the cores stood idle on cold models (the testbenches' `tests`:
# 277 s for 397 s of CPU; 185 s for 366 s at four).
RUST_TEST_THREADS=4 cargo test --workspace --locked "${features[@]}"
took

step "Verilator lint of hdl-out/ and of raster_top without cull_sort and pixel_out"
lint_ok=0
wait $lint || lint_ok=$?
cat "$out/lint-step.log"
if [[ $lint_ok -ne 0 ]]; then
    echo "lint failed (above)" >&2
    exit 1
fi
took

step "Yosys synthesis of hdl-out/ (each distinct module once; the four largest elaborated)"
synth_ok=0
wait $synth || synth_ok=$?
cat "$out/synth-step.log"
if [[ $synth_ok -ne 0 ]]; then
    echo "synthesis failed (above)" >&2
    exit 1
fi
took

printf '\n== all tests passed in %d s\n' $((SECONDS - start))
