//! `texture_path`: a textured fragment's way from `span` to the blending `pixel_out` (paper
//! 001 §II-5: the texture coordinates interpolated per pixel, then the texture unit), cycle
//! for cycle as the RTL unit `rtl::texture_path` runs it:
//!
//! ```text
//!  fragment + its triangle ──> texture_setup's pixel part ──> texture_unit ──> fragment, alpha, mode
//!   (x, y, z, lit rgb;          (s·q, t·q, q at the pixel,     (21 + 3 + 2 + 5
//!    `new`: a triangle's         3 stages)                      stages)
//!    first fragment)
//!        └─ a triangle's first fragment: drain the pixel part, load the texture's state
//!           (when it changed: once texture_unit is idle), run texture_setup (30 cycles)
//! ```
//!
//! **A triangle's first fragment** (`new`) brings the triangle (its [`TexVtx`]s, its
//! texture's state and its blend mode; the RTL also takes the reciprocal of twice its area
//! that triangle setup's divider computed, `model::divider::reciprocal`, which
//! [`texture_setup`] forms itself). The fragment waits until the pixel part is empty
//! (`texture_setup` changes the planes under any pixel in it); then, in one cycle,
//! `texture_setup` starts and, if the triangle's state differs from the one loaded and
//! `texture_unit` is idle (its state may change only then), the state is loaded; in the
//! cycle `texture_setup` is done the fragment is taken. A first fragment whose triangle
//! has the loaded state costs 1 + [`SETUP_CYCLES`] cycles beyond a pixel's one.
//!
//! **The other fragments** are taken while the pixel part moves: its last stage is empty
//! or `texture_unit` takes its pixel. A pixel leaves the pixel part with the triangle's
//! level-of-detail gradients (`texture_setup`'s, held until the next start) and its lit
//! colour. Out of `texture_unit`, each fragment gets the texture environment's colour and
//! alpha, and its position, depth and blend mode, which waited in a side memory.
//!
//! Its memory port and counters are `texture_unit`'s; the output is the fragment stream of
//! the blending `pixel_out` (`pixel_out::Framebuffer::pixel_out_blended`'s arguments).

use crate::cull_sort::Clip;
use crate::divider::{reciprocal, Recip};
use crate::guard_band;
use crate::input::{to_fixed, Vtx};
use crate::render::{triangle_ranged, Dropped, Options, Texturing, Work};
use crate::span::Pixel;
use crate::texture_cache::{Counters, MemAsk, MemIn, Params};
use crate::texture_setup::{area2, tex_vertices, texture_setup, TexVtx, TexturePlanes};
use crate::texture_unit::pipeline::{Pipeline, Pixel as UnitPixel, UnitIn};
use crate::texture_unit::{TexIn, TexState};
use fx::{Formats, TexFormats};
use std::collections::VecDeque;
use texture::{BlendMode, LodRule};

/// `texture_setup`'s pixel part: its stages (`rtl::texture_setup::LATENCY`).
pub const PIXEL_STAGES: usize = 3;
/// `texture_setup`'s start to done (`rtl::texture_setup::SETUP_CYCLES`).
pub const SETUP_CYCLES: u32 = 30;

/// A textured triangle, as its first fragment brings it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TexTriangle {
    /// Its vertices as the texture path takes them (`texture_setup::tex_vertices`).
    pub v: [TexVtx; 3],
    pub state: TexState,
    pub blend: BlendMode,
}

/// A fragment offered: the pixel (its colour the lit one), whether it is its triangle's
/// first, and its triangle (read only with `new`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Fragment {
    pub pixel: Pixel,
    pub new: bool,
    pub tri: TexTriangle,
}

/// A textured fragment out: the pixel with the environment's colour, its alpha and its
/// triangle's blend mode.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Textured {
    pub pixel: Pixel,
    pub alpha: u8,
    pub blend: BlendMode,
}

/// The path's inputs in one cycle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PathIn {
    pub inp_valid: bool,
    pub frag: Fragment,
    /// A pulse: texture_unit's cache invalidates every line.
    pub flush: bool,
    pub out_ready: bool,
}

/// The path's outputs in one cycle, before the clock edge.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PathOut {
    pub inp_ready: bool,
    pub out_valid: bool,
    /// Meaningful with `out_valid`.
    pub out: Textured,
    /// `texture_unit`'s read port and counters.
    pub mem: MemAsk,
    pub counters: Counters,
    /// No fragment in the path, and no triangle being set up.
    pub idle: bool,
}

/// Where the path is with the triangles.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Phase {
    /// Fragments of the set-up triangle are taken.
    Run,
    /// A first fragment waits for the pixel part to drain (and texture_unit to idle).
    Drain,
    /// texture_setup runs: the cycles to done.
    Setup(u32),
    /// The set-up triangle's first fragment is taken when the pixel part moves.
    First,
}

/// A fragment in the pixel part: its texture inputs (the planes are constant while it is
/// there) and its lit colour.
#[derive(Clone, Copy, Debug)]
struct InPixel {
    p: TexIn,
    cf: [u8; 3],
}

/// The texture path, cycle for cycle: see the module documentation.
#[derive(Clone, Debug)]
pub struct TexturePath {
    f: Formats,
    tf: TexFormats,
    unit: Pipeline,
    phase: Phase,
    planes: Option<TexturePlanes>,
    loaded: Option<TexState>,
    stages: [Option<InPixel>; PIXEL_STAGES],
    /// Each fragment's position, depth and blend mode from its taking to its output.
    side: VecDeque<(Pixel, BlendMode)>,
}

impl TexturePath {
    /// The path at screen formats `f` (the size class 10's, `rtl::texture_setup`'s) and
    /// texture formats `tf`, over a cache of geometry `cache`, the level of detail by `lod`.
    pub fn new(f: Formats, tf: TexFormats, cache: Params, lod: LodRule) -> Result<TexturePath, String> {
        Ok(TexturePath {
            f,
            tf,
            unit: Pipeline::new(tf, cache, lod)?,
            phase: Phase::Run,
            planes: None,
            loaded: None,
            stages: [None; PIXEL_STAGES],
            side: VecDeque::new(),
        })
    }

    /// Whether texture_unit's cache has left its power-up Clear.
    pub fn cache_running(&self) -> bool {
        self.unit.cache_running()
    }

    /// No fragment in the path and no triangle being set up: between two steps, the output
    /// `idle` of the next, whatever its inputs.
    pub fn is_idle(&self) -> bool {
        self.unit.is_idle() && self.stages.iter().all(Option::is_none) && self.phase == Phase::Run
    }

    /// One clock: the outputs of this cycle for inputs `i` and the texture memory's `m`,
    /// then the edge. Panics when a triangle of zero area brings fragments (the rasterizer
    /// draws none).
    pub fn step(&mut self, i: &PathIn, m: MemIn) -> PathOut {
        let idle = self.is_idle();
        let drained = self.stages.iter().all(Option::is_none);
        let same = self.loaded == Some(i.frag.tri.state);
        let start = self.phase == Phase::Drain && drained && (same || self.unit.is_idle());
        let st_load = start && !same;
        let last = self.stages[PIXEL_STAGES - 1];
        let grad = self.planes.map(|p| p.grad()).unwrap_or_default();
        let ui = UnitIn {
            inp_valid: last.is_some(),
            pixel: last.map_or(UnitPixel::default(), |x| UnitPixel { p: x.p, g: grad, cf: x.cf, tag: 0 }),
            st_load,
            state: i.frag.tri.state,
            flush: i.flush,
            out_ready: i.out_ready,
        };
        let uo = self.unit.step(&ui, m);
        let en = last.is_none() || uo.inp_ready;
        let inp_ready = en
            && match self.phase {
                Phase::Run => !i.frag.new,
                Phase::First => true,
                Phase::Drain | Phase::Setup(_) => false,
            };
        let accept = i.inp_valid && inp_ready;
        let (pixel, blend) = self.side.front().copied().unwrap_or_default();
        let [r, g, b, alpha] = uo.out_rgba;
        let out = PathOut {
            inp_ready,
            out_valid: uo.out_valid,
            out: Textured { pixel: Pixel { rgb: [r, g, b], ..pixel }, alpha, blend },
            mem: uo.mem,
            counters: uo.counters,
            idle,
        };

        // The edge.
        if uo.out_valid && i.out_ready {
            self.side.pop_front();
        }
        if en {
            let entering = accept.then(|| {
                let planes = self.planes.expect("a fragment's triangle has an area");
                self.side.push_back((i.frag.pixel, i.frag.tri.blend));
                InPixel { p: planes.at(i.frag.pixel.x, i.frag.pixel.y), cf: i.frag.pixel.rgb }
            });
            self.stages.copy_within(0..PIXEL_STAGES - 1, 1);
            self.stages[0] = entering;
        }
        self.phase = match self.phase {
            Phase::Run if i.inp_valid && i.frag.new => Phase::Drain,
            Phase::Drain if start => {
                self.planes = texture_setup(&i.frag.tri.v, &self.f, &self.tf);
                self.loaded = Some(i.frag.tri.state);
                Phase::Setup(SETUP_CYCLES)
            }
            Phase::Setup(1) => Phase::First,
            Phase::Setup(n) => Phase::Setup(n - 1),
            Phase::First if accept => Phase::Run,
            p => p,
        };
        out
    }
}

/// A triangle a scene draws: its fragments (lit colours, before the depth test) and blend
/// mode, and when textured the triangle the texture path takes with its first fragment and
/// the reciprocal of twice its area (`tri$mant`, `tri$exp`).
#[derive(Clone, Debug)]
pub struct Draw {
    pub pixels: Vec<Pixel>,
    pub blend: BlendMode,
    pub tex: Option<(TexTriangle, Recip)>,
}

/// The triangles `render::render_with(list, f, opts, Some(texturing))` draws with the
/// scanline method, in drawing order (the guard band's pieces that are neither culled nor
/// dropped), each as the texture path takes it: textured where `Texturing::apply` textures.
pub fn draws(list: &scene::Trilist, f: &Formats, opts: &Options, texturing: &Texturing) -> Vec<Draw> {
    let drawn = sent_work(list, f, opts, Some(texturing)).into_iter().filter(|s| s.drawn);
    drawn
        .map(|s| Draw {
            blend: s.sent.blend,
            tex: s.sent.tex.map(|t| (t, reciprocal(area2(&t.v).abs(), f))),
            pixels: s.pixels,
        })
        .collect()
}

/// A triangle as the textured `raster_top` (`rtl::raster_top_textured`) takes it: its input
/// words, its blend mode and, when textured, its texture words (`tex$*` and `tex_state$*`: the triangle
/// `texture_path` takes, whose reciprocal setup's divider computes on the way).
#[derive(Clone, Copy, Debug)]
pub struct Sent {
    pub v: [Vtx; 3],
    pub blend: BlendMode,
    pub tex: Option<TexTriangle>,
}

/// The triangles a host sends the textured `raster_top` to draw `list` as
/// `render::render_with(list, f, opts, texturing)` draws it with the scanline method: the
/// guard band's pieces whose vertices and texture vertices fit their formats (`to_fixed`,
/// `tex_vertices`; the render drops the others), culled or not, in order; textured where
/// `Texturing::apply` textures (a piece of zero area is culled).
pub fn sent(list: &scene::Trilist, f: &Formats, texturing: Option<&Texturing>) -> Vec<Sent> {
    sendable(list, f, texturing).map(|(_, s)| s).collect()
}

/// [`sent`]'s triangles, each with its guard-band piece.
fn sendable<'a>(
    list: &'a scene::Trilist,
    f: &'a Formats,
    texturing: Option<&'a Texturing>,
) -> impl Iterator<Item = (scene::Triangle, Sent)> + 'a {
    guard_band::pieces(list, f, false).triangles.into_iter().filter_map(move |tri| {
        let v = to_fixed(&tri, f).ok()?;
        let tex = match texturing {
            None => None,
            Some(tx) => {
                let tv = tex_vertices(&tri, &v, &tx.unit.formats, tx.affine).ok()?;
                tv.zip(tri[0].tex).filter(|(tv, _)| area2(tv) != 0).map(|(tv, tex)| TexTriangle {
                    v: tv,
                    state: tx.memory.states[tex.texture as usize],
                    blend: tri[0].blend,
                })
            }
        };
        let blend = tri[0].blend;
        Some((tri, Sent { v, blend, tex }))
    })
}

/// A triangle sent ([`sent`]) with what the scanline pipeline makes of it under `opts`:
/// its work (`render::Work`, for the cycle model) and its fragments in the order `span`
/// sends them (lit colours, before the depth test).
#[derive(Clone, Debug)]
pub struct SentWork {
    pub sent: Sent,
    pub work: Work,
    pub pixels: Vec<Pixel>,
    /// Whether it is drawn: neither culled nor dropped (an overflow passes `cull_sort`).
    pub drawn: bool,
}

/// [`sent`]'s triangles with their work and fragments under `opts` (its cull).
pub fn sent_work(list: &scene::Trilist, f: &Formats, opts: &Options, texturing: Option<&Texturing>) -> Vec<SentWork> {
    let clip = Clip { width: list.width, height: list.height };
    let sent = sendable(list, f, texturing);
    sent.map(|(tri, sent)| match triangle_ranged(&tri, clip, f, opts).0 {
        Ok(t) => SentWork { sent, work: t.work, pixels: t.pixels, drawn: true },
        Err(why) => {
            let work = Work { passed_cull: matches!(why, Dropped::Overflow(_)), ..Work::default() };
            SentWork { sent, work, pixels: Vec::new(), drawn: false }
        }
    })
    .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::texture_unit::TextureUnit;
    use texture::{EnvMode, Filter, MipMode, Sampler, TexelFormat, Weights, Wrap};

    const TF: TexFormats = TexFormats::DEFAULT;
    const CACHE: Params = Params { sets: 64, ways: 2, line: 4 };

    fn state(base: u32) -> TexState {
        TexState {
            size_log2: [1, 1],
            levels: 1,
            base,
            format: TexelFormat::Rgba8888,
            sampler: Sampler {
                min: Filter::Nearest,
                mag: Filter::Nearest,
                mip: MipMode::None,
                wrap_s: Wrap::Repeat,
                wrap_t: Wrap::Repeat,
                weights: Weights::Linear,
            },
            env: EnvMode::Replace,
            lod: LodRule::Max,
        }
    }

    /// A right triangle over pixels (0..8, 0..8) of a class-10 screen, s and t 0 to 2 over
    /// it (a 2 x 2 texture repeated), q = 1.
    fn triangle(f: &Formats, state: TexState, blend: BlendMode) -> TexTriangle {
        let px = 1i128 << f.xy.frac;
        let one_st = 1i128 << TF.st.frac;
        let q = 1i128 << TF.q.frac;
        let v = |x: i128, y: i128, s: i128, t: i128| TexVtx { x: x * px, y: y * px, a: [s, t, q] };
        TexTriangle { v: [v(0, 0, 0, 0), v(16, 0, 4 * one_st, 0), v(0, 16, 0, 4 * one_st)], state, blend }
    }

    /// Runs fragments (each with its triangle, `new` on a triangle's first) through the
    /// path behind a memory answering in 1 cycle, the output always ready; the textured
    /// fragments and the cycle each came out.
    fn run(memory: &[u32], frags: &[Fragment]) -> Vec<(u64, Textured)> {
        let f = Formats::for_n(10);
        let mut path = TexturePath::new(f, TF, CACHE, LodRule::Max).unwrap();
        let mut answers: VecDeque<u32> = VecDeque::new();
        let mut out = Vec::new();
        let (mut next, mut now) = (0, 0u64);
        while out.len() < frags.len() {
            assert!(now < 10_000, "the path hangs");
            let due = answers.pop_front();
            let i = PathIn {
                inp_valid: next < frags.len() && path.cache_running(),
                frag: frags.get(next).copied().unwrap_or(frags[0]),
                flush: false,
                out_ready: true,
            };
            let o = path.step(&i, MemIn { ack: true, rvalid: due.is_some(), rdata: due.unwrap_or(0) });
            if o.mem.valid {
                answers.push_back(memory.get(o.mem.addr as usize).copied().unwrap_or(0));
            }
            next += (i.inp_valid && o.inp_ready) as usize;
            if o.out_valid {
                out.push((now, o.out));
            }
            now += 1;
        }
        out
    }

    /// Two triangles of 10 fragments each, the second with another texture: every colour is
    /// `TextureUnit::sample`'s at `texture_setup`'s planes (REPLACE: the texel), every
    /// position, depth and mode the fragment's, in order; and the second triangle's first
    /// fragment comes out only after the state load and the setup.
    #[test]
    fn texture_path_textures_each_fragment_with_its_triangles_planes() {
        let f = Formats::for_n(10);
        let memory: Vec<u32> = (0..8).map(|k| 0x1020_3000 + k * 0x0101_0101).collect();
        let tris = [triangle(&f, state(0), BlendMode::Alpha), triangle(&f, state(4), BlendMode::Additive)];
        let mut frags = Vec::new();
        for (t, tri) in tris.iter().enumerate() {
            for k in 0..10u32 {
                let pixel = Pixel { x: k % 4, y: k / 4, z: 100 * t as u32 + k, rgb: [k as u8, 2, 3] };
                frags.push(Fragment { pixel, new: k == 0, tri: *tri });
            }
        }
        let out = run(&memory, &frags);
        let unit = TextureUnit::new(TF).unwrap();
        for (n, ((_, o), x)) in out.iter().zip(&frags).enumerate() {
            let planes = texture_setup(&x.tri.v, &f, &TF).unwrap();
            let c = unit.sample(&x.tri.state, &memory, &planes.at(x.pixel.x, x.pixel.y), &planes.grad(), x.pixel.rgb);
            let want = Textured {
                pixel: Pixel { rgb: [c.colour[0], c.colour[1], c.colour[2]], ..x.pixel },
                alpha: c.colour[3],
                blend: x.tri.blend,
            };
            assert_eq!(*o, want, "fragment {n}");
        }
        // The second triangle's first fragment waits for the pixel part to drain,
        // texture_unit to idle (its state changes), the start and texture_setup's 30 cycles,
        // then the unit's latency.
        let gap = out[10].0 - out[9].0;
        assert!(gap > u64::from(SETUP_CYCLES) + crate::texture_unit::pipeline::LATENCY, "gap {gap}");
    }
}
