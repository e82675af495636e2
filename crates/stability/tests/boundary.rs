//! The failure boundaries pinned, for each family and method at the default formats (4
//! subpixel bits half-up, a 16-bit depth buffer): a cell just inside draws correctly, a cell
//! just outside shows the documented failure. Every expectation follows from the geometry
//! and the formats (how a vertex snaps, which depths round together), not from a run.

use scene::measure::{edge_distance, inside};
use scene::Triangle;
use stability::cell::{run, Cell, FormatsPoint, Measure};
use stability::family::Family;
use stability::geometry::{depth, depth_pair};
use sweep::grid::Method;

fn at(family: Family, method: Method, x: f64, y: Option<f64>) -> Cell {
    run(family, method, &FormatsPoint::default_point(), x, y)
}

fn measured(c: &Cell) -> &Measure {
    c.measure.as_ref().unwrap_or_else(|| panic!("{:?} {:?} x = {} not run: {:?}", c.family, c.method, c.x, c.skipped))
}

fn passes(c: &Cell) -> &Measure {
    let m = measured(c);
    assert_eq!(c.failure, None, "{:?} {:?} x = {} y = {:?}: {m:?}", c.family, c.method, c.x, c.y);
    m
}

fn fails(c: &Cell) -> &Measure {
    let m = measured(c);
    assert!(c.failure.is_some(), "{:?} {:?} x = {} y = {:?} should fail: {m:?}", c.family, c.method, c.x, c.y);
    m
}

/// A needle along a row (column) of pixel centres covers every centre strictly inside,
/// L - 1 of them, in the reference. At 4 subpixel bits its base vertices, t/2 above and
/// below the axis, snap onto the axis when t/2 < 1/32 (half-up: 4.5 - 1/64 and 4.5 + 1/64
/// both round to 4.5): t = 2^-5 has zero area and draws nothing. At t = 2^-4 they snap to
/// 4.5 and 4.5 + 1/16: the axis is the snapped needle's top (left) edge, which the fill rule
/// includes, so every centre the reference covers is drawn.
#[test]
fn slivers_thinner_than_one_lsb_vanish_along_rows_and_columns() {
    for family in [Family::SliverH, Family::SliverV] {
        for m in Method::ALL {
            for l in [64.0, 1024.0] {
                let inside = passes(&at(family, m, (-4f64).exp2(), Some(l))).clone();
                assert!(inside.pixels_reference >= l as u64 - 1, "{family:?} {m:?} L = {l}: {inside:?}");
                assert_eq!((inside.holes, inside.degenerate), (0, 0), "{family:?} {m:?} L = {l}: {inside:?}");
                let outside = fails(&at(family, m, (-5f64).exp2(), Some(l))).clone();
                assert!(outside.pixels_reference >= l as u64 - 1, "{family:?} {m:?} L = {l}: {outside:?}");
                assert_eq!((outside.pixels_fixed, outside.degenerate), (0, 1), "{family:?} {m:?} L = {l}: {outside:?}");
            }
        }
    }
}

/// The needle of issue 15: 600 px long, 0.03 px thick, through a row of centres: all but its
/// tip's centre in the reference, none in any fixed-point engine at 4 subpixel bits.
#[test]
fn the_issues_needle_covers_nothing_at_four_subpixel_bits() {
    for m in Method::ALL {
        let c = fails(&at(Family::SliverH, m, 0.03, Some(600.0))).clone();
        assert!(c.pixels_reference >= 599 && c.pixels_fixed == 0, "{m:?}: {c:?}");
    }
}

/// The diagonal needle's base vertices sit t / (2 sqrt 2) off its axis in x and in y: at
/// t = 2^-4 that is 0.022 px, under half an LSB (1/32), so both snap to the axis point and the
/// needle has zero area; at t = 2^-3 (0.044 px) they snap to one LSB either side, symmetric
/// about the axis, which keeps every diagonal centre strictly inside.
#[test]
fn diagonal_slivers_vanish_below_an_lsb_times_root_two() {
    for m in Method::ALL {
        let l = 1024.0;
        let k = (l / 2f64.sqrt()).round() as u64;
        let inside = passes(&at(Family::SliverD, m, (-3f64).exp2(), Some(l))).clone();
        assert!(inside.pixels_reference >= k - 1 && inside.holes == 0, "{m:?}: {inside:?}");
        let outside = fails(&at(Family::SliverD, m, (-4f64).exp2(), Some(l))).clone();
        assert!(outside.pixels_reference >= k - 1 && outside.pixels_fixed == 0, "{m:?}: {outside:?}");
        assert_eq!(outside.degenerate, 1, "{m:?}: the needle snaps to zero area: {outside:?}");
    }
}

/// Each tiny triangle lies over one pixel centre, and one of area 1/4 or less (no angle
/// under 43 degrees, so at most 0.91 px across) over no other: the reference covers
/// exactly the 256 triangles' 256 centres. Snapping by up to 1/32 px moves the edges of a
/// triangle a few hundredths of a pixel across, so as the area falls more of the centres
/// fall outside: every difference is a documented tie (an edge within an LSB), none is
/// unexplained. At 2^-3 px^2 (0.5 px across) at most 1 in 10 differs, at 2^-4 more do; at
/// 2^-10 px^2 (0.05 px across, under one LSB) most triangles snap to a point or a segment.
#[test]
fn tiny_triangles_lose_their_pixel_below_an_eighth_of_a_pixel() {
    for m in Method::ALL {
        let inside = passes(&at(Family::Tiny, m, (-3f64).exp2(), None)).clone();
        let outside = fails(&at(Family::Tiny, m, (-4f64).exp2(), None)).clone();
        let smallest = fails(&at(Family::Tiny, m, (-10f64).exp2(), None)).clone();
        for c in [&inside, &outside, &smallest] {
            assert_eq!((c.pixels_reference, c.coverage_unexplained), (256, 0), "{m:?}: {c:?}");
        }
        assert!(10 * outside.coverage_differs > 256, "{m:?}: {outside:?}");
        assert!(4 * smallest.pixels_fixed < 256, "{m:?}: {smallest:?}");
    }
}

/// A span on whole-pixel vertices is exact in every format: coverage equal to the
/// reference's, colour and depth off by the output's rounding only, however long (4096 px,
/// the largest screen) for scanline and vector. The shading engines reach 2047 columns (their
/// multipliers' 11-bit X): a 1024-px span draws correctly, a 2048-px screen has no SE array.
#[test]
fn long_spans_keep_colour_and_depth_within_one_lsb() {
    for m in [Method::Scanline, Method::Vector] {
        let c = passes(&at(Family::Span, m, 4096.0, None)).clone();
        assert_eq!((c.pixels_fixed, c.coverage_differs), (c.pixels_reference, 0), "{m:?}: {c:?}");
    }
    let c = passes(&at(Family::Span, Method::Se, 1024.0, None)).clone();
    assert_eq!(c.pixels_fixed, c.pixels_reference, "{c:?}");
    let too_wide = at(Family::Span, Method::Se, 2048.0, None);
    assert!(too_wide.skipped.as_deref().is_some_and(|w| w.contains("no SE array")), "{too_wide:?}");
}

/// Vertices 2^16 px beyond the left and top edges, far outside the vertex format, draw what
/// the reference draws: the front end clips them to the guard band, and snapping the new
/// vertices moves an edge by at most an LSB (a documented tie). The shading engines add a
/// second rounding to the scanline pipeline's spans (README: within 1 LSB of it), so their
/// colour error stays under 1.5 LSB at every distance.
#[test]
fn far_away_vertices_draw_as_the_reference_does() {
    for d in [0.0, 65536.0] {
        let mut scanline = None;
        for m in [Method::Scanline, Method::Vector] {
            let c = passes(&at(Family::Offscreen, m, d, None)).clone();
            assert!(c.pixels_reference > 28_000 && c.coverage_differs <= 2, "{m:?} d = {d}: {c:?}");
            scanline.get_or_insert(c.pixels_fixed);
        }
        let se = measured(&at(Family::Offscreen, Method::Se, d, None)).clone();
        assert_eq!(Some(se.pixels_fixed), scanline, "se d = {d}: {se:?}");
        assert!(se.problems == 0 && se.color_max < 1.5, "se d = {d}: {se:?}");
    }
}

/// Pixel centres of a 64 x 64 screen inside both triangles, and whether any lies within
/// 10^-9 px of an edge (the fill rule would decide it).
fn overlap(a: &Triangle, b: &Triangle) -> (u64, bool) {
    let (mut n, mut on_edge) = (0, false);
    for j in 0..64 {
        for i in 0..64 {
            let (x, y) = (i as f64 + 0.5, j as f64 + 0.5);
            n += (inside(a, x, y) && inside(b, x, y)) as u64;
            on_edge |= edge_distance(a, x, y) < 1e-9 || edge_distance(b, x, y) < 1e-9;
        }
    }
    (n, on_edge)
}

/// Two constant depths a full LSB (2^-16) apart round to different buffer values whatever
/// they are (round(z + 1 LSB) = round(z) + 1), so the nearer wins wherever they overlap. Near
/// 0 the nearer sits at 2^-10 = 64 LSBs exactly and the farther 2^-18 = 1/4 LSB above rounds
/// to 64 too; near 1 the farther sits at 1 - 2^-10 exactly and the nearer 2^-17 = 1/2 LSB
/// below rounds half-up onto it. Equal depths fail LESS, so the farther triangle, drawn first,
/// keeps every pixel of the overlap: inversions = the overlap, each a documented tie.
#[test]
fn depths_closer_than_one_lsb_invert_over_the_whole_overlap() {
    let list = depth(1.0, false);
    let (n, on_edge) = overlap(&list.triangles[0], &list.triangles[1]);
    assert!(!on_edge && n > 500, "{n} {on_edge}");
    for (near_one, outside) in [(false, (-18f64).exp2()), (true, (-17f64).exp2())] {
        let y = Some(f64::from(near_one as u8));
        let (zf, zn) = depth_pair(outside, near_one);
        let buffer = |z: f64| (z * 65536.0 + 0.5).floor();
        assert_eq!(buffer(zf), buffer(zn), "the pair must round together");
        for m in Method::ALL {
            let inside = passes(&at(Family::Depth, m, (-16f64).exp2(), y)).clone();
            assert_eq!(inside.inversions, 0, "{m:?}: {inside:?}");
            let c = fails(&at(Family::Depth, m, outside, y)).clone();
            assert_eq!((c.inversions, c.inversions_unexplained), (n, 0), "{m:?} near 1 = {near_one}: {c:?}");
        }
    }
}

/// With w = 1 and 2 at the ends of edge AB, the perspective-correct colour at its midpoint
/// weights A by (1/2 / 1) / (1/2 / 1 + 1/2 / 2) = 2/3, where screen-linear interpolation
/// weights it 1/2: 1/6 of 255, 42 LSBs, between red and green there. Scanline and the shading
/// engines interpolate screen-linearly: right at w ratio 1, wrong from 2. The vector method
/// corrects with w_min / w in U1.15: exact for a ratio of 2^15 (1/w = one LSB), not for 2^16
/// (1/w = half an LSB, rounded up to a whole one: the vertex weighs twice what it should).
#[test]
fn perspective_fails_linear_methods_at_once_and_vector_past_its_inverse_w() {
    for m in [Method::Scanline, Method::Se] {
        passes(&at(Family::Perspective, m, 1.0, None));
        let c = fails(&at(Family::Perspective, m, 2.0, None)).clone();
        assert!(c.color_max > 30.0, "{m:?}: {c:?}");
    }
    passes(&at(Family::Perspective, Method::Vector, 32768.0, None));
    let c = fails(&at(Family::Perspective, Method::Vector, 65536.0, None)).clone();
    assert!(c.color_max > 1.0 && c.problems == 0, "{c:?}");
}

/// On the largest screen (4096 x 4096, 13-bit positions) the scanline and vector methods
/// still draw vertices on the 1/4-px grid and depths on multiples of 2^-12 exactly: the same
/// coverage, colour and depth within the output's rounding. The shading engines draw up to
/// 1024 columns; from 2048 there is no SE array (11-bit X, 13-bit span ends).
#[test]
fn the_largest_screen_draws_exactly_and_the_shading_engines_stop_at_1024() {
    for m in [Method::Scanline, Method::Vector] {
        let c = passes(&at(Family::Screen, m, 4096.0, None)).clone();
        assert_eq!((c.pixels_fixed, c.coverage_differs), (c.pixels_reference, 0), "{m:?}: {c:?}");
        assert!(c.color_max <= 0.51 && c.depth_max_lsb <= 0.51, "{m:?}: {c:?}");
    }
    passes(&at(Family::Screen, Method::Se, 1024.0, None));
    for s in [2048.0, 4096.0] {
        let c = at(Family::Screen, Method::Se, s, None);
        assert!(c.skipped.as_deref().is_some_and(|w| w.contains("no SE array")), "{c:?}");
    }
}

/// The densest shared-edge meshes of the map, fans and grids of 512 triangles: no hole, no
/// double hit, nothing outside, in every method (the property tests run thousands more).
#[test]
fn shared_edges_have_no_holes_and_no_double_hits() {
    for m in Method::ALL {
        for kind in [0.0, 1.0] {
            let c = passes(&at(Family::Shared, m, 512.0, Some(kind))).clone();
            assert_eq!((c.holes, c.double_hits, c.spills()), (0, Some(0), 0), "{m:?} {kind}: {c:?}");
            assert!(c.pixels_reference > 4 * 5000, "{m:?} {kind}: {c:?}");
        }
    }
}

/// The boundary moves with the formats: at 2 subpixel bits (LSB 1/4 px) a needle's base
/// vertices snap onto its axis below t = 1/4 (t/2 < 1/8), so t = 2^-3 vanishes and t = 2^-2
/// draws.
#[test]
fn two_subpixel_bits_lose_slivers_below_a_quarter_pixel() {
    let narrow = FormatsPoint { name: "xy2".into(), overrides: Some(serde_json::json!({"xy": "S11.2 half-up"})) };
    for m in Method::ALL {
        let inside = run(Family::SliverH, m, &narrow, 0.25, Some(64.0));
        assert_eq!(measured(&inside).holes, 0, "{m:?}: {inside:?}");
        let outside = run(Family::SliverH, m, &narrow, 0.125, Some(64.0));
        assert_eq!(measured(&outside).pixels_fixed, 0, "{m:?}: {outside:?}");
        assert!(outside.failure.is_some() && inside.failure.is_none());
    }
}
