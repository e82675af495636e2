//! The clipping front end (`model::guard_band`): triangles beyond the vertex format and
//! vertices behind the eye are clipped before conversion, so every fixed-point engine
//! draws what the float reference draws.

use fx::Formats;
use model::cull_sort::Cull;
use model::guard_band::pieces;
use model::render::{render, Method, Options};
use scene::{Triangle, Trilist, Vertex};

const METHODS: [Method; 3] =
    [Method::Scanline, Method::Vector { lanes: 4, perspective: true }, Method::Vector { lanes: 4, perspective: false }];

fn list(width: u32, height: u32, t: Triangle) -> Trilist {
    Trilist { width, height, triangles: vec![t], textures: Vec::new() }
}

/// Every engine's coverage against the reference's (`perspective`: the reference
/// interpolates with w): the pixels written by exactly one of them, and the reference's count.
fn coverage_differences(l: &Trilist, method: Method) -> (usize, usize) {
    let f = Formats::for_resolution(l.width, l.height);
    let opts = Options { method, cull: Cull::None, analysis: true, background: [0; 3] };
    let fixed = render(l, &f, &opts, &mut |_| {});
    assert!(fixed.problems.is_empty(), "{method:?}: {:?}", fixed.problems);
    let perspective = matches!(method, Method::Vector { perspective: true, .. });
    let ropts = reference::Options { ignore_w: !perspective, ..Default::default() };
    let (want, _) = reference::render(l, &ropts, &mut |_| {});
    let differ = (0..want.written.len()).filter(|&i| want.written[i] != fixed.fb.written[i]).count();
    (differ, want.written.iter().filter(|w| **w).count())
}

/// The full-screen triangle of real frames, its vertices 10,000 px away (issue 15): every
/// pixel, in every engine, with the reference's colours.
#[test]
fn guard_band_full_screen_triangle_with_far_vertices_covers_the_screen() {
    let c = [[255.0, 0.0, 0.0], [0.0, 255.0, 0.0], [0.0, 0.0, 255.0]];
    let p = [(-10000.0, 10000.0), (10000.0, 10000.0), (320.0, -10000.0)];
    let t: Triangle = std::array::from_fn(|k| Vertex::new(p[k].0, p[k].1, 0.5, c[k]));
    let l = list(640, 480, t);
    let f = Formats::for_resolution(640, 480);
    let cut = pieces(&l, &f, false);
    assert_eq!(cut.clipped, 1);
    assert!(cut.triangles.len() >= 2 && cut.source.iter().all(|&s| s == 0));
    let (reference, _) =
        reference::render(&l, &reference::Options { ignore_w: true, ..Default::default() }, &mut |_| {});
    for method in METHODS {
        assert_eq!(coverage_differences(&l, method), (0, 640 * 480), "{method:?}");
        let opts = Options { method, cull: Cull::None, analysis: true, background: [0; 3] };
        let fixed = render(&l, &f, &opts, &mut |_| {});
        assert_eq!(fixed.stats.clipped, 1);
        let rgb = reference.rgb8();
        let worst = (0..rgb.len())
            .map(|i| (0..3).map(|ch| (fixed.fb.rgb[i][ch] as i32 - rgb[i][ch] as i32).abs()).max().unwrap())
            .max()
            .unwrap();
        assert!(worst <= 1, "{method:?}: a colour {worst} LSB from the reference's");
    }
    let se = model::se::array::render(&l, &f, Cull::None, [0; 3]).unwrap();
    assert!(se.fb.written.iter().all(|w| *w), "the shading engines draw every pixel too");
    let rtl = model::raster_top::raster_top(&fx::Build::for_screen(640, 480), &l, Cull::None, [0; 3]).unwrap();
    assert!(rtl.skipped.is_empty() && rtl.triangles.len() == cut.triangles.len());
    assert!(rtl.render.fb.written.iter().all(|w| *w), "raster_top is sent the pieces");
}

/// A vertex behind the eye (w = -1): the part in front is drawn, as the reference draws it.
#[test]
fn guard_band_vertex_behind_the_eye_draws_the_part_in_front() {
    let t: Triangle = [
        Vertex { w: Some(1.0), ..Vertex::new(8.0, 6.0, 0.4, [200.0, 30.0, 30.0]) },
        Vertex { w: Some(2.0), ..Vertex::new(58.0, 12.0, 0.6, [30.0, 200.0, 30.0]) },
        Vertex { w: Some(-1.0), ..Vertex::new(20.0, 70.0, 0.5, [30.0, 30.0, 200.0]) },
    ];
    let l = list(64, 64, t);
    for method in METHODS {
        let (differ, covered) = coverage_differences(&l, method);
        assert!(covered > 100, "the reference draws the part in front: {covered} pixels");
        // Only where snapping the new vertices to 1/16 px moves an edge across a centre.
        assert!(differ <= covered / 100, "{method:?}: {differ} of {covered} pixels differ");
    }
}

/// What fits the vertex format and lies in front of the eye passes unchanged.
#[test]
fn guard_band_leaves_a_triangle_inside_untouched() {
    let t: Triangle = [
        Vertex { w: Some(3.0), ..Vertex::new(-300.0, 10.5, 0.1, [1.0, 2.0, 3.0]) },
        Vertex::new(900.25, 400.0, 0.9, [4.0, 5.0, 6.0]),
        Vertex::new(20.0, -200.0, 0.5, [7.0, 8.0, 9.0]),
    ];
    let l = list(640, 480, t);
    let cut = pieces(&l, &Formats::for_resolution(640, 480), true);
    assert_eq!((cut.triangles, cut.source, cut.clipped), (vec![t], vec![0], 0));
}

/// A textured triangle beyond the guard band: its pieces keep its texture and blend mode,
/// and every new vertex's s and t are the perspective-correct values at its place (s/w and
/// 1/w linear on screen).
#[test]
fn guard_band_pieces_carry_texture_coordinates_perspective_correct() {
    // On screen: 1/w = 0.0001 x + 0.0002 y + 1, s/w = 0.003 x - 0.001 y + 0.5,
    // t/w = 0.002 y + 0.25 (every w > 0: the 2-D clip of step 2).
    let inv_w = |x: f64, y: f64| 0.0001 * x + 0.0002 * y + 1.0;
    let (s_w, t_w) = (|x: f64, y: f64| 0.003 * x - 0.001 * y + 0.5, |_x: f64, y: f64| 0.002 * y + 0.25);
    let p = [(-3000.0, 50.0), (600.0, 20.0), (300.0, 400.0)];
    let t: Triangle = std::array::from_fn(|k| {
        let (x, y) = p[k];
        let w = 1.0 / inv_w(x, y);
        Vertex {
            w: Some(w),
            tex: Some(scene::Tex { s: s_w(x, y) * w, t: t_w(x, y) * w, texture: 0 }),
            blend: texture::BlendMode::Alpha,
            ..Vertex::new(x, y, 0.5, [9.0; 3])
        }
    });
    let f = Formats::for_resolution(640, 480);
    let cut = pieces(&list(640, 480, t), &f, false);
    assert_eq!(cut.clipped, 1);
    assert!(cut.triangles.len() >= 2);
    for v in cut.triangles.iter().flatten() {
        let tex = v.tex.expect("a piece keeps its texture");
        assert_eq!((tex.texture, v.blend), (0, texture::BlendMode::Alpha));
        let w = 1.0 / inv_w(v.x, v.y);
        assert!((v.w.unwrap() - w).abs() < 1e-12 * w, "w {} at ({}, {}), want {w}", v.w.unwrap(), v.x, v.y);
        for (got, want) in [(tex.s, s_w(v.x, v.y) * w), (tex.t, t_w(v.x, v.y) * w)] {
            assert!((got - want).abs() < 1e-12 * (1.0 + want.abs()), "({}, {}): {got} against {want}", v.x, v.y);
        }
    }
}
