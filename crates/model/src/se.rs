//! The shading engine (SE) of paper 000 (Bang, Bae, Kyung, KAIST 1990: "A Graphics
//! Accelerator for Hidden Surface Removal and Color Shading"), cycle-exact: every output
//! port of `rtl::se` (`hdl-out/se.v`) on every clock, from the same inputs.
//!
//! One SE owns P = 64 pixels of a scanline, its region [XL_i, XR_i) = [64 i, 64 (i + 1));
//! several identical engines tile a screen (000 Fig. 5). A span command (Xl, Xr, and for z,
//! R, G and B the line f(X) = A X + B) is latched by the control block; the L and R serial
//! multipliers (Fig. 7, [`mul`]) evaluate each line at XL_i and XR_i; the bit-serial
//! midpoint-subdivision interpolator (Figs. 8-9, [`interp`]) fills the region's pixels;
//! the EPT (paper 002, [`crate::ept`], reused) masks the pixels outside [Xl, Xr]; the old-z
//! block holds the z-buffer's words, compared bit-serially with the new z per pixel
//! (Fig. 10, [`zcmp`]); write enable = mask AND z flag goes into the WE storage; the new-z
//! and RGB shift registers are written out through 4 interleaved ports (pixel 4j + k on
//! port k). Block diagram: Fig. 6.
//!
//! # Words and formats
//!
//! | quantity | format | note |
//! |---|---|---|
//! | Xl, Xr (`xl`, `xr`) | S12.0 [13] | pixel columns, inclusive; anywhere in the coordinate range |
//! | A, B of z (`za`, `zb`) | S(zw-1).frac [zw+frac] | slope per pixel and f(0), in z-word LSBs; taken modulo 2^(zw+frac) |
//! | A, B of R, G, B (`ra` .. `bb`) | S(cw-1).frac [cw+frac] | likewise in colour-word LSBs |
//! | z word (new z, old z) | [zw], integer | new z two's complement, compared unsigned (below) |
//! | colour word | S(cw-1).0 [cw] | |
//!
//! A word is an integer whose LSB is the SE's output LSB. The engine's arithmetic is exact
//! except for two roundings, both half up: f(XL_i) and f(XR_i) to integers (the
//! multipliers), and each pixel to the nearest integer (the interpolator). Because A and B
//! only matter modulo 2^(n+frac), a line with a large f(0) costs nothing; but the line's
//! values at the region's ends must fit the word, or the interpolation is wrong (Fig. 9
//! sign-extends them). The span backend ([`array`]) maps a depth LSB and a colour level to
//! a word LSB and sizes the words so that no line can overflow there (29 and 21 bits for
//! the default formats; 000's 24 and 16 bits overflow on steep slivers).
//!
//! **z compare.** The new z (two's complement) and the old z (the buffer's word, zero
//! extended) are compared *unsigned*: a negative new z reads as at least 2^(zw-1) and
//! is never nearer than a stored depth. So the SE clips z < 0 for free, and with the buffer
//! cleared to z_max, never writes z >= z_max: the same pixels paper 003's per-pixel z clip
//! and a LESS depth test keep.
//!
//! # Cycle schedule
//!
//! Cycle 0 is the clock in which `valid` and `ready` are both high. With the default
//! parameters (P = 64, zw = 24, cw = 16, frac = 16, so K = log2 P = 6 levels, A/B words of
//! ZA = 40 and CA = 32 bits, HEAD = ZA + 3 CA = 136):
//!
//! ```text
//! === CONTROL BLOCK: latch ==================================== cycle 0
//!   Xl, Xr -> ML_i, MR_i, hit (for the EPT); A, B of z, R, G, B into one A/B shift chain
//! === OLD-Z BLOCK: load ======================================= cycles 1 .. P/4 (1..16)
//!   oz_rd, oz_addr = j: the z-buffer's words of pixels 4j .. 4j+3 on oz0 .. oz3, same clock
//! === L/R MULTIPLIERS (Fig. 7) ================================ cycles M_j .. M_j + n_j + frac - 1
//!   A, B bits LSB first: z M_0 = 1 (1..40), R M_1 = 41 (41..72), G M_2 = 73, B M_3 = 105 (..136)
//!   bit c of A*X + B leaves each multiplier at M_j + c + 1
//! === INTERPOLATOR (Figs. 8, 9), stream of attribute j ========= from T_j = M_j + frac
//!   s = 0            the half (1) enters both ends; rounding carry := bit frac-1 of A*X + B
//!   s = 1 .. n       bits 0 .. n-1 of round(f(XL_i)), round(f(XR_i))
//!   s = n+1 .. n+K   sign extension (Fig. 9): the MSB again
//!   s = K+1 .. K+n   bit s-K-1 of every pixel's word shifts into the new-z or R/G/B block
//!   z:  T_0 = 17, pixel bits at cycles 24 .. 47   R: T_1 = 57, 64 .. 79
//!   G:  T_2 = 89, 96 .. 111                        B: T_3 = 121, 128 .. 143
//! === Z COMPARE (Fig. 10) ===================================== z's pixel bits, 24 .. 47
//!   old z shifts out of the old-z block LSB first beside the new z; flag per pixel
//! === WE STORAGE ============================================== z's s = K + zw + 1 (48)
//!   WE := EPT mask AND hit AND flag
//! === OUTPUT, 4-way interleaved =============================== B's s = K+cw+2 .. +P/4 (145..160)
//!   wr, wr_addr = j: pixels 4j + k on nz_k, r_k, g_k, b_k, we_k (k = 0..3)
//!   (wr low: nz_k, r_k, g_k, b_k, we_k are 0). One clock after B's last bit (s = K+cw+1):
//!   the RTL's new-z and colour blocks take a clock to write a bit plane
//! ```
//!
//! Latency: [`SeParams::latency`] = 161 clocks from the accept to the last write (000: 170
//! clocks per span, 17 us at 10 MHz). `ready` is high when idle and in the last clock of
//! the multipliers (cycle HEAD = 136), so spans can follow back to back every
//! [`SeParams::ii`] = 136 clocks: the next span's multipliers and old-z load overlap this
//! span's last colour bits and its output, which ends no later than the clock the next
//! span's first new-z bit goes in (160 here: a bit plane is written at the end of the
//! clock, after the port group is read). Constraints that make this hold
//! ([`SeParams::check`]): frac >= K + 2 (a stream ends before the next begins) and
//! P/4 <= frac (the output ends in time).
//!
//! The model keeps the state at word level: per pixel the old-z word (shifted out as 000's
//! shift register does), the new-z and R, G, B words (bit b set by bit plane b and read by
//! port group, as the RTL's corner-turning memories, `rtl::se::turn`, hold them), the z
//! flag and the WE bit; the interpolator's words are computed by [`interp::interp`] when
//! its stream starts and fed in bit by bit.

pub mod array;
pub mod interp;
pub mod mul;
pub mod zcmp;

use crate::ept::{ept, EptIn};
use fx::{wrap_s, wrap_u, Formats, RTL_CLASS};

/// Bits of X in the serial multipliers: 000 Fig. 7's 11 stages, screens up to 1024 wide.
pub const X_BITS: u32 = RTL_CLASS + 1;
/// Bits of a span's ends Xl, Xr: a pixel column anywhere in the coordinate range.
pub const SPAN_X_BITS: u32 = Formats::for_n(RTL_CLASS).derived().pixel_bits;
/// Memory ports (000: 4-way interleaving).
pub const PORTS: usize = 4;

/// The engine's parameters.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SeParams {
    /// Pixels per engine (the region's width), 8, 16, 32 or 64 (000: 64).
    pub p: u32,
    /// Bits of a z word (000: 24).
    pub zw: u32,
    /// Bits of a colour word (000: 16).
    pub cw: u32,
    /// Fraction bits of A and B.
    pub frac: u32,
    /// Engine index i: the region is [XL_i, XR_i) = [p i, p (i + 1)).
    pub index: u32,
}

impl SeParams {
    /// 000's engine: 64 pixels, 24-bit z, 16-bit colours; 16 fraction bits in A and B.
    pub const fn paper(index: u32) -> SeParams {
        SeParams { p: 64, zw: 24, cw: 16, frac: 16, index }
    }

    /// Whether the engine can be built with these parameters; the error says why not.
    pub fn check(&self) -> Result<(), String> {
        let (p, k) = (self.p, self.levels());
        if !(p.is_power_of_two() && (8..=64).contains(&p)) {
            return Err(format!("P = {p}: the region width must be 8, 16, 32 or 64"));
        }
        if !(2..=32).contains(&self.zw) || !(2..=32).contains(&self.cw) {
            return Err(format!("ZW = {}, CW = {}: word widths must be 2 to 32 bits", self.zw, self.cw));
        }
        if self.frac < k + 2 || self.frac < p / 4 {
            return Err(format!(
                "F = {}: P = {p} needs at least {} fraction bits (K + 2 = {}, so interpolator streams do not meet; P/4 = {}, so the output ends before the next span's z)",
                self.frac,
                (k + 2).max(p / 4),
                k + 2,
                p / 4
            ));
        }
        if self.zw + self.frac > 48 || self.cw + self.frac > 48 {
            return Err(format!(
                "A and B words of more than 48 bits (ZW, CW = {}, {}; F = {})",
                self.zw, self.cw, self.frac
            ));
        }
        if (self.index as u64 + 1) * p as u64 >= 1 << X_BITS {
            let last = (1u32 << X_BITS) - 1;
            return Err(format!(
                "I = {}: XR_i = P (I + 1) must be at most {last}, the multipliers' {X_BITS}-bit X",
                self.index
            ));
        }
        Ok(())
    }

    /// K = log2 P, the interpolator's levels.
    pub const fn levels(&self) -> u32 {
        self.p.trailing_zeros()
    }

    /// The region [XL_i, XR_i): XL_i = P i, XR_i = XL_i + P.
    pub fn region(&self) -> (i128, i128) {
        let xl = self.p as i128 * self.index as i128;
        (xl, xl + self.p as i128)
    }

    /// Bits of attribute `att`'s word (attributes in the order the engine interpolates
    /// them, 000: z first, then R, G, B): zw for z, cw for the colours.
    pub fn width(&self, att: usize) -> u32 {
        if att == 0 {
            self.zw
        } else {
            self.cw
        }
    }

    /// Bits of attribute `att`'s A and B words.
    pub fn ab_bits(&self, att: usize) -> u32 {
        self.width(att) + self.frac
    }

    /// The multipliers' clocks per span: all A and B bits, z then R, G, B.
    pub fn head(&self) -> u32 {
        (0..4).map(|j| self.ab_bits(j)).sum()
    }

    /// M_j: the cycle bit 0 of attribute `att`'s A and B enters the multipliers.
    pub fn mul_start(&self, att: usize) -> u32 {
        1 + (0..att).map(|j| self.ab_bits(j)).sum::<u32>()
    }

    /// T_j: the cycle attribute `att`'s interpolator stream starts (s = 0).
    pub fn stream_start(&self, att: usize) -> u32 {
        self.mul_start(att) + self.frac
    }

    /// Clocks from accepting a span to its last write, both included.
    pub fn latency(&self) -> u32 {
        self.stream_start(3) + self.levels() + self.cw + self.p / 4 + 2
    }

    /// Clocks between spans accepted back to back.
    pub fn ii(&self) -> u32 {
        self.head()
    }

    /// The interpolator's last clock of attribute `att`, as s: z's WE latch, a colour's MSB.
    fn stream_end(&self, att: usize) -> u32 {
        self.levels() + self.width(att) + (att == 0) as u32
    }
}

/// One span command, as the RTL's input ports.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SeCmd {
    /// Xl, Xr: first and last pixel of the span (inclusive), S12.0 [13].
    pub xl: i128,
    pub xr: i128,
    /// A (slope) of z, R, G, B with `frac` fraction bits, in word LSBs per pixel.
    pub a: [i128; 4],
    /// B (f(0), the intercept) of z, R, G, B with `frac` fraction bits, in word LSBs.
    pub b: [i128; 4],
}

/// The inputs of one clock.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SeIn {
    /// A span command is offered; taken when `ready` is high too.
    pub valid: bool,
    pub cmd: SeCmd,
    /// The z-buffer's words for the read `oz_rd`, `oz_addr` asks for this clock: pixel
    /// XL_i + 4 oz_addr + k on port k, zero extended to zw bits.
    pub oz: [u64; PORTS],
}

/// The outputs of one clock, before its rising edge.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SeOut {
    /// A span command can be taken this clock.
    pub ready: bool,
    /// Reading old z: pixels XL_i + 4 `oz_addr` + k, k = 0..3, wanted on `oz` this clock.
    pub oz_rd: bool,
    pub oz_addr: u32,
    /// Writing: pixels XL_i + 4 `wr_addr` + k, k = 0..3, on the ports below.
    pub wr: bool,
    pub wr_addr: u32,
    /// New z of each port's pixel (zw bits); this and `c`, `we` are 0 when `wr` is low.
    pub nz: [u64; PORTS],
    /// R, G, B of each port's pixel (cw bits each).
    pub c: [[u64; PORTS]; 3],
    /// Write enable of each port's pixel, for its z and its colour.
    pub we: [bool; PORTS],
}

/// The engine, clock by clock.
#[derive(Clone, Debug)]
pub struct Se {
    prm: SeParams,
    // Control block: the latched command and its masks.
    cmd: SeCmd,
    ml: u32,
    mr: u32,
    hit: bool,
    /// Head counter: 0 idle, else the clock since the accept (1 ..= HEAD).
    h: u32,
    /// Interpolator stream counter: 0 idle, else s + 1.
    sc: u32,
    /// Attribute in the interpolator (0 z, 1..3 R, G, B).
    att: usize,
    /// Output counter: 0 idle, else j + 1 while writing pixels 4j .. 4j + 3.
    dc: u32,
    /// The output starts next clock (B's last bit went into its block the clock before).
    dgo: bool,
    /// The pixel words the interpolator's current stream produces.
    words: Vec<u64>,
    ozr: Vec<u64>,
    nzr: Vec<u64>,
    cr: [Vec<u64>; 3],
    flag: Vec<bool>,
    wes: Vec<bool>,
}

impl Se {
    /// An engine at power-up: idle, every register zero (as the RTL's DFFs start).
    /// Panics on parameters [`SeParams::check`] rejects.
    pub fn new(prm: SeParams) -> Se {
        prm.check().unwrap_or_else(|e| panic!("{e}"));
        let p = prm.p as usize;
        Se {
            prm,
            cmd: SeCmd::default(),
            ml: 0,
            mr: 0,
            hit: false,
            h: 0,
            sc: 0,
            att: 0,
            dc: 0,
            dgo: false,
            words: vec![0; p],
            ozr: vec![0; p],
            nzr: vec![0; p],
            cr: std::array::from_fn(|_| vec![0; p]),
            flag: vec![false; p],
            wes: vec![false; p],
        }
    }

    /// Nothing in flight: every counter idle. Clocking an idle engine with `valid` low
    /// changes no register the outputs depend on.
    pub fn idle(&self) -> bool {
        self.h == 0 && self.sc == 0 && self.dc == 0 && !self.dgo
    }

    /// The outputs before this clock's edge (they depend on registers only).
    pub fn outputs(&self) -> SeOut {
        let q = self.prm.p / 4;
        SeOut {
            ready: self.h == 0 || self.h == self.prm.head(),
            oz_rd: (1..=q).contains(&self.h),
            oz_addr: self.h.wrapping_sub(1) & (q - 1),
            wr: self.dc != 0,
            wr_addr: self.dc.wrapping_sub(1) & (q - 1),
            nz: std::array::from_fn(|k| self.port(&self.nzr, k)),
            c: std::array::from_fn(|ch| std::array::from_fn(|k| self.port(&self.cr[ch], k))),
            we: std::array::from_fn(|k| self.dc != 0 && self.wes[k]),
        }
    }

    /// Port `k`'s word of block `words` while writing (port group dc - 1), else 0.
    fn port(&self, words: &[u64], k: usize) -> u64 {
        if self.dc == 0 {
            0
        } else {
            words[PORTS * (self.dc as usize - 1) + k]
        }
    }

    /// One clock: the outputs before the edge, then the edge.
    pub fn step(&mut self, i: &SeIn) -> SeOut {
        let out = self.outputs();
        let prm = self.prm;
        let (p, k, q) = (prm.p as usize, prm.levels(), prm.p / 4);

        // === INTERPOLATOR and the blocks it feeds, by stream clock s = sc - 1 ===
        let s = self.sc.wrapping_sub(1);
        let n = prm.width(self.att);
        let in_window = self.sc != 0 && (k + 1..=k + n).contains(&s);
        let we_latch = self.sc != 0 && self.att == 0 && s == k + prm.zw + 1;
        let b_done = self.sc != 0 && self.att == 3 && s == k + prm.cw;
        debug_assert!(!(we_latch && self.dc != 0), "schedule clash: WE latch during the output");
        debug_assert!(!(in_window && self.att == 0 && out.oz_rd), "schedule clash: old-z load during the z compare");
        if in_window {
            let bit = s - k - 1;
            for x in 0..p {
                let b = (self.words[x] >> bit) & 1;
                if self.att == 0 {
                    // RTL: bit plane into the new-z block, out of the old-z block, Zcmp per pixel.
                    let oz = self.ozr[x] & 1 == 1;
                    self.flag[x] = zcmp::step(self.flag[x], bit == 0, b == 1, oz);
                    self.ozr[x] >>= 1;
                    self.nzr[x] = (self.nzr[x] & !(1 << bit)) | (b << bit);
                } else {
                    let reg = &mut self.cr[self.att - 1][x];
                    *reg = (*reg & !(1 << bit)) | (b << bit);
                }
            }
        }
        if we_latch {
            let mask = ept(p, EptIn { xl: self.ml, xr: self.mr }).px;
            for ((we, m), flag) in self.wes.iter_mut().zip(mask).zip(&self.flag) {
                *we = m && self.hit && *flag;
            }
        }

        // === OUTPUT: the WE storage shifts down by one port group ===
        if self.dc != 0 {
            self.wes.rotate_left(PORTS);
            self.wes[p - PORTS..].fill(false);
        }

        // === OLD-Z BLOCK: load 4 words, shifting down ===
        if out.oz_rd {
            self.ozr.rotate_left(PORTS);
            for (port, w) in i.oz.iter().enumerate() {
                self.ozr[p - PORTS + port] = w & ((1u64 << prm.zw) - 1);
            }
        }

        // === Counters ===
        let start = (0..4).find(|&j| self.h != 0 && self.h + 1 == prm.stream_start(j));
        self.dc = if self.dgo {
            1
        } else if self.dc == 0 || self.dc == q {
            0
        } else {
            self.dc + 1
        };
        self.dgo = b_done;
        self.sc = if start.is_some() {
            1
        } else if self.sc == 0 || s == prm.stream_end(self.att) {
            0
        } else {
            self.sc + 1
        };
        if let Some(j) = start {
            // The multipliers have the latched command's A and B; their rounded ends are
            // what the interpolator's stream carries.
            let (xl, xr) = prm.region();
            let e = |x| mul::endpoint(self.cmd.a[j], self.cmd.b[j], x, prm.width(j), prm.frac);
            let w = prm.width(j);
            self.words = interp::interp(e(xl), e(xr), prm.p).into_iter().map(|v| wrap_u(v, w) as u64).collect();
            self.att = j;
        }

        // === CONTROL BLOCK: head counter and command latch ===
        let accept = i.valid && out.ready;
        self.h = if accept {
            1
        } else if self.h == 0 || self.h == prm.head() {
            0
        } else {
            self.h + 1
        };
        if accept {
            self.latch(&i.cmd);
        }
        out
    }

    /// The control block at an accept: the command, and ML_i, MR_i and `hit` for the EPT.
    fn latch(&mut self, cmd: &SeCmd) {
        let prm = self.prm;
        for x in [cmd.xl, cmd.xr] {
            assert_eq!(wrap_s(x, SPAN_X_BITS), x, "span end {x} does not fit {SPAN_X_BITS} bits");
        }
        let (lo, hi) = (prm.region().0, prm.region().1 - 1);
        // RTL: unsigned compares of the sign-flipped ends; the low K bits are the offset in
        // the region, since XL_i is a multiple of P.
        let offset = |x: i128| (x - lo).rem_euclid(prm.p as i128) as u32;
        self.ml = if cmd.xl >= lo { offset(cmd.xl) } else { 0 };
        self.mr = if cmd.xr <= hi { offset(cmd.xr) } else { prm.p - 1 };
        self.hit = cmd.xl <= cmd.xr && cmd.xl <= hi && cmd.xr >= lo;
        let wrap = |v: &[i128; 4]| std::array::from_fn(|j| wrap_s(v[j], prm.ab_bits(j)));
        self.cmd = SeCmd { xl: cmd.xl, xr: cmd.xr, a: wrap(&cmd.a), b: wrap(&cmd.b) };
    }
}

/// The line through (x0, v0) and (x1, v1) (x0 < x1, values in word LSBs) as A and B with
/// `frac` fraction bits: A rounded half up, B so that f(x0) = v0 exactly.
pub fn line_through(x0: i128, v0: i128, x1: i128, v1: i128, frac: u32) -> (i128, i128) {
    assert!(x0 < x1, "x0 = {x0} must be left of x1 = {x1}");
    let a = (((v1 - v0) << (frac + 1)) + (x1 - x0)).div_euclid(2 * (x1 - x0));
    (a, (v0 << frac) - x0 * a)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The schedule of the module doc, for 000's widths.
    #[test]
    fn se_schedule_paper_widths() {
        let prm = SeParams::paper(0);
        prm.check().unwrap();
        let m: Vec<u32> = (0..4).map(|j| prm.mul_start(j)).collect();
        let t: Vec<u32> = (0..4).map(|j| prm.stream_start(j)).collect();
        assert_eq!((prm.head(), m, t), (136, vec![1, 41, 73, 105], vec![17, 57, 89, 121]));
        assert_eq!((prm.latency(), prm.ii()), (161, 136));
        assert_eq!(SPAN_X_BITS, 13);
    }

    #[test]
    fn se_params_check_names_the_problem() {
        let bad = |prm: SeParams, want: &str| {
            let e = prm.check().expect_err(want);
            assert!(e.contains(want), "{e}");
        };
        bad(SeParams { p: 128, ..SeParams::paper(0) }, "P = 128");
        bad(SeParams { frac: 12, ..SeParams::paper(0) }, "at least 16 fraction bits");
        bad(SeParams::paper(31), "I = 31");
        SeParams::paper(30).check().unwrap();
    }

    #[test]
    fn se_line_through_hits_its_first_point() {
        let (a, b) = line_through(2, 0x010, 9, 0x3ff, 16);
        assert_eq!(a, 9_427_822); // 1007/7 = 143.857 with 16 fraction bits
        assert_eq!(2 * a + b, 0x010 << 16);
    }
}
