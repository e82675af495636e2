//! The SE span backend: the scanline pipeline's spans (paper 001 setup and edge walk with
//! 003's Y clip) drawn by an array of ceil(W / P) shading engines (000 Fig. 5), each a
//! cycle-exact [`Se`] over its own P columns, reading and writing the depth and colour
//! buffers through its ports. `edgepaint render --engine se`.
//!
//! # From a span command to an SE command
//!
//! [`crate::se_cmd`]: the lines f(X) = A X + B of z, R, G and B in SE word LSBs, spans wholly
//! off screen dropped, and the issue onto the span bus. The z-buffer's words (z.frac bits)
//! are read zero extended; a written z word is stored as is (the SE writes only 0 <= z <
//! old z <= z_max); a colour word is clamped to 0..255 on its way into the 8-bit frame
//! buffer.
//!
//! # Rounding difference from the scanline model
//!
//! Per pixel and attribute, |SE - scanline| <= 1 LSB (a depth LSB, a colour level), as
//! long as the line at the region's ends fits the SE word ([`ends_fit`]). Derivation: let
//! g be the exact line `span` accumulates. A and B rounded to `frac` bits move f(X) by at
//! most (X + 1) 2^-(frac+1) <= 1025 / 2^17 < 0.008 for X <= 1024; the multipliers round
//! f(XL_i), f(XR_i) by at most 1/2 more; the interpolator is exact, so before its final
//! rounding each pixel is within 0.508 of g (a convex combination of the two ends' errors).
//! Rounded, it is within 1.008 of g, and the scanline's round(g) within 0.5: two integers
//! less than 2 apart, so at most 1 apart. Where they differ: a pixel whose exact value lies
//! within 0.508 of a rounding boundary (x.5).
//!
//! Whole frames then differ only where the depth test decides differently: two triangles'
//! depths at a pixel within 2 LSB of each other (each engine's depth may move by 1), or a
//! depth within 1 LSB of the z clip at 0 or of the buffer's clear value z_max. Test:
//! `se_renders_every_shipped_scene_within_1_lsb` (crates/model/tests/se.rs).
//!
//! # Cycles
//!
//! The engines share one span bus (000 Fig. 5): every span goes to all engines at once,
//! and the ones it misses write nothing (the model skips them; they would only run their
//! counters). A span is issued [`SeParams::ii`] clocks after the previous one (136), but
//! [`SeParams::latency`] (161) after it when both are on the same row: the next span's
//! old-z read would otherwise overtake the previous span's writes to that row. Spans
//! wholly off screen are not issued. Frame cycles: the last issue plus the latency.

use super::{Se, SeCmd, SeIn, SeParams, PORTS, SPAN_X_BITS};
use crate::ctx::Ctx;
use crate::cull_sort::{cull_sort, z_max, Clip, Cull, Reject};
use crate::edge_walk::edge_walk;
use crate::guard_band;
use crate::input::to_fixed;
use crate::pixel_out::Framebuffer;
use crate::se_cmd::{issue_gap, on_screen, se_cmd};
use crate::triangle_setup::triangle_setup;
use fx::{fits_s, shr_half_up, signed_bits, wrap_s, Formats};
use scene::Trilist;
use std::collections::VecDeque;

/// The engines the backend builds for `f`: 000's P = 64 and 16 fraction bits, with z and
/// colour words just wide enough that no line the formats can carry overflows at the
/// region's ends. A line's value there is its value v0 at a pixel of the span plus at
/// most P steps: |f(X)| < 2^a + 2^b with 2^a bounding v0 (`z_acc`, `c_acc`) and 2^b
/// bounding P |A| (`dz`, `dc`), all in word LSBs. Default formats: z words of 29 bits
/// (|v0| < 2 z, |A| < 32 z per pixel: a = 17, b = 27), colour words of 21 bits
/// (a = 9, b = 19). 000's 24 and 16 bits would overflow on steep slivers: all.json has
/// spans with colour slopes of 1100 levels per pixel.
pub const fn engine_params(f: &Formats) -> SeParams {
    const fn word(a: u32, b: u32) -> u32 {
        signed_bits((1i128 << a) + (1i128 << b) + 1)
    }
    let paper = SeParams::paper(0);
    let k = paper.levels();
    SeParams { zw: word(f.z_acc.int + f.z.frac, f.dz.int + f.z.frac + k), cw: word(f.c_acc.int, f.dc.int + k), ..paper }
}

/// Whether every attribute's line, rounded at the region's ends as the multipliers round
/// it, fits the SE word. If not, the multipliers wrap and the engine's pixels are wrong.
pub fn ends_fit(cmd: &SeCmd, prm: &SeParams) -> bool {
    let (xl, xr) = prm.region();
    (0..4).all(|j| [xl, xr].iter().all(|&x| fits_s(shr_half_up(cmd.a[j] * x + cmd.b[j], prm.frac), prm.width(j))))
}

/// A span bound for the engines: its triangle, row and command.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SeSpan {
    /// Index of its triangle in the list (the frame buffer records the writer).
    pub tri: u32,
    pub y: u32,
    pub cmd: SeCmd,
}

/// What became of the triangles on their way to spans.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct SpanStats {
    pub triangles_in: u64,
    /// Vertices that do not fit the input formats.
    pub input_rejected: u64,
    pub culled_outside: u64,
    pub culled_back: u64,
    pub degenerate: u64,
    pub drawn: u64,
    /// Spans reaching the screen (issued to the engines).
    pub spans: u64,
}

/// The spans of every triangle, in drawing order, as the SE commands for `frac`
/// fraction bits; spans wholly off screen are left out.
pub fn spans(list: &Trilist, f: &Formats, cull: Cull, frac: u32) -> (Vec<SeSpan>, SpanStats) {
    let clip = Clip { width: list.width, height: list.height };
    let mut st = SpanStats { triangles_in: list.triangles.len() as u64, ..SpanStats::default() };
    let mut out = Vec::new();
    let pieces = guard_band::pieces(list, f, false);
    for (tri, &i) in pieces.triangles.iter().zip(&pieces.source) {
        let Ok(v) = to_fixed(tri, f) else {
            st.input_rejected += 1;
            continue;
        };
        let sorted = match cull_sort(&v, clip, cull, f) {
            Ok(s) => s,
            Err(Reject::Outside(_)) => {
                st.culled_outside += 1;
                continue;
            }
            Err(Reject::BackFace) => {
                st.culled_back += 1;
                continue;
            }
            Err(Reject::ZeroArea) => {
                st.degenerate += 1;
                continue;
            }
        };
        st.drawn += 1;
        let mut ctx = Ctx::new(*f);
        let setup = triangle_setup(&sorted, &mut ctx);
        for span in edge_walk(&setup, clip, &mut ctx).spans() {
            if !on_screen(span, list.width) {
                continue;
            }
            out.push(SeSpan { tri: i as u32, y: span.y as u32, cmd: se_cmd(span, f, frac) });
        }
    }
    st.spans = out.len() as u64;
    (out, st)
}

/// The clock each span is issued in, the first in clock 0 and each next one
/// [`issue_gap`] after the one before (spans always waiting: the engines alone).
pub fn issue_cycles(spans: &[SeSpan], prm: &SeParams) -> Vec<u64> {
    let mut at = Vec::with_capacity(spans.len());
    for (k, s) in spans.iter().enumerate() {
        let c = match k {
            0 => 0,
            _ => at[k - 1] + issue_gap(prm, spans[k - 1].y == s.y),
        };
        at.push(c);
    }
    at
}

/// A frame drawn by the engine array, and its cycle count.
#[derive(Clone, Debug)]
pub struct SeRender {
    pub fb: Framebuffer,
    pub stats: SpanStats,
    /// Engines across the screen: ceil(W / P).
    pub engines: u32,
    /// Spans an engine took whose line did not fit its words at the region's ends.
    pub ends_overflowed: u64,
    /// Spans issued a full latency after the previous one (same row).
    pub same_row_stalls: u64,
    /// Pixels written (z and colour).
    pub pixels_written: u64,
    /// Clocks from the first span issued to the last pixel written.
    pub cycles: u64,
}

/// The engines of [`engine_params`] for a screen `width` columns wide (index 0); errs when
/// they cannot draw it: the screen wider than the engines' X reaches, span ends (anywhere
/// in the `xy` range the front end clips to) beyond the engines' [`SPAN_X_BITS`]-bit span
/// ends, or the formats need words wider than 32 bits.
pub fn array_params(width: u32, f: &Formats) -> Result<SeParams, String> {
    if f.xy.int + 1 > SPAN_X_BITS {
        return Err(format!(
            "no SE array at xy = {}: its span ends reach +-2^{} px, the engines' span ends hold {SPAN_X_BITS} bits",
            f.xy, f.xy.int
        ));
    }
    let prm = engine_params(f);
    let engines = width.div_ceil(prm.p);
    let why =
        |e| format!("no SE array for {width} columns with {}- and {}-bit z and colour words: {e}", prm.zw, prm.cw);
    SeParams { index: engines - 1, ..prm }.check().map_err(why)?;
    Ok(prm)
}

/// Cycles of `list`'s frame through the whole SE back end (`rtl::raster_top` with `METHOD =
/// 2`): the scanline front end at `timing`, `se_cmd` and the engines
/// (`cycles::se_frame`), triangles back to back. Errs as [`array_params`].
pub fn back_end_cycles(
    list: &Trilist,
    f: &Formats,
    cull: Cull,
    background: [u8; 3],
    timing: &crate::cycles::Timing,
) -> Result<u64, String> {
    let prm = array_params(list.width, f)?;
    let opts = crate::render::Options { method: crate::render::Method::Scanline, cull, analysis: false, background };
    let work = crate::render::render(list, f, &opts, &mut |_| {}).work;
    Ok(crate::cycles::se_frame(&work, timing, &prm, crate::se_cmd::ready_after(f)).total)
}

/// Draws `list` with the engines of [`engine_params`], one per P columns. Errs when the
/// screen is wider than the engines' X reaches or the formats need words wider than 32 bits.
pub fn render(list: &Trilist, f: &Formats, cull: Cull, background: [u8; 3]) -> Result<SeRender, String> {
    let prm = array_params(list.width, f)?;
    let (w, h) = (list.width, list.height);
    let engines = w.div_ceil(prm.p);
    let (spans, stats) = spans(list, f, cull, prm.frac);
    let issue = issue_cycles(&spans, &prm);
    let mut r = SeRender {
        fb: Framebuffer::new(w, h, z_max(f) as u32, background),
        stats,
        engines,
        ends_overflowed: 0,
        same_row_stalls: spans.windows(2).filter(|p| p[0].y == p[1].y).count() as u64,
        pixels_written: 0,
        cycles: issue.last().map_or(0, |c| c + prm.latency() as u64),
    };
    for index in 0..engines {
        let prm = SeParams { index, ..prm };
        let (lo, hi) = prm.region();
        let mine: Vec<(u64, &SeSpan)> =
            issue.iter().copied().zip(&spans).filter(|(_, s)| s.cmd.xl < hi && s.cmd.xr >= lo).collect();
        r.ends_overflowed += mine.iter().filter(|(_, s)| !ends_fit(&s.cmd, &prm)).count() as u64;
        r.pixels_written += run_engine(prm, &mine, &mut r.fb);
    }
    Ok(r)
}

/// One engine through its spans (issue clock, span), against the frame buffer; returns
/// the pixels it wrote. Idle stretches are skipped: an idle engine's clocks change nothing.
fn run_engine(prm: SeParams, spans: &[(u64, &SeSpan)], fb: &mut Framebuffer) -> u64 {
    let mut se = Se::new(prm);
    let (lo, _) = prm.region();
    let (q, width) = (prm.p / 4, fb.width as i128);
    // Spans accepted and not yet written out: (row, triangle).
    let mut pending: VecDeque<(u32, u32)> = VecDeque::new();
    let mut written = 0;
    let mut clock = |se: &mut Se, cmd: Option<&SeSpan>, pending: &mut VecDeque<(u32, u32)>| {
        let before = se.outputs();
        let mut i = SeIn { valid: cmd.is_some(), cmd: cmd.map_or(SeCmd::default(), |s| s.cmd), oz: [0; PORTS] };
        if before.oz_rd {
            // The span being loaded is the one accepted last.
            let row = pending.back().expect("a load follows an accept").0;
            for (k, oz) in i.oz.iter_mut().enumerate() {
                let x = lo + 4 * before.oz_addr as i128 + k as i128;
                *oz = if x < width { fb.depth[(row * fb.width) as usize + x as usize] as u64 } else { 0 };
            }
        }
        let out = se.step(&i);
        if let Some(s) = cmd {
            assert!(out.ready, "span issued to a busy engine");
            pending.push_back((s.y, s.tri));
        }
        if out.wr {
            let (row, tri) = *pending.front().expect("a write follows an accept");
            for k in 0..PORTS {
                let x = lo + 4 * out.wr_addr as i128 + k as i128;
                if out.we[k] && x < width {
                    let at = (row * fb.width) as usize + x as usize;
                    fb.depth[at] = out.nz[k] as u32;
                    fb.rgb[at] = std::array::from_fn(|ch| wrap_s(out.c[ch][k] as i128, prm.cw).clamp(0, 255) as u8);
                    fb.written[at] = true;
                    fb.writer[at] = tri;
                    written += 1;
                }
            }
            if out.wr_addr == q - 1 {
                pending.pop_front();
            }
        }
    };
    let mut now = 0u64;
    for &(at, span) in spans {
        while now < at && !se.idle() {
            clock(&mut se, None, &mut pending);
            now += 1;
        }
        now = at;
        clock(&mut se, Some(span), &mut pending);
        now += 1;
    }
    while !se.idle() {
        clock(&mut se, None, &mut pending);
    }
    written
}
