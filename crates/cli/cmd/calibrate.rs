//! `edgepaint sweep --calibrate -o DIR`: synthesizes the area model's calibration builds
//! (`crates/sweep/area/builds.json`) with Yosys through `edgepaint report --no-pnr`, fits
//! the model (`sweep::area`) to them and reports its error on the builds held out of the
//! fit. Each (build, unit) is a run of its own in `DIR/<build>/<unit>/`, kept: an
//! interrupted calibration resumes. Writes `DIR/yosys.json` (the samples, the file the
//! sweep's model is fitted from: `--area DIR/yosys.json`, or commit it as
//! `crates/sweep/area/yosys.json`) and `DIR/area.md` (the validation).

use anyhow::{bail, Context, Result};
use std::path::Path;
use std::process::Command;
use sweep::area::{fit, Build, Sample};

pub fn run(out: &Path) -> Result<()> {
    let exe = std::env::current_exe().context("locating edgepaint")?;
    let mut samples = Vec::new();
    for build in Build::all() {
        let dir = out.join(&build.name);
        std::fs::create_dir_all(&dir).with_context(|| format!("{}: cannot create", dir.display()))?;
        let formats = dir.join("formats.json");
        std::fs::write(&formats, serde_json::to_string(&build.formats)?)
            .with_context(|| format!("{}: cannot write", formats.display()))?;
        for unit in build.units() {
            let unit_dir = dir.join(&unit);
            let report = unit_dir.join("report.json");
            if !report.is_file() {
                eprintln!("calibrate: {} {unit}", build.name);
                let mut cmd = Command::new(&exe);
                cmd.args(["report", "--no-pnr", "--unit", &unit, "--param", &format!("N={}", build.class)]);
                // K and L always (the sample's design), not the units' defaults.
                let design = build.design().map_err(anyhow::Error::msg)?;
                if matches!(unit.as_str(), "triangle_setup" | "raster_top") {
                    cmd.args(["--param", &format!("K={}", design.k)]);
                }
                if matches!(unit.as_str(), "divider" | "triangle_setup" | "raster_top") {
                    cmd.args(["--param", &format!("L={}", design.l)]);
                }
                if !build.formats.is_empty() {
                    cmd.arg("--formats").arg(&formats);
                }
                let status = cmd.arg("-o").arg(&unit_dir).status().context("running edgepaint report")?;
                if !status.success() {
                    bail!(
                        "calibration build {} failed on {unit} ({status}); its files: {}",
                        build.name,
                        unit_dir.display()
                    );
                }
            }
            let text =
                std::fs::read_to_string(&report).with_context(|| format!("{}: cannot read", report.display()))?;
            let json = serde_json::from_str(&text).with_context(|| format!("{}: malformed", report.display()))?;
            samples.push(build.sample(&unit, &json).map_err(anyhow::Error::msg)?);
        }
    }
    let model = fit(&samples).map_err(anyhow::Error::msg)?;
    let path = out.join("yosys.json");
    super::input::write(&path, "the calibration samples", samples_json(&samples).as_bytes())?;
    let md = sweep::area::validation_report(&model);
    super::input::write(&out.join("area.md"), "the area model's validation", md.as_bytes())?;
    print!("{md}");
    println!("wrote {} and {}", path.display(), out.join("area.md").display());
    Ok(())
}

/// The samples, one per line.
fn samples_json(samples: &[Sample]) -> String {
    let lines: Vec<String> =
        samples.iter().map(|s| format!("  {}", serde_json::to_string(s).expect("a sample serialises"))).collect();
    format!("[\n{}\n]\n", lines.join(",\n"))
}
