//! One module per subcommand: argument parsing and glue only.

pub mod accuracy;
pub mod emit;
pub mod engine;
pub mod input;
pub mod rebuild;
pub mod render;
pub mod report;
pub mod rtl;
pub mod sweep;
pub mod trilist;
