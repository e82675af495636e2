//! The texture unit fitted to shipped workloads (`fit::texture`): what each needs of it, and
//! the narrowest knobs with which every fragment stays within the conformance tolerance.

use fit::texture::{fit_formats, needs, TexScene, TexTarget};
use scene::Scene;
use std::path::Path;
use sweep::texture::{Knob, Knobs};

fn scene(path: &str) -> TexScene {
    let p = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenes").join(path);
    let name = p.file_stem().unwrap().to_string_lossy().into_owned();
    TexScene { name, list: Scene::load(&p).unwrap().to_trilist().unwrap() }
}

#[test]
fn an_untextured_scene_needs_no_texture_unit_and_a_textured_one_what_it_samples_with() {
    let none = needs(&[scene("cube.json")]);
    assert_eq!((none.unit, none.filter, none.mip), (None, None, None));
    // Nearest filtering from a chain: the unit and its mip levels, no bilinear filter.
    let mip = needs(&[scene("textured/mip-levels.json")]);
    assert_eq!(mip.unit.as_deref(), Some("mip-levels"));
    assert_eq!(mip.filter, None);
    assert_eq!(mip.mip.as_deref(), Some("mip-levels"));
    // The crate's default sampler filters bilinearly; with the cube first, the crate is
    // named as the scene needing each part.
    let both = needs(&[scene("cube.json"), scene("textured/crate.json")]);
    assert_eq!(both.unit.as_deref(), Some("crate"));
    assert_eq!(both.filter.as_deref(), Some("crate"));
}

#[test]
fn the_fitted_knobs_pass_on_the_scene_and_each_one_bit_narrower_fails() {
    for (path, psnr) in [("textured/mip-levels.json", None), ("textured/crate.json", Some(50.0))] {
        let scenes = [scene(path)];
        let fit = fit_formats(&scenes, &TexTarget { psnr_db: psnr }).unwrap();
        let k = Knobs::of(&fit.formats);
        println!("{path}: fitted {} in {} trials; scenes {:?}", k.label(), fit.trials, fit.scenes);
        for (name, fragments, failures, p) in &fit.scenes {
            assert!(*fragments > 5_000 && *failures == 0, "{name}: {failures} of {fragments}");
            assert!(psnr.is_none_or(|t| p.is_none_or(|p| p >= t)), "{name}: {p:?}");
        }
        for knob in Knob::ALL {
            assert!(k.get(knob) <= Knobs::DEFAULT.get(knob), "{path}: {} above its default", knob.name());
        }
        for (knob, trial) in &fit.narrower {
            println!("  {} = {}: {:?}", knob.name(), trial.knobs.get(*knob), trial.miss);
            assert!(trial.miss.is_some());
        }
        assert!(k != Knobs::DEFAULT, "{path}: nothing narrower than the defaults");
    }
    // An impossible target is an error naming the miss.
    let e = fit_formats(&[scene("textured/crate.json")], &TexTarget { psnr_db: Some(90.0) }).unwrap_err();
    assert!(e.contains("default formats miss") && e.contains("PSNR"), "{e}");
}
