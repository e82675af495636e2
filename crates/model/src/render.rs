//! Whole frames through the fixed-point pipelines, as the hardware would draw them.
//!
//! * scanline (001 + 003): `cull_sort` -> `triangle_setup` (with the `divider`)
//!   -> `edge_walk` -> `span` -> `pixel_out`;
//! * vector (004): `cull_sort` -> `vector` -> `pixel_out`.
//!
//! A textured triangle's fragments ([`render_with`] and a [`Texturing`]) go through
//! `texture_setup`'s planes and the texture unit (`texture_unit`, 001 §II-5) between the
//! back end and `pixel_out`, which blends them onto the colour buffer by the triangle's blend
//! mode (`blend`, 001's six modes) after the depth test.
//!
//! In analysis mode every emitted depth and colour is compared with the exact
//! value of the triangle's plane at that pixel (f64, from the same fixed-point
//! vertices). Positions never wrap (their formats hold the whole coordinate
//! range), so a wrap can only corrupt attributes; a triangle with an attribute
//! off by more than [`HARM_COLOR`] or a quarter of the depth range overflowed
//! harmfully, and is reported, with the registers that wrapped, instead of drawn. So is
//! every triangle in which a quantity narrower than the modular minimum wrapped
//! (`fx::Formats::narrowed`: integer bits fitted to a workload's ranges), whatever its
//! pixels: there a wrap is not known to be harmless, and the RTL need not agree with the
//! model on it.
//!
//! [`Render::ranges`] is the smallest and largest value each quantity's registers were
//! given over the frame (`model::ctx::Ranges`): the integer bits it needs.

use crate::ctx::{Ctx, Ranges, Q};
use crate::cull_sort::{cull_sort, z_max, Clip, Cull, Reject};
use crate::edge_walk::edge_walk;
use crate::guard_band;
use crate::input::{to_fixed, InputError, Vtx};
use crate::pixel_out::Framebuffer;
use crate::span::{span, Pixel};
use crate::texture_memory::TextureMemory;
use crate::texture_setup::{tex_vertices, texture_setup};
use crate::texture_unit::{Fetch, TextureUnit};
use crate::triangle_setup::triangle_setup;
use crate::vector::{vector, WalkRow};
use fx::Formats;
use scene::{Triangle, Trilist};

/// Which rasterization method, with its parameters.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// Setup, edge walk and span (001, 003).
    Scanline,
    /// Per-pixel barycentrics (004): `lanes` pixels per cycle; `perspective`
    /// corrects colour with w when the input carries it.
    Vector { lanes: u32, perspective: bool },
}

/// Rendering options.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Options {
    pub method: Method,
    pub cull: Cull,
    /// Check every triangle for harmful overflow (twice the work).
    pub analysis: bool,
    pub background: [u8; 3],
}

/// The work one triangle made for each unit: what the cycle model needs.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Work {
    /// Whether it went past `cull_sort`.
    pub passed_cull: bool,
    /// Per scanline the edge walk stepped through, the span command it emitted, if
    /// any (scanline method).
    pub scanlines: Vec<Option<SpanWork>>,
    /// The rows of the vector unit's walk of its box (vector method; none for an empty box).
    pub vector_rows: Vec<WalkRow>,
    /// The place in that walk (row, chunk) of the vector unit's last pixel sent to
    /// `pixel_out`, if any.
    pub vector_last_sent: Option<(u32, u32)>,
}

/// What one span command cost `span` (`model::span::SpanOut`): its cycles, and those
/// that sent no pixel to `pixel_out`; and what the SE back end needs of
/// it (`cycles::se_frame`): its row, and whether it meets the screen (`se_cmd::on_screen`).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct SpanWork {
    pub cycles: u32,
    /// The walk's cycles that sent nothing (`model::span::SpanOut::unsent`).
    pub unsent: Vec<u32>,
    pub y: u32,
    pub on_screen: bool,
}

/// One triangle's pixels (before the depth test) and work.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Trace {
    pub pixels: Vec<Pixel>,
    pub work: Work,
    pub z_clipped: u32,
    pub spans: u32,
    /// The clip planes the triangle crosses (`cull_sort`'s OR of outcodes).
    pub crosses: u8,
}

/// One triangle through the pipeline under `ctx`, from hardware vertices.
pub fn trace(v: &[Vtx; 3], clip: Clip, opts: &Options, ctx: &mut Ctx) -> Result<Trace, Reject> {
    let sorted = cull_sort(v, clip, opts.cull, &ctx.f)?;
    let mut t =
        Trace { work: Work { passed_cull: true, ..Work::default() }, crosses: sorted.crosses, ..Trace::default() };
    match opts.method {
        Method::Scanline => {
            let setup = triangle_setup(&sorted, ctx);
            let walk = edge_walk(&setup, clip, ctx);
            for cmd in &walk.scanlines {
                let work = cmd.as_ref().map(|cmd| {
                    let o = span(cmd, clip, ctx);
                    t.spans += 1;
                    t.z_clipped += o.z_clipped;
                    t.pixels.extend(o.pixels);
                    SpanWork {
                        cycles: o.cycles,
                        unsent: o.unsent,
                        y: cmd.y as u32,
                        on_screen: crate::se_cmd::on_screen(cmd, clip.width),
                    }
                });
                t.work.scanlines.push(work);
            }
        }
        Method::Vector { lanes, perspective } => {
            let o = vector(&sorted, clip, lanes, perspective, ctx);
            t.work.vector_last_sent = o.at.last().copied();
            t.work.vector_rows = o.rows;
            t.z_clipped = o.z_clipped;
            t.pixels = o.pixels;
        }
    }
    Ok(t)
}

/// Why a triangle drew nothing.
#[derive(Clone, Debug, PartialEq)]
pub enum Dropped {
    /// Its vertices do not fit the input formats.
    Input(InputError),
    Rejected(Reject),
    /// It overflowed harmfully (analysis mode): the quantities that did not fit.
    Overflow(Vec<Q>),
}

/// A colour this many LSBs from the exact value can only come from a wrap.
pub const HARM_COLOR: f64 = 64.0;

/// Depth (in depth-buffer LSBs) and colour of the plane through the hardware
/// vertices at the centre of pixel (x, y), in f64; colour perspective-correct
/// when `perspective`.
pub fn exact_at(v: &[Vtx; 3], f: &Formats, x: u32, y: u32, perspective: bool) -> (f64, [f64; 3]) {
    let s = 1i128 << f.xy.frac;
    let (cx, cy) = (x as i128 * s + s / 2, y as i128 * s + s / 2);
    let e = |a: &Vtx, b: &Vtx| ((b.x - a.x) * (cy - a.y) - (b.y - a.y) * (cx - a.x)) as f64;
    let area = e(&v[0], &v[1]) + e(&v[1], &v[2]) + e(&v[2], &v[0]);
    let l = [e(&v[1], &v[2]) / area, e(&v[2], &v[0]) / area, e(&v[0], &v[1]) / area];
    let z = (0..3).map(|k| l[k] * v[k].z as f64).sum::<f64>();
    let wgt: [f64; 3] = if perspective {
        let q: [f64; 3] = std::array::from_fn(|k| l[k] * v[k].iw as f64);
        let sum = q[0] + q[1] + q[2];
        q.map(|q| q / sum)
    } else {
        l
    };
    let cs = (-(f.color.frac as f64)).exp2();
    (z, std::array::from_fn(|i| (0..3).map(|k| wgt[k] * v[k].c[i] as f64 * cs).sum::<f64>().clamp(0.0, 255.0)))
}

/// One triangle, with analysis if asked: its pixels, or why there are none, and
/// (in analysis mode) the registers that wrapped on the way.
pub fn triangle(tri: &Triangle, clip: Clip, f: &Formats, opts: &Options) -> (Result<Trace, Dropped>, Vec<Q>) {
    let (got, wrapped, _) = triangle_ranged(tri, clip, f, opts);
    (got, wrapped)
}

/// [`triangle`], with the values each quantity was given on the way.
pub fn triangle_ranged(
    tri: &Triangle,
    clip: Clip,
    f: &Formats,
    opts: &Options,
) -> (Result<Trace, Dropped>, Vec<Q>, Ranges) {
    let v = match to_fixed(tri, f) {
        Ok(v) => v,
        Err(e) => return (Err(Dropped::Input(e)), Vec::new(), Ranges::default()),
    };
    let mut ctx = Ctx::new(*f);
    let got = trace(&v, clip, opts, &mut ctx).map_err(Dropped::Rejected);
    let ranges = *ctx.ranges();
    if !opts.analysis {
        return (got, Vec::new(), ranges);
    }
    let wrapped = ctx.overflowed();
    let narrowed = f.narrowed();
    let perspective = matches!(opts.method, Method::Vector { perspective: true, .. });
    let harm_z = (f.z.frac as f64 - 2.0).exp2();
    let harmful = got.as_ref().is_ok_and(|t| {
        wrapped.iter().any(|q| narrowed.contains(&q.name()))
            || !wrapped.is_empty()
                && t.pixels.iter().any(|p| {
                    let (z, c) = exact_at(&v, f, p.x, p.y, perspective);
                    (p.z as f64 - z).abs() > harm_z || (0..3).any(|i| (p.rgb[i] as f64 - c[i]).abs() > HARM_COLOR)
                })
    });
    if harmful {
        (Err(Dropped::Overflow(wrapped.clone())), wrapped, ranges)
    } else {
        (got, wrapped, ranges)
    }
}

/// Triangle and pixel counts of one render.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Stats {
    pub triangles_in: u64,
    /// Input triangles the front end clipped (`guard_band`): beyond the `xy` range, or
    /// behind the eye. Every other count is of the triangles drawn: the pieces.
    pub clipped: u64,
    /// Triangles whose vertices did not fit the input formats.
    pub input_rejected: u64,
    pub culled_outside: u64,
    pub culled_back: u64,
    pub degenerate: u64,
    /// Triangles dropped for a harmful overflow (analysis mode).
    pub overflowed: u64,
    /// Triangles that wrapped somewhere without harm (analysis mode).
    pub wrapped_harmlessly: u64,
    pub drawn: u64,
    pub spans: u64,
    pub fragments: u64,
    pub z_clipped: u64,
    pub pixels_written: u64,
    /// Fragments on a pixel an earlier fragment wrote (what a depth test decides).
    pub overdraw: u64,
    /// The clip planes some triangle drawn crosses (OR of `model::cull_sort::outcode`s):
    /// which clipping the frame needs.
    pub crosses: u8,
}

/// A triangle the render could not draw, and why.
#[derive(Clone, Debug, PartialEq)]
pub struct Problem {
    pub triangle: usize,
    pub why: Dropped,
}

/// A rendered frame with its accounting.
#[derive(Clone, Debug)]
pub struct Render {
    pub fb: Framebuffer,
    pub stats: Stats,
    /// Triangles dropped for input or overflow problems (not culling).
    pub problems: Vec<Problem>,
    /// Per-triangle work, in drawing order (the front end's pieces), for the cycle model.
    pub work: Vec<Work>,
    /// The smallest and largest value each quantity's registers were given, over every
    /// triangle that reached `cull_sort` (those dropped for an overflow too).
    pub ranges: Ranges,
    /// The texture unit's cache accesses, in drawing order (textured renders).
    pub fetches: Vec<Fetch>,
}

/// How the fixed-point engines texture (paper 001 §II-5): every fragment of a textured
/// triangle, before the depth test, through `texture_setup`'s planes and the texture unit,
/// its lit colour going in as the fragment colour of the texture environment.
#[derive(Clone, Debug)]
pub struct Texturing {
    pub unit: TextureUnit,
    pub memory: TextureMemory,
    /// Screen-linear texture coordinates (q = 1 at every vertex): the rubber sheet.
    pub affine: bool,
}

impl Texturing {
    /// Textures the pixels of triangle `tri` (hardware vertices `v`, at screen formats `f`):
    /// their colours, and their alphas in `alpha`; its cache accesses go to `fetches`.
    /// Untextured triangles are left alone.
    pub fn apply(
        &self,
        tri: &Triangle,
        v: &[Vtx; 3],
        f: &Formats,
        pixels: &mut [Pixel],
        alpha: &mut Vec<u8>,
        fetches: &mut Vec<Fetch>,
    ) -> Result<(), InputError> {
        let Some(tv) = tex_vertices(tri, v, &self.unit.formats, self.affine)? else { return Ok(()) };
        let (Some(planes), Some(tex)) = (texture_setup(&tv, f, &self.unit.formats), tri[0].tex) else { return Ok(()) };
        let state = &self.memory.states[tex.texture as usize];
        let g = planes.grad();
        alpha.clear();
        for p in pixels {
            let sample = self.unit.sample(state, &self.memory.words, &planes.at(p.x, p.y), &g, p.rgb);
            p.rgb = [sample.colour[0], sample.colour[1], sample.colour[2]];
            alpha.push(sample.colour[3]);
            fetches.extend(sample.fetches);
        }
        Ok(())
    }
}

/// Renders a trilist through the fixed-point pipeline chosen in `opts`, untextured.
pub fn render(list: &Trilist, f: &Formats, opts: &Options, progress: &mut dyn FnMut(usize)) -> Render {
    render_with(list, f, opts, None, progress)
}

/// [`render`], texturing textured triangles with `texturing` when given.
pub fn render_with(
    list: &Trilist,
    f: &Formats,
    opts: &Options,
    texturing: Option<&Texturing>,
    progress: &mut dyn FnMut(usize),
) -> Render {
    let clip = Clip { width: list.width, height: list.height };
    let mut fb = Framebuffer::new(list.width, list.height, z_max(f) as u32, opts.background);
    let mut stats = Stats { triangles_in: list.triangles.len() as u64, ..Stats::default() };
    let mut problems = Vec::new();
    let perspective = matches!(opts.method, Method::Vector { perspective: true, .. });
    let pieces = guard_band::pieces(list, f, perspective);
    stats.clipped = pieces.clipped;
    let mut work = Vec::with_capacity(pieces.triangles.len());
    let mut ranges = Ranges::default();
    let (mut fetches, mut alpha) = (Vec::new(), Vec::new());
    for (k, tri) in pieces.triangles.iter().enumerate() {
        let i = pieces.source[k];
        let (mut res, over, seen) = triangle_ranged(tri, clip, f, opts);
        ranges.merge(&seen);
        alpha.clear();
        if let (Some(tx), Ok(t)) = (texturing, &mut res) {
            let v = to_fixed(tri, f).expect("triangle_ranged converted it");
            if let Err(e) = tx.apply(tri, &v, f, &mut t.pixels, &mut alpha, &mut fetches) {
                res = Err(Dropped::Input(e));
            }
        }
        match res {
            Ok(t) => {
                stats.drawn += 1;
                stats.wrapped_harmlessly += (!over.is_empty()) as u64;
                stats.spans += t.spans as u64;
                stats.fragments += t.pixels.len() as u64;
                stats.z_clipped += t.z_clipped as u64;
                stats.crosses |= t.crosses;
                for (n, p) in t.pixels.iter().enumerate() {
                    stats.overdraw += fb.written[(p.y * fb.width + p.x) as usize] as u64;
                    let a = alpha.get(n).copied().unwrap_or(255);
                    stats.pixels_written += fb.pixel_out_blended(p, a, tri[0].blend, i as u32) as u64;
                }
                work.push(t.work);
            }
            Err(why) => {
                match &why {
                    Dropped::Input(_) => stats.input_rejected += 1,
                    Dropped::Rejected(Reject::Outside(_)) => stats.culled_outside += 1,
                    Dropped::Rejected(Reject::BackFace) => stats.culled_back += 1,
                    Dropped::Rejected(Reject::ZeroArea) => stats.degenerate += 1,
                    Dropped::Overflow(_) => stats.overflowed += 1,
                }
                let passed_cull = matches!(why, Dropped::Overflow(_));
                work.push(Work { passed_cull, ..Work::default() });
                if matches!(why, Dropped::Input(_) | Dropped::Overflow(_)) {
                    problems.push(Problem { triangle: i, why });
                }
            }
        }
        if k % 256 == 255 {
            progress(i + 1);
        }
    }
    progress(list.triangles.len());
    Render { fb, stats, problems, work, ranges, fetches }
}
