//! The texture unit's stress families (`stability::texture`) at the default formats: no
//! fragment out of conformance tolerance in any cell the formats can hold, and the cells
//! they cannot hold refused with the reason instead of drawn wrong.

use fx::TexFormats;
use stability::texture::{run, TexFamily};

#[test]
fn every_texture_family_passes_the_conformance_check_at_the_default_formats() {
    let points = [("default".to_string(), TexFormats::default())];
    let cells = run(&TexFamily::ALL, &points, 0, &|| {}).unwrap();
    for c in &cells {
        println!(
            "{} {}: {} fragments, {} failures, max {:.2} LSB{}",
            c.family.name(),
            c.label,
            c.fragments,
            c.failures,
            c.max_error_lsb,
            c.refused.as_deref().map_or(String::new(), |r| format!(", refused: {r}"))
        );
        assert_ne!(c.passes(), Some(false), "{} {}: {:?}", c.family.name(), c.label, c.worst);
    }
    // Only q below U1.20's LSB is refused: w ratios of 2^21 and 2^22 at the default formats.
    let refused: Vec<(&str, &str)> =
        cells.iter().filter(|c| c.passes().is_none()).map(|c| (c.family.name(), c.label.as_str())).collect();
    assert_eq!(refused, [("tex-near-w0", "2^21"), ("tex-near-w0", "2^22")]);
    assert!(cells.iter().filter(|c| c.refused.is_some()).all(|c| c
        .refused
        .as_ref()
        .unwrap()
        .contains("below q's LSB")));
    // Every drawn cell drew something.
    assert!(cells.iter().filter(|c| c.refused.is_none()).all(|c| c.fragments > 0));
}

#[test]
fn coarse_formats_fail_where_the_defaults_pass_and_saturating_inputs_are_refused() {
    // 2 sub-texel bits: the wrap seams' bilinear cells fail.
    let coarse = TexFormats { subtexel: 2, weight: 2, ..TexFormats::default() };
    let cells = run(&[TexFamily::TexWrap], &[("coarse".into(), coarse)], 0, &|| {}).unwrap();
    assert!(cells.iter().any(|c| c.passes() == Some(false)), "{cells:?}");
    // A narrower st (S4.20: s·q up to 16) cannot hold the minified cells' coordinates.
    let narrow = TexFormats { st: fx::Fmt::s(4, 20).saturating(), ..TexFormats::default() };
    let cells = run(&[TexFamily::TexMinify], &[("narrow".into(), narrow)], 0, &|| {}).unwrap();
    let refused: Vec<&str> = cells.iter().filter(|c| c.passes().is_none()).map(|c| c.label.as_str()).collect();
    assert_eq!(refused, ["2^3", "2^4", "2^5", "2^6"]);
    assert!(cells.iter().filter_map(|c| c.refused.as_ref()).all(|r| r.contains("beyond st = S4.20")), "{cells:?}");
}
