//! The textured `raster_top` (`rtl::raster_top_textured`, `raster_top` with `TEXTURE = 1`):
//! whole frames of every shipped textured scene, and of the blend modes' scene, in
//! Verilator; the same scenes shrunk in rust-hdl and Verilator in lockstep, every output
//! compared every cycle. The triangles go in as a host sends them
//! (`model::texture_path::sent`: the input words and each one's texture words on `tex$*`,
//! `sim::textured`), behind a framebuffer memory that reads colour for blending and a
//! texture memory of latency 10 (refusing words at random in the lockstep); the image and
//! depth written equal the textured scanline render's (`model::render::render_with`), the
//! cache's hits, misses and fills those of the render's accesses, and the cycles and
//! counters those of the cycle model (`model::cycles::textured`).

use fx::{Formats, TexFormats};
use model::cull_sort::Cull;
use model::cycles::textured::textured_frame;
use model::cycles::Timing;
use model::render::{render_with, Method, Options, Render, Texturing};
use model::texture_cache::{hit_rate_of_trace, Params};
use model::texture_memory::ReadPort;
use model::texture_path::{sent_work, TexturePath};
use model::texture_unit::TextureUnit;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rtl::raster_top_textured::RasterTopTextured;
use rtl::switch::Parts;
use sim::streams::as_pins;
use sim::textured::{draw, Clock, TexturedOut, TexturedVl};
use testbenches::{seed, verilated_with, Dual};
use texture::LodRule;

const F: Formats = rtl::n10::FORMATS;
const TF: TexFormats = TexFormats::DEFAULT;
const CACHE: Params = Params { sets: 64, ways: 2, line: 4 };
/// The default build's setup multipliers and divider stages.
const K: usize = 7;
const L: usize = model::divider::LATENCY as usize;
const OPTS: Options = Options { method: Method::Scanline, cull: Cull::None, analysis: false, background: [20, 24, 32] };

/// A scene's trilist, its textures in memory, how it is drawn (its cull) and its textured
/// scanline render.
struct Scene {
    name: String,
    list: scene::Trilist,
    texturing: Texturing,
    opts: Options,
    want: Render,
}

/// The shipped scene at `path`, its vertices' x and y scaled by `shrink`.
fn scene(path: &std::path::Path, shrink: f64) -> Scene {
    let name = path.strip_prefix(scene::shipped::dir()).unwrap_or(path).display().to_string();
    let mut list = scene::Scene::load(path).unwrap().to_trilist().unwrap();
    for v in list.triangles.iter_mut().flatten() {
        (v.x, v.y) = (v.x * shrink, v.y * shrink);
    }
    drawn(name, list, OPTS)
}

/// `list`, named `name`, drawn under `opts`.
fn drawn(name: String, list: scene::Trilist, opts: Options) -> Scene {
    assert_eq!(Formats::for_resolution(list.width, list.height), F, "{name} is of size class 10");
    let memory = model::texture_memory::TextureMemory::load(&list, LodRule::Max).unwrap();
    let texturing = Texturing { unit: TextureUnit::new(TF).unwrap(), memory, affine: false };
    let want = render_with(&list, &F, &opts, Some(&texturing), &mut |_| {});
    Scene { name, list, texturing, opts, want }
}

/// A texture memory of latency 10 holding `s`'s textures, and whether it takes a request
/// in each cycle, asked in order from cycle 0: with probability `ack_chance`, from the
/// test's seed.
fn texture_memory(s: &Scene, ack_chance: f64) -> (ReadPort, impl FnMut(u64) -> bool) {
    let mut rng = ChaCha8Rng::seed_from_u64(seed());
    (ReadPort::new(s.texturing.memory.words.clone(), 10), move |_| ack_chance >= 1.0 || rng.gen_bool(ack_chance))
}

/// `s` drawn through `cycle` behind a texture memory acknowledging a request with
/// probability `ack_chance`: the image and depth must be the render's, the cache's
/// counters those of its accesses, the cycles and counters those of the cycle model
/// (`model::cycles::textured`) behind the same memory.
fn check(s: &Scene, cycle: &mut Clock, ack_chance: f64) -> TexturedOut {
    let work = sent_work(&s.list, &F, &s.opts, Some(&s.texturing));
    let tris: Vec<_> = work.iter().map(|w| w.sent).collect();
    let (mut tex, mut ack) = texture_memory(s, ack_chance);
    let size = (s.list.width, s.list.height);
    let cull_back = s.opts.cull == Cull::Back;
    let drawn = draw(cycle, &tris, size, s.opts.background, cull_back, &mut tex, &mut ack, 10_000_000)
        .unwrap_or_else(|e| panic!("{}: {e}", s.name));
    if let Some(why) = drawn.memory.differs_from(&s.want.fb) {
        panic!("{}: {why}", s.name);
    }
    let c = hit_rate_of_trace(&CACHE, &s.want.fetches);
    assert_eq!(drawn.counters, [c.hits, c.misses, c.fills], "{}: the cache's hits, misses and fills", s.name);
    let path = TexturePath::new(F, TF, CACHE, LodRule::Max).unwrap();
    let (mut tex, mut ack) = texture_memory(s, ack_chance);
    let model = textured_frame(&work, &Timing::default(), path, &mut tex, &mut ack, &|_| true);
    assert_eq!((drawn.cycles, drawn.counters), (model.frame.total, model.counters), "{}: cycles, counters", s.name);
    drawn
}

/// The textured scenes with their triangles shrunk to an eighth (a few hundred fragments),
/// and a textured triangle of the blend modes' scene followed by 40 tiny ones, most of them
/// back faces (the texture words' 16 slots fill and their index wraps while the first is
/// walked), drawn by the textured `raster_top` in rust-hdl and Verilator in lockstep, every
/// output compared every cycle, behind a texture memory that refuses three requests in
/// ten: the frames equal the render's.
#[test]
fn raster_top_textured_lockstep_on_small_textured_frames() {
    let vl = verilated_with("raster_top", [("TEXTURE", 1)]);
    let mut scenes: Vec<Scene> =
        ["textured/env-modes", "textured/mip-levels"].map(|p| scene(&scene::shipped::path(p), 0.125)).into();
    let base = blend_modes();
    let mut rng = ChaCha8Rng::seed_from_u64(seed());
    let mut list = mix(&mut rng, &base, 41, 32.0, 0.8);
    let first = base.triangles.iter().find(|t| t[0].tex.is_some()).unwrap();
    list.triangles[0] = first.map(|v| scene::Vertex { x: 200.0 + v.x / 8.0, y: 40.0 + v.y / 8.0, ..v });
    scenes.push(drawn("a walk and 40 tiny triangles".into(), list, Options { cull: Cull::Back, ..OPTS }));
    for s in scenes {
        let unit = RasterTopTextured::new(K, L, &Parts::ALL, false).unwrap();
        let mut dual = Dual::new(unit, vl.model().unwrap_or_else(|e| panic!("{e}")));
        let drawn = check(&s, &mut |pins| dual.cycle(&as_pins(pins)).map_err(|m| m.to_string()), 0.7);
        println!(
            "raster_top TEXTURE=1 lockstep {}: {} fragments in {} cycles",
            s.name, s.want.stats.fragments, drawn.cycles
        );
    }
}

/// The blend modes' scene's trilist (textured and untextured triangles, every blend mode).
fn blend_modes() -> scene::Trilist {
    scene::Scene::load(&scene::shipped::path("blend/blend-modes")).unwrap().to_trilist().unwrap()
}

/// `n` of `base`'s triangles at random, each shrunk about its centroid to between 1/64 and
/// 1/`largest` of its size and moved anywhere on the screen (or partly off it); wound
/// backwards with probability `backwards`, and a third of them with the texture taken away.
fn mix(rng: &mut ChaCha8Rng, base: &scene::Trilist, n: usize, largest: f64, backwards: f64) -> scene::Trilist {
    let (w, h) = (base.width as f64, base.height as f64);
    let triangles = (0..n)
        .map(|_| {
            let mut t = base.triangles[rng.gen_range(0..base.triangles.len())];
            let (cx, cy) = ((t[0].x + t[1].x + t[2].x) / 3.0, (t[0].y + t[1].y + t[2].y) / 3.0);
            let scale = 1.0 / rng.gen_range(largest..64.0);
            let (tx, ty) = (rng.gen_range(-16.0..w + 16.0), rng.gen_range(-16.0..h + 16.0));
            for v in &mut t {
                (v.x, v.y) = (tx + (v.x - cx) * scale, ty + (v.y - cy) * scale);
            }
            if rng.gen_bool(backwards) {
                t.swap(1, 2);
            }
            if rng.gen_bool(1.0 / 3.0) {
                t.iter_mut().for_each(|v| v.tex = None);
            }
            t
        })
        .collect();
    scene::Trilist { triangles, ..base.clone() }
}

/// The blend modes' scene's triangles (textured and not, blending and not) drawn 400 at a
/// time at random: each shrunk about its centroid to between 1/64 and 1/4 of its size and
/// moved anywhere on the screen (or partly off it), a third wound backwards and culled as
/// back faces, a third with its texture taken away; in Verilator behind a texture memory
/// that refuses three requests in ten. The many small and culled triangles fill the
/// texture words' slots (15 in use at most) behind the walks, and untextured triangles
/// wait for the texture path to empty: the frames equal the render's, the cycles and the
/// cache's counters the cycle model's.
#[test]
fn raster_top_textured_random_mixes_of_textured_untextured_and_culled_triangles() {
    let base = blend_modes();
    let mut rng = ChaCha8Rng::seed_from_u64(seed());
    let mut vl = TexturedVl::new(false).unwrap_or_else(|e| panic!("{e}"));
    for frame in 0..2 {
        let list = mix(&mut rng, &base, 400, 4.0, 1.0 / 3.0);
        let s = drawn(format!("random frame {frame}"), list, Options { cull: Cull::Back, ..OPTS });
        let out = check(&s, &mut |pins| vl.cycle(pins), 0.7);
        println!(
            "raster_top TEXTURE=1 {}: {} fragments in {} cycles, {} culled",
            s.name, s.want.stats.fragments, out.cycles, s.want.stats.culled_back
        );
        assert!(s.want.stats.culled_back > 50 && s.want.stats.fragments > 1000, "{}: a mix worth drawing", s.name);
        vl = TexturedVl::new(false).unwrap_or_else(|e| panic!("{e}"));
    }
}

/// Every shipped textured scene and the blend modes' scene, drawn by the textured
/// `raster_top` in Verilator: image and depth equal the textured scanline render's, the
/// cache's counters those of its accesses.
#[test]
#[ignore = "long: scripts/soak.sh runs it"]
fn raster_top_textured_frames_equal_the_textured_render() {
    let mut scenes = scene::shipped::textured().unwrap();
    scenes.push(scene::shipped::path("blend/blend-modes"));
    for path in scenes {
        let s = scene(&path, 1.0);
        let mut vl = TexturedVl::new(false).unwrap_or_else(|e| panic!("{e}"));
        let drawn = check(&s, &mut |pins| vl.cycle(pins), 1.0);
        let c = hit_rate_of_trace(&CACHE, &s.want.fetches);
        println!(
            "raster_top TEXTURE=1 {}: {} triangles, {} fragments in {} cycles ({:.3} a clock), hit rate {:.3}",
            s.name,
            sent_work(&s.list, &F, &OPTS, Some(&s.texturing)).len(),
            s.want.stats.fragments,
            drawn.cycles,
            s.want.stats.fragments as f64 / drawn.cycles as f64,
            c.hits as f64 / (c.hits + c.misses).max(1) as f64
        );
    }
}
