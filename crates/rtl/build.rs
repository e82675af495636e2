//! Writes `$OUT_DIR/custom.rs`: the size class and formats of `rtl::custom`, the copy of
//! the scanline units built at formats given when edgepaint is compiled.
//!
//! - `EDGEPAINT_CLASS`: the size class (8 to 12, `config::CLASS_MIN` to `CLASS_MAX`); default 10.
//! - `EDGEPAINT_FORMATS`: a JSON object of formats over the class's defaults, as
//!   `--formats FILE` takes them (e.g. `{"z": "S1.24 half-up"}`); default the file
//!   `custom-formats.json` beside this script (24-bit depth, 3 subpixel bits, colours with
//!   2 fraction bits: every width differs from the defaults, so the tests of `rtl::custom`
//!   exercise the units away from them).
//!
//! `edgepaint emit|render --formats FILE` sets both and rebuilds when the formats asked
//! for are no build's. The build is checked (`config::check`) before it is written.

#[path = "src/config.rs"]
#[allow(dead_code)]
mod config;

use fx::{Fmt, Formats};

const DEFAULT_CLASS: u32 = 10;
const DEFAULT_FORMATS: &str = "custom-formats.json";

fn main() {
    println!("cargo:rerun-if-env-changed=EDGEPAINT_CLASS");
    println!("cargo:rerun-if-env-changed=EDGEPAINT_FORMATS");
    println!("cargo:rerun-if-changed={DEFAULT_FORMATS}");
    println!("cargo:rerun-if-changed=src/config.rs");
    if let Err(e) = write() {
        eprintln!("error: rtl::custom: {e}");
        std::process::exit(1);
    }
}

fn write() -> Result<(), String> {
    let class = match std::env::var("EDGEPAINT_CLASS") {
        Ok(s) => s.trim().parse().map_err(|_| {
            format!("EDGEPAINT_CLASS = \"{s}\" is not a size class ({} to {})", config::CLASS_MIN, config::CLASS_MAX)
        })?,
        Err(_) => DEFAULT_CLASS,
    };
    let (source, text) = match std::env::var("EDGEPAINT_FORMATS") {
        Ok(s) => ("EDGEPAINT_FORMATS".to_owned(), s),
        Err(_) => (
            format!("crates/rtl/{DEFAULT_FORMATS}"),
            std::fs::read_to_string(DEFAULT_FORMATS).map_err(|e| format!("reading {DEFAULT_FORMATS}: {e}"))?,
        ),
    };
    let json: serde_json::Value = serde_json::from_str(&text).map_err(|e| format!("{source}: not JSON: {e}"))?;
    if !(config::CLASS_MIN..=config::CLASS_MAX).contains(&class) {
        return Err(format!(
            "EDGEPAINT_CLASS = {class}: size classes are {} to {}",
            config::CLASS_MIN,
            config::CLASS_MAX
        ));
    }
    let f = Formats::with_overrides_at(class, &json).map_err(|e| format!("{source}: {e}"))?;
    config::check(class, &f).map_err(|e| format!("{source}: {e}"))?;
    let fields: Vec<String> = f.named().iter().map(|(name, fmt)| format!("    {name}: {},\n", fmt_expr(fmt))).collect();
    let code = format!(
        "// Written by crates/rtl/build.rs from {source}.\n\
         /// The size class of these units.\n\
         pub const CLASS: u32 = {class};\n\
         /// The formats of these units ({source} over `Formats::for_n({class})`).\n\
         pub const FORMATS: fx::Formats = fx::Formats {{\n{}}};\n\
         /// Where the formats came from.\n\
         pub const SOURCE: &str = {source:?};\n",
        fields.concat()
    );
    let out = std::path::Path::new(&std::env::var("OUT_DIR").map_err(|e| e.to_string())?).join("custom.rs");
    std::fs::write(&out, code).map_err(|e| format!("writing {}: {e}", out.display()))
}

/// `f` as a Rust constant expression.
fn fmt_expr(f: &Fmt) -> String {
    format!(
        "fx::Fmt {{ signed: {}, int: {}, frac: {}, rounding: fx::Rounding::{:?}, overflow: fx::Overflow::{:?} }}",
        f.signed, f.int, f.frac, f.rounding, f.overflow
    )
}
