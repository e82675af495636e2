//! One module per subcommand: argument parsing and glue only.

pub mod accuracy;
pub mod calibrate;
pub mod emit;
pub mod engine;
pub mod fit;
pub mod input;
pub mod inspect;
pub mod pack;
pub mod rebuild;
pub mod render;
pub mod report;
pub mod rtl;
pub mod stability;
pub mod sweep;
pub mod trilist;
