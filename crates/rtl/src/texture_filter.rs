//! The filter stage of paper 001's texture unit (Woo, Jang and Lee 2004, section II-5): texel
//! decode, the bilinear filter with linear or Gaussian-approximating weights (Fig. 6), the
//! blend between two mip levels and the texture environment, one pixel a clock.
//!
//! Model, bit for bit: `model::texture_filter::texel` at `fx::TexFormats::DEFAULT`
//! (subtexel 8, weight 8, lod_frac 6 bits), then `model::texture_filter::environment`
//! with the fragment colour `[R, G, B, 255]`. Tests: `testbenches/tests/texture_filter.rs`.
//! Emitted: `hdl-out/texture_filter.v` (`edgepaint emit --unit texture_filter`).
//!
//! # Stages
//!
//! ```text
//!  stage  register       what                                              multipliers
//!  1      s1_*           decode the 8 words by bit replication (Decode);   -
//!                        the 4 weights a0 b0 a1 b1 in 0..=2^8 (Weight:
//!                        alpha's top bits, or the Gaussian ROM of Fig. 6)
//!  2      Level::h_r     per level, channel and row j:                      16 x (9 x 10)
//!                        H_j = T(i0,j)·(2^8 - a) + T(i1,j)·a  [16 bits]
//!  3      Level::c_r     per level and channel: V = H_0·(2^8 - b) + H_1·b   8 x (17 x 10)
//!                        [24 bits], C = (V + 2^15) >> 16: half up, once
//!  4      s4_cs          C = (C0·(2^6 - f) + C1·f + 2^5) >> 6               4 x (9 x 7)
//!                        (f = 0 with one level: C = C0)
//!  5      s5_*           the environment: round(x·y / 255) exactly          3 x (9 x 9)
//!                        (EnvChannel), alpha As or 255 (DECAL)
//! ```
//!
//! Latency [`LATENCY`] = 5 enabled clocks: a pixel presented in cycle c with `en` high is on
//! `out_*` in cycle c + 5 when `en` is high in cycles c .. c + 4. `en` low holds every
//! register (the texture cache stalls the whole texture unit so); the outputs hold too.
//! `inp_valid` travels with the pixel to `out_valid`; the data of an invalid pixel flows
//! through all the same.
//!
//! Each weighted pair is computed as x0·2^S + (x1 - x0)·w ([`Lerp`]): one signed multiply
//! instead of two, the same integer as the model's x0·(2^S - w) + x1·w. The model's single
//! rounding of Σ T·w_s·w_t is kept: H and V carry every bit (H ≤ 255·2^8, V ≤ 255·2^16),
//! and only V is rounded. Products use `crate::mul::Mul` (rust-hdl's `*` is 16 x 16 only);
//! every operand is given one bit more than its unsigned width, so it reads as signed.
//!
//! # Codes
//!
//! `inp_format` is the index in `texture::TexelFormat::ALL` ([`FORMATS`]: 0 Rgb565,
//! 1 Rgba5551, 2 Rgba4444, 3 Rgb888, 4 Rgba8888); codes 5 to 7 decode as Rgba8888.
//! `inp_env` is the index in `texture::EnvMode`'s declaration order ([`ENVS`]: 0 Replace,
//! 1 Modulate, 2 Decal, 3 Blend, 4 Add); codes 5 to 7 act as Replace. `inp_gaussian`
//! chooses `Weights::Gaussian`, else `Weights::Linear`. The names in [`FORMATS`] and
//! [`ENVS`] are those scene files give (`scene::TextureSpec`'s JSON).
//!
//! The fragment's alpha is 255 (001's environment takes the lit colour, which has none), so
//! MODULATE, BLEND and ADD give alpha round(255·As / 255) = As and DECAL gives 255: the unit
//! computes no product for alpha.

use crate::emit::{emit, Emitted};
use crate::mul::Mul;
use crate::parts::defaults;
use crate::Params;
use blank::Blank;
use fx::TexFormats;
use rust_hdl::prelude::*;
use rust_hdl::widgets::prelude::ROM;

/// Fraction bits of texel coordinates, alpha and beta (`TexFormats::subtexel`).
pub const SUB: usize = TexFormats::DEFAULT.subtexel as usize;
/// Fraction bits of the bilinear weights (`TexFormats::weight`).
pub const WT: usize = TexFormats::DEFAULT.weight as usize;
/// Fraction bits of the weight between levels (`TexFormats::lod_frac`).
pub const LF: usize = TexFormats::DEFAULT.lod_frac as usize;
/// Bits of a weight in 0..=2^WT.
pub const W1: usize = WT + 1;
/// Bits of a horizontal sum H = T0·(2^WT - a) + T1·a of 8-bit texels.
const H: usize = 8 + WT;
/// Bits of a bilinear sum V = H0·(2^WT - b) + H1·b.
const V: usize = H + WT;
/// Bits of the sum between levels C0·(2^LF - f) + C1·f.
const BL: usize = 8 + LF;

/// Enabled clocks from a pixel in to its colour out.
pub const LATENCY: usize = 5;

/// The `inp_format` codes: `texture::TexelFormat::ALL`'s order, by the names scene files
/// use. Codes 5 to 7 decode as Rgba8888.
pub const FORMATS: [&str; 5] = ["rgb565", "rgba5551", "rgba4444", "rgb888", "rgba8888"];
/// The `inp_env` codes: `texture::EnvMode`'s declaration order, by the names scene files
/// use. Codes 5 to 7 act as Replace.
pub const ENVS: [&str; 5] = ["replace", "modulate", "decal", "blend", "add"];

const RGB565: u64 = 0;
const RGBA5551: u64 = 1;
const RGBA4444: u64 = 2;
const RGB888: u64 = 3;
const MODULATE: u64 = 1;
const DECAL: u64 = 2;
const BLEND: u64 = 3;
const ADD: u64 = 4;

/// One texture word decoded (`model::texture_filter::decode`): each c-bit channel
/// widened to 8 bits by repeating its bits from the top ({c, c[4:2]} for 5 bits, {c, c[5:4]}
/// for 6, {c, c} for 4, eight copies of a 1-bit alpha), alpha 255 for a format without one.
/// Channels from the word's low bits up: the last channel (alpha, or blue) lowest. Bits
/// above the format's are ignored. Combinational.
#[derive(LogicBlock, Blank)]
pub struct Decode {
    /// The texel's word, its format's bits low.
    pub word: Signal<In, Bits<32>>,
    /// The format code ([`FORMATS`]).
    pub format: Signal<In, Bits<3>>,
    /// R 31..24, G 23..16, B 15..8, A 7..0.
    pub rgba: Signal<Out, Bits<32>>,
    rgb565: Constant<Bits<3>>,
    rgba5551: Constant<Bits<3>>,
    rgba4444: Constant<Bits<3>>,
    rgb888: Constant<Bits<3>>,
    /// The channels' codes and each widened to 8 bits.
    c5r: Signal<Local, Bits<5>>,
    c5g: Signal<Local, Bits<5>>,
    c6g: Signal<Local, Bits<6>>,
    r: Signal<Local, Bits<8>>,
    g: Signal<Local, Bits<8>>,
    b: Signal<Local, Bits<8>>,
    a: Signal<Local, Bits<8>>,
}

impl Default for Decode {
    fn default() -> Self {
        Decode {
            rgb565: Constant::new(RGB565.to_bits()),
            rgba5551: Constant::new(RGBA5551.to_bits()),
            rgba4444: Constant::new(RGBA4444.to_bits()),
            rgb888: Constant::new(RGB888.to_bits()),
            ..Decode::blank()
        }
    }
}

impl Logic for Decode {
    #[hdl_gen]
    fn update(&mut self) {
        self.c5r.next = self.word.val().get_bits::<5>(11);
        self.c5g.next = self.word.val().get_bits::<5>(6);
        self.c6g.next = self.word.val().get_bits::<6>(5);
        // Rgba8888, and codes 5 to 7.
        self.r.next = self.word.val().get_bits::<8>(24);
        self.g.next = self.word.val().get_bits::<8>(16);
        self.b.next = self.word.val().get_bits::<8>(8);
        self.a.next = self.word.val().get_bits::<8>(0);
        if self.format.val() == self.rgb565.val() {
            // R 15..11, G 10..5, B 4..0.
            self.r.next = (bit_cast::<8, 5>(self.c5r.val()) << 3) | bit_cast::<8, 3>(self.c5r.val().get_bits::<3>(2));
            self.g.next = (bit_cast::<8, 6>(self.c6g.val()) << 2) | bit_cast::<8, 2>(self.c6g.val().get_bits::<2>(4));
            self.b.next = (bit_cast::<8, 5>(self.word.val().get_bits::<5>(0)) << 3)
                | bit_cast::<8, 3>(self.word.val().get_bits::<3>(2));
            self.a.next = 255.into();
        }
        if self.format.val() == self.rgba5551.val() {
            // R 15..11, G 10..6, B 5..1, A 0.
            self.r.next = (bit_cast::<8, 5>(self.c5r.val()) << 3) | bit_cast::<8, 3>(self.c5r.val().get_bits::<3>(2));
            self.g.next = (bit_cast::<8, 5>(self.c5g.val()) << 3) | bit_cast::<8, 3>(self.c5g.val().get_bits::<3>(2));
            self.b.next = (bit_cast::<8, 5>(self.word.val().get_bits::<5>(1)) << 3)
                | bit_cast::<8, 3>(self.word.val().get_bits::<3>(3));
            self.a.next = 0.into();
            if self.word.val().get_bit(0) {
                self.a.next = 255.into();
            }
        }
        if self.format.val() == self.rgba4444.val() {
            // R 15..12, G 11..8, B 7..4, A 3..0.
            self.r.next = (bit_cast::<8, 4>(self.word.val().get_bits::<4>(12)) << 4)
                | bit_cast::<8, 4>(self.word.val().get_bits::<4>(12));
            self.g.next = (bit_cast::<8, 4>(self.word.val().get_bits::<4>(8)) << 4)
                | bit_cast::<8, 4>(self.word.val().get_bits::<4>(8));
            self.b.next = (bit_cast::<8, 4>(self.word.val().get_bits::<4>(4)) << 4)
                | bit_cast::<8, 4>(self.word.val().get_bits::<4>(4));
            self.a.next = (bit_cast::<8, 4>(self.word.val().get_bits::<4>(0)) << 4)
                | bit_cast::<8, 4>(self.word.val().get_bits::<4>(0));
        }
        if self.format.val() == self.rgb888.val() {
            // R 23..16, G 15..8, B 7..0.
            self.r.next = self.word.val().get_bits::<8>(16);
            self.g.next = self.word.val().get_bits::<8>(8);
            self.b.next = self.word.val().get_bits::<8>(0);
            self.a.next = 255.into();
        }
        self.rgba.next = (bit_cast::<32, 8>(self.r.val()) << 24)
            | (bit_cast::<32, 8>(self.g.val()) << 16)
            | (bit_cast::<32, 8>(self.b.val()) << 8)
            | bit_cast::<32, 8>(self.a.val());
    }
}

/// The weight of the second texel of a pair at fraction `alpha`
/// (`model::texture_filter::weight`): alpha's top `WT` bits (linear), or the Gaussian
/// ROM, round((3x² - 2x³)·2^WT) at x = alpha / 2^SUB (001 Fig. 6), whose entries are
/// `model::texture_filter::gaussian_table`'s by construction. Combinational.
#[derive(LogicBlock, Blank)]
pub struct Weight {
    /// The fraction, `SUB` bits.
    pub alpha: Signal<In, Bits<SUB>>,
    /// High: the Gaussian weights; low: linear.
    pub gaussian: Signal<In, Bit>,
    /// The weight, 0..=2^WT.
    pub w: Signal<Out, Bits<W1>>,
    #[given]
    rom: ROM<Bits<W1>, SUB>,
    /// alpha >> down << up: SUB - WT or 0, WT - SUB or 0.
    down: Constant<Bits<8>>,
    up: Constant<Bits<8>>,
}

impl Default for Weight {
    fn default() -> Self {
        let table = model::texture_filter::gaussian_table(&TexFormats::DEFAULT);
        assert_eq!(table.len(), 1 << SUB, "one Gaussian weight per fraction");
        assert!(table.iter().all(|&w| w <= 1 << WT), "Gaussian weights in 0..=2^{WT}");
        Weight {
            down: Constant::new(SUB.saturating_sub(WT).to_bits()),
            up: Constant::new(WT.saturating_sub(SUB).to_bits()),
            ..Weight::blank(WeightGiven { rom: ROM::from(table.into_iter().map(|w| Bits::<W1>::from(u64::from(w)))) })
        }
    }
}

impl Logic for Weight {
    #[hdl_gen]
    fn update(&mut self) {
        self.rom.address.next = self.alpha.val();
        self.w.next = bit_cast::<W1, SUB>(self.alpha.val() >> self.down.val()) << self.up.val();
        if self.gaussian.val() {
            self.w.next = self.rom.data.val();
        }
    }
}

/// `y = x0·2^S + (x1 - x0)·w` = x0·(2^S - w) + x1·w, exactly, for `w` in 0..=2^S and
/// unsigned `X`-bit `x0`, `x1`: the weighted pair of the bilinear filter and of the blend
/// between levels. `W = S + 1` bits of weight; the difference is `D = X + 1` bits signed,
/// the weight `WB = W + 1` bits signed (a zero on top), the product and sum `P = Y + 1`
/// bits, of which `y` is the low `Y = X + S` (the sum lies in 0..=(2^X - 1)·2^S, so those
/// are it). Combinational.
#[derive(LogicBlock, Blank)]
pub struct Lerp<const X: usize, const D: usize, const W: usize, const WB: usize, const P: usize, const Y: usize> {
    pub x0: Signal<In, Bits<X>>,
    pub x1: Signal<In, Bits<X>>,
    pub w: Signal<In, Bits<W>>,
    pub y: Signal<Out, Bits<Y>>,
    /// S = W - 1.
    s: Constant<Bits<8>>,
    mul: Mul<D, WB, P>,
}

impl<const X: usize, const D: usize, const W: usize, const WB: usize, const P: usize, const Y: usize> Default
    for Lerp<X, D, W, WB, P, Y>
{
    fn default() -> Self {
        assert!(D == X + 1 && WB == W + 1 && Y == X + W - 1 && P == Y + 1, "Lerp<{X}, {D}, {W}, {WB}, {P}, {Y}>");
        Lerp { s: Constant::new((W - 1).to_bits()), ..Lerp::blank() }
    }
}

impl<const X: usize, const D: usize, const W: usize, const WB: usize, const P: usize, const Y: usize> Logic
    for Lerp<X, D, W, WB, P, Y>
{
    #[hdl_gen]
    fn update(&mut self) {
        self.mul.a.next = bit_cast::<D, X>(self.x1.val()) - bit_cast::<D, X>(self.x0.val());
        self.mul.b.next = bit_cast::<WB, W>(self.w.val());
        self.y.next = bit_cast::<Y, P>((bit_cast::<P, X>(self.x0.val()) << self.s.val()) + self.mul.p.val());
    }
}

/// Stage 2's pairs along s: 8-bit texels, weight 0..=2^WT.
type HLerp = Lerp<8, 9, W1, { W1 + 1 }, { H + 1 }, H>;
/// Stage 3's pairs along t: the `H`-bit sums, weight 0..=2^WT.
type VLerp = Lerp<H, { H + 1 }, W1, { W1 + 1 }, { V + 1 }, V>;
/// Stage 4's pairs of levels: 8-bit colours, weight 0..2^LF.
type LevelLerp = Lerp<8, 9, { LF + 1 }, { LF + 2 }, { BL + 1 }, BL>;

/// `y = (x + 2^(S-1)) >> S`, S = IN - 8: a sum of 8-bit values weighted by 2^S in all,
/// rounded half up to 8 bits. x ≤ 255·2^S, so x + 2^(S-1) < 2^IN: nothing wraps (and in
/// Verilog the sum is `IN` bits wide, as here). Combinational.
#[derive(LogicBlock, Blank)]
pub struct Round<const IN: usize> {
    pub x: Signal<In, Bits<IN>>,
    pub y: Signal<Out, Bits<8>>,
    half: Constant<Bits<IN>>,
    shift: Constant<Bits<8>>,
}

impl<const IN: usize> Default for Round<IN> {
    fn default() -> Self {
        assert!(IN > 8, "Round<{IN}>");
        Round {
            half: Constant::new((1u64 << (IN - 9)).to_bits()),
            shift: Constant::new((IN - 8).to_bits()),
            ..Round::blank()
        }
    }
}

impl<const IN: usize> Logic for Round<IN> {
    #[hdl_gen]
    fn update(&mut self) {
        self.y.next = bit_cast::<8, IN>((self.x.val() + self.half.val()) >> self.shift.val());
    }
}

/// One level's bilinear filter (`model::texture_filter::bilinear`), stages 2 and 3:
/// `c` is the filtered colour of the texels and weights given two enabled clocks before.
/// Channel lane j is bits 8j..8j+7 of a texel and of `c` (j = 0: A, 3: R).
#[derive(LogicBlock, Blank)]
pub struct Level {
    pub clock: Signal<In, Clock>,
    pub en: Signal<In, Bit>,
    /// The decoded footprint `[T(i0, j0), T(i1, j0), T(i0, j1), T(i1, j1)]`.
    pub t0: Signal<In, Bits<32>>,
    pub t1: Signal<In, Bits<32>>,
    pub t2: Signal<In, Bits<32>>,
    pub t3: Signal<In, Bits<32>>,
    /// The weights of T(i1, .) along s and T(., j1) along t, 0..=2^WT.
    pub a: Signal<In, Bits<W1>>,
    pub b: Signal<In, Bits<W1>>,
    /// The filtered colour, R 31..24 .. A 7..0.
    pub c: Signal<Out, Bits<32>>,
    /// Lane j of row 0 (t0, t1) at j, of row 1 (t2, t3) at 4 + j.
    h: [HLerp; 8],
    /// Stage 2: the horizontal sums, and b.
    h_r: [DFF<Bits<H>>; 8],
    b_r: DFF<Bits<W1>>,
    v: [VLerp; 4],
    /// (V + 2^(2 WT - 1)) >> 2 WT.
    round: [Round<V>; 4],
    /// Stage 3: each lane's colour.
    c_r: [DFF<Bits<8>>; 4],
}

impl Default for Level {
    fn default() -> Self {
        Level { h: defaults(), h_r: defaults(), v: defaults(), round: defaults(), c_r: defaults(), ..Level::blank() }
    }
}

impl Logic for Level {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, b_r);
        for i in 0..8 {
            self.h_r[i].clock.next = self.clock.val();
            self.h_r[i].d.next = self.h_r[i].q.val();
        }
        for j in 0..4 {
            self.c_r[j].clock.next = self.clock.val();
            self.c_r[j].d.next = self.c_r[j].q.val();
        }
        for j in 0..4 {
            self.h[j].x0.next = self.t0.val().get_bits::<8>(j * 8);
            self.h[j].x1.next = self.t1.val().get_bits::<8>(j * 8);
            self.h[j].w.next = self.a.val();
            self.h[j + 4].x0.next = self.t2.val().get_bits::<8>(j * 8);
            self.h[j + 4].x1.next = self.t3.val().get_bits::<8>(j * 8);
            self.h[j + 4].w.next = self.a.val();
            self.v[j].x0.next = self.h_r[j].q.val();
            self.v[j].x1.next = self.h_r[j + 4].q.val();
            self.v[j].w.next = self.b_r.q.val();
            self.round[j].x.next = self.v[j].y.val();
        }
        if self.en.val() {
            for i in 0..8 {
                self.h_r[i].d.next = self.h[i].y.val();
            }
            self.b_r.d.next = self.b.val();
            for j in 0..4 {
                self.c_r[j].d.next = self.round[j].y.val();
            }
        }
        self.c.next = (bit_cast::<32, 8>(self.c_r[3].q.val()) << 24)
            | (bit_cast::<32, 8>(self.c_r[2].q.val()) << 16)
            | (bit_cast::<32, 8>(self.c_r[1].q.val()) << 8)
            | bit_cast::<32, 8>(self.c_r[0].q.val());
    }
}

/// One colour channel of the texture environment (`model::texture_filter::environment`)
/// of fragment channel `cf`, texel channel `cs` and texel alpha `a_s`, as
/// P = base + d·m, then round(P / 255) = (P + 128 + ((P + 128) >> 8)) >> 8 (exact for
/// P ≤ 255², `env::div255`):
///
/// | mode | base | d | m | out |
/// |---|---|---|---|---|
/// | MODULATE | 0 | cf | cs | round(cf·cs / 255) |
/// | DECAL | 255·cf | cs - cf | As | round((cf·(255 - As) + cs·As) / 255) |
/// | BLEND | 0 | cf | 255 - cs | round(cf·(255 - cs) / 255) |
/// | ADD | | | | min(cf + cs, 255) |
/// | REPLACE, 5..7 | | | | cs |
///
/// Combinational.
#[derive(LogicBlock, Blank)]
pub struct EnvChannel {
    pub cf: Signal<In, Bits<8>>,
    pub cs: Signal<In, Bits<8>>,
    pub a_s: Signal<In, Bits<8>>,
    /// The mode code ([`ENVS`]).
    pub mode: Signal<In, Bits<3>>,
    pub out: Signal<Out, Bits<8>>,
    mul: Mul<9, 9, 17>,
    /// base + d·m, in 0..=255²; then + 128.
    prod: Signal<Local, Bits<17>>,
    biased: Signal<Local, Bits<17>>,
    /// round(P / 255), in 0..=255 (the sum before the shift is below 2^17).
    rounded: Signal<Local, Bits<8>>,
    /// cf + cs.
    sum: Signal<Local, Bits<9>>,
    /// 255 - cs, in 8 bits: Verilog would widen `cs` to the 9 bits of `mul.b` before
    /// inverting it.
    inv_cs: Signal<Local, Bits<8>>,
    base: Signal<Local, Bits<17>>,
    modulate: Constant<Bits<3>>,
    decal: Constant<Bits<3>>,
    blend: Constant<Bits<3>>,
    add: Constant<Bits<3>>,
}

impl Default for EnvChannel {
    fn default() -> Self {
        EnvChannel {
            modulate: Constant::new(MODULATE.to_bits()),
            decal: Constant::new(DECAL.to_bits()),
            blend: Constant::new(BLEND.to_bits()),
            add: Constant::new(ADD.to_bits()),
            ..EnvChannel::blank()
        }
    }
}

impl Logic for EnvChannel {
    #[hdl_gen]
    fn update(&mut self) {
        // MODULATE, and the default.
        self.base.next = 0.into();
        self.mul.a.next = bit_cast::<9, 8>(self.cf.val());
        self.mul.b.next = bit_cast::<9, 8>(self.cs.val());
        self.inv_cs.next = !self.cs.val();
        if self.mode.val() == self.blend.val() {
            self.mul.b.next = bit_cast::<9, 8>(self.inv_cs.val());
        }
        if self.mode.val() == self.decal.val() {
            self.base.next = (bit_cast::<17, 8>(self.cf.val()) << 8) - bit_cast::<17, 8>(self.cf.val());
            self.mul.a.next = bit_cast::<9, 8>(self.cs.val()) - bit_cast::<9, 8>(self.cf.val());
            self.mul.b.next = bit_cast::<9, 8>(self.a_s.val());
        }
        self.prod.next = self.base.val() + self.mul.p.val();
        self.biased.next = self.prod.val() + 128;
        self.rounded.next = bit_cast::<8, 17>((self.biased.val() + (self.biased.val() >> 8)) >> 8);
        self.sum.next = bit_cast::<9, 8>(self.cf.val()) + bit_cast::<9, 8>(self.cs.val());
        // REPLACE, and codes 5 to 7.
        self.out.next = self.cs.val();
        if (self.mode.val() == self.modulate.val())
            | (self.mode.val() == self.decal.val())
            | (self.mode.val() == self.blend.val())
        {
            self.out.next = self.rounded.val();
        }
        if self.mode.val() == self.add.val() {
            self.out.next = self.sum.val().get_bits::<8>(0);
            if self.sum.val().get_bit(8) {
                self.out.next = 255.into();
            }
        }
    }
}

/// The filter stage of 001's texture unit: see the module doc.
#[derive(LogicBlock, Blank)]
pub struct TextureFilter {
    pub clock: Signal<In, Clock>,
    /// High: every register moves on; low: every register holds (a stall).
    pub en: Signal<In, Bit>,
    /// A pixel is on the inputs.
    pub inp_valid: Signal<In, Bit>,
    /// Level 0's footprint `[T(i0, j0), T(i1, j0), T(i0, j1), T(i1, j1)]`, texture words
    /// (the format's bits low).
    pub inp_words0_0: Signal<In, Bits<32>>,
    pub inp_words0_1: Signal<In, Bits<32>>,
    pub inp_words0_2: Signal<In, Bits<32>>,
    pub inp_words0_3: Signal<In, Bits<32>>,
    /// Level 1's footprint, read when `inp_two_levels`.
    pub inp_words1_0: Signal<In, Bits<32>>,
    pub inp_words1_1: Signal<In, Bits<32>>,
    pub inp_words1_2: Signal<In, Bits<32>>,
    pub inp_words1_3: Signal<In, Bits<32>>,
    /// Level 0's fractions along s and t, U0.SUB.
    pub inp_alpha0: Signal<In, Bits<SUB>>,
    pub inp_beta0: Signal<In, Bits<SUB>>,
    /// Level 1's fractions along s and t, U0.SUB.
    pub inp_alpha1: Signal<In, Bits<SUB>>,
    pub inp_beta1: Signal<In, Bits<SUB>>,
    /// The weight of level 1 between the two, U0.LF.
    pub inp_frac: Signal<In, Bits<LF>>,
    /// High: blend the two levels; low: level 0 alone.
    pub inp_two_levels: Signal<In, Bit>,
    /// The texel format code ([`FORMATS`]).
    pub inp_format: Signal<In, Bits<3>>,
    /// High: 001's Gaussian weights (Fig. 6); low: linear.
    pub inp_gaussian: Signal<In, Bit>,
    /// The environment mode code ([`ENVS`]).
    pub inp_env: Signal<In, Bits<3>>,
    /// The fragment's lit colour: R 23..16, G 15..8, B 7..0 (alpha 255).
    pub inp_cf: Signal<In, Bits<24>>,
    /// `inp_valid` of the pixel `LATENCY` enabled clocks before.
    pub out_valid: Signal<Out, Bit>,
    /// Its colour: R 31..24, G 23..16, B 15..8, A 7..0.
    pub out_rgba: Signal<Out, Bits<32>>,
    /// Level l's word k at 4 l + k.
    decode: [Decode; 8],
    /// alpha0, beta0, alpha1, beta1.
    weight: [Weight; 4],
    /// Stage 1: the decoded texels, the weights and the pixel's other inputs.
    s1_texel: [DFF<Bits<32>>; 8],
    s1_a: [DFF<Bits<W1>>; 2],
    s1_b: [DFF<Bits<W1>>; 2],
    s1_frac: DFF<Bits<LF>>,
    s1_two: DFF<Bit>,
    s1_env: DFF<Bits<3>>,
    s1_cf: DFF<Bits<24>>,
    s1_valid: DFF<Bit>,
    /// Stages 2 and 3 of each level.
    level: [Level; 2],
    s2_frac: DFF<Bits<LF>>,
    s2_two: DFF<Bit>,
    s2_env: DFF<Bits<3>>,
    s2_cf: DFF<Bits<24>>,
    s2_valid: DFF<Bit>,
    s3_frac: DFF<Bits<LF>>,
    s3_two: DFF<Bit>,
    s3_env: DFF<Bits<3>>,
    s3_cf: DFF<Bits<24>>,
    s3_valid: DFF<Bit>,
    /// Lane j (bits 8j..) of the two levels.
    mix: [LevelLerp; 4],
    /// The weight of level 1: `frac`, or 0 with one level.
    mix_w: Signal<Local, Bits<{ LF + 1 }>>,
    /// (C0·(2^LF - f) + C1·f + 2^(LF - 1)) >> LF.
    mix_round: [Round<BL>; 4],
    /// Stage 4: the filtered texel Cs, lane j.
    s4_cs: [DFF<Bits<8>>; 4],
    s4_env: DFF<Bits<3>>,
    s4_cf: DFF<Bits<24>>,
    s4_valid: DFF<Bit>,
    /// R, G, B.
    environment: [EnvChannel; 3],
    /// The output's alpha: As, or 255 for DECAL.
    alpha: Signal<Local, Bits<8>>,
    /// Stage 5: the output.
    s5_rgba: DFF<Bits<32>>,
    s5_valid: DFF<Bit>,
    decal: Constant<Bits<3>>,
}

impl Default for TextureFilter {
    fn default() -> Self {
        TextureFilter {
            decode: defaults(),
            weight: defaults(),
            s1_texel: defaults(),
            s1_a: defaults(),
            s1_b: defaults(),
            level: defaults(),
            mix: defaults(),
            mix_round: defaults(),
            s4_cs: defaults(),
            environment: defaults(),
            decal: Constant::new(DECAL.to_bits()),
            ..TextureFilter::blank()
        }
    }
}

impl Logic for TextureFilter {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, s1_frac, s1_two, s1_env, s1_cf, s1_valid, s2_frac, s2_two, s2_env, s2_cf, s2_valid, s3_frac,
            s3_two, s3_env, s3_cf, s3_valid, s4_env, s4_cf, s4_valid, s5_rgba, s5_valid
        );
        for i in 0..8 {
            self.s1_texel[i].clock.next = self.clock.val();
            self.s1_texel[i].d.next = self.s1_texel[i].q.val();
        }
        for l in 0..2 {
            self.s1_a[l].clock.next = self.clock.val();
            self.s1_a[l].d.next = self.s1_a[l].q.val();
            self.s1_b[l].clock.next = self.clock.val();
            self.s1_b[l].d.next = self.s1_b[l].q.val();
            self.level[l].clock.next = self.clock.val();
            self.level[l].en.next = self.en.val();
        }
        for j in 0..4 {
            self.s4_cs[j].clock.next = self.clock.val();
            self.s4_cs[j].d.next = self.s4_cs[j].q.val();
        }

        // Stage 1: decode, weights.
        self.decode[0].word.next = self.inp_words0_0.val();
        self.decode[1].word.next = self.inp_words0_1.val();
        self.decode[2].word.next = self.inp_words0_2.val();
        self.decode[3].word.next = self.inp_words0_3.val();
        self.decode[4].word.next = self.inp_words1_0.val();
        self.decode[5].word.next = self.inp_words1_1.val();
        self.decode[6].word.next = self.inp_words1_2.val();
        self.decode[7].word.next = self.inp_words1_3.val();
        for i in 0..8 {
            self.decode[i].format.next = self.inp_format.val();
        }
        self.weight[0].alpha.next = self.inp_alpha0.val();
        self.weight[1].alpha.next = self.inp_beta0.val();
        self.weight[2].alpha.next = self.inp_alpha1.val();
        self.weight[3].alpha.next = self.inp_beta1.val();
        for k in 0..4 {
            self.weight[k].gaussian.next = self.inp_gaussian.val();
        }

        // Stages 2 and 3: each level's bilinear filter.
        for l in 0..2 {
            self.level[l].a.next = self.s1_a[l].q.val();
            self.level[l].b.next = self.s1_b[l].q.val();
        }
        self.level[0].t0.next = self.s1_texel[0].q.val();
        self.level[0].t1.next = self.s1_texel[1].q.val();
        self.level[0].t2.next = self.s1_texel[2].q.val();
        self.level[0].t3.next = self.s1_texel[3].q.val();
        self.level[1].t0.next = self.s1_texel[4].q.val();
        self.level[1].t1.next = self.s1_texel[5].q.val();
        self.level[1].t2.next = self.s1_texel[6].q.val();
        self.level[1].t3.next = self.s1_texel[7].q.val();

        // Stage 4: between the levels.
        self.mix_w.next = 0.into();
        if self.s3_two.q.val() {
            self.mix_w.next = bit_cast::<{ LF + 1 }, LF>(self.s3_frac.q.val());
        }
        for j in 0..4 {
            self.mix[j].x0.next = self.level[0].c.val().get_bits::<8>(j * 8);
            self.mix[j].x1.next = self.level[1].c.val().get_bits::<8>(j * 8);
            self.mix[j].w.next = self.mix_w.val();
            self.mix_round[j].x.next = self.mix[j].y.val();
        }

        // Stage 5: the environment, R, G, B.
        self.environment[0].cf.next = self.s4_cf.q.val().get_bits::<8>(16);
        self.environment[0].cs.next = self.s4_cs[3].q.val();
        self.environment[1].cf.next = self.s4_cf.q.val().get_bits::<8>(8);
        self.environment[1].cs.next = self.s4_cs[2].q.val();
        self.environment[2].cf.next = self.s4_cf.q.val().get_bits::<8>(0);
        self.environment[2].cs.next = self.s4_cs[1].q.val();
        for i in 0..3 {
            self.environment[i].a_s.next = self.s4_cs[0].q.val();
            self.environment[i].mode.next = self.s4_env.q.val();
        }
        self.alpha.next = self.s4_cs[0].q.val();
        if self.s4_env.q.val() == self.decal.val() {
            self.alpha.next = 255.into();
        }

        if self.en.val() {
            for i in 0..8 {
                self.s1_texel[i].d.next = self.decode[i].rgba.val();
            }
            self.s1_a[0].d.next = self.weight[0].w.val();
            self.s1_b[0].d.next = self.weight[1].w.val();
            self.s1_a[1].d.next = self.weight[2].w.val();
            self.s1_b[1].d.next = self.weight[3].w.val();
            self.s1_frac.d.next = self.inp_frac.val();
            self.s1_two.d.next = self.inp_two_levels.val();
            self.s1_env.d.next = self.inp_env.val();
            self.s1_cf.d.next = self.inp_cf.val();
            self.s1_valid.d.next = self.inp_valid.val();

            self.s2_frac.d.next = self.s1_frac.q.val();
            self.s2_two.d.next = self.s1_two.q.val();
            self.s2_env.d.next = self.s1_env.q.val();
            self.s2_cf.d.next = self.s1_cf.q.val();
            self.s2_valid.d.next = self.s1_valid.q.val();

            self.s3_frac.d.next = self.s2_frac.q.val();
            self.s3_two.d.next = self.s2_two.q.val();
            self.s3_env.d.next = self.s2_env.q.val();
            self.s3_cf.d.next = self.s2_cf.q.val();
            self.s3_valid.d.next = self.s2_valid.q.val();

            for j in 0..4 {
                self.s4_cs[j].d.next = self.mix_round[j].y.val();
            }
            self.s4_env.d.next = self.s3_env.q.val();
            self.s4_cf.d.next = self.s3_cf.q.val();
            self.s4_valid.d.next = self.s3_valid.q.val();

            self.s5_rgba.d.next = (bit_cast::<32, 8>(self.environment[0].out.val()) << 24)
                | (bit_cast::<32, 8>(self.environment[1].out.val()) << 16)
                | (bit_cast::<32, 8>(self.environment[2].out.val()) << 8)
                | bit_cast::<32, 8>(self.alpha.val());
            self.s5_valid.d.next = self.s4_valid.q.val();
        }
        self.out_valid.next = self.s5_valid.q.val();
        self.out_rgba.next = self.s5_rgba.q.val();
    }
}

crate::pins!(TextureFilter {
    clock: clock,
    inputs: [
        en,
        inp_valid,
        inp_words0_0,
        inp_words0_1,
        inp_words0_2,
        inp_words0_3,
        inp_words1_0,
        inp_words1_1,
        inp_words1_2,
        inp_words1_3,
        inp_alpha0,
        inp_beta0,
        inp_alpha1,
        inp_beta1,
        inp_frac,
        inp_two_levels,
        inp_format,
        inp_gaussian,
        inp_env,
        inp_cf,
    ],
    outputs: [out_valid, out_rgba],
});

/// `UNITS` entry: the filter stage at `fx::TexFormats::DEFAULT` (it has no parameters).
pub fn emit_texture_filter(params: &Params) -> Result<Emitted, String> {
    Ok(emit::<TextureFilter>("texture_filter", params.clone()))
}
