//! The arithmetic context every unit model computes in: the formats, and a
//! record of which quantities did not fit them.
//!
//! Every value a register holds goes through [`Ctx::put`], which stores it the
//! way the hardware does (wrap or saturate, per its format) and notes when the
//! value did not fit. Wrapping is often harmless (see `fx::formats`, "modular
//! arithmetic"); `raster`'s analysis mode decides per triangle by comparing what
//! was emitted with the exact values. It also keeps, per quantity, the smallest and
//! largest value its registers were given ([`Ranges`]): the integer bits a workload
//! needs (`edgepaint fit`).

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

/// Per quantity, the smallest and largest raw value (at its format's fraction bits, before
/// it was wrapped or saturated) its registers were given: what the hardware must hold for
/// nothing to wrap.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Ranges {
    lo: [i128; 11],
    hi: [i128; 11],
    /// Bit `q as usize` set once a value of `q` was seen.
    seen: u16,
}

impl Ranges {
    /// Notes a value of `q`.
    pub fn see(&mut self, q: Q, raw: i128) {
        let (i, bit) = (q as usize, 1u16 << q as u16);
        if self.seen & bit == 0 {
            (self.lo[i], self.hi[i]) = (raw, raw);
            self.seen |= bit;
        } else {
            self.lo[i] = self.lo[i].min(raw);
            self.hi[i] = self.hi[i].max(raw);
        }
    }

    /// The smallest and largest raw value of `q` seen, if any.
    pub fn get(&self, q: Q) -> Option<(i128, i128)> {
        (self.seen & (1 << q as u16) != 0).then(|| (self.lo[q as usize], self.hi[q as usize]))
    }

    /// Both records in one (the ranges must be at the same formats).
    pub fn merge(&mut self, other: &Ranges) {
        for q in Q::ALL {
            if let Some((lo, hi)) = other.get(q) {
                self.see(q, lo);
                self.see(q, hi);
            }
        }
    }

    /// The fewest integer bits with which `q`'s format in `f` (its sign and fraction bits,
    /// the formats the values were seen at) holds every value seen: `None` when none was.
    pub fn int_bits(&self, q: Q, f: &Formats) -> Option<u32> {
        let (lo, hi) = self.get(q)?;
        q.of(f).int_bits_for(lo, hi)
    }

    /// The largest magnitude seen of `q`, in its units (raw / 2^frac of its format in `f`).
    pub fn max_abs(&self, q: Q, f: &Formats) -> Option<f64> {
        let (lo, hi) = self.get(q)?;
        Some(lo.unsigned_abs().max(hi.unsigned_abs()) as f64 * (-(q.of(f).frac as f64)).exp2())
    }
}

/// Formats to compute in, and the record of values that did not fit.
#[derive(Clone, Debug)]
pub struct Ctx {
    /// The formats the arithmetic uses.
    pub f: Formats,
    /// Bit `q as usize` set when a value of quantity `q` did not fit its format.
    overflowed: u16,
    /// Every value each quantity was given.
    ranges: Ranges,
}

impl Ctx {
    /// The hardware's arithmetic in `f`.
    pub fn new(f: Formats) -> Ctx {
        Ctx { f, overflowed: 0, ranges: Ranges::default() }
    }

    /// Stores `raw` (already at the format's fraction bits) as a register of
    /// quantity `q` does.
    pub fn put(&mut self, q: Q, raw: i128) -> i128 {
        let f = q.of(&self.f);
        self.ranges.see(q, raw);
        if !f.fits(raw) {
            self.overflowed |= 1 << q as u16;
        }
        f.store(raw)
    }

    /// The values each quantity was given since the context was made.
    pub fn ranges(&self) -> &Ranges {
        &self.ranges
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
