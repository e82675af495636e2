//! Every shipped scene through both fixed-point methods, against the reference.

use accuracy::{compare, Report, Setup};
use fx::Formats;
use model::cycles::Timing;
use model::render::Method;
use std::path::{Path, PathBuf};

fn shipped_scenes() -> Vec<PathBuf> {
    let v = scene::shipped::all().expect("the shipped scenes");
    assert!(v.len() >= 7, "expected the shipped scenes in {}", scene::shipped::dir().display());
    v
}

fn run(path: &Path, method: Method, wide: bool) -> Report {
    let scene = scene::Scene::load(path).unwrap();
    let list = scene.to_trilist().unwrap();
    let formats =
        if wide { Formats::wide(list.width, list.height) } else { Formats::for_resolution(list.width, list.height) };
    let setup =
        Setup { method, formats, cull_back: scene.cull_back, background: scene.background, timing: Timing::default() };
    compare(&list, &setup)
}

const METHODS: [Method; 2] = [Method::Scanline, Method::Vector { lanes: 4, perspective: true }];

#[test]
fn accuracy_wide_formats_match_the_reference_on_every_shipped_scene() {
    for path in shipped_scenes() {
        for m in METHODS {
            let r = run(&path, m, true);
            let name = format!("{} {}", path.display(), r.method);
            assert_eq!(r.problems, 0, "{name}");
            assert_eq!(r.coverage_unexplained, 0, "{name}: coverage differs beyond ties\n{}", r.table());
            assert_eq!(r.winner_unexplained, 0, "{name}: another triangle won beyond ties\n{}", r.table());
            assert!(r.errors.color_max <= 1.0, "{name}: colour beyond 1 LSB\n{}", r.table());
            assert!(r.pixels_fixed > 1000, "{name}");
        }
    }
}
