//! The textured `raster_top` (`rtl::raster_top_textured`, `raster_top` with `TEXTURE = 1`):
//! whole frames of every shipped textured scene, and of the blend modes' scene, in
//! Verilator. The triangles go in as a host sends them (`model::texture_path::sent`: the
//! input words and each one's texture words on `tex$*`), behind a framebuffer memory that
//! reads colour for blending and a texture memory of latency 10; the image and depth
//! written equal the textured scanline render's (`model::render::render_with`), and the
//! cache's hits, misses and fills those of the render's accesses.

use crate::texture_unit::{state_pins, Memory as TexMemory};
use fx::{Formats, TexFormats};
use model::blend::MODES;
use model::cull_sort::z_max;
use model::render::{render_with, Method, Options, Texturing};
use model::texture_cache::{hit_rate_of_trace, Params};
use model::texture_path::{sent, Sent};
use model::texture_unit::TextureUnit;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use rtl::raster_top_textured::RasterTopTextured;
use rtl::switch::Parts;
use rtl::texture_setup::{QB, ST};
use sim::frame::triangle_pins;
use sim::streams::as_pins;
use sim::streams::raw;
use sim::{Outputs, Sim};
use std::collections::VecDeque;
use testbenches::memory::{Memory, ReadDuringWrite, Request};
use testbenches::{seed, verilated_with, Dual, Value};
use texture::LodRule;

const F: Formats = rtl::n10::FORMATS;
const TF: TexFormats = TexFormats::DEFAULT;
const CACHE: Params = Params { sets: 64, ways: 2, line: 4 };
const DEPTH: usize = rtl::n10::widths::DEPTH;
const DIM: usize = rtl::n10::widths::DIM;
/// The default build's setup multipliers and divider stages.
const K: usize = 7;
const L: usize = model::divider::LATENCY as usize;

fn bit(b: bool) -> Value {
    Value::new(1, b.into())
}

/// Triangle `s` on the pins `inp$*` and `tex$*` (an untextured one's texture words but
/// `textured` and `mode` are left as they were).
fn triangle(s: &Sent) -> Vec<(String, Value)> {
    let mut pins = triangle_pins(&fx::Build::of_class(10), &s.v);
    let mode = MODES.iter().position(|m| *m == s.blend).unwrap() as u128;
    pins.extend([("tex$textured".to_string(), bit(s.tex.is_some())), ("tex$mode".into(), Value::new(3, mode))]);
    if let Some(t) = &s.tex {
        for (k, v) in t.v.iter().enumerate() {
            pins.push((format!("tex$sq{k}"), raw(ST, v.a[0])));
            pins.push((format!("tex$tq{k}"), raw(ST, v.a[1])));
            pins.push((format!("tex$q{k}"), raw(QB, v.a[2])));
        }
        pins.extend(
            state_pins(&t.state).into_iter().map(|(n, v)| (format!("tex${}", n.strip_prefix("st_").unwrap()), v)),
        );
    }
    pins
}

/// A frame's cycles, from the first triangle offered to `done`, and the cache's counters
/// then.
struct Drawn {
    cycles: u64,
    counters: [u64; 3],
}

/// One clock of the textured `raster_top` in some simulator: the inputs given, the outputs
/// sampled before the edge.
type Clock<'a> = dyn FnMut(&[(String, Value)]) -> Outputs + 'a;

/// The frame of `tris` on a `width` x `height` screen through `cycle`, into `fb`, the
/// textures in `tex`.
fn draw(cycle: &mut Clock, tris: &[Sent], (width, height): (u32, u32), fb: &mut Memory, tex: &mut TexMemory) -> Drawn {
    let mut rng = ChaCha8Rng::seed_from_u64(seed());
    let mut next = 0;
    for now in 0..200_000_000u64 {
        let m = tex.answer(now, &mut rng);
        let mut pins = vec![
            ("width".to_string(), Value::new(DIM, width.into())),
            ("height".into(), Value::new(DIM, height.into())),
            ("cull_back".into(), bit(false)),
            ("inp_flush".into(), bit(false)),
            ("inp$valid".into(), bit(next < tris.len())),
            ("inp_last".into(), bit(next + 1 == tris.len())),
            ("mem$ready".into(), bit(true)),
            ("mem$rd_z".into(), fb.rd_z_value(DEPTH)),
            ("mem$rd_rgb".into(), fb.rd_rgb_value()),
            ("tex_mem_ack".into(), bit(m.ack)),
            ("tex_mem_rvalid".into(), bit(m.rvalid)),
            ("tex_mem_rdata".into(), Value::new(32, m.rdata.into())),
        ];
        if let Some(s) = tris.get(next) {
            pins.extend(triangle(s));
        }
        let o = cycle(&pins);
        let get = |pin: &str| o.get(pin).to_u128() as u32;
        if get("done") == 1 && next == tris.len() {
            return Drawn { cycles: now, counters: ["hits", "misses", "fills"].map(|p| u64::from(get(p))) };
        }
        next += usize::from(next < tris.len() && get("inp$ready") == 1);
        fb.edge(true, &Request::of(&o));
        tex.ask(now, &m, get("tex_mem_valid") == 1, get("tex_mem_addr"));
    }
    panic!("raster_top (TEXTURE = 1): no done");
}

/// The outputs [`draw`] reads.
const READ: [&str; 13] = [
    "done",
    "inp$ready",
    "hits",
    "misses",
    "fills",
    "mem$rd_en",
    "mem$rd_addr",
    "mem$wr_en",
    "mem$wr_addr",
    "mem$wr_z",
    "mem$wr_rgb",
    "tex_mem_valid",
    "tex_mem_addr",
];

/// A scene's trilist, its textures in memory and its textured scanline render.
struct Scene {
    name: String,
    list: scene::Trilist,
    texturing: Texturing,
    want: model::render::Render,
}

fn scene(path: &std::path::Path, shrink: f64) -> Scene {
    let name = path.strip_prefix(scene::shipped::dir()).unwrap_or(path).display().to_string();
    let mut list = scene::Scene::load(path).unwrap().to_trilist().unwrap();
    for v in list.triangles.iter_mut().flatten() {
        (v.x, v.y) = (v.x * shrink, v.y * shrink);
    }
    assert_eq!(Formats::for_resolution(list.width, list.height), F, "{name} is of size class 10");
    let memory = model::texture_memory::TextureMemory::load(&list, LodRule::Max).unwrap();
    let texturing = Texturing { unit: TextureUnit::new(TF).unwrap(), memory, affine: false };
    let want = render_with(&list, &F, &OPTS, Some(&texturing), &mut |_| {});
    Scene { name, list, texturing, want }
}

const OPTS: Options =
    Options { method: Method::Scanline, cull: model::cull_sort::Cull::None, analysis: false, background: [20, 24, 32] };

/// `s` drawn through `cycle`: the image and depth must be the render's, the cache's counters
/// those of its accesses.
fn check(s: &Scene, cycle: &mut Clock) -> Drawn {
    let tris = sent(&s.list, &F, &s.texturing);
    let size = (s.list.width, s.list.height);
    let mut fb = Memory::new(10, 1, size, z_max(&F) as u32, OPTS.background, ReadDuringWrite::Old);
    let words = s.texturing.memory.words.clone();
    let mut tex = TexMemory { words, latency: 10, ack_chance: 1.0, queue: VecDeque::new() };
    let drawn = draw(cycle, &tris, size, &mut fb, &mut tex);
    if let Some(why) = fb.differs_from(&s.want.fb) {
        panic!("{}: {why}", s.name);
    }
    let c = hit_rate_of_trace(&CACHE, &s.want.fetches);
    assert_eq!(drawn.counters, [c.hits, c.misses, c.fills], "{}: the cache's hits, misses and fills", s.name);
    drawn
}

/// The textured scenes' triangles shrunk to an eighth (a few hundred fragments), drawn by
/// the textured `raster_top` in rust-hdl and Verilator in lockstep, every output compared
/// every cycle: the frames equal the render's.
#[test]
fn raster_top_textured_lockstep_on_small_textured_frames() {
    let vl = verilated_with("raster_top", [("TEXTURE", 1)]);
    for path in [scene::shipped::path("textured/env-modes"), scene::shipped::path("textured/mip-levels")] {
        let s = scene(&path, 0.125);
        let unit = RasterTopTextured::new(K, L, &Parts::ALL, false).unwrap();
        let mut dual = Dual::new(unit, vl.model().unwrap_or_else(|e| panic!("{e}")));
        let drawn = check(&s, &mut |pins| dual.cycle(&as_pins(pins)).unwrap_or_else(|m| panic!("{}: {m}", s.name)));
        println!(
            "raster_top TEXTURE=1 lockstep {}: {} fragments in {} cycles",
            s.name, s.want.stats.fragments, drawn.cycles
        );
    }
}

/// Every shipped textured scene and the blend modes' scene, drawn by the textured
/// `raster_top` in Verilator: image and depth equal the textured scanline render's, the
/// cache's counters those of its accesses.
#[test]
fn raster_top_textured_frames_equal_the_textured_render() {
    let vl = verilated_with("raster_top", [("TEXTURE", 1)]);
    let mut scenes = scene::shipped::textured().unwrap();
    scenes.push(scene::shipped::path("blend/blend-modes"));
    for path in scenes {
        let s = scene(&path, 1.0);
        let mut vl = vl.model().unwrap_or_else(|e| panic!("{e}"));
        let drawn = check(&s, &mut |pins| {
            for (pin, v) in pins {
                vl.set(pin, v);
            }
            vl.settle();
            let o = Outputs(READ.iter().map(|p| (p.to_string(), vl.get(p))).collect());
            vl.clock();
            o
        });
        let c = hit_rate_of_trace(&CACHE, &s.want.fetches);
        println!(
            "raster_top TEXTURE=1 {}: {} triangles, {} fragments in {} cycles ({:.3} a clock), hit rate {:.3}",
            s.name,
            sent(&s.list, &F, &s.texturing).len(),
            s.want.stats.fragments,
            drawn.cycles,
            s.want.stats.fragments as f64 / drawn.cycles as f64,
            c.hits as f64 / (c.hits + c.misses).max(1) as f64
        );
    }
}
