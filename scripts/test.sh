#!/usr/bin/env bash
# edgepaint's one test command (README, "Test"); CI's .ci/run calls exactly this.
# On a fresh Debian 12 machine it installs the pinned hardware tools, then builds
# and tests everything: formatting, lints, every Rust test (models, reference,
# RTL in rust-hdl's simulator and in Verilator, the CLI as a process), then
# Verilator lint and Yosys synthesis of every file in hdl-out/.
set -euo pipefail
cd "$(dirname "$0")/.."

step() { printf '\n== %s\n' "$*"; }

step "tools"
scripts/setup-tools.sh
# shellcheck source=scripts/tools-env.sh
source scripts/tools-env.sh

step "format and lints"
cargo fmt --all -- --check
cargo clippy --workspace --all-targets --locked -- -D warnings

step "tests"
cargo test --workspace --locked

step "Verilator lint of hdl-out/"
scripts/lint.sh

step "Yosys synthesis of hdl-out/"
scripts/synth.sh

step "all tests passed"
