//! `edge_walk`: the edge walk of paper 001 with the Y clipping of paper 003
//! (Lee 2008, §II.1.다.(2), Fig. 5).
//!
//! Walks the triangle one scanline per cycle with two exact edge steppers (see
//! `triangle_setup`): the long edge on one side, the two short edges in turn on
//! the other, and emits one span command per scanline that has pixels.
//!
//! **Y clipping (003).** 003 walks from the vertex farthest from the "lower"
//! clip boundary. Reading 003's Y as ours (y grows down the screen), the lower
//! boundary is row 0, the top of the screen:
//! * a triangle that crosses row 0 and not the bottom of the screen is walked
//!   from vMax *up* and stops after row 0: no cycle is spent above the screen;
//! * any other triangle is walked from vMin *down* and stops after the last row
//!   of the screen or at vMax. One that crosses both boundaries spends cycles on
//!   its rows above the screen (003 accepts this: it is rare).
//!
//! Latency 2 (003 Table 1: edge walk 2 cycles); one scanline per cycle.
//! Mirrors `rtl::edge_walk` (`hdl-out/edge_walk.v`).

use crate::ctx::Ctx;
use crate::cull_sort::Clip;
use crate::triangle_setup::{Attrs, Edge, TriangleSetupOut, Walk};

/// Cycles from a setup result to its first span command (003 Table 1).
pub const LATENCY: u32 = 2;
/// Cycles per scanline walked.
pub const II: u32 = 1;

/// A span command: one scanline of a triangle, for `span`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SpanCmd {
    /// Scanline (0 <= y < height).
    pub y: i32,
    /// First and last pixel inside (inclusive; xl <= xr). They may lie off screen:
    /// `span` clips x.
    pub xl: i128,
    pub xr: i128,
    /// Attributes at pixel xl and at pixel xr (`z_acc`, `c_acc`).
    pub left: Attrs,
    pub right: Attrs,
    /// Per-pixel steps (`dz`, `dc`).
    pub ddx: Attrs,
}

/// What the walk produced: one entry per scanline walked (one cycle each), with
/// the span command it emitted, if any (none off screen or where the span is empty).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct EdgeWalkOut {
    pub scanlines: Vec<Option<SpanCmd>>,
}

impl EdgeWalkOut {
    /// The span commands emitted, in order.
    pub fn spans(&self) -> impl Iterator<Item = &SpanCmd> {
        self.scanlines.iter().flatten()
    }
}

/// One exact edge stepper (001's edge walk, exact in the manner of Bresenham).
#[derive(Clone, Copy, Debug)]
struct Stepper(Edge);

impl Stepper {
    /// Next scanline down: x moves q or q + 1 pixels.
    fn down(&mut self, ctx: &mut Ctx) {
        let e = &mut self.0;
        if e.r < e.rho {
            e.x += e.q + 1;
            e.r += e.d - e.rho;
            e.at = e.at.step(&e.inc1, 1, ctx);
        } else {
            e.x += e.q;
            e.r -= e.rho;
            e.at = e.at.step(&e.inc0, 1, ctx);
        }
    }

    /// Next scanline up: the exact inverse of `down`.
    fn up(&mut self, ctx: &mut Ctx) {
        let e = &mut self.0;
        if e.r + e.rho < e.d {
            e.x -= e.q;
            e.r += e.rho;
            e.at = e.at.step(&e.inc0, -1, ctx);
        } else {
            e.x -= e.q + 1;
            e.r += e.rho - e.d;
            e.at = e.at.step(&e.inc1, -1, ctx);
        }
    }
}

/// Walks one set-up triangle.
pub fn edge_walk(s: &TriangleSetupOut, clip: Clip, ctx: &mut Ctx) -> EdgeWalkOut {
    let h = clip.height as i32;
    let mut long = Stepper(s.maj);
    let mut short = Stepper(s.short[0]);
    let mut scanlines = Vec::new();
    let total = s.maj.count;
    for k in 0..total {
        let j = match s.walk {
            Walk::Down => s.maj.j + k as i32,
            Walk::Up => s.maj.j - k as i32,
        };
        // Y clip: stop at the boundary the walk runs towards.
        if (s.walk == Walk::Down && j >= h) || (s.walk == Walk::Up && j < 0) {
            break;
        }
        if k == s.short[0].count {
            short = Stepper(s.short[1]);
        } else if k > 0 {
            match s.walk {
                Walk::Down => short.down(ctx),
                Walk::Up => short.up(ctx),
            }
        }
        if k > 0 {
            match s.walk {
                Walk::Down => long.down(ctx),
                Walk::Up => long.up(ctx),
            }
        }
        let (l, r) = if s.maj_left { (&long.0, &short.0) } else { (&short.0, &long.0) };
        let (xl, xr) = (l.x, r.x - 1);
        let has_pixels = j >= 0 && xl <= xr;
        scanlines.push(has_pixels.then_some(SpanCmd { y: j, xl, xr, left: l.at, right: r.at, ddx: s.ddx }));
    }
    EdgeWalkOut { scanlines }
}
