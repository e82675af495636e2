//! Overflow: default formats hold everything at the largest resolution; a
//! format too narrow is reported, and its triangle not drawn, instead of garbage.

use fx::{Fmt, Formats};
use model::ctx::Q;
use model::cull_sort::{Clip, Cull};
use model::render::{render, triangle, Dropped, Method, Options};
use scene::{Triangle, Trilist, Vertex, MAX_RESOLUTION};

const METHODS: [Method; 2] = [Method::Scanline, Method::Vector { lanes: 16, perspective: true }];

fn opts(method: Method, analysis: bool) -> Options {
    Options { method, cull: Cull::None, analysis, background: [0; 3] }
}

/// Two triangles covering the whole screen, and one larger than it, with the
/// extremes of z and colour at their corners.
fn whole_screen(n: f64) -> Vec<Triangle> {
    let v = |x, y, z, c: [f64; 3], w: f64| Vertex { w: Some(w), ..Vertex::new(x, y, z, c) };
    vec![
        [
            v(0.0, 0.0, 0.0, [0.0; 3], 1.0),
            v(n, 0.0, 1.0, [255.0, 0.0, 255.0], 8.0),
            v(0.0, n, 0.5, [0.0, 255.0, 0.0], 2.0),
        ],
        [
            v(n, 0.0, 1.0, [255.0, 0.0, 255.0], 8.0),
            v(n, n, 0.0, [255.0; 3], 1.0),
            v(0.0, n, 0.5, [0.0, 255.0, 0.0], 2.0),
        ],
        [
            v(-n / 2.0, -n / 2.0, -0.5, [255.0, 0.0, 0.0], 1.0),
            v(1.5 * n, -n / 2.0, 1.5, [0.0, 255.0, 0.0], 16.0),
            v(n / 2.0, 1.5 * n, 0.25, [0.0, 0.0, 255.0], 4.0),
        ],
    ]
}

#[test]
fn overflow_whole_screen_triangles_at_the_largest_resolution_fit_default_formats() {
    let n = MAX_RESOLUTION;
    let f = Formats::for_resolution(n, n);
    let list = Trilist { width: n, height: n, triangles: whole_screen(n as f64), textures: Vec::new() };
    // The methods side by side (each draws 16.8 million pixels twice over, 12 s).
    std::thread::scope(|s| {
        for m in METHODS {
            let (list, f) = (&list, &f);
            s.spawn(move || {
                let r = render(list, f, &opts(m, true), &mut |_| {});
                assert_eq!(r.problems, vec![], "{m:?}");
                assert_eq!(r.stats.drawn, 3, "{m:?}");
                // Stronger than harmless: no register wrapped at all.
                assert_eq!(r.stats.wrapped_harmlessly, 0, "{m:?}");
                assert_eq!(r.fb.written.iter().filter(|&&w| w).count() as u64, (n as u64) * (n as u64), "{m:?}");
            });
        }
    });
}

/// A vertex format narrower than the screen (`Formats::check` refuses it for this screen;
/// the models must still not draw garbage): the front end (`guard_band`) clips the
/// whole-screen triangles to the format's range, [-256, 256) for S8.4, and exactly the
/// pixels whose centres lie in it are drawn, correctly.
#[test]
fn overflow_narrow_vertex_format_draws_what_it_can_represent() {
    let n = MAX_RESOLUTION;
    let f = Formats { xy: Fmt::s(8, 4).half_up(), ..Formats::for_resolution(n, n) };
    let list = Trilist { width: n, height: n, triangles: whole_screen(n as f64), textures: Vec::new() };
    for m in METHODS {
        for analysis in [false, true] {
            let r = render(&list, &f, &opts(m, analysis), &mut |_| {});
            assert_eq!((r.stats.input_rejected, r.stats.clipped), (0, 3), "{m:?}");
            assert!(r.problems.is_empty(), "{m:?}: {:?}", r.problems);
            for (i, &w) in r.fb.written.iter().enumerate() {
                let (x, y) = (i as u32 % n, i as u32 / n);
                assert_eq!(w, x < 256 && y < 256, "{m:?}: pixel ({x}, {y})");
            }
        }
    }
}

#[test]
fn overflow_narrow_accumulator_is_reported_in_analysis_mode_instead_of_garbage() {
    // c_acc S7 holds [-128, 128): bright colours wrap to negative ones. (Formats::check
    // rejects this; the models still must not draw its garbage in analysis mode.)
    let base = Formats::for_resolution(64, 64);
    let f = Formats { c_acc: Fmt::s(7, base.c_acc.frac), ..base };
    let t: Triangle = [
        Vertex::new(2.0, 2.0, 0.5, [250.0, 10.0, 10.0]),
        Vertex::new(60.0, 5.0, 0.5, [240.0, 20.0, 10.0]),
        Vertex::new(8.0, 60.0, 0.5, [200.0, 30.0, 10.0]),
    ];
    let clip = Clip { width: 64, height: 64 };
    for m in METHODS {
        // The hardware draws garbage: red comes out clamped to 0.
        let hw = triangle(&t, clip, &f, &opts(m, false)).0.unwrap();
        assert!(hw.pixels.iter().any(|p| p.rgb[0] == 0), "{m:?}: the wrap should be visible in hardware mode");
        // Analysis mode reports the wrapped register and draws nothing.
        match triangle(&t, clip, &f, &opts(m, true)).0 {
            Err(Dropped::Overflow(q)) => assert!(q.contains(&Q::CAcc), "{m:?}: {q:?}"),
            other => panic!("{m:?}: expected an overflow report, got {other:?}"),
        }
        // At default formats the same triangle is fine.
        assert!(triangle(&t, clip, &base, &opts(m, true)).0.is_ok());
    }
}
