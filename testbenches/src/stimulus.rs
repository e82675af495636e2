//! Triangle stimulus for the front end (`cull_sort`, `triangle_setup`) and the units it
//! feeds: the shipped scenes through the geometry stage and `model::input::to_fixed`
//! (realistic triangles), random triangles skewed toward the degenerate ones, and
//! synthetic triangles at the limits of the vertex formats. All of it in the formats the
//! RTL is built with, `Formats::for_n(RTL_CLASS)` (screens up to 1024 x 1024).

use model::cull_sort::{z_max, Clip, Cull};
use model::input::{to_fixed, Vtx};
use rand::Rng;
use rtl::widths::FORMATS;

/// One triangle as it enters `cull_sort`, with the screen and the culling it meets there.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Case {
    pub v: [Vtx; 3],
    pub clip: Clip,
    pub cull: Cull,
}

/// The triangles of shipped scene `name` (`scenes/<name>.json`) at its own resolution,
/// through the software geometry stage and `to_fixed`, each with `cull`.
pub fn scene(name: &str, cull: Cull) -> Vec<Case> {
    let path = scene::shipped::path(name);
    let tris =
        scene::Scene::load(&path).and_then(|s| s.to_trilist()).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let clip = Clip { width: tris.width, height: tris.height };
    tris.triangles
        .iter()
        .map(|t| Case { v: to_fixed(t, &FORMATS).unwrap_or_else(|e| panic!("{name}: {e}")), clip, cull })
        .collect()
}

/// Screens the random cases use: small, 003's and 001's, and the largest the RTL serves.
pub const SCREENS: [Clip; 4] = [
    Clip { width: 64, height: 48 },
    Clip { width: 320, height: 240 },
    Clip { width: 800, height: 600 },
    Clip { width: 1024, height: 1024 },
];

/// A random vertex attribute set: z over its whole format (mostly inside [0, 1]), colours
/// and `inv_w` anywhere in theirs, extremes often.
fn attrs(rng: &mut impl Rng, v: &mut Vtx) {
    let (z, one) = (FORMATS.z, 1i128 << FORMATS.z.frac);
    v.z = match rng.gen_range(0..8) {
        0 => [z.min_raw(), z.max_raw(), 0, one - 1, one, -1][rng.gen_range(0..6)],
        1 => rng.gen_range(z.min_raw()..=z.max_raw()),
        _ => rng.gen_range(0..one),
    };
    for c in &mut v.c {
        *c = if rng.gen_bool(0.2) { [0, 255][rng.gen_range(0..2)] } else { rng.gen_range(0..=255) };
    }
    v.iw = rng.gen_range(0..=FORMATS.inv_w.max_raw());
}

/// A random triangle for `clip`, skewed toward what breaks rasterizers: vertices on pixel
/// centres and on the clip planes, shared coordinates (equal y, collinear and coincident
/// vertices), tiny and huge triangles, coordinates at the limits of `xy`.
pub fn random_triangle(rng: &mut impl Rng, clip: Clip) -> [Vtx; 3] {
    let f = FORMATS.xy;
    let px = 1i128 << f.frac;
    let (w, h) = (clip.width as i128 * px, clip.height as i128 * px);
    let coord = |rng: &mut dyn rand::RngCore, size: i128| -> i128 {
        match rng.gen_range(0..10) {
            0 => rng.gen_range(f.min_raw()..=f.max_raw()),
            1 => [f.min_raw(), f.max_raw(), 0, -1, size, size + 1][rng.gen_range(0..6)],
            2 => rng.gen_range(-size / 2..size + size / 2) / px * px + px / 2,
            _ => rng.gen_range(-size / 2..size + size / 2),
        }
    };
    let mut v = [Vtx::default(); 3];
    for p in &mut v {
        p.x = coord(rng, w);
        p.y = coord(rng, h);
        attrs(rng, p);
    }
    match rng.gen_range(0..12) {
        // Two vertices on one scanline (a flat top or bottom), or all three (zero area).
        0 => v[1].y = v[0].y,
        1 => (v[1].y, v[2].y) = (v[0].y, v[0].y),
        // Coincident vertices.
        2 => (v[1].x, v[1].y) = (v[0].x, v[0].y),
        // Collinear: v2 on the line through v0 and v1.
        3 => {
            let k = rng.gen_range(-2..=2);
            v[2].x = (v[0].x + k * (v[1].x - v[0].x)).clamp(f.min_raw(), f.max_raw());
            v[2].y = (v[0].y + k * (v[1].y - v[0].y)).clamp(f.min_raw(), f.max_raw());
        }
        // Small: the others within a few subpixels of v0.
        4 | 5 => {
            for i in 1..3 {
                v[i].x = (v[0].x + rng.gen_range(-40..=40)).clamp(f.min_raw(), f.max_raw());
                v[i].y = (v[0].y + rng.gen_range(-40..=40)).clamp(f.min_raw(), f.max_raw());
            }
        }
        _ => {}
    }
    v
}

/// A random [`Case`]: a random screen, triangle and culling.
pub fn random_case(rng: &mut impl Rng) -> Case {
    let clip = SCREENS[rng.gen_range(0..SCREENS.len())];
    let cull = if rng.gen_bool(0.5) { Cull::Back } else { Cull::None };
    Case { v: random_triangle(rng, clip), clip, cull }
}

/// Synthetic triangles at the limits, each with what it is: the corners of the `xy`
/// range (the largest area, either winding), unit and zero areas, triangles outside each
/// clip plane alone and across two, vertices exactly on the planes, z and colours at their
/// limits, slivers with the steepest edges. On the largest screen, both cullings.
pub fn extremes() -> Vec<(&'static str, Case)> {
    let (f, clip) = (FORMATS.xy, Clip { width: 1024, height: 1024 });
    let (lo, hi, px) = (f.min_raw(), f.max_raw(), 1i128 << f.frac);
    let (w, h) = (clip.width as i128 * px, clip.height as i128 * px);
    let zmax = z_max(&FORMATS);
    let vtx = |x: i128, y: i128, z: i128| Vtx { x, y, z, c: [0, 128, 255], iw: FORMATS.inv_w.max_raw() };
    let tri = |p: [(i128, i128); 3], z: i128| p.map(|(x, y)| vtx(x, y, z));
    let mut out: Vec<(&'static str, [Vtx; 3])> = vec![
        ("corners of the xy range, clockwise", tri([(lo, lo), (hi, lo), (lo, hi)], 0)),
        ("corners of the xy range, counter-clockwise", tri([(lo, lo), (lo, hi), (hi, lo)], 0)),
        ("corners of the xy range, the other diagonal", tri([(hi, hi), (lo, hi), (hi, lo)], 0)),
        ("unit area (twice the area = 1)", tri([(100, 100), (101, 100), (100, 101)], 100)),
        ("unit area, other winding", tri([(100, 100), (100, 101), (101, 100)], 100)),
        ("all three vertices equal", tri([(500, 500); 3], 0)),
        ("two vertices equal", tri([(500, 500), (500, 500), (900, 40)], 0)),
        ("collinear, horizontal", tri([(10, 300), (600, 300), (90, 300)], 0)),
        ("collinear, vertical", tri([(300, 10), (300, 600), (300, 90)], 0)),
        ("collinear, diagonal", tri([(0, 0), (3200, 3200), (16, 16)], 0)),
        ("wholly left", tri([(-1, 0), (-5000, 8000), (lo, hi)], 0)),
        ("wholly right", tri([(w + 1, 0), (hi, 8000), (w + 900, hi)], 0)),
        ("wholly above", tri([(0, -1), (8000, lo), (hi, -9)], 0)),
        ("wholly below", tri([(0, h + 1), (8000, hi), (w, h + 50)], 0)),
        ("wholly near (z < 0)", tri([(0, 0), (800, 0), (0, 800)], -1)),
        ("wholly far (z > z_max)", tri([(0, 0), (800, 0), (0, 800)], zmax + 1)),
        ("left and above, but not wholly outside one plane", tri([(-160, 160), (160, -160), (-160, -160)], 0)),
        ("on the planes x = 0, x = width, y = 0, y = height", tri([(0, 0), (w, 0), (w, h)], 0)),
        ("spanning the screen and the guard band", tri([(lo, 8), (hi, 24), (40, hi)], 0)),
        ("steepest edge: dy = 1 subpixel, dx the whole range", tri([(lo, 0), (hi, 1), (0, 4000)], 0)),
        ("steep sliver crossing a pixel centre", tri([(0, 7), (30000, 9), (15, 8)], 0)),
        ("flat top on a pixel centre", tri([(8, 8), (1000, 8), (500, 900)], 0)),
        ("flat bottom on a pixel centre", tri([(500, 8), (1000, 808), (8, 808)], 0)),
        ("vertical edge through pixel centres", tri([(24, 8), (24, 1000), (900, 500)], 0)),
    ];
    let mut z_limits = tri([(40, 40), (4000, 200), (900, 3000)], 0);
    z_limits[0].z = FORMATS.z.min_raw();
    z_limits[1].z = FORMATS.z.max_raw();
    z_limits[2].z = zmax;
    z_limits[0].c = [255, 0, 255];
    z_limits[1].iw = 0;
    out.push(("z at both format limits and z_max, colours at 0 and 255", z_limits));
    out.into_iter().flat_map(|(what, v)| [Cull::None, Cull::Back].map(|cull| (what, Case { v, clip, cull }))).collect()
}

/// The shipped scenes the default build draws (size class 10), each packed into a vertex
/// buffer with back faces culled and background (9, 8, 7): the command parser's and
/// `gpu_top`'s frames. Named by path.
pub fn shipped_buffers() -> Vec<(String, model::vertex_buffer::VertexBuffer)> {
    let build = fx::Build::default();
    let mut out = Vec::new();
    for path in scene::shipped::all().expect("scenes/") {
        let list = scene::Scene::load(&path).and_then(|s| s.to_trilist()).expect("a shipped scene");
        if fx::Build::for_screen(list.width, list.height) == build {
            let (vb, _) = model::vertex_buffer::pack(&list, &build, true, [9, 8, 7]).expect("packs");
            out.push((path.display().to_string(), vb));
        }
    }
    assert!(out.len() >= 5, "shipped scenes at class 10: {}", out.len());
    out
}
