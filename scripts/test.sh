#!/usr/bin/env bash
# edgepaint's one test command (README, "Test"); CI's .ci/run calls exactly this.
# On a fresh Debian 12 machine it installs the pinned hardware tools, then builds and
# tests everything: formatting, lints, every Rust test (models, reference, every RTL unit
# against its model in rust-hdl's simulator and in Verilator, raster_top frames in
# Verilator, the CLI as a process), then Verilator lint of every emitted file and Yosys
# synthesis of each distinct module. One optimised build (the test profile) serves the
# tests, the lint's extra variants and the CLI tests. Each step prints its time; the long
# checks are in scripts/soak.sh.
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

step "format and lints"
cargo fmt --all -- --check
cargo clippy --workspace --all-targets --locked -- -D warnings
took

step "tests"
cargo test --workspace --locked
took

step "Verilator lint of hdl-out/ and of raster_top's other builds"
scripts/lint.sh
took

step "Yosys synthesis of hdl-out/ (each distinct module once)"
scripts/synth.sh
took

printf '\n== all tests passed in %d s\n' $((SECONDS - start))
