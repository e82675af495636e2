//! The SE span backend (`model::se::array`, `edgepaint render --engine se`) on every shipped
//! scene, against the scanline model: within the rounding bound documented there.

use fx::Formats;
use model::ctx::Ctx;
use model::cull_sort::{cull_sort, z_max, Clip, Cull};
use model::edge_walk::edge_walk;
use model::input::to_fixed;
use model::render::{render, Method, Options};
use model::se::array;
use model::se::{interp::interp, mul::endpoint, SeParams};
use model::se_cmd::se_cmd;
use model::span::span;
use model::triangle_setup::triangle_setup;
use std::collections::HashMap;
use std::path::PathBuf;

fn shipped_scenes() -> Vec<PathBuf> {
    let v = scene::shipped::all().expect("the shipped scenes");
    assert!(v.len() >= 7, "expected the shipped scenes in {}", scene::shipped::dir().display());
    v
}

/// Per (triangle, pixel index): the scanline's depth and colour (None where its z clip
/// dropped the pixel) and the SE's z word and colour words (every pixel of the span on
/// screen), computed span by span from the same span commands.
type Fragments = HashMap<(u32, usize), (Option<(i128, [u8; 3])>, (i128, [i128; 3]))>;

fn fragments(list: &scene::Trilist, f: &Formats, cull: Cull, prm: &SeParams) -> Fragments {
    let clip = Clip { width: list.width, height: list.height };
    let mut out = Fragments::new();
    for (t, tri) in list.triangles.iter().enumerate() {
        let Ok(v) = to_fixed(tri, f) else { continue };
        let Ok(sorted) = cull_sort(&v, clip, cull, f) else { continue };
        let mut ctx = Ctx::new(*f);
        let setup = triangle_setup(&sorted, &mut ctx);
        for cmd in edge_walk(&setup, clip, &mut ctx).spans() {
            let row = cmd.y as usize * list.width as usize;
            let se = se_cmd(cmd, f, prm.frac);
            let (lo, hi) = (cmd.xl.max(0), cmd.xr.min(list.width as i128 - 1));
            for x in lo..=hi {
                let prm = SeParams { index: (x / prm.p as i128) as u32, ..*prm };
                let (xl, xr) = prm.region();
                let word = |j: usize| {
                    let e = |at| endpoint(se.a[j], se.b[j], at, prm.width(j), prm.frac);
                    interp(e(xl), e(xr), prm.p)[(x - xl) as usize]
                };
                out.insert((t as u32, row + x as usize), (None, (word(0), [word(1), word(2), word(3)])));
            }
            for p in span(cmd, clip, &mut ctx).pixels {
                let at = p.y as usize * list.width as usize + p.x as usize;
                out.get_mut(&(t as u32, at)).expect("scanline pixels lie in the span").0 = Some((p.z as i128, p.rgb));
            }
        }
    }
    out
}

/// Per pixel: |SE - scanline| <= 1 LSB in depth and in each colour (SE colour clamped as
/// the frame buffer takes it); where the scanline's z clip dropped a pixel, the SE's z is
/// within 1 of the clip. Per frame: where both engines drew the same triangle, depth and
/// colour within 1 LSB; where they drew different ones, a near-tie (`model::se::array`).
#[test]
fn se_renders_every_shipped_scene_within_1_lsb() {
    for path in shipped_scenes() {
        let name = path.display().to_string();
        let sc = scene::Scene::load(&path).unwrap();
        let list = sc.to_trilist().unwrap();
        let f = Formats::for_resolution(list.width, list.height);
        let cull = if sc.cull_back { Cull::Back } else { Cull::None };
        let bg = sc.background.map(|c| c.round() as u8);
        let zmax = z_max(&f);
        let prm = array::engine_params(&f);
        assert_eq!((prm.zw, prm.cw), (29, 21), "the default formats' words");

        let frags = fragments(&list, &f, cull, &prm);
        let mut differ = 0;
        for ((t, at), (scan, (z, c))) in &frags {
            let c8 = c.map(|c| c.clamp(0, 255) as u8);
            match scan {
                Some((zs, cs)) => {
                    let ok = (z - zs).abs() <= 1 && (0..3).all(|i| c8[i].abs_diff(cs[i]) <= 1);
                    assert!(ok, "{name}: triangle {t} pixel {at}: SE z {z} rgb {c8:?}, scanline z {zs} rgb {cs:?}");
                    differ += (z != zs || c8 != *cs) as u64;
                }
                None => assert!(
                    *z <= 0 || *z >= zmax,
                    "{name}: triangle {t} pixel {at}: z-clipped in the scanline model, SE z {z}"
                ),
            }
        }

        let opts = Options { method: Method::Scanline, cull, analysis: false, background: bg };
        let want = render(&list, &f, &opts, &mut |_| {}).fb;
        let got = array::render(&list, &f, cull, bg).unwrap();
        assert_eq!(got.ends_overflowed, 0, "{name}: a span's line does not fit the SE words at its region's ends");
        assert_eq!(got.engines, list.width.div_ceil(64));
        let se_z = |t: u32, at: usize| frags[&(t, at)].1 .0;
        let mut winner_differs = 0;
        for at in 0..want.depth.len() {
            let (a, b) = (want.writer[at], got.fb.writer[at]);
            let none = u32::MAX;
            if a == b {
                let dz = (want.depth[at] as i64 - got.fb.depth[at] as i64).abs();
                let dc = (0..3).map(|i| want.rgb[at][i].abs_diff(got.fb.rgb[at][i])).max().unwrap();
                assert!(dz <= 1 && dc <= 1, "{name}: pixel {at} of triangle {a}: depth {dz} LSB, colour {dc} apart");
                continue;
            }
            winner_differs += 1;
            // Near-ties (model::se::array): a depth within 1 LSB of the clip at 0 or of
            // the cleared z_max, or two triangles within 2 LSB of each other.
            let tie = match (a == none, b == none) {
                (false, true) => [0, zmax - 1].contains(&frags[&(a, at)].0.expect("drawn").0),
                (true, false) => [0, zmax - 1].contains(&se_z(b, at)),
                _ => {
                    let gap = se_z(a, at) - se_z(b, at);
                    (0..=2).contains(&gap) || frags[&(b, at)].0.is_none() && se_z(b, at) == 0
                }
            };
            assert!(tie, "{name}: pixel {at}: scanline drew triangle {a}, the SE triangle {b}: no near-tie");
        }
        let written = want.written.iter().filter(|w| **w).count();
        println!(
            "{name}: {} spans, {} engines, {} cycles ({:.1} per span), {} same-row stalls; {} fragments, {differ} differ by 1 LSB; {winner_differs} of {written} pixels drawn by another triangle",
            got.stats.spans,
            got.engines,
            got.cycles,
            got.cycles as f64 / got.stats.spans.max(1) as f64,
            got.same_row_stalls,
            frags.len()
        );
    }
}

/// Formats whose `xy` range reaches beyond the engines' 13-bit span ends (S13 on a small
/// screen) are refused with a reason, never a panic: a triangle reaching far left of such
/// a screen is clipped by the front end to x = -8192, a span end the engines cannot hold.
#[test]
fn se_refuses_xy_ranges_beyond_its_span_ends() {
    let at = |xy: &str| {
        let f = Formats { xy: xy.parse().unwrap(), ..Formats::for_resolution(256, 256) }.follow(10, fx::Given::NONE);
        f.check(256, 256).unwrap();
        f
    };
    let f = at("S13.2 half-up");
    let tri = [
        scene::Vertex::new(-65536.0, 100.25, 0.25, [255.0, 0.0, 0.0]),
        scene::Vertex::new(200.5, 20.75, 0.3, [0.0, 255.0, 0.0]),
        scene::Vertex::new(210.25, 180.5, 0.35, [0.0, 0.0, 255.0]),
    ];
    let list = scene::Trilist { width: 256, height: 256, triangles: vec![tri], textures: Vec::new() };
    let err = array::render(&list, &f, Cull::None, [0; 3]).unwrap_err();
    assert!(err.contains("span ends") && err.contains("S13.2"), "{err}");
    let f = at("S12.2 half-up");
    let r = array::render(&list, &f, Cull::None, [0; 3]).unwrap();
    assert!(r.pixels_written > 10_000, "{}", r.pixels_written);
}
