//! `fit` end to end on a small workload: the fitted design meets the target on every
//! scene, is minimal knob by knob (checked here through `accuracy::compare` directly, not
//! through the search), and beats the default design's area.

use fit::search::{fit, Objective, Search};
use fit::target::Target;
use std::collections::BTreeMap;
use std::path::PathBuf;
use sweep::area::Model;
use sweep::run::{Input, Options};

/// `scenes/<name>.json` at `w` x `h`.
fn input(name: &str, w: u32, h: u32) -> Input {
    let path = PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../../scenes")).join(format!("{name}.json"));
    Input::scene(&path, w, h).expect("a shipped scene loads")
}

/// The accuracy of `set` on `inp`, measured without the search: the formats resolved as
/// the search resolves them, the model and the reference through `accuracy::compare`.
fn measure(search: &Search, inp: &Input, set: &BTreeMap<String, u32>) -> Option<accuracy::Report> {
    let d = search.design(set).ok()?;
    rtl::config::check(d.class, &d.formats).ok()?;
    let setup = accuracy::Setup {
        method: model::render::Method::Scanline,
        formats: d.formats,
        cull_back: inp.cull_back,
        background: inp.background,
        timing: Default::default(),
    };
    Some(accuracy::compare(&inp.trilist, &setup))
}

#[test]
fn fit_meets_the_target_minimally_and_smaller_than_the_default() {
    let inputs = [input("cube", 64, 48), input("cone", 64, 48)];
    let target = Target::parse("psnr>=30,coverage_unexplained<=8,depth_order=exact").unwrap();
    let opts = Options::default();
    let fitted = fit(&inputs, &target, Objective::Area, 0, &opts).unwrap();
    assert_eq!(fitted.rows.len(), 2);
    for r in &fitted.rows {
        assert!(target.misses(r).is_empty(), "{}: {:?}", r.scene, target.misses(r));
    }
    let search = Search::new(&inputs, &target, &opts);
    // Every knob above its floor was tried one bit narrower and failed; check a few
    // of those independently.
    assert!(fitted.narrower.len() >= 3, "{:?}", fitted.narrower.iter().map(|n| &n.0).collect::<Vec<_>>());
    for (knob, trial) in fitted.narrower.iter().take(4) {
        assert!(!trial.passes(), "{knob}");
        let missed = inputs.iter().any(|inp| match measure(&search, inp, &trial.set) {
            None => true, // the RTL cannot be built there
            Some(r) => {
                r.errors.psnr_db < 30.0 || r.coverage_unexplained > 8 || r.winner_unexplained > 0 || r.problems > 0
            }
        });
        assert!(missed, "{knob} = {} one bit narrower still meets the target", trial.set[knob]);
    }
    // The objective is area: fewer gate equivalents than the default design.
    let model = Model::calibrated();
    let default = search.design(&BTreeMap::new()).unwrap();
    assert!(model.pipeline(&fitted.design).ge < 0.7 * model.pipeline(&default).ge);
}

#[test]
fn a_target_unreachable_even_wide_is_an_error_naming_the_miss() {
    let inputs = [input("cube", 64, 48)];
    let target = Target::parse("colour_max_lsb<=0,coverage_differs=0").unwrap();
    let e = fit(&inputs, &target, Objective::Area, 0, &Options::default()).unwrap_err();
    assert!(e.contains("not met even with every knob at its ceiling") && e.contains("cube: "), "{e}");
}
