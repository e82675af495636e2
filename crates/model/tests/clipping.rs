//! Clipping without new vertices (paper 003): cull_sort rejects what lies
//! wholly outside one plane, edge_walk clips y, span clips x and z. The results
//! must equal the float reference clipped the same way (at default formats,
//! within the snapping ties), and the walks must spend no cycles where 003 says
//! they do not.

mod common;

use common::{agree, Case, Tol, METHODS};
use fx::Formats;
use model::ctx::Ctx;
use model::cull_sort::{outcode, Clip, Cull, Reject};
use model::edge_walk::{edge_walk, SpanCmd};
use model::input::to_fixed;
use model::render::{render, triangle, Dropped, Method, Options};
use model::span::span;
use model::triangle_setup::{triangle_setup, Attrs, Walk};
use scene::{Triangle, Trilist, Vertex};

const W: u32 = 80;
const H: u32 = 60;

fn tri(p: [(f64, f64, f64); 3]) -> Triangle {
    let c = [[250.0, 10.0, 40.0], [20.0, 240.0, 90.0], [60.0, 70.0, 230.0]];
    [0, 1, 2].map(|k| Vertex::new(p[k].0, p[k].1, p[k].2, c[k]))
}

/// Triangles crossing each boundary, pairs of boundaries, and the z range.
fn crossing_cases() -> Vec<(&'static str, Triangle)> {
    vec![
        ("left", tri([(-20.3, 10.2, 0.3), (30.7, 5.1, 0.5), (10.1, 50.6, 0.7)])),
        ("right", tri([(60.3, 10.2, 0.3), (101.7, 25.1, 0.5), (50.1, 50.6, 0.7)])),
        ("top", tri([(20.3, -25.2, 0.3), (60.7, 15.1, 0.5), (10.1, 40.6, 0.7)])),
        ("bottom", tri([(20.3, 25.2, 0.3), (70.7, 45.1, 0.5), (10.1, 83.6, 0.7)])),
        ("left and right", tri([(-30.3, 20.2, 0.3), (111.7, 25.1, 0.5), (40.1, 50.6, 0.7)])),
        ("top and bottom", tri([(20.3, -30.2, 0.3), (60.7, 25.1, 0.5), (30.1, 90.6, 0.7)])),
        ("all four", tri([(-40.3, -30.2, 0.3), (130.7, -10.1, 0.5), (30.1, 120.6, 0.7)])),
        ("near", tri([(5.3, 5.2, -0.4), (75.7, 15.1, 0.5), (20.1, 55.6, 0.6)])),
        ("far", tri([(5.3, 5.2, 0.4), (75.7, 15.1, 1.4), (20.1, 55.6, 0.6)])),
        ("near and far", tri([(5.3, 5.2, -0.45), (75.7, 15.1, 1.45), (20.1, 55.6, 0.6)])),
    ]
}

#[test]
fn clipping_matches_the_reference_clipped_the_same_way() {
    let f = Formats::for_resolution(W, H);
    // Default formats: vertices snap to 1/16 px, vertex colours to whole LSBs.
    let tol = Tol { tie: (-(f.xy.frac as f64)).exp2(), color: 1.0, depth: 1.0 };
    for (name, t) in crossing_cases() {
        for method in METHODS {
            agree(&Case { t: &t, size: (W, H), f: &f, method }, &tol)
                .unwrap_or_else(|e| panic!("{name} {method:?}: {e}"));
        }
    }
}

#[test]
fn clipping_cull_sort_rejects_triangles_wholly_outside_before_setup() {
    let f = Formats::for_resolution(W, H);
    let cases = [
        (outcode::LEFT, tri([(-20.0, 5.0, 0.5), (-1.0, 30.0, 0.5), (-9.0, 50.0, 0.5)])),
        (outcode::RIGHT, tri([(81.0, 5.0, 0.5), (99.0, 30.0, 0.5), (90.0, 50.0, 0.5)])),
        (outcode::TOP, tri([(5.0, -20.0, 0.5), (60.0, -1.0, 0.5), (30.0, -9.0, 0.5)])),
        (outcode::BOTTOM, tri([(5.0, 61.0, 0.5), (60.0, 90.0, 0.5), (30.0, 70.0, 0.5)])),
        (outcode::NEAR, tri([(5.0, 5.0, -0.1), (60.0, 9.0, -0.3), (30.0, 50.0, -0.2)])),
        (outcode::FAR, tri([(5.0, 5.0, 1.1), (60.0, 9.0, 1.3), (30.0, 50.0, 1.2)])),
    ];
    for (plane, t) in cases {
        for method in METHODS {
            let opts = Options { method, cull: Cull::None, analysis: false, background: [0; 3] };
            let got = triangle(&t, Clip { width: W, height: H }, &f, &opts).0;
            assert_eq!(got, Err(Dropped::Rejected(Reject::Outside(plane))), "{method:?} plane {plane:#b}");
            let r = render(
                &Trilist { width: W, height: H, triangles: vec![t], textures: Vec::new() },
                &f,
                &opts,
                &mut |_| {},
            );
            assert!(!r.work[0].passed_cull, "{method:?}: a rejected triangle must not reach setup");
            assert_eq!(r.stats.culled_outside, 1);
        }
    }
}

/// Edge walk of one triangle at default formats.
fn walk(t: &Triangle) -> (Walk, Vec<Option<SpanCmd>>) {
    let f = Formats::for_resolution(W, H);
    let clip = Clip { width: W, height: H };
    let sorted = model::cull_sort::cull_sort(&to_fixed(t, &f).unwrap(), clip, Cull::None, &f).unwrap();
    let mut ctx = Ctx::new(f);
    let s = triangle_setup(&sorted, &mut ctx);
    (s.walk, edge_walk(&s, clip, &mut ctx).scanlines)
}

#[test]
fn clipping_edge_walk_y_clip_follows_003() {
    // Crossing the top (y = 0) only: walked up from vMax, stopping after row 0:
    // rows 0..=40 walked, none above the screen.
    let (dir, rows) = walk(&tri([(20.3, -25.2, 0.3), (60.7, 15.1, 0.5), (10.1, 40.6, 0.7)]));
    assert_eq!(dir, Walk::Up);
    // (Row 40 holds only the tip of vMax at y = 40.6: walked, but its span is empty.)
    assert_eq!(rows.len(), 41, "rows 40 down to 0");
    assert_eq!(rows.iter().flatten().map(|s| s.y).min(), Some(0));
    assert_eq!(rows.last().unwrap().map(|s| s.y), Some(0), "the walk ends on row 0");
    // Crossing the bottom only: walked down from vMin (row 25), stopping after row 59.
    let (dir, rows) = walk(&tri([(20.3, 25.2, 0.3), (70.7, 45.1, 0.5), (10.1, 83.6, 0.7)]));
    assert_eq!(dir, Walk::Down);
    assert_eq!(rows.len(), 35, "rows 25 to 59");
    // Crossing both: walked down from vMin at row -30, spending 30 cycles above the
    // screen (003 accepts this), emitting only rows 0..=59.
    let (dir, rows) = walk(&tri([(20.3, -30.2, 0.3), (60.7, 25.1, 0.5), (30.1, 90.6, 0.7)]));
    assert_eq!(dir, Walk::Down);
    assert_eq!(rows.len(), 90, "rows -30 to 59");
    assert!(rows[..30].iter().all(Option::is_none));
    assert_eq!(rows.iter().flatten().count(), 60);
}

#[test]
fn clipping_span_walks_right_to_left_when_it_starts_left_of_the_screen() {
    let f = Formats::for_resolution(W, H);
    let clip = Clip { width: W, height: H };
    let at = |z: i128| Attrs { z: z << (f.z_acc.frac - f.z.frac), c: [0; 3] };
    let cmd = |xl, xr| SpanCmd { y: 3, xl, xr, left: at(1000), right: at(1000), ddx: Attrs::default() };
    let mut ctx = Ctx::new(f);
    // Starts at -7: walked from 12 down to 0, 13 cycles, pixels in decreasing x.
    let o = span(&cmd(-7, 12), clip, &mut ctx);
    assert_eq!(o.cycles, 13);
    assert_eq!(o.pixels.iter().map(|p| p.x).collect::<Vec<_>>(), (0..=12).rev().collect::<Vec<_>>());
    // Starts on screen, ends beyond it: left to right, stopping at column 79.
    let o = span(&cmd(70, 95), clip, &mut ctx);
    assert_eq!((o.cycles, o.pixels.first().map(|p| p.x), o.pixels.last().map(|p| p.x)), (10, Some(70), Some(79)));
    // Crosses both sides: walked right to left from 90, wasting the 10 cycles of 90..=81 (003).
    let o = span(&cmd(-5, 90), clip, &mut ctx);
    assert_eq!((o.cycles, o.pixels.len()), (91, 80));
    // Wholly outside: dropped in its command cycle.
    assert_eq!((span(&cmd(80, 90), clip, &mut ctx).cycles, span(&cmd(-9, -1), clip, &mut ctx).pixels.len()), (1, 0));
    // Both ends beyond the far plane: dropped.
    let far = Attrs { z: 70000 << (f.z_acc.frac - f.z.frac), c: [0; 3] };
    let o = span(&SpanCmd { y: 3, xl: 2, xr: 9, left: far, right: far, ddx: Attrs::default() }, clip, &mut ctx);
    assert_eq!((o.cycles, o.pixels.len()), (1, 0));
}

#[test]
fn clipping_vector_method_needs_no_walk_direction() {
    // The vector method clips by its bounding box: a triangle crossing all four
    // sides walks only on-screen rows and pixels.
    let f = Formats::for_resolution(W, H);
    let opts = Options {
        method: Method::Vector { lanes: 1, perspective: false },
        cull: Cull::None,
        analysis: false,
        background: [0; 3],
    };
    let t = &crossing_cases()[6].1;
    let tr = triangle(t, Clip { width: W, height: H }, &f, &opts).0.unwrap();
    assert_eq!(tr.work.vector_rows.len() as u32, H);
    assert!(tr.work.vector_rows.iter().all(|r| r.chunks <= W));
    assert_eq!(tr.work.vector_rows.iter().map(|r| r.chunks).sum::<u32>(), tr.pixels.len() as u32 + tr.z_clipped);
}
