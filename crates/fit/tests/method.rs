//! The method `fit --method auto` chooses: each method's designs run on the workload, the
//! choice the one that best meets the objective among those that meet the target, and
//! the back ends built at one size class and one set of formats ruled out where those do
//! not serve.

use fit::method::{self, Candidate};
use fit::search::{fit, Objective};
use fit::target::Target;
use std::path::PathBuf;
use sweep::area::Model;
use sweep::grid::Method;
use sweep::run::{Input, Options};

/// `scenes/<name>.json` at `w` x `h`.
fn input(name: &str, w: u32, h: u32) -> Input {
    let path = PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../../scenes")).join(format!("{name}.json"));
    Input::scene(&path, w, h).expect("a shipped scene loads")
}

/// Every method's candidates on `inputs` for `target`, the scanline one fitted for
/// `objective`.
fn candidates(inputs: &[Input], target: &Target, objective: Objective) -> Vec<Candidate> {
    let opts = Options::default();
    let fitted = fit(inputs, target, objective, 0, &opts);
    let mut all = vec![method::scanline(&fitted, Model::calibrated())];
    all.extend(method::vector(inputs, target, &opts).unwrap());
    all.push(method::se(inputs, target, &opts).unwrap());
    all
}

fn ge(c: &Candidate) -> f64 {
    c.cost.expect("a priced candidate").0.ge
}

#[test]
fn auto_chooses_among_the_methods_by_the_objective() {
    let inputs = [input("cube", 64, 48), input("torus", 64, 48)];
    let target = Target::parse("psnr>=40,colour_max_lsb<=8,depth_order=exact,coverage_unexplained=0").unwrap();
    let area = candidates(&inputs, &target, Objective::Area);
    let labels: Vec<String> = area.iter().map(Candidate::label).collect();
    assert_eq!(labels[1..], ["vector lanes=1", "vector lanes=2", "vector lanes=4", "vector lanes=8", "se engines=1"]);
    for c in &area {
        assert!(c.passes(), "{}: {:?}", c.label(), c.misses);
        assert_eq!(c.rows.len(), 2, "{}", c.label());
    }
    // The vector unit's lanes trade area for cycles; the SE at 64 columns has one engine,
    // priced as the calibration measured it.
    let vector: Vec<&Candidate> = area.iter().filter(|c| c.method == Method::Vector).collect();
    for w in vector.windows(2) {
        assert!(w[1].cycles() < w[0].cycles(), "{} against {}", w[1].label(), w[0].label());
        assert!(ge(w[1]) > ge(w[0]), "{} against {}", w[1].label(), w[0].label());
    }
    assert_eq!(area[5].cost.unwrap(), sweep::area::se_pipeline(64).unwrap());
    // Area: the fitted scanline design, smaller than every other.
    let chosen = method::choose(&area, Objective::Area).unwrap();
    assert_eq!(chosen.method, Method::Scanline);
    assert!(area[1..].iter().all(|c| ge(c) > ge(chosen)));
    // Cycles: the fewest over every design that passes. On the torus's small triangles
    // the scanline design with a one-stage divider; on the cube's large ones the vector
    // unit at eight lanes.
    let cycles = candidates(&inputs, &target, Objective::Cycles);
    let chosen = method::choose(&cycles, Objective::Cycles).unwrap();
    assert!(cycles.iter().filter(|c| c.label() != chosen.label()).all(|c| c.cycles() > chosen.cycles()));
    let cube = candidates(&inputs[..1], &target, Objective::Cycles);
    assert_eq!(method::choose(&cube, Objective::Cycles).unwrap().label(), "vector lanes=8");
    // Time: the shortest frame at each design's clock.
    let time = candidates(&inputs, &target, Objective::Time);
    let chosen = method::choose(&time, Objective::Time).unwrap();
    let frame = |c: &Candidate| c.frame_us().expect("a clocked candidate");
    assert!(time.iter().filter(|c| c.label() != chosen.label()).all(|c| frame(c) > frame(chosen)));
    // Their product: the least of it over every design that passes.
    let product = |c: &Candidate| ge(c) * c.cycles();
    let chosen = method::choose(&cycles, Objective::AreaCycles).unwrap();
    assert!(cycles.iter().all(|c| product(c) >= product(chosen)));
}

#[test]
fn a_target_the_built_formats_miss_leaves_the_scanline_design() {
    // The back ends' default formats draw the torus up to 4.2 LSB from the reference (the
    // vector unit) and 3.6 (the SE); the fitted scanline formats reach 2.
    let inputs = [input("torus", 64, 48)];
    let target = Target::parse("colour_max_lsb<=2,depth_order=exact").unwrap();
    let all = candidates(&inputs, &target, Objective::Cycles);
    for c in &all[1..] {
        assert!(!c.passes(), "{}", c.label());
        assert!(c.misses.iter().any(|m| m.starts_with("torus: colour_max_lsb is")), "{}: {:?}", c.label(), c.misses);
    }
    assert_eq!(method::choose(&all, Objective::Cycles).unwrap().method, Method::Scanline);
}

#[test]
fn screens_beyond_the_back_ends_rule_them_out_by_name() {
    let inputs = [input("cube", 1100, 64)];
    let target = Target::parse("psnr>=30").unwrap();
    let opts = Options::default();
    for c in method::vector(&inputs, &target, &opts).unwrap() {
        assert!(!c.passes());
        assert!(c.misses.iter().any(|m| m.contains("built at size class 10")), "{}: {:?}", c.label(), c.misses);
    }
    let se = method::se(&inputs, &target, &opts).unwrap();
    assert!(se.rows.is_empty() && se.cost.is_none());
    assert!(se.misses[0].contains("none covers a screen 1100 columns wide"), "{:?}", se.misses);
    assert!(method::choose(&[se], Objective::Area).is_none());
}
