//! One fixed-point number format: signedness, integer and fraction bits,
//! rounding into it and what happens when a value does not fit.
//!
//! Notation: `S<i>.<f> [bits]` or `U<i>.<f> [bits]`, the sign not counted in
//! `i`, the total in brackets: `S11.4 [16]` holds [-2048, 2048) in steps of 1/16.
//! A raw value is the integer `value * 2^f`, held in an `i128`.
//!
//! Rounding words are exact. *truncate* drops low bits: it is floor, also for
//! negative values (-3 >> 1 = -2). *half-up* adds half an LSB, then floors.

use serde::{Deserialize, Deserializer, Serialize, Serializer};
use std::fmt;
use std::str::FromStr;

/// How a value with more fraction bits is brought into a format.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Rounding {
    /// Drop the extra bits (floor).
    Truncate,
    /// Add half an LSB of the format, then drop (round half up).
    HalfUp,
}

/// What storing a value that does not fit does.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Overflow {
    /// Keep the low bits (two's complement wrap), as a plain register does.
    Wrap,
    /// Clamp to the nearest representable value.
    Saturate,
}

/// A fixed-point format.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Fmt {
    pub signed: bool,
    /// Integer bits, not counting the sign.
    pub int: u32,
    /// Fraction bits.
    pub frac: u32,
    pub rounding: Rounding,
    pub overflow: Overflow,
}

/// The widest format the models compute in: raw values live in an `i128`.
pub const MAX_BITS: u32 = 120;

/// Sign-extends the low `bits` of `v`: what a `bits`-wide signed register holds.
pub const fn wrap_s(v: i128, bits: u32) -> i128 {
    (v << (128 - bits)) >> (128 - bits)
}

/// The low `bits` of `v` as an unsigned value.
pub const fn wrap_u(v: i128, bits: u32) -> i128 {
    ((v as u128) << (128 - bits) >> (128 - bits)) as i128
}

/// Whether `v` fits a `bits`-wide signed register.
pub const fn fits_s(v: i128, bits: u32) -> bool {
    wrap_s(v, bits) == v
}

/// Floor of `v / 2^n` (dropping bits of a two's complement value).
pub const fn shr_floor(v: i128, n: u32) -> i128 {
    v >> n
}

/// `v / 2^n` rounded half up: add `2^(n-1)`, then floor.
pub const fn shr_half_up(v: i128, n: u32) -> i128 {
    if n == 0 {
        v
    } else {
        (v + (1 << (n - 1))) >> n
    }
}

/// Bits needed to hold `v` as a signed value (at least 1).
pub const fn signed_bits(v: i128) -> u32 {
    let m = if v < 0 { !v } else { v };
    129 - m.leading_zeros()
}

/// Bits needed to hold a non-negative `v` as an unsigned value (at least 1).
pub const fn unsigned_bits(v: u128) -> u32 {
    if v == 0 {
        1
    } else {
        128 - v.leading_zeros()
    }
}

/// The smallest `k` with `2^k >= n` (for n >= 1).
pub const fn clog2(n: u64) -> u32 {
    if n <= 1 {
        0
    } else {
        64 - (n - 1).leading_zeros()
    }
}

impl Fmt {
    /// A signed format `S<int>.<frac>`, truncating, wrapping.
    pub const fn s(int: u32, frac: u32) -> Fmt {
        Fmt { signed: true, int, frac, rounding: Rounding::Truncate, overflow: Overflow::Wrap }
    }

    /// An unsigned format `U<int>.<frac>`, truncating, wrapping.
    pub const fn u(int: u32, frac: u32) -> Fmt {
        Fmt { signed: false, int, frac, rounding: Rounding::Truncate, overflow: Overflow::Wrap }
    }

    /// The same format rounding half up.
    pub const fn half_up(self) -> Fmt {
        Fmt { rounding: Rounding::HalfUp, ..self }
    }

    /// The same format saturating.
    pub const fn saturating(self) -> Fmt {
        Fmt { overflow: Overflow::Saturate, ..self }
    }

    /// Total width in bits.
    pub const fn bits(self) -> u32 {
        self.int + self.frac + self.signed as u32
    }

    /// Smallest raw value.
    pub const fn min_raw(self) -> i128 {
        if self.signed {
            -(1i128 << (self.int + self.frac))
        } else {
            0
        }
    }

    /// Largest raw value.
    pub const fn max_raw(self) -> i128 {
        (1i128 << (self.int + self.frac)) - 1
    }

    /// The fewest integer bits with which this format (its sign and fraction bits kept)
    /// holds every raw value in `lo..=hi` (0 when the fraction bits alone do); `None` for a
    /// negative value in an unsigned format.
    pub fn int_bits_for(self, lo: i128, hi: i128) -> Option<u32> {
        let need = |v: i128| -> Option<u32> {
            let bits = match (self.signed, v) {
                (true, v) => signed_bits(v) - 1,
                (false, v) if v < 0 => return None,
                (false, 0) => 0,
                (false, v) => unsigned_bits(v as u128),
            };
            Some(bits.saturating_sub(self.frac))
        };
        Some(need(lo)?.max(need(hi)?))
    }

    /// Whether a raw value is representable.
    pub const fn fits(self, raw: i128) -> bool {
        raw >= self.min_raw() && raw <= self.max_raw()
    }

    /// What a register of this format holds after storing `raw` (already scaled
    /// to this format's fraction bits): `raw` itself when it fits, else wrapped
    /// or clamped.
    pub const fn store(self, raw: i128) -> i128 {
        if self.fits(raw) {
            raw
        } else {
            match self.overflow {
                Overflow::Wrap => {
                    if self.signed {
                        wrap_s(raw, self.bits())
                    } else {
                        wrap_u(raw, self.bits())
                    }
                }
                Overflow::Saturate => {
                    if raw < self.min_raw() {
                        self.min_raw()
                    } else {
                        self.max_raw()
                    }
                }
            }
        }
    }

    /// Rescales `raw`, which has `from_frac` fraction bits, to this format's
    /// fraction bits with this format's rounding (left shift when it has more).
    /// Range is not checked: see [`Fmt::store`].
    pub const fn rescale(self, raw: i128, from_frac: u32) -> i128 {
        if from_frac <= self.frac {
            raw << (self.frac - from_frac)
        } else {
            match self.rounding {
                Rounding::Truncate => shr_floor(raw, from_frac - self.frac),
                Rounding::HalfUp => shr_half_up(raw, from_frac - self.frac),
            }
        }
    }

    /// The raw value nearest `v` under this format's rounding, or `None` when
    /// `v` is not finite or does not fit.
    pub fn from_f64(self, v: f64) -> Option<i128> {
        let scaled = v * (self.frac as f64).exp2();
        let raw = match self.rounding {
            Rounding::Truncate => scaled.floor(),
            Rounding::HalfUp => (scaled + 0.5).floor(),
        };
        (raw.is_finite() && raw >= self.min_raw() as f64 && raw <= self.max_raw() as f64).then_some(raw as i128)
    }

    /// The value a raw number stands for.
    pub fn to_f64(self, raw: i128) -> f64 {
        raw as f64 * (-(self.frac as f64)).exp2()
    }

    /// Value of one LSB.
    pub fn lsb(self) -> f64 {
        (-(self.frac as f64)).exp2()
    }

    /// This format with `int` integer bits (same fraction, rounding and overflow).
    pub const fn with_int(self, int: u32) -> Fmt {
        Fmt { int, ..self }
    }
}

impl fmt::Display for Fmt {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let s = if self.signed { 'S' } else { 'U' };
        write!(f, "{s}{}.{} [{}]", self.int, self.frac, self.bits())?;
        if self.rounding == Rounding::HalfUp {
            f.write_str(" half-up")?;
        }
        if self.overflow == Overflow::Saturate {
            f.write_str(" saturate")?;
        }
        Ok(())
    }
}

/// Parses `S11.4`, optionally followed by ` [16]`, `half-up`/`truncate` and
/// `wrap`/`saturate` in any order.
impl FromStr for Fmt {
    type Err = String;
    fn from_str(s: &str) -> Result<Fmt, String> {
        let mut words = s.split_whitespace();
        let head = words.next().ok_or("an empty format; write e.g. \"S11.4\" or \"U8.0 half-up saturate\"")?;
        let signed = match head.chars().next() {
            Some('S' | 's') => true,
            Some('U' | 'u') => false,
            _ => return Err(format!("\"{s}\": a format starts with S (signed) or U (unsigned), e.g. S11.4")),
        };
        let (i, f) =
            head[1..].split_once('.').ok_or_else(|| format!("\"{s}\": expected <S|U><int>.<frac>, e.g. S11.4"))?;
        let num = |t: &str, what: &str| {
            t.parse::<u32>().map_err(|_| format!("\"{s}\": {what} bits \"{t}\" is not a whole number"))
        };
        let mut fmt = Fmt {
            signed,
            int: num(i, "integer")?,
            frac: num(f, "fraction")?,
            rounding: Rounding::Truncate,
            overflow: Overflow::Wrap,
        };
        if fmt.int + fmt.frac == 0 {
            return Err(format!("\"{s}\": a format needs at least one integer or fraction bit"));
        }
        if fmt.bits() > MAX_BITS {
            return Err(format!("\"{s}\": {} bits is more than the {MAX_BITS} the models support", fmt.bits()));
        }
        for w in words {
            match w {
                "half-up" => fmt.rounding = Rounding::HalfUp,
                "truncate" => fmt.rounding = Rounding::Truncate,
                "wrap" => fmt.overflow = Overflow::Wrap,
                "saturate" => fmt.overflow = Overflow::Saturate,
                _ if w.starts_with('[') && w.ends_with(']') => {
                    let n = num(&w[1..w.len() - 1], "total")?;
                    if n != fmt.bits() {
                        return Err(format!("\"{s}\": {head} has {} bits, not {n}", fmt.bits()));
                    }
                }
                _ => {
                    return Err(format!("\"{s}\": unknown word \"{w}\" (expected half-up, truncate, wrap or saturate)"))
                }
            }
        }
        Ok(fmt)
    }
}

impl Serialize for Fmt {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(&self.to_string())
    }
}

impl<'de> Deserialize<'de> for Fmt {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Fmt, D::Error> {
        String::deserialize(d)?.parse().map_err(serde::de::Error::custom)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fmt_rounding_words_are_exact() {
        assert_eq!(shr_floor(-3, 1), -2);
        assert_eq!(shr_half_up(-3, 1), -1); // -1.5 rounds up to -1
        assert_eq!(shr_half_up(5, 1), 3); // 2.5 rounds up to 3
        assert_eq!(Fmt::s(3, 1).rescale(-3, 2), -2); // -0.75 truncated (floor) to S3.1 is -1.0
        assert_eq!(Fmt::s(3, 1).half_up().rescale(-3, 2), -1); // -0.75 -> -0.5 (raw -1)
        assert_eq!(Fmt::s(3, 0).half_up().rescale(-2, 2), 0); // -0.5 -> 0 half up
    }

    #[test]
    fn fmt_store_wraps_or_saturates() {
        let f = Fmt::s(3, 0); // [-8, 7]
        assert_eq!(f.store(9), -7);
        assert_eq!(f.saturating().store(9), 7);
        assert_eq!(f.saturating().store(-100), -8);
        assert_eq!(Fmt::u(3, 0).store(9), 1);
        assert_eq!(Fmt::u(3, 0).saturating().store(-2), 0);
    }

    #[test]
    fn fmt_parses_and_prints_the_house_notation() {
        let f: Fmt = "S11.4 [16] half-up".parse().unwrap();
        assert_eq!(f, Fmt::s(11, 4).half_up());
        assert_eq!(f.to_string(), "S11.4 [16] half-up");
        assert_eq!(f.to_string().parse::<Fmt>().unwrap(), f);
        for bad in ["", "X3.4", "S3", "S3.x", "S3.4 [9]", "S3.4 round", "S100.100", "U0.0"] {
            assert!(bad.parse::<Fmt>().is_err(), "{bad:?} should not parse");
        }
    }

    #[test]
    fn fmt_from_f64_rounds_and_checks_range() {
        let f = Fmt::s(3, 2).half_up();
        assert_eq!(f.from_f64(1.125), Some(5)); // 4.5 -> 5
        assert_eq!(f.from_f64(-1.125), Some(-4)); // -4.5 -> -4
        assert_eq!(f.from_f64(8.0), None);
        assert_eq!(f.from_f64(f64::NAN), None);
        assert_eq!(signed_bits(-8), 4);
        assert_eq!(signed_bits(7), 4);
        assert_eq!(signed_bits(8), 5);
        assert_eq!(clog2(640), 10);
        assert_eq!(clog2(1024), 10);
    }
}
