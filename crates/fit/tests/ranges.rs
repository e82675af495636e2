//! Integer bits from a workload's ranges (`fit::search::Search::ints`): what the ranges need
//! and no more, the pixels unchanged, and a scene beyond the ranges reported by the
//! analysis mode instead of drawn wrong.

use fit::search::{IntFit, Search, Set};
use fit::target::Target;
use fx::{Fmt, Formats};
use model::ctx::Q;
use model::render::{render, Dropped, Method, Options, Render};
use scene::{Trilist, Vertex};
use sweep::run::{Input, Options as RunOptions};

/// A 64 x 48 workload (size class 8, the smallest) of `tris`.
fn input(name: &str, tris: Vec<[Vertex; 3]>) -> Input {
    let trilist = Trilist { width: 64, height: 48, triangles: tris, textures: Vec::new() };
    Input { name: name.into(), key: 1, trilist, background: [0.0; 3], cull_back: false }
}

/// A small, gently shaded scene: two triangles, colours within 40 levels and depths within
/// 0.1 over 40 pixels: small gradients.
fn gentle() -> Input {
    let v = |x, y, z, c: f64| Vertex::new(x, y, z, [c, c + 10.0, c + 20.0]);
    input(
        "gentle",
        vec![
            [v(4.0, 4.0, 0.40, 100.0), v(44.0, 6.0, 0.45, 120.0), v(8.0, 40.0, 0.50, 140.0)],
            [v(44.0, 6.0, 0.45, 120.0), v(60.0, 44.0, 0.48, 110.0), v(8.0, 40.0, 0.50, 140.0)],
        ],
    )
}

/// Steep gradients on the same screen: a sliver going from black to white and from the
/// near plane to the far one across two pixels, a wide triangle with full-range colour
/// over a few pixels, and one whose depth spans [0, 1] in under half a pixel.
fn steep() -> Trilist {
    let v = |x, y, z, c: f64| Vertex::new(x, y, z, [c, 255.0 - c, c]);
    Trilist {
        width: 64,
        height: 48,
        triangles: vec![
            [v(10.0, 2.0, 0.0, 0.0), v(12.0, 2.5, 1.0, 255.0), v(30.0, 46.0, 0.5, 0.0)],
            [v(2.0, 20.0, 0.9, 255.0), v(62.0, 21.0, 0.1, 0.0), v(3.0, 23.0, 0.2, 0.0)],
            [v(40.0, 10.0, 0.0, 0.0), v(40.4, 10.2, 1.0, 0.0), v(50.0, 40.0, 0.5, 0.0)],
        ],
        textures: Vec::new(),
    }
}

fn draw(list: &Trilist, f: &Formats, analysis: bool) -> Render {
    let opts = Options { method: Method::Scanline, cull: model::cull_sort::Cull::None, analysis, background: [0; 3] };
    render(list, f, &opts, &mut |_| {})
}

fn fit_of<'a>(fits: &'a [IntFit], q: &str) -> &'a IntFit {
    fits.iter().find(|i| i.quantity == q).unwrap_or_else(|| panic!("{q} is fitted"))
}

/// The fitted integer bits hold every value the workload gives and one fewer would not
/// (where the fit is not at the floor or the default); `margin` adds to them; nothing
/// drawn changes.
#[test]
fn fitted_integer_bits_are_what_the_ranges_need() {
    let inputs = [gentle()];
    let target = Target::parse("psnr>=20").unwrap();
    let opts = RunOptions::default();
    let mut search = Search::new(&inputs, &target, &opts);
    assert_eq!(search.class, 8, "a 64 x 48 workload is size class 8, the smallest");
    let base = search.design(&Set::new()).unwrap().formats;
    assert_eq!(base, Formats::for_n(8));
    let (set, fits) = search.ints(&Set::new(), 0).unwrap();
    let ranges = search.ranges(&base);
    let mut exact = 0;
    for i in &fits {
        let q = model::ctx::Q::ALL.into_iter().find(|q| q.name() == i.quantity).unwrap();
        let (lo, hi) = ranges.get(q).expect("every fitted quantity was given values");
        let fmt = |int: u32| Fmt { int, ..q.of(&base) };
        assert_eq!(i.needed, q.of(&base).int_bits_for(lo, hi).unwrap(), "{i:?}");
        assert_eq!(i.fitted, i.needed.max(i.floor).min(i.default), "{i:?}");
        assert!(fmt(i.fitted).fits(lo) && fmt(i.fitted).fits(hi), "{}: {} bits hold the range", i.quantity, i.fitted);
        if i.fitted == i.needed && i.needed > 0 {
            exact += 1;
            let less = fmt(i.fitted - 1);
            assert!(!less.fits(lo) || !less.fits(hi), "{}: one bit fewer would still hold the range", i.quantity);
        }
    }
    assert!(exact >= 1, "some quantity is fitted to its range exactly: {fits:?}");
    // The colours of a gently shaded scene stay in [-256, 256): c_acc S8 and dc with it;
    // its gradients need far fewer bits than dz and dc keep (the RTL's floor).
    let (dz, dc, c_acc) = (fit_of(&fits, "dz"), fit_of(&fits, "dc"), fit_of(&fits, "c_acc"));
    assert_eq!((c_acc.fitted, c_acc.default), (8, 9));
    assert!(dc.fitted < dc.default && dc.needed < dc.floor && dz.needed < dz.floor, "{dz:?} {dc:?}");
    let fitted = search.design(&set).unwrap().formats;
    assert_eq!(fitted.narrowed(), ["c_acc"]);
    rtl::config::check(8, &fitted).unwrap();
    // The pixels and depths are the defaults' and nothing is reported.
    let (a, b) = (draw(&inputs[0].trilist, &base, true), draw(&inputs[0].trilist, &fitted, true));
    assert!(b.problems.is_empty() && b.stats.overflowed == 0, "{:?}", b.problems);
    assert!(a.fb == b.fb && b.stats.drawn == 2);
    // A margin of 2 bits: two more where neither bound is in the way.
    let (_, wider) = search.ints(&Set::new(), 2).unwrap();
    for (i, w) in fits.iter().zip(&wider) {
        assert_eq!(w.fitted, (i.needed + 2).max(w.floor).min(w.default), "{w:?}");
    }
    assert!(wider.iter().zip(&fits).any(|(w, i)| w.fitted > i.fitted), "{wider:?}");
}

/// A design fitted to the gentle scene, given a scene with steep gradients: the analysis
/// mode reports the overflow (`Dropped::Overflow`, naming the narrowed quantity that
/// wrapped) instead of drawing the triangle; without analysis it is drawn unreported; at the
/// default formats nothing is reported.
#[test]
fn a_scene_beyond_the_fitted_ranges_is_reported_not_drawn_wrong() {
    let inputs = [gentle()];
    let target = Target::parse("psnr>=20").unwrap();
    let opts = RunOptions::default();
    let mut search = Search::new(&inputs, &target, &opts);
    let (set, _) = search.ints(&Set::new(), 0).unwrap();
    let fitted = search.design(&set).unwrap().formats;
    let default = Formats::for_n(8);
    let list = steep();

    let at_default = draw(&list, &default, true);
    assert!(at_default.problems.is_empty() && at_default.stats.overflowed == 0, "{:?}", at_default.problems);
    assert_eq!(at_default.stats.drawn, 3);

    let at_fitted = draw(&list, &fitted, true);
    assert!(at_fitted.stats.overflowed > 0, "{:?}", at_fitted.stats);
    let reported: Vec<&Vec<Q>> = at_fitted
        .problems
        .iter()
        .filter_map(|p| match &p.why {
            Dropped::Overflow(qs) => Some(qs),
            _ => None,
        })
        .collect();
    assert_eq!(reported.len() as u64, at_fitted.stats.overflowed);
    assert!(
        reported.iter().all(|qs| qs.iter().any(|q| fitted.narrowed().contains(&q.name()))),
        "each names a narrowed quantity: {reported:?}"
    );
    // Its ranges show why: a value beyond the fitted integer bits.
    let beyond: Vec<&str> = Q::ALL
        .into_iter()
        .filter(|q| fitted.narrowed().contains(&q.name()))
        .filter(|q| at_fitted.ranges.int_bits(*q, &fitted).is_some_and(|n| n > q.of(&fitted).int))
        .map(|q| q.name())
        .collect();
    assert!(!beyond.is_empty(), "a narrowed quantity was given a value beyond its integer bits");
    // Without the analysis the same triangles are drawn, unreported: the analysis is what
    // stands between a scene beyond the fitted ranges and its pixels.
    let blind = draw(&list, &fitted, false);
    assert_eq!(blind.stats.overflowed, 0);
    assert_eq!(blind.stats.drawn, at_fitted.stats.drawn + at_fitted.stats.overflowed);
}
