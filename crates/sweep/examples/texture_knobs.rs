//! The texture unit's precision knobs against its error: every shipped textured scene
//! through the bit-exact unit (`accuracy::texture`) at each value of one knob, the others at
//! their defaults, judged as the conformance tests judge filtering. Writes
//! `docs/texture/knobs.png` and `.svg` (or the folder given), with Vulkan 1.0's minimums and
//! Roadmap 2022's values of `subtexel` and `lod_frac` drawn as rules, and prints a Markdown
//! table. The same points, with area, cache and frame time, are `edgepaint sweep --texture`'s
//! sensitivity points (`sweep::texture`).
//!
//! `cargo run --release -p sweep --example texture_knobs [DIR]`

use accuracy::texture::{judge, TextureSetup};
use fx::TexFormats;
use scene::{Scene, Trilist};
use std::path::PathBuf;
use sweep::chart::{draw, Chart, Pt, Series};
use sweep::texture::{rules, Knob, Knobs};
use texture::LodRule;

/// Each knob's values.
fn values(knob: Knob) -> std::ops::RangeInclusive<u32> {
    match knob {
        Knob::Subtexel | Knob::Weight => 1..=10,
        Knob::LodFrac => 1..=8,
        Knob::Recip => 8..=24,
    }
}

fn main() -> Result<(), String> {
    let dir = std::env::args().nth(1).map_or_else(|| PathBuf::from("docs/texture"), PathBuf::from);
    let paths = scene::shipped::textured().map_err(|e| e.to_string())?;
    let lists: Vec<Trilist> = paths
        .iter()
        .map(|p| Scene::load(p).and_then(|s| s.to_trilist()).map_err(|e| format!("{}: {e}", p.display())))
        .collect::<Result<_, _>>()?;
    println!("| knob | bits | fragments out of tolerance | worst error (LSB) | PSNR (dB, worst scene) |");
    println!("|---|---:|---:|---:|---:|");
    let mut series = Vec::new();
    let mut marks = Vec::new();
    for knob in Knob::ALL {
        let mut points = Vec::new();
        for bits in values(knob) {
            let formats = Knobs::DEFAULT.with(knob, bits).formats();
            let setup = TextureSetup { formats, lod: LodRule::Max, affine: false };
            let (mut pixels, mut failures, mut worst, mut psnr) = (0, 0, 0.0f64, f64::INFINITY);
            for list in &lists {
                let r = judge(list, &setup)?;
                (pixels, failures) = (pixels + r.pixels, failures + r.failures);
                worst = worst.max(r.max_error_lsb);
                psnr = psnr.min(r.psnr_db);
            }
            let percent = 100.0 * failures as f64 / pixels.max(1) as f64;
            println!("| {} | {bits} | {failures} of {pixels} ({percent:.3}%) | {worst:.2} | {psnr:.1} |", knob.name());
            let label = format!("{}={bits}", knob.name());
            if formats == TexFormats::DEFAULT {
                // One mark where two knobs' defaults coincide (subtexel and weight at 8).
                match marks.iter_mut().find(|m: &&mut Pt| (m.x, m.y) == (f64::from(bits), percent)) {
                    Some(m) => m.label = format!("{label} {}", m.label),
                    None => marks.push(Pt { x: f64::from(bits), y: percent, label: label.clone() }),
                }
            }
            points.push(Pt { x: f64::from(bits), y: percent, label });
        }
        series.push(Series { name: knob.name().to_owned(), points });
    }
    let chart = Chart {
        stem: "knobs".into(),
        // subtexel and weight give the same figures: the bilinear weights keep the fewer of
        // their bits and alpha's, so either knob alone sets the filter's resolution.
        title: "Texture unit: fragments out of conformance tolerance by knob (others at defaults)".into(),
        x_label: "bits".into(),
        y_label: "% of textured fragments out of tolerance (0 drawn at 1e-4)".into(),
        x_log: false,
        y_log: true,
        series,
        front: Vec::new(),
        marks,
        // Vulkan 1.0's minimums and Roadmap 2022's values of subtexel and lod_frac.
        rules: rules(&[Knob::Subtexel, Knob::LodFrac]),
    };
    draw(&chart, &dir)?;
    println!("\nwrote {}", dir.join("knobs.png").display());
    Ok(())
}
