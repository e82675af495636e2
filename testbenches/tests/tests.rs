//! The one test binary of the testbenches crate (see its Cargo.toml): one module per unit,
//! plus the harness's own tests.

mod ept;
mod harness;
mod se;
