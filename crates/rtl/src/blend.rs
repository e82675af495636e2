//! `blend`: framebuffer blending, paper 001 section II-5's six blend modes, as OpenGL 4.6
//! section 17.3.6 blends (blend equation FUNC_ADD, one glBlendFunc pair per mode) in 8-bit
//! fixed point: a fragment's colour `src` (RGBA) onto the framebuffer's `dst` (RGBA), per
//! channel, alpha with its own channel. Combinational; bit-exact to `model::blend::blend`.
//!
//! Each channel is one multiply, one exact division by 255 and one saturating add:
//! out = min(round((base + x·y) / 255) + add, 255), with
//! round(P / 255) = (P + 128 + ((P + 128) >> 8)) >> 8 for P in 0..=255²
//! (`model::texture_filter::div255`), Cs and Cd the channel's source and destination, As
//! the source alpha:
//!
//! | code | mode (`model::blend::MODES`) | base | x | y | add | out |
//! |---|---|---|---|---|---|---|
//! | 0, 6, 7 | opaque (ONE, ZERO) | | | | | Cs |
//! | 1 | alpha (SRC_ALPHA, ONE_MINUS_SRC_ALPHA) | 255·Cd | Cs - Cd | As | 0 | round((Cs·As + Cd·(255 - As)) / 255) |
//! | 2 | additive (ONE, ONE) | 0 | Cs | 255 | Cd | min(Cs + Cd, 255) |
//! | 3 | multiply (DST_COLOR, ZERO) | 0 | Cs | Cd | 0 | round(Cs·Cd / 255) |
//! | 4 | premultiplied alpha (ONE, ONE_MINUS_SRC_ALPHA) | 0 | Cd | 255 - As | Cs | min(Cs + round(Cd·(255 - As) / 255), 255) |
//! | 5 | alpha additive (SRC_ALPHA, ONE) | 0 | Cs | As | Cd | min(round(Cs·As / 255) + Cd, 255) |
//!
//! Ports: `src`, `dst` and `color` pack a colour R 7..0, G 15..8, B 23..16, A 31..24;
//! `mode` is the code above. Tests: `testbenches/tests/blend.rs`.

use crate::emit::{emit_unit, Emitted};
use crate::mul::Mul;
use crate::sim::{Pins, Value};
use crate::Params;
use rust_hdl::prelude::*;

/// One channel: see the module's table. Combinational.
#[derive(LogicBlock, Default)]
pub struct BlendChannel {
    /// The source channel Cs, destination channel Cd and source alpha As.
    pub cs: Signal<In, Bits<8>>,
    pub cd: Signal<In, Bits<8>>,
    pub a_s: Signal<In, Bits<8>>,
    /// The mode code.
    pub mode: Signal<In, Bits<3>>,
    pub out: Signal<Out, Bits<8>>,
    /// x · y, x signed (Cs - Cd in alpha mode), y in 0..=255.
    mul: Mul<9, 9, 17>,
    /// 255 - As, in 8 bits: Verilog would widen `a_s` to the 9 bits of `mul.b` before
    /// inverting it.
    inv_a: Signal<Local, Bits<8>>,
    /// base, and P = base + x·y in 0..=255², then P + 128.
    base: Signal<Local, Bits<17>>,
    prod: Signal<Local, Bits<17>>,
    biased: Signal<Local, Bits<17>>,
    /// round(P / 255), in 0..=255 (the sum before the shift is below 2^17).
    rounded: Signal<Local, Bits<8>>,
    add: Signal<Local, Bits<8>>,
    /// rounded + add, in 9 bits: its top bit saturates.
    sum: Signal<Local, Bits<9>>,
}

impl Logic for BlendChannel {
    #[hdl_gen]
    fn update(&mut self) {
        // Additive, and the default: round(Cs·255 / 255) = Cs, plus Cd.
        self.base.next = 0.into();
        self.mul.a.next = bit_cast::<9, 8>(self.cs.val());
        self.mul.b.next = bits::<9>(255);
        self.add.next = self.cd.val();
        self.inv_a.next = !self.a_s.val();
        if self.mode.val() == 1 {
            self.base.next = (bit_cast::<17, 8>(self.cd.val()) << 8) - bit_cast::<17, 8>(self.cd.val());
            self.mul.a.next = bit_cast::<9, 8>(self.cs.val()) - bit_cast::<9, 8>(self.cd.val());
            self.mul.b.next = bit_cast::<9, 8>(self.a_s.val());
            self.add.next = 0.into();
        }
        if self.mode.val() == 3 {
            self.mul.b.next = bit_cast::<9, 8>(self.cd.val());
            self.add.next = 0.into();
        }
        if self.mode.val() == 4 {
            self.mul.a.next = bit_cast::<9, 8>(self.cd.val());
            self.mul.b.next = bit_cast::<9, 8>(self.inv_a.val());
            self.add.next = self.cs.val();
        }
        if self.mode.val() == 5 {
            self.mul.b.next = bit_cast::<9, 8>(self.a_s.val());
        }
        self.prod.next = self.base.val() + self.mul.p.val();
        self.biased.next = self.prod.val() + 128;
        self.rounded.next = bit_cast::<8, 17>((self.biased.val() + (self.biased.val() >> 8)) >> 8);
        self.sum.next = bit_cast::<9, 8>(self.rounded.val()) + bit_cast::<9, 8>(self.add.val());
        self.out.next = self.sum.val().get_bits::<8>(0);
        if self.sum.val().get_bit(8) {
            self.out.next = 255.into();
        }
        // Opaque, and codes 6 and 7.
        if (self.mode.val() == 0) | (self.mode.val() == 6) | (self.mode.val() == 7) {
            self.out.next = self.cs.val();
        }
    }
}

/// The blend unit: four [`BlendChannel`]s, the source alpha shared. Combinational.
#[derive(LogicBlock, Default)]
pub struct Blend {
    /// The fragment's colour (source), R 7..0, G 15..8, B 23..16, A 31..24.
    pub src: Signal<In, Bits<32>>,
    /// The framebuffer's colour (destination), packed as `src`.
    pub dst: Signal<In, Bits<32>>,
    /// The mode code (the module's table; `model::blend::MODES`' order).
    pub mode: Signal<In, Bits<3>>,
    /// The colour to store, packed as `src`.
    pub color: Signal<Out, Bits<32>>,
    ch: [BlendChannel; 4],
}

impl Logic for Blend {
    #[hdl_gen]
    fn update(&mut self) {
        self.ch[0].cs.next = self.src.val().get_bits::<8>(0);
        self.ch[1].cs.next = self.src.val().get_bits::<8>(8);
        self.ch[2].cs.next = self.src.val().get_bits::<8>(16);
        self.ch[3].cs.next = self.src.val().get_bits::<8>(24);
        self.ch[0].cd.next = self.dst.val().get_bits::<8>(0);
        self.ch[1].cd.next = self.dst.val().get_bits::<8>(8);
        self.ch[2].cd.next = self.dst.val().get_bits::<8>(16);
        self.ch[3].cd.next = self.dst.val().get_bits::<8>(24);
        for k in 0..4 {
            self.ch[k].a_s.next = self.src.val().get_bits::<8>(24);
            self.ch[k].mode.next = self.mode.val();
        }
        self.color.next = (bit_cast::<32, 8>(self.ch[3].out.val()) << 24)
            | (bit_cast::<32, 8>(self.ch[2].out.val()) << 16)
            | (bit_cast::<32, 8>(self.ch[1].out.val()) << 8)
            | bit_cast::<32, 8>(self.ch[0].out.val());
    }
}

impl Pins for Blend {
    fn set(&mut self, pin: &str, value: &Value) {
        match pin {
            "src" => self.src.next = value.to_bits(),
            "dst" => self.dst.next = value.to_bits(),
            "mode" => self.mode.next = value.to_bits(),
            _ => panic!("blend has no input pin {pin}"),
        }
    }
    fn get(&self, pin: &str) -> Value {
        match pin {
            "color" => Value::from_bits(self.color.val()),
            _ => panic!("blend has no output pin {pin}"),
        }
    }
}

/// `UNITS` entry: the blend unit (no parameters).
pub fn emit_blend(params: &Params) -> Result<Emitted, String> {
    Ok(emit_unit("blend", Blend::default(), params))
}
