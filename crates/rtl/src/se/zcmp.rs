//! The bit-serial z compare of one pixel: paper 000 (Bang, Bae, Kyung 1990), Fig. 10.
//! Model: `model::se::zcmp`.

use crate::sim::{Pins, Value};
use rust_hdl::prelude::*;

/// Bit-serial z compare for one pixel, LSB first (000 Fig. 10, "Z-depth comparison logic
/// for one pixel"). One bit of the new z (`nz`) and of the stored z (`oz`) per clock,
/// `first` high with bit 0. After the clock of the MSB, `closer` = new z < old z
/// (unsigned); the SE ANDs it with the EPT mask into the WE storage. Latency: W clocks for
/// a W-bit z, no pipelining (II = W).
///
/// Reading of the text: flag 1 "holds" where NZ_i >= OZ_i; taken literally that makes
/// 0b10 < 0b01, so here a differing bit always decides: set where NZ_i < OZ_i, clear where
/// NZ_i > OZ_i, hold where equal (model test `zcmp_paper_000_literal_reading_is_wrong`).
#[derive(LogicBlock, Default)]
pub struct Zcmp {
    pub clock: Signal<In, Clock>,
    /// High in the clock that carries bit 0; the flag starts from 0.
    pub first: Signal<In, Bit>,
    /// Bit i of the new z, from the interpolator.
    pub nz: Signal<In, Bit>,
    /// Bit i of the stored z, from the old-z block.
    pub oz: Signal<In, Bit>,
    /// "flag 1" of Fig. 10.
    pub closer: Signal<Out, Bit>,
    flag: DFF<Bit>,
    /// The flag as it stands before this bit (0 at bit 0).
    held: Signal<Local, Bit>,
}

impl Logic for Zcmp {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, flag);
        self.held.next = self.flag.q.val() & !self.first.val();
        self.flag.d.next = self.held.val();
        if self.nz.val() != self.oz.val() {
            // nz = 0, oz = 1 at this bit: new z is the smaller so far.
            self.flag.d.next = self.oz.val();
        }
        self.closer.next = self.flag.q.val();
    }
}

impl Pins for Zcmp {
    fn set(&mut self, pin: &str, v: &Value) {
        match pin {
            "first" => self.first.next = v.bit(0),
            "nz" => self.nz.next = v.bit(0),
            "oz" => self.oz.next = v.bit(0),
            _ => panic!("zcmp has no input pin {pin}"),
        }
    }
    fn get(&self, pin: &str) -> Value {
        match pin {
            "closer" => Value::from_bools(&[self.closer.val()]),
            _ => panic!("zcmp has no output pin {pin}"),
        }
    }
    fn clock(&mut self) -> Option<&mut Signal<In, Clock>> {
        Some(&mut self.clock)
    }
}
