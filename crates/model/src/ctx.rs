//! The arithmetic context every unit model computes in: the formats, and a
//! record of which quantities did not fit them.
//!
//! Every value a register holds goes through [`Ctx::put`], which stores it the
//! way the hardware does (wrap or saturate, per its format) and notes when the
//! value did not fit. Wrapping is often harmless (see `fx::formats`, "modular
//! arithmetic"); `raster`'s analysis mode decides per triangle by comparing what
//! was emitted with the exact values.

use fx::{Fmt, Formats};

/// A configurable quantity (a field of [`Formats`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Q {
    Xy,
    Z,
    Color,
    InvW,
    Ooa,
    OoaD,
    Dz,
    ZAcc,
    Dc,
    CAcc,
    Bary,
}

impl Q {
    /// Its format in `f`.
    pub fn of(self, f: &Formats) -> Fmt {
        match self {
            Q::Xy => f.xy,
            Q::Z => f.z,
            Q::Color => f.color,
            Q::InvW => f.inv_w,
            Q::Ooa => f.ooa,
            Q::OoaD => f.ooa_d,
            Q::Dz => f.dz,
            Q::ZAcc => f.z_acc,
            Q::Dc => f.dc,
            Q::CAcc => f.c_acc,
            Q::Bary => f.bary,
        }
    }

    /// The field name in [`Formats`].
    pub fn name(self) -> &'static str {
        match self {
            Q::Xy => "xy",
            Q::Z => "z",
            Q::Color => "color",
            Q::InvW => "inv_w",
            Q::Ooa => "ooa",
            Q::OoaD => "ooa_d",
            Q::Dz => "dz",
            Q::ZAcc => "z_acc",
            Q::Dc => "dc",
            Q::CAcc => "c_acc",
            Q::Bary => "bary",
        }
    }

    pub const ALL: [Q; 11] = [Q::Xy, Q::Z, Q::Color, Q::InvW, Q::Ooa, Q::OoaD, Q::Dz, Q::ZAcc, Q::Dc, Q::CAcc, Q::Bary];
}

/// Formats to compute in, and the record of values that did not fit.
#[derive(Clone, Debug)]
pub struct Ctx {
    /// The formats the arithmetic uses.
    pub f: Formats,
    /// Bit `q as usize` set when a value of quantity `q` did not fit its format.
    overflowed: u16,
}

impl Ctx {
    /// The hardware's arithmetic in `f`.
    pub fn new(f: Formats) -> Ctx {
        Ctx { f, overflowed: 0 }
    }

    /// Stores `raw` (already at the format's fraction bits) as a register of
    /// quantity `q` does.
    pub fn put(&mut self, q: Q, raw: i128) -> i128 {
        let f = q.of(&self.f);
        if !f.fits(raw) {
            self.overflowed |= 1 << q as u16;
        }
        f.store(raw)
    }

    /// Rescales `raw` from `from_frac` fraction bits to quantity `q`'s format
    /// (with its rounding) and stores it.
    pub fn put_scaled(&mut self, q: Q, raw: i128, from_frac: u32) -> i128 {
        let r = q.of(&self.f).rescale(raw, from_frac);
        self.put(q, r)
    }

    /// The quantities that wrapped or saturated since the context was made.
    pub fn overflowed(&self) -> Vec<Q> {
        Q::ALL.into_iter().filter(|q| self.overflowed & (1 << *q as u16) != 0).collect()
    }
}
