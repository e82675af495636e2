//! `span`: span processing of paper 001 with the X and Z clipping of paper 003
//! (Lee 2008, §II.1.다.(3), Fig. 6). One pixel per cycle.
//!
//! * A span wholly left or right of the screen is dropped, and so is one whose
//!   two ends both lie beyond the same z boundary. (003 says "both ends outside
//!   the z range"; a span running from z < 0 to z > 1 crosses the whole range,
//!   so only ends beyond the *same* boundary are dropped.)
//! * A span that starts left of the screen is walked right to left from its
//!   last pixel and stops at column 0; any other is walked left to right from
//!   its first pixel and stops at the last column or its end. A span crossing
//!   both sides walks its off-screen right part for nothing (003 accepts this).
//! * Each pixel's depth is checked against [0, z_max] before it goes out.
//!
//! Output per pixel: depth rounded to the z format's fraction bits (the depth
//! buffer width) and colour rounded to 8 bits, clamped to [0, 255].
//! Latency 2 (003 Table 1: span 1 cycle; the RTL walks a pixel in the cycle after it
//! takes a command and presents it from a pixel register the cycle after that, for the
//! clock). Mirrors `rtl::span` (`hdl-out/span.v`).

use crate::ctx::Ctx;
use crate::cull_sort::{z_max, Clip};
use crate::edge_walk::SpanCmd;
use crate::triangle_setup::Attrs;
use fx::Fmt;

/// Cycles from a span command taken to its first pixel out: one to the walk's first cycle,
/// one in the pixel register (003 Table 1 has 1).
pub const LATENCY: u32 = 2;
/// Cycles per pixel walked.
pub const II: u32 = 1;

/// A pixel leaving the rasterizer, before the depth test.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Pixel {
    pub x: u32,
    pub y: u32,
    /// Depth in [0, z_max], `z.frac` bits.
    pub z: u32,
    pub rgb: [u8; 3],
}

/// What one span produced and the cycles it took (pixels walked; 1 for a
/// dropped span, which still takes its command cycle).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SpanOut {
    pub pixels: Vec<Pixel>,
    pub cycles: u32,
    /// Pixels walked whose depth fell outside [0, z_max].
    pub z_clipped: u32,
    /// The cycles of the walk (from 0) that sent no pixel: right of the screen, outside the
    /// depth range (the walk may end on such pixels, which go nowhere), or the one cycle of
    /// a dropped span. A stalled output holds the walk in those too
    /// (`cycles::scanline_frame_stalled`).
    pub unsent: Vec<u32>,
}

/// A z accumulator rounded to the depth buffer's fraction bits (may be out of range).
pub fn depth_of(z_acc: i128, f: &fx::Formats) -> i128 {
    Fmt { frac: f.z.frac, ..f.z }.rescale(z_acc, f.z_acc.frac)
}

/// A colour accumulator rounded half up to an integer and clamped to [0, 255].
pub fn color_of(c_acc: i128, f: &fx::Formats) -> u8 {
    Fmt::s(9, 0).half_up().rescale(c_acc, f.c_acc.frac).clamp(0, 255) as u8
}

/// Processes one span command.
pub fn span(cmd: &SpanCmd, clip: Clip, ctx: &mut Ctx) -> SpanOut {
    let f = ctx.f;
    let (w, zmax) = (clip.width as i128, z_max(&f));
    let (zl, zr) = (depth_of(cmd.left.z, &f), depth_of(cmd.right.z, &f));
    let outside_x = cmd.xl > w - 1 || cmd.xr < 0;
    let outside_z = (zl < 0 && zr < 0) || (zl > zmax && zr > zmax);
    if outside_x || outside_z {
        return SpanOut { pixels: Vec::new(), cycles: 1, z_clipped: 0, unsent: vec![0] };
    }
    // 003: a span starting left of the screen is walked right to left.
    let (mut x, last, dir, mut a): (i128, i128, i128, Attrs) =
        if cmd.xl < 0 { (cmd.xr, 0, -1, cmd.right) } else { (cmd.xl, cmd.xr.min(w - 1), 1, cmd.left) };
    let mut out = SpanOut { pixels: Vec::new(), cycles: 0, z_clipped: 0, unsent: Vec::new() };
    loop {
        out.cycles += 1;
        if x < w {
            let z = depth_of(a.z, &f);
            if (0..=zmax).contains(&z) {
                let rgb = a.c.map(|c| color_of(c, &f));
                out.pixels.push(Pixel { x: x as u32, y: cmd.y as u32, z: z as u32, rgb });
            } else {
                out.z_clipped += 1;
                out.unsent.push(out.cycles - 1);
            }
        } else {
            out.unsent.push(out.cycles - 1);
        }
        if x == last {
            break;
        }
        x += dir;
        a = a.step(&cmd.ddx, dir, ctx);
    }
    out
}
