//! Formats other than a size class's defaults for the RTL: which build of the scanline
//! units a command needs (`fx::Build`), and, when this edgepaint does not hold it,
//! the same command run again in an edgepaint compiled at it.
//!
//! rust-hdl's widths are compile-time constants: edgepaint holds the units at the
//! defaults of size classes 10, 11 and 12 (11 and 12 with the feature `classes-11-12`, on by
//! default) and at one more build, `rtl::custom` (the feature `custom-formats`, on by
//! default), set when it is compiled (`EDGEPAINT_CLASS`, 8 to 12, `EDGEPAINT_FORMATS`;
//! `crates/rtl/build.rs`). For any other build, [`ensure`] runs `cargo run --release` on
//! edgepaint's sources with those variables set, in a target directory of its own (`target/formats`, so the usual build
//! is not disturbed): a full build the first time, the `rtl` crate and what uses it after.

use anyhow::{bail, Context, Result};
use fx::Build;
use std::path::Path;
use std::process::Command;

/// Set in the rebuilt edgepaint's environment: it must not rebuild again.
const REBUILT: &str = "EDGEPAINT_REBUILT";

/// The build at size class `class` with the formats file `path` over its defaults
/// (`Formats::for_n(class)`, a class below 10 too), or at the defaults without a file,
/// checked for the RTL; with what names it in messages.
pub fn build_at(class: u32, path: Option<&Path>) -> Result<(Build, String)> {
    let (min, max) = (rtl::config::CLASS_MIN, rtl::config::CLASS_MAX);
    if !(min..=max).contains(&class) {
        bail!("size class N = {class} is not built: the scanline units take {min} to {max} (screens up to 2^N x 2^N)");
    }
    let Some(path) = path else {
        let build = Build::of_class(class);
        rtl::config::check(class, &build.formats).map_err(|e| anyhow::anyhow!("size class {class}: {e}"))?;
        return Ok((build, format!("size class {class}")));
    };
    let formats = fx::Formats::with_overrides_at(class, &super::engine::formats_json(path)?)
        .map_err(|e| anyhow::anyhow!("{}: {e}", path.display()))?;
    rtl::config::check(class, &formats).map_err(|e| anyhow::anyhow!("{}: {e}", path.display()))?;
    Ok((Build { class, formats }, format!("the formats of {}", path.display())))
}

/// `Ok(false)` when this edgepaint holds `build`: go on. Otherwise runs this command again
/// in an edgepaint compiled at `build` (`why` names the formats for the messages) and
/// returns `Ok(true)` when it succeeded; an error when it failed or cannot be built here.
pub fn ensure(build: &Build, why: &str) -> Result<bool> {
    if rtl::built(build) {
        return Ok(false);
    }
    if std::env::var_os(REBUILT).is_some() {
        bail!("edgepaint was rebuilt for {why} but does not hold that build: EDGEPAINT_FORMATS did not reach crates/rtl/build.rs");
    }
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let manifest = root.join("Cargo.toml");
    let formats = serde_json::to_string(&build.formats).expect("formats serialise");
    if !manifest.is_file() {
        let custom = rtl::CUSTOM.map_or(String::new(), |(class, source)| format!(" and at {source} (class {class})"));
        bail!(
            "{why}: this edgepaint holds the scanline units at the size classes' default formats{custom}; other \
             formats need them compiled: build edgepaint from its sources with EDGEPAINT_CLASS={} \
             EDGEPAINT_FORMATS='{formats}' (its sources are not at {})",
            build.class,
            root.display()
        );
    }
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let target = root.join("target").join("formats");
    eprintln!(
        "edgepaint: the scanline units are not built at {why} (class {}); compiling edgepaint at them in {} \
         (several minutes the first time, about two after), then running this command there",
        build.class,
        target.display()
    );
    let status = Command::new(&cargo)
        .args(["run", "--release", "--manifest-path"])
        .arg(&manifest)
        .arg("--target-dir")
        .arg(&target)
        .arg("--")
        .args(std::env::args_os().skip(1))
        .env("EDGEPAINT_CLASS", build.class.to_string())
        .env("EDGEPAINT_FORMATS", &formats)
        .env(REBUILT, "1")
        .status()
        .with_context(|| format!("running {}", Path::new(&cargo).display()))?;
    if !status.success() {
        bail!("edgepaint compiled at {why} failed ({status})");
    }
    Ok(true)
}
