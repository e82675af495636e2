//! `se_cmd`: the scanline pipeline's span command made into a shading-engine command and
//! issued onto the span bus every engine of the array shares (paper 000, Fig. 5): the SE
//! back end's unit between the span FIFO and the engines. Mirrors `rtl::se_cmd`.
//!
//! # The command
//!
//! A scanline span ([`SpanCmd`]) carries its ends xl, xr, the attributes at one end in the
//! accumulator formats (`z_acc`, `c_acc`) and the per-pixel steps (`dz`, `dc`). The SE
//! takes, per attribute, the line f(X) = A X + B over screen columns X ([`se_cmd`]):
//!
//! * A = the step, B = v0 - x0 A, from the end the scanline's `span` walks from (xl, or xr
//!   for a span starting left of the screen), so that f is exactly the line `span`
//!   accumulates;
//! * in SE word LSBs with `frac` fraction bits (default 16), rounded half up: z words
//!   count depth-buffer LSBs (2^-z.frac, the scanline's depth), colour words count colour
//!   levels. From the default formats: A, B of z from `z_acc` S1.34 (18 fraction bits below
//!   a depth LSB), of colour from `c_acc` S9.22 (22 below a level).
//!
//! A span wholly off screen (xr < 0 or xl >= width) is dropped ([`on_screen`]).
//!
//! # Timing
//!
//! The unit takes a span when it holds none. An off-screen span is dropped in the cycle it
//! is taken. For one on screen, x0 A is formed by a serial multiplier, one bit of x0 a
//! cycle (`pixel_bits` of them), and the command is offered [`ready_after`] cycles after
//! the span was taken; it is issued to every engine at once when it is offered and
//! [`issue_gap`] cycles have passed since the previous issue (the engines' `ready`): the
//! engines' II after a span on another row, their latency after one on the same row (the
//! next span's old-z reads would otherwise overtake the previous span's writes to that
//! row). The unit takes the next span the cycle after an issue.

use crate::edge_walk::SpanCmd;
use crate::se::{SeCmd, SeParams};
use crate::triangle_setup::Attrs;
use fx::{shr_half_up, Formats};

/// A value with `from` fraction bits at `frac` fraction bits, rounded half up: the
/// quotient of v 2^frac by 2^from, rounded half up.
fn to_frac(v: i128, from: u32, frac: u32) -> i128 {
    shr_half_up(v << frac, from)
}

/// The SE command for one scanline span, for engines with `frac` fraction bits in A, B.
pub fn se_cmd(span: &SpanCmd, f: &Formats, frac: u32) -> SeCmd {
    // Fraction bits of the accumulators below an SE word's LSB.
    let below = [f.z_acc.frac - f.z.frac, f.c_acc.frac, f.c_acc.frac, f.c_acc.frac];
    let (x0, at): (i128, Attrs) = if span.xl < 0 { (span.xr, span.right) } else { (span.xl, span.left) };
    let v0 = [at.z, at.c[0], at.c[1], at.c[2]];
    let step = [span.ddx.z, span.ddx.c[0], span.ddx.c[1], span.ddx.c[2]];
    SeCmd {
        xl: span.xl,
        xr: span.xr,
        a: std::array::from_fn(|j| to_frac(step[j], below[j], frac)),
        b: std::array::from_fn(|j| to_frac(v0[j] - x0 * step[j], below[j], frac)),
    }
}

/// Whether `span` meets a screen `width` columns wide (else it is dropped).
pub fn on_screen(span: &SpanCmd, width: u32) -> bool {
    span.xr >= 0 && span.xl < width as i128
}

/// Cycles from taking an on-screen span to offering its command: one per bit of x0 in the
/// serial multiplier, and one to form B.
pub fn ready_after(f: &Formats) -> u64 {
    f.derived().pixel_bits as u64 + 1
}

/// Cycles from one issue to the next at the least: the engines' II, or their latency when
/// both spans are on one row.
pub fn issue_gap(prm: &SeParams, same_row: bool) -> u64 {
    if same_row {
        prm.latency() as u64
    } else {
        prm.ii() as u64
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn span(xl: i128, xr: i128, z: i128, dz: i128) -> SpanCmd {
        let at = |z| Attrs { z, c: [0; 3] };
        SpanCmd { y: 3, xl, xr, left: at(z), right: at(z + (xr - xl) * dz), ddx: at(dz) }
    }

    #[test]
    fn se_cmd_lines_pass_through_the_span_ends() {
        let f = Formats::for_n(10);
        let below = f.z_acc.frac - f.z.frac;
        // z = 100.5 depth LSBs at x = 7, rising 0.25 LSB a pixel.
        let (z, dz) = (201i128 << (below - 1), 1i128 << (below - 2));
        let c = se_cmd(&span(7, 20, z, dz), &f, 16);
        assert_eq!((c.a[0], c.b[0]), (1 << 14, (100 << 16) + (1 << 15) - 7 * (1 << 14)));
        // Starting left of the screen the line is taken from xr: the same line.
        let left = se_cmd(&span(-5, 20, z - 12 * dz, dz), &f, 16);
        assert_eq!((left.a[0], left.b[0], left.xl), (c.a[0], c.b[0], -5));
        assert!(on_screen(&span(-5, 0, 0, 0), 64) && !on_screen(&span(-5, -1, 0, 0), 64));
        assert!(on_screen(&span(63, 70, 0, 0), 64) && !on_screen(&span(64, 70, 0, 0), 64));
    }

    #[test]
    fn issue_gap_is_the_engines_ii_or_their_latency_on_one_row() {
        let prm = SeParams::paper(0);
        assert_eq!((issue_gap(&prm, false), issue_gap(&prm, true)), (136, 161));
        assert_eq!(ready_after(&Formats::for_n(10)), Formats::for_n(10).derived().pixel_bits as u64 + 1);
    }
}
