//! One module per subcommand: argument parsing and glue only.

pub mod emit;
pub mod input;
pub mod render;
pub mod report;
pub mod trilist;
