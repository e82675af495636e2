//! The texture path (paper 001 §II-5: a fragment's texture coordinates from its triangle's
//! planes, then the texture unit): rust-hdl and Verilator in lockstep with
//! `model::texture_path::TexturePath`, every output compared every cycle (the fragment out
//! when `out$valid`), behind the texture unit's test memory (latency 1, 5 or 20 cycles,
//! refusing words at random), with random gaps between fragments and random output
//! backpressure. Random perspective triangles of `texture_setup`'s test (slivers, giants,
//! q near 0), each with a random texture state of `texture_unit`'s test (every format,
//! filter, mip mode, wrap, environment) or its predecessor's, and a random blend mode; their
//! fragments at random pixels in and around them. Every fragment out is also checked
//! against `TextureUnit::sample` at `texture_setup`'s planes, in order.

use crate::texture_setup::{pixel, setup, start_pins, triangle};
use crate::texture_unit::{mem_pins, random_state, request_pins, Memory, MEMORY};
use fx::{Formats, TexFormats};
use model::blend::MODES;
use model::span::Pixel;
use model::texture_cache::{MemAsk, Params};
use model::texture_path::{Fragment, PathIn, PathOut, TexTriangle, TexturePath};
use model::texture_unit::TextureUnit;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rtl::texture_path::TexturePath as Rtl;
use sim::textured::state_pins;
use std::collections::VecDeque;
use testbenches::{count, seed, verilated_with, Dual, Value};
use texture::LodRule;

const F: Formats = rtl::n10::FORMATS;
const TF: TexFormats = TexFormats::DEFAULT;
const CACHE: Params = Params { sets: 64, ways: 2, line: 4 };
const DEPTH: usize = rtl::n10::widths::DEPTH;
const SCREEN: usize = rtl::n10::widths::SCREEN;

fn bit(b: bool) -> Value {
    Value::new(1, b.into())
}

/// A triangle's fragments and the reciprocal of twice its area (a `tri$` input).
struct Tri {
    tri: TexTriangle,
    recip: model::divider::Recip,
    frags: Vec<Pixel>,
}

/// Random triangles over `memory` (their textures written into it), `n` fragments in all.
fn random_tris(rng: &mut ChaCha8Rng, memory: &mut [u32], lod: LodRule, n: usize) -> Vec<Tri> {
    let mut tris: Vec<Tri> = Vec::new();
    let mut made = 0;
    while made < n {
        let Some((v, _, recip)) = setup(&triangle(rng)) else { continue };
        // The previous triangle's state half the time: no load, no wait for idle.
        let state = match tris.last() {
            Some(t) if rng.gen() => t.tri.state,
            _ => random_state(rng, memory, lod),
        };
        let blend = MODES[rng.gen_range(0..MODES.len())];
        let frags: Vec<Pixel> = (0..rng.gen_range(1..=24))
            .map(|_| {
                let (x, y) = pixel(rng, &v);
                Pixel { x, y, z: rng.gen_range(0..1 << DEPTH), rgb: rng.gen() }
            })
            .collect();
        made += frags.len();
        tris.push(Tri { tri: TexTriangle { v, state, blend }, recip, frags });
    }
    tris
}

/// The path's input pins: the fragment, its triangle, the output's ready.
fn pins(i: &PathIn, recip: &model::divider::Recip) -> Vec<(String, Value)> {
    let (p, t) = (&i.frag.pixel, &i.frag.tri);
    let mut pins: Vec<(String, Value)> = vec![
        ("inp$valid".into(), bit(i.inp_valid)),
        ("inp$x".into(), Value::new(SCREEN, p.x.into())),
        ("inp$y".into(), Value::new(SCREEN, p.y.into())),
        ("inp$z".into(), Value::new(DEPTH, p.z.into())),
        ("inp$rgb0".into(), Value::new(8, p.rgb[0].into())),
        ("inp$rgb1".into(), Value::new(8, p.rgb[1].into())),
        ("inp$rgb2".into(), Value::new(8, p.rgb[2].into())),
        ("inp_new".into(), bit(i.frag.new)),
        ("tri_mode".into(), Value::new(3, MODES.iter().position(|m| *m == t.blend).unwrap() as u128)),
        ("inp_flush".into(), bit(i.flush)),
        ("out$ready".into(), bit(i.out_ready)),
    ];
    // texture_setup's `tri$*` are the path's; texture_unit's `st$*` are its `state$*`.
    let tri = start_pins(&t.v, recip).into_iter().filter(|(n, _)| *n != "start").map(|(n, v)| (n.to_string(), v));
    let state = state_pins(&t.state).into_iter().map(|(n, v)| (format!("state${}", n.strip_prefix("st$").unwrap()), v));
    pins.extend(tri.chain(state));
    pins
}

/// The model's outputs compared every cycle, and the fragment out with `out$valid`.
fn outputs(o: &PathOut) -> Vec<(&'static str, Value)> {
    let mut want = vec![("inp$ready", bit(o.inp_ready)), ("out$valid", bit(o.out_valid)), ("idle", bit(o.idle))];
    want.extend(request_pins(o.mem, o.counters));
    if o.out_valid {
        let p = &o.out.pixel;
        want.extend([
            ("out$x", Value::new(SCREEN, p.x.into())),
            ("out$y", Value::new(SCREEN, p.y.into())),
            ("out$z", Value::new(DEPTH, p.z.into())),
            ("out$rgb0", Value::new(8, p.rgb[0].into())),
            ("out$rgb1", Value::new(8, p.rgb[1].into())),
            ("out$rgb2", Value::new(8, p.rgb[2].into())),
            ("out$alpha", Value::new(8, o.out.alpha.into())),
            ("out$mode", Value::new(3, MODES.iter().position(|m| *m == o.out.blend).unwrap() as u128)),
        ]);
    }
    want
}

/// Random triangles through the path (level-of-detail rule `lod`) at each memory latency,
/// both simulators and the model in lockstep.
fn lockstep(lod: LodRule, salt: u64) {
    let exact = u64::from(lod == LodRule::Exact);
    let vl = verilated_with("texture_path", [("EXACT", exact)]);
    let unit = TextureUnit::new(TF).unwrap();
    for (k, latency) in [1u64, 5, 20].into_iter().enumerate() {
        let mut rng = ChaCha8Rng::seed_from_u64(seed() ^ salt ^ latency);
        let mut words: Vec<u32> = (0..MEMORY).map(|_| rng.gen()).collect();
        let tris = random_tris(&mut rng, &mut words, lod, count() / 2 + 1);
        // Every fragment's colour by `sample`, once every texture is in memory.
        let mut want = VecDeque::new();
        for t in &tris {
            let planes = model::texture_setup::texture_setup(&t.tri.v, &F, &TF).unwrap();
            for p in &t.frags {
                let c = unit.sample(&t.tri.state, &words, &planes.at(p.x, p.y), &planes.grad(), p.rgb).colour;
                want.push_back((Pixel { rgb: [c[0], c[1], c[2]], ..*p }, c[3], t.tri.blend));
            }
        }
        let total = want.len();
        let mut dual = Dual::new(Rtl::new(exact == 1), vl.model().unwrap_or_else(|e| panic!("{e}")));
        let mut model = TexturePath::new(F, TF, CACHE, lod).unwrap();
        let mut mem = Memory::new(words, latency, if k == 2 { 0.7 } else { 1.0 });
        let ready_chance = [1.0, 0.7, 0.4][k];
        let frags: Vec<(usize, usize)> =
            tris.iter().enumerate().flat_map(|(t, x)| (0..x.frags.len()).map(move |f| (t, f))).collect();
        let (mut next, mut now) = (0, 0u64);
        let limit = 300 * (total as u64 + 100);
        while !want.is_empty() {
            assert!(now < limit, "{} of {total} fragments out (seed {})", total - want.len(), seed());
            let m = mem.answer(now, &mut rng);
            let (t, f) = frags.get(next).copied().unwrap_or((0, 0));
            let i = PathIn {
                inp_valid: next < frags.len() && model.cache_running() && rng.gen_range(0..6) != 0,
                frag: Fragment { pixel: tris[t].frags[f], new: f == 0, tri: tris[t].tri },
                flush: false,
                out_ready: rng.gen_bool(ready_chance),
            };
            let mut inputs = pins(&i, &tris[t].recip);
            inputs.extend(mem_pins(&m).map(|(n, v)| (n.to_string(), v)));
            let inputs: Vec<(&str, Value)> = inputs.iter().map(|(n, v)| (n.as_str(), v.clone())).collect();
            let got = dual.cycle(&inputs).unwrap_or_else(|e| panic!("{e}"));
            let o = model.step(&i, m);
            for (pin, v) in outputs(&o) {
                dual.expect(&got, pin, &v).unwrap_or_else(|e| panic!("{e} (seed {})", seed()));
            }
            mem.ask(now, &m, o.mem);
            next += usize::from(i.inp_valid && o.inp_ready);
            if o.out_valid && i.out_ready {
                let (pixel, alpha, blend) = want.pop_front().unwrap();
                assert_eq!((o.out.pixel, o.out.alpha, o.out.blend), (pixel, alpha, blend), "seed {}", seed());
            }
            now += 1;
        }
        println!("texture_path {lod:?} latency {latency}: {} triangles, {total} fragments, {now} cycles", tris.len());
    }
}

#[test]
fn texture_path_lockstep_with_the_model_max_rule() {
    lockstep(LodRule::Max, 0x7a7);
}

#[test]
#[ignore = "long: scripts/soak.sh runs it"]
fn texture_path_lockstep_with_the_model_exact_rule() {
    lockstep(LodRule::Exact, 0x7a8);
}

/// The fragments of every textured triangle of each shipped textured scene (and of the
/// blend modes' scene) through the path in Verilator, in drawing order, behind a memory
/// holding the scene's textures (latency 10), the output always ready; the frame they make
/// with the untextured triangles' fragments (`Framebuffer::pixel_out_blended`, as the
/// blending `pixel_out` writes them) equals the textured scanline render's, image and
/// depth, and the cache's counters are those of the render's accesses.
#[test]
#[ignore = "long: scripts/soak.sh runs it"]
fn texture_path_frames_of_the_shipped_textured_scenes_equal_the_models() {
    use model::pixel_out::Framebuffer;
    use model::render::{render_with, Method, Options, Texturing};
    use model::texture_cache::hit_rate_of_trace;
    use model::texture_path::draws;
    use sim::Sim;
    let vl = verilated_with("texture_path", [("EXACT", 0)]);
    let mut scenes = scene::shipped::textured().unwrap();
    scenes.push(scene::shipped::path("blend/blend-modes"));
    for path in scenes {
        let list = scene::Scene::load(&path).unwrap().to_trilist().unwrap();
        assert_eq!(Formats::for_resolution(list.width, list.height), F, "{} is of size class 10", path.display());
        let memory = model::texture_memory::TextureMemory::load(&list, LodRule::Max).unwrap();
        let texturing = Texturing { unit: TextureUnit::new(TF).unwrap(), memory, affine: false };
        let opts =
            Options { method: Method::Scanline, cull: Default::default(), analysis: false, background: [20, 24, 32] };
        let want = render_with(&list, &F, &opts, Some(&texturing), &mut |_| {});
        let draws = draws(&list, &F, &opts, &texturing);
        let frags: Vec<(usize, usize)> = (0..draws.len())
            .filter(|&d| draws[d].tex.is_some())
            .flat_map(|d| (0..draws[d].pixels.len()).map(move |k| (d, k)))
            .collect();

        let mut vl = vl.model().unwrap_or_else(|e| panic!("{e}"));
        let mut mem = Memory::new(texturing.memory.words.clone(), 10, 1.0);
        let mut rng = ChaCha8Rng::seed_from_u64(seed());
        let (mut next, mut now, mut out) = (0, 0u64, Vec::with_capacity(frags.len()));
        let mut counters = [0u64; 3];
        while out.len() < frags.len() {
            assert!(now < 100 * frags.len() as u64 + 1000, "{}: the path hangs", path.display());
            let m = mem.answer(now, &mut rng);
            let (d, k) = frags.get(next).copied().unwrap_or(frags[0]);
            let (tri, recip) = draws[d].tex.unwrap();
            let i = PathIn {
                inp_valid: next < frags.len(),
                frag: Fragment { pixel: draws[d].pixels[k], new: k == 0, tri },
                flush: false,
                out_ready: true,
            };
            for (pin, v) in
                pins(&i, &recip).iter().map(|(n, v)| (n.as_str(), v)).chain(mem_pins(&m).iter().map(|(n, v)| (*n, v)))
            {
                vl.set(pin, v);
            }
            vl.settle();
            let got = |vl: &mut sim::verilator::VlSim, pin: &str| vl.get(pin).to_u128() as u32;
            next += usize::from(i.inp_valid && got(&mut vl, "inp$ready") == 1);
            if got(&mut vl, "out$valid") == 1 {
                let pixel = Pixel {
                    x: got(&mut vl, "out$x"),
                    y: got(&mut vl, "out$y"),
                    z: got(&mut vl, "out$z"),
                    rgb: ["out$rgb0", "out$rgb1", "out$rgb2"].map(|p| got(&mut vl, p) as u8),
                };
                out.push((pixel, got(&mut vl, "out$alpha") as u8, MODES[got(&mut vl, "out$mode") as usize]));
            }
            mem.ask(now, &m, MemAsk { valid: got(&mut vl, "mem$valid") == 1, addr: got(&mut vl, "mem$addr") });
            counters = ["counters$hits", "counters$misses", "counters$fills"].map(|p| u64::from(got(&mut vl, p)));
            vl.clock();
            now += 1;
        }

        let mut fb = Framebuffer::new(list.width, list.height, model::cull_sort::z_max(&F) as u32, opts.background);
        let mut textured = out.into_iter();
        for (k, d) in draws.iter().enumerate() {
            for p in &d.pixels {
                let (p, alpha, blend) = match d.tex {
                    Some(_) => textured.next().unwrap(),
                    None => (*p, 255, d.blend),
                };
                fb.pixel_out_blended(&p, alpha, blend, k as u32);
            }
        }
        let name = path.strip_prefix(scene::shipped::dir()).unwrap_or(&path).display();
        assert!(fb.rgb == want.fb.rgb, "{name}: the image differs from the model's");
        assert!(fb.depth == want.fb.depth, "{name}: the depth differs from the model's");
        let s = hit_rate_of_trace(&CACHE, &want.fetches);
        assert_eq!(counters, [s.hits, s.misses, s.fills], "{name}: the cache's hits, misses and fills");
        println!(
            "texture_path {name}: {} textured fragments of {} triangles in {} cycles from power-up ({:.3} a clock), hit \
             rate {:.3}",
            frags.len(),
            draws.iter().filter(|d| d.tex.is_some() && !d.pixels.is_empty()).count(),
            now,
            frags.len() as f64 / now as f64,
            s.hits as f64 / (s.hits + s.misses).max(1) as f64
        );
    }
}
