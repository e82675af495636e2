//! The dual-simulation harness.
