#!/usr/bin/env bash
# edgepaint's one test command (README, "Test"); CI's .ci/run calls exactly this.
# On a fresh Debian 12 machine it installs the pinned hardware tools, then builds and
# tests everything: formatting, lints, every Rust test (models, reference, every RTL unit
# against its model in rust-hdl's simulator and in Verilator, raster_top frames in
# Verilator, the CLI as a process), then Verilator lint of every emitted file and Yosys
# synthesis of each distinct module. One optimised build (the test profile) serves the
# tests, the lint's extra variants and the CLI tests. Each step prints its time; the long
# checks are in scripts/soak.sh. Clippy runs beside the test build, and synthesis beside the
# tests, so that neither leaves a core idle.
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

step "format, lints and the test build"
cargo fmt --all -- --check
# Clippy checks in a target directory of its own, beside the tests' optimised build: the two
# share no artifacts (a check build against a code-generating one), and each alone leaves a
# core idle for long stretches (the rtl crate).
mkdir -p target
CARGO_TARGET_DIR=target/clippy cargo clippy --workspace --all-targets --locked -- -D warnings \
    >target/clippy.log 2>&1 &
clippy=$!
cargo test --workspace --locked --no-run
clippy_ok=0
wait $clippy || clippy_ok=$?
cat target/clippy.log
if [[ $clippy_ok -ne 0 ]]; then
    echo "clippy failed (above)" >&2
    exit 1
fi
took

step "tests, and Yosys synthesis of hdl-out/ beside them (each distinct module once)"
# Synthesis needs only hdl-out/: it runs on the core the tests leave idle in their tails.
scripts/synth.sh >target/synth-step.log 2>&1 &
synth=$!
cargo test --workspace --locked
took

step "Verilator lint of hdl-out/ and of raster_top's other builds"
scripts/lint.sh
took

step "waiting for the synthesis"
synth_ok=0
wait $synth || synth_ok=$?
cat target/synth-step.log
if [[ $synth_ok -ne 0 ]]; then
    echo "synthesis failed (above)" >&2
    exit 1
fi
took

printf '\n== all tests passed in %d s\n' $((SECONDS - start))
