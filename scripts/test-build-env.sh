# Sourced by scripts/test.sh and scripts/mutate.sh: how the test command builds, so that
# both use (and reuse) the one build.
#
# Clippy's lints come with the tests' build: clippy-driver compiles the workspace's crates
# (rustc with clippy's lints; the dependencies are compiled by rustc) as
# `cargo clippy --workspace --all-targets -- -D warnings` sets it up, so one build both
# lints every target (libraries, binaries, tests, examples; there are no benches) and makes
# the tests. A separate `cargo clippy` checked every dependency and crate a second time
# (173 s of a clean clone). The variables stay set for `cargo test`: they are part of what
# Cargo compiled with, and a run without them would build everything again.
clippy_driver=$(rustc --print sysroot)/bin/clippy-driver
[[ -x $clippy_driver ]] || clippy_driver=$(command -v clippy-driver)
export RUSTC_WORKSPACE_WRAPPER=$clippy_driver
export CLIPPY_ARGS=-D__CLIPPY_HACKERY__warnings__CLIPPY_HACKERY__
# No incremental compilation: a clean clone gains nothing from its caches, and without it
# each crate is compiled in 16 code-generation units rather than 256 (less work repeated
# across units at opt-level 3, and no cache written).
export CARGO_INCREMENTAL=0
# Without edgepaint's default features classes-11-12 and custom-formats: the copies of the
# scanline units at size classes 11 and 12 and at rtl::custom's formats, most of the rtl
# crate (the build's longest), are the soak's.
# shellcheck disable=SC2034 # used by the scripts that source this file
features=(--no-default-features)
# Verilated models' per-cycle code at -O1 rather than -O2 (crates/sim/src/verilator.rs,
# EDGEPAINT_MODEL_OPT): the test command builds some sixty models cold, and -O1 compiles a
# large one's code a third faster (raster_top's: 3.9 s against 5.8); the tests do not notice
# its halved speed. Part of each model's cache key, so these models never serve
# `render --engine rtl` outside the test command.
export EDGEPAINT_MODEL_OPT=-O1
