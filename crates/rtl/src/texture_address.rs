//! `texture_address`: the second stage of paper 001's texture unit (section II-5), between
//! `texture_coords` and the texture cache: from a pixel's s, t and lambda, the level it
//! reads (OpenGL 4.6 sections 8.14.3 and 8.15: magnified, one level, or the first or second
//! of two), the 2x2 footprint's texels in it with their fractions (section 8.14.2), each
//! index wrapped on its own, and each texel's word in `model::texture_memory`'s parity
//! planes: one cache access, a word per bank. Combinational; bit-exact to
//! `model::texture_unit::request` at `fx::TexFormats::DEFAULT`.
//!
//! ```text
//!  lambda ─> level d (magnify: 0; nearest: clamp((lambda + 31) >> 6, 0, q); linear: lambda >> 6 (+1 second))
//!  s, t ──> u = s >> (12 - max(ws - d, 0)) (8 sub-texel bits), minus 1/2 when linear:
//!           i0 = u >> 8, alpha = u & 255; i1 = i0 + 1; wrap each (repeat, mirrored, clamp)
//!  (i, j) of each footprint texel ─> bank (j & 1)·2 + (i & 1), word
//!           base + offset(d) + bank · plane(d) + (j >> 1) · pitch(d) + (i >> 1)
//! ```
//!
//! The state (size, levels, filters, mipmapping, wrap, base) is the texture's, held by the
//! texture unit while a triangle is drawn. Tests: `testbenches/tests/texture_address.rs`.

use crate::emit::{emit_unit, Emitted};
use crate::sim::{Pins, Value};
use crate::Params;
use fx::TexFormats;
use rust_hdl::prelude::*;

const F: TexFormats = TexFormats::DEFAULT;
/// s and t (`st`).
pub const ST: usize = F.st.bits() as usize;
/// lambda, as `texture_coords` gives it.
pub const LAMBDA: usize = crate::texture_coords::LAMBDA;
/// Word addresses of texture memory (`model::texture_memory::ADDR_BITS`).
pub const ADDR: usize = model::texture_memory::ADDR_BITS as usize;
/// Sub-texel bits and level-of-detail fraction bits.
pub const SUB: usize = F.subtexel as usize;
pub const LF: usize = F.lod_frac as usize;
/// A coordinate in a level's sub-texel bits (signed, with room for the half texel), texel
/// indices before wrapping (signed, with room for i0 + 1) and after.
const U: usize = ST + 1;
const I: usize = U - SUB;
const IW: usize = fx::texture::MAX_SIZE_LOG2 as usize + 1;
/// Levels of the largest chain.
const LEVELS: usize = fx::texture::MAX_SIZE_LOG2 as usize + 1;
// rust-hdl's `hdl_gen` reads a Rust constant in an expression as a Verilog name, so bit
// positions and rounding terms are literals below: ST - 1 = 28, U - 1 = 29, I - 1 = 21, LAMBDA - 1 =
// 31, sub-texel bits 8 (1/2 is 128), 2^(LF - 1) - 1 = 31 and LF = 6, 12 = st.frac - SUB.
const _: () = assert!(
    F.st.frac as usize == SUB + fx::texture::MAX_SIZE_LOG2 as usize
        && ST == 29
        && I == 22
        && LAMBDA == 32
        && SUB == 8
        && LF == 6
        && fx::texture::MAX_SIZE_LOG2 == 12
);

/// One axis of the footprint: the level's size, the coordinate's texel indices (wrapped)
/// and fraction.
#[derive(LogicBlock, Default)]
pub struct Axis {
    /// The coordinate (`st`), log2 of the level's size along the axis, whether the filter
    /// is linear, the wrap mode (0 repeat, 1 mirrored repeat, 2 clamp to edge).
    pub coord: Signal<In, Bits<ST>>,
    pub size_log2: Signal<In, Bits<4>>,
    pub linear: Signal<In, Bit>,
    pub wrap: Signal<In, Bits<2>>,
    pub i0: Signal<Out, Bits<IW>>,
    pub i1: Signal<Out, Bits<IW>>,
    pub frac: Signal<Out, Bits<SUB>>,
    wide: Signal<Local, Bits<U>>,
    u: Signal<Local, Bits<U>>,
    first: Signal<Local, Bits<I>>,
    second: Signal<Local, Bits<I>>,
    wrap0: Wrap,
    wrap1: Wrap,
}

impl Logic for Axis {
    #[hdl_gen]
    fn update(&mut self) {
        // u = coord >> (12 - size_log2), arithmetic, in one bit more than coord (room for
        // the half texel a linear filter subtracts): sub-texel bits of the level.
        self.wide.next = bit_cast::<U, ST>(self.coord.val());
        if self.coord.val().get_bit(28) {
            self.wide.next = bit_cast::<U, ST>(self.coord.val()) | bits::<U>(0x2000_0000);
        }
        self.u.next = self.wide.val() >> (bits::<U>(12) - bit_cast::<U, 4>(self.size_log2.val()));
        if self.coord.val().get_bit(28) {
            self.u.next = (self.wide.val() >> (bits::<U>(12) - bit_cast::<U, 4>(self.size_log2.val())))
                | !(bits::<U>(0x3fff_ffff) >> (bits::<U>(12) - bit_cast::<U, 4>(self.size_log2.val())));
        }
        if self.linear.val() {
            self.u.next = self.u.val() - bits::<U>(128);
        }
        // i0 = u >> 8: the top I bits of u, its sign among them.
        self.first.next = self.u.val().get_bits::<I>(8);
        self.second.next = self.first.val();
        self.frac.next = 0.into();
        if self.linear.val() {
            self.second.next = self.first.val() + 1;
            self.frac.next = self.u.val().get_bits::<SUB>(0);
        }
        self.wrap0.i.next = self.first.val();
        self.wrap0.size_log2.next = self.size_log2.val();
        self.wrap0.mode.next = self.wrap.val();
        self.wrap1.i.next = self.second.val();
        self.wrap1.size_log2.next = self.size_log2.val();
        self.wrap1.mode.next = self.wrap.val();
        self.i0.next = self.wrap0.wrapped.val();
        self.i1.next = self.wrap1.wrapped.val();
    }
}

/// A texel index wrapped into 0..2^size_log2: REPEAT a mask, MIRRORED_REPEAT a mask and a
/// reflection, CLAMP_TO_EDGE a clamp (`model::texture_address::wrap_index`).
#[derive(LogicBlock, Default)]
pub struct Wrap {
    pub i: Signal<In, Bits<I>>,
    pub size_log2: Signal<In, Bits<4>>,
    pub mode: Signal<In, Bits<2>>,
    pub wrapped: Signal<Out, Bits<IW>>,
    n: Signal<Local, Bits<I>>,
    p: Signal<Local, Bits<I>>,
}

impl Logic for Wrap {
    #[hdl_gen]
    fn update(&mut self) {
        self.n.next = bits::<I>(1) << bit_cast::<I, 4>(self.size_log2.val());
        // Repeat (and the default for mode 3).
        self.wrapped.next = bit_cast::<IW, I>(self.i.val() & (self.n.val() - 1));
        self.p.next = self.i.val() & ((self.n.val() << 1) - 1);
        if self.mode.val() == 1 {
            self.wrapped.next = bit_cast::<IW, I>(self.p.val());
            if self.p.val() >= self.n.val() {
                self.wrapped.next = bit_cast::<IW, I>((self.n.val() << 1) - 1 - self.p.val());
            }
        }
        if self.mode.val() == 2 {
            self.wrapped.next = bit_cast::<IW, I>(self.i.val());
            if self.i.val().get_bit(21) {
                self.wrapped.next = 0.into();
            } else if self.i.val() >= self.n.val() {
                self.wrapped.next = bit_cast::<IW, I>(self.n.val() - 1);
            }
        }
    }
}

/// One footprint texel's bank and word: base + offset(d) + bank · plane(d) + (j >> 1) ·
/// pitch(d) + (i >> 1), plane(d) = 2^(pw + ph) and pitch(d) = 2^pw.
#[derive(LogicBlock, Default)]
pub struct Word {
    pub i: Signal<In, Bits<IW>>,
    pub j: Signal<In, Bits<IW>>,
    /// The level's first word (base + offset(d)), log2 of its planes' width and height.
    pub first: Signal<In, Bits<ADDR>>,
    pub pw: Signal<In, Bits<4>>,
    pub ph: Signal<In, Bits<4>>,
    pub bank: Signal<Out, Bits<2>>,
    pub addr: Signal<Out, Bits<ADDR>>,
}

impl Logic for Word {
    #[hdl_gen]
    fn update(&mut self) {
        self.bank.next =
            (bit_cast::<2, 1>(self.j.val().get_bits::<1>(0)) << 1) | bit_cast::<2, 1>(self.i.val().get_bits::<1>(0));
        self.addr.next = self.first.val()
            + (bit_cast::<ADDR, 2>(self.bank.val())
                << (bit_cast::<ADDR, 4>(self.pw.val()) + bit_cast::<ADDR, 4>(self.ph.val())))
            + (bit_cast::<ADDR, IW>(self.j.val() >> 1) << bit_cast::<ADDR, 4>(self.pw.val()))
            + bit_cast::<ADDR, IW>(self.i.val() >> 1);
    }
}

/// The texture address unit (combinational).
#[derive(LogicBlock)]
pub struct TextureAddress {
    pub s: Signal<In, Bits<ST>>,
    pub t: Signal<In, Bits<ST>>,
    pub lambda: Signal<In, Bits<LAMBDA>>,
    /// The access of the second of a pixel's two levels.
    pub second: Signal<In, Bit>,
    /// The texture's state: log2 of its sides, its levels (1 to 13), its base address, the
    /// filters (1: linear), mipmapping (0 none, 1 nearest, 2 linear), wrap per axis.
    pub ws: Signal<In, Bits<4>>,
    pub hs: Signal<In, Bits<4>>,
    pub levels: Signal<In, Bits<4>>,
    pub base: Signal<In, Bits<ADDR>>,
    pub min_linear: Signal<In, Bit>,
    pub mag_linear: Signal<In, Bit>,
    pub mip: Signal<In, Bits<2>>,
    pub wrap_s: Signal<In, Bits<2>>,
    pub wrap_t: Signal<In, Bits<2>>,
    /// The access: each bank's enable and word address, the bank of each footprint texel
    /// (2 bits each, T(i0, j0) lowest), the fractions, and the pixel's levels.
    pub lanes: Signal<Out, Bits<4>>,
    pub addr0: Signal<Out, Bits<ADDR>>,
    pub addr1: Signal<Out, Bits<ADDR>>,
    pub addr2: Signal<Out, Bits<ADDR>>,
    pub addr3: Signal<Out, Bits<ADDR>>,
    pub banks: Signal<Out, Bits<8>>,
    pub alpha: Signal<Out, Bits<SUB>>,
    pub beta: Signal<Out, Bits<SUB>>,
    pub two_levels: Signal<Out, Bit>,
    pub frac: Signal<Out, Bits<LF>>,

    magnify: Signal<Local, Bit>,
    q: Signal<Local, Bits<LAMBDA>>,
    d: Signal<Local, Bits<LAMBDA>>,
    level: Signal<Local, Bits<4>>,
    sw: Signal<Local, Bits<4>>,
    sh: Signal<Local, Bits<4>>,
    pw: Signal<Local, Bits<4>>,
    ph: Signal<Local, Bits<4>>,
    offset: Signal<Local, Bits<ADDR>>,
    /// ws, hs and the level in ADDR bits; each level k's log2 of its four planes' words.
    ws_a: Signal<Local, Bits<ADDR>>,
    hs_a: Signal<Local, Bits<ADDR>>,
    level_a: Signal<Local, Bits<ADDR>>,
    pk: [Signal<Local, Bits<ADDR>>; LEVELS],
    across: Axis,
    up: Axis,
    word: [Word; 4],
    addr: [Signal<Local, Bits<ADDR>>; 4],
    bank_id: [Constant<Bits<2>>; 4],
    lane_bit: [Constant<Bits<4>>; 4],
    level_id: [Constant<Bits<ADDR>>; LEVELS],
}

impl Default for TextureAddress {
    fn default() -> Self {
        Self {
            s: Default::default(),
            t: Default::default(),
            lambda: Default::default(),
            second: Default::default(),
            ws: Default::default(),
            hs: Default::default(),
            levels: Default::default(),
            base: Default::default(),
            min_linear: Default::default(),
            mag_linear: Default::default(),
            mip: Default::default(),
            wrap_s: Default::default(),
            wrap_t: Default::default(),
            lanes: Default::default(),
            addr0: Default::default(),
            addr1: Default::default(),
            addr2: Default::default(),
            addr3: Default::default(),
            banks: Default::default(),
            alpha: Default::default(),
            beta: Default::default(),
            two_levels: Default::default(),
            frac: Default::default(),
            magnify: Default::default(),
            q: Default::default(),
            d: Default::default(),
            level: Default::default(),
            sw: Default::default(),
            sh: Default::default(),
            pw: Default::default(),
            ph: Default::default(),
            offset: Default::default(),
            ws_a: Default::default(),
            hs_a: Default::default(),
            level_a: Default::default(),
            pk: Default::default(),
            across: Default::default(),
            up: Default::default(),
            word: Default::default(),
            addr: Default::default(),
            bank_id: std::array::from_fn(|b| Constant::new(b.to_bits())),
            lane_bit: std::array::from_fn(|b| Constant::new((1usize << b).to_bits())),
            level_id: std::array::from_fn(|k| Constant::new(k.to_bits())),
        }
    }
}

impl Logic for TextureAddress {
    #[hdl_gen]
    fn update(&mut self) {
        // The level (section 8.14.3): q = levels - 1; lambda <= 0 magnifies.
        self.q.next = bit_cast::<LAMBDA, 4>(self.levels.val()) - 1;
        self.magnify.next = self.lambda.val().get_bit(31) | !self.lambda.val().any();
        self.two_levels.next = false;
        self.frac.next = 0.into();
        self.d.next = 0.into();
        if !self.magnify.val() {
            if self.mip.val() == 1 {
                // ceil(lambda + 1/2) - 1 = (lambda + 2^(LF-1) - 1) >> LF, at most q.
                self.d.next = (self.lambda.val() + 31) >> 6;
                if self.d.val() > self.q.val() {
                    self.d.next = self.q.val();
                }
            }
            if self.mip.val() == 2 {
                self.d.next = self.lambda.val() >> 6;
                if self.d.val() >= self.q.val() {
                    self.d.next = self.q.val();
                } else {
                    self.two_levels.next = true;
                    self.frac.next = self.lambda.val().get_bits::<LF>(0);
                    if self.second.val() {
                        self.d.next = self.d.val() + 1;
                    }
                }
            }
        }
        self.level.next = self.d.val().get_bits::<4>(0);
        // The level's sides: max(ws - d, 0), max(hs - d, 0); a plane's, one less.
        self.sw.next = 0.into();
        if self.ws.val() > self.level.val() {
            self.sw.next = self.ws.val() - self.level.val();
        }
        self.sh.next = 0.into();
        if self.hs.val() > self.level.val() {
            self.sh.next = self.hs.val() - self.level.val();
        }
        self.pw.next = 0.into();
        if self.sw.val().any() {
            self.pw.next = self.sw.val() - 1;
        }
        self.ph.next = 0.into();
        if self.sh.val().any() {
            self.ph.next = self.sh.val() - 1;
        }
        // The levels before d: 4 planes of 2^(max(ws - k - 1, 0) + max(hs - k - 1, 0)) each.
        self.ws_a.next = bit_cast::<ADDR, 4>(self.ws.val());
        self.hs_a.next = bit_cast::<ADDR, 4>(self.hs.val());
        self.level_a.next = bit_cast::<ADDR, 4>(self.level.val());
        self.offset.next = self.base.val();
        for k in 0..LEVELS {
            self.pk[k].next = 2.into();
            if self.ws_a.val() > self.level_id[k].val() + 1 {
                self.pk[k].next = self.pk[k].val() + self.ws_a.val() - self.level_id[k].val() - 1;
            }
            if self.hs_a.val() > self.level_id[k].val() + 1 {
                self.pk[k].next = self.pk[k].val() + self.hs_a.val() - self.level_id[k].val() - 1;
            }
            if self.level_id[k].val() < self.level_a.val() {
                self.offset.next = self.offset.val() + (bits::<ADDR>(1) << self.pk[k].val());
            }
        }

        // The footprint (section 8.14.2).
        self.across.coord.next = self.s.val();
        self.across.size_log2.next = self.sw.val();
        self.across.wrap.next = self.wrap_s.val();
        self.up.coord.next = self.t.val();
        self.up.size_log2.next = self.sh.val();
        self.up.wrap.next = self.wrap_t.val();
        self.across.linear.next = self.min_linear.val();
        self.up.linear.next = self.min_linear.val();
        if self.magnify.val() {
            self.across.linear.next = self.mag_linear.val();
            self.up.linear.next = self.mag_linear.val();
        }
        self.alpha.next = self.across.frac.val();
        self.beta.next = self.up.frac.val();
        self.word[0].i.next = self.across.i0.val();
        self.word[1].i.next = self.across.i1.val();
        self.word[2].i.next = self.across.i0.val();
        self.word[3].i.next = self.across.i1.val();
        self.word[0].j.next = self.up.i0.val();
        self.word[1].j.next = self.up.i0.val();
        self.word[2].j.next = self.up.i1.val();
        self.word[3].j.next = self.up.i1.val();

        // Each texel's bank and word; each bank's enable and address.
        for p in 0..4 {
            self.word[p].first.next = self.offset.val();
            self.word[p].pw.next = self.pw.val();
            self.word[p].ph.next = self.ph.val();
        }
        self.banks.next = bit_cast::<8, 2>(self.word[0].bank.val())
            | (bit_cast::<8, 2>(self.word[1].bank.val()) << 2)
            | (bit_cast::<8, 2>(self.word[2].bank.val()) << 4)
            | (bit_cast::<8, 2>(self.word[3].bank.val()) << 6);
        self.lanes.next = 0.into();
        for b in 0..4 {
            self.addr[b].next = 0.into();
            for p in 0..4 {
                if self.word[p].bank.val() == self.bank_id[b].val() {
                    self.addr[b].next = self.word[p].addr.val();
                    self.lanes.next = self.lanes.val() | self.lane_bit[b].val();
                }
            }
        }
        self.addr0.next = self.addr[0].val();
        self.addr1.next = self.addr[1].val();
        self.addr2.next = self.addr[2].val();
        self.addr3.next = self.addr[3].val();
    }
}

impl Pins for TextureAddress {
    fn set(&mut self, pin: &str, value: &Value) {
        match pin {
            "s" => self.s.next = value.to_bits(),
            "t" => self.t.next = value.to_bits(),
            "lambda" => self.lambda.next = value.to_bits(),
            "second" => self.second.next = value.bit(0),
            "ws" => self.ws.next = value.to_bits(),
            "hs" => self.hs.next = value.to_bits(),
            "levels" => self.levels.next = value.to_bits(),
            "base" => self.base.next = value.to_bits(),
            "min_linear" => self.min_linear.next = value.bit(0),
            "mag_linear" => self.mag_linear.next = value.bit(0),
            "mip" => self.mip.next = value.to_bits(),
            "wrap_s" => self.wrap_s.next = value.to_bits(),
            "wrap_t" => self.wrap_t.next = value.to_bits(),
            _ => panic!("texture_address has no input pin {pin}"),
        }
    }
    fn get(&self, pin: &str) -> Value {
        match pin {
            "lanes" => Value::from_bits(self.lanes.val()),
            "addr0" => Value::from_bits(self.addr0.val()),
            "addr1" => Value::from_bits(self.addr1.val()),
            "addr2" => Value::from_bits(self.addr2.val()),
            "addr3" => Value::from_bits(self.addr3.val()),
            "banks" => Value::from_bits(self.banks.val()),
            "alpha" => Value::from_bits(self.alpha.val()),
            "beta" => Value::from_bits(self.beta.val()),
            "two_levels" => Value::new(1, self.two_levels.val().into()),
            "frac" => Value::from_bits(self.frac.val()),
            _ => panic!("texture_address has no output pin {pin}"),
        }
    }
}

/// `UNITS` entry: the unit at `fx::TexFormats::DEFAULT`.
pub fn emit_texture_address(params: &Params) -> Result<Emitted, String> {
    Ok(emit_unit("texture_address", TextureAddress::default(), params))
}
