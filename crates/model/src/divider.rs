//! `divider`: the one shared pipelined divider of paper 001 (Woo 2004, §II.2.라).
//!
//! 001 replaces the seven dividers of a parallel triangle setup by one pipelined
//! divider that takes a division per cycle. Ours is a radix-2 restoring divider:
//! one quotient bit per step, the steps spread over `latency` pipeline stages.
//! Where 001's Taylor-series divider is off by up to 1 LSB, this one is exact:
//!
//! **Error bound.** `q = floor(n / d)` and `r = n - q*d` with `0 <= r < d`
//! exactly; as a reciprocal, `0 <= 2^k/d - q < 1 LSB` of `q`. Measured by
//! `divider_exhaustive_w8_is_floor_division` and
//! `divider_random_full_width_is_floor_division`, and as a reciprocal by
//! `divider_reciprocal_error_below_1_lsb`.
//!
//! Setup issues its seven divisions (1/area, and per edge the start and the
//! step of the exact edge walker) one per cycle. A division whose result will
//! not be used (an edge that crosses no scanline centre) is issued as 0/1, so
//! every quotient the divider produces is in range.
//!
//! Mirrors `rtl::divider` (`hdl-out/divider.v`).

use fx::{unsigned_bits, Formats};

/// Divisions accepted per cycle: one (001: "throughput 1 cycle").
pub const II: u32 = 1;
/// Default pipeline depth: one quotient step per stage at size class 10 (its 25 steps),
/// so that a stage is one subtract and select, for a 100 MHz clock (issue 17: 141.9 MHz
/// alone on ECP5, against 39.6 at five steps a stage). 001's divider has 5 stages
/// (`--param L=5`).
pub const LATENCY: u32 = 25;
/// The deepest divider built: stages past the quotient's steps (at formats with fewer than
/// [`LATENCY`] quotient bits, say) are registers only, so the default depth builds at any
/// formats.
pub const LATENCY_MAX: u32 = 32;

/// One division: signed dividend, positive divisor.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DividerIn {
    pub n: i128,
    pub d: i128,
}

/// Its result: floor quotient and the remainder in [0, d).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DividerOut {
    pub q: i128,
    pub r: i128,
}

/// Floor division with remainder, as the hardware computes it.
pub fn divider(i: DividerIn, f: &Formats) -> DividerOut {
    assert!(i.d > 0, "divider: divisor {} must be positive (setup issues 0/1 for unused divisions)", i.d);
    let q = i.n.div_euclid(i.d);
    let dv = f.derived();
    // Setup keeps every dividend, divisor and quotient within the divider's
    // widths (see `Formats::derived` for the three kinds of division).
    debug_assert!(fx::fits_s(i.n, dv.div_dividend_bits), "dividend {} exceeds {} bits", i.n, dv.div_dividend_bits);
    debug_assert!(
        unsigned_bits(i.d as u128) <= dv.div_divisor_bits,
        "divisor {} exceeds {} bits",
        i.d,
        dv.div_divisor_bits
    );
    debug_assert!(fx::fits_s(q, dv.div_quotient_bits), "quotient {q} exceeds {} bits", dv.div_quotient_bits);
    DividerOut { q, r: i.n.rem_euclid(i.d) }
}

/// A reciprocal `1/a ~= mant * 2^-(ooa.frac + exp)` with `mant` in
/// (2^(frac-1), 2^frac], `exp` = the index of `a`'s top bit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Recip {
    /// The mantissa, in the `ooa` format (U1.frac, value in [1/2, 1]).
    pub mant: i128,
    pub exp: u32,
}

/// The divider's operands for `1/a` (a >= 1): `a` normalised so its top bit
/// sits at bit `area_bits - 2`, divided into `2^(area_bits - 2 + ooa.frac)`. An `a` wider
/// than that (the vector method's perspective sum at more `bary` fraction bits than
/// `area_bits - 1`) keeps its top `area_bits - 1` bits, as the divider's divisor port
/// holds no more: truncated, a relative error below 2^-(area_bits - 2).
pub fn recip_operands(a: i128, f: &Formats) -> (DividerIn, u32) {
    assert!(a >= 1, "reciprocal of {a}");
    let top = f.derived().area_bits - 2;
    let exp = 127 - a.leading_zeros();
    let d = if exp <= top { a << (top - exp) } else { a >> (exp - top) };
    (DividerIn { n: 1i128 << (top + f.ooa.frac), d }, exp)
}

/// `1/a` through the divider.
pub fn reciprocal(a: i128, f: &Formats) -> Recip {
    let (op, exp) = recip_operands(a, f);
    Recip { mant: divider(op, f).q, exp }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};

    /// A reciprocal of a value wider than the divisor port: its top bits, to the
    /// mantissa's precision.
    #[test]
    fn divider_reciprocal_of_a_wide_value_keeps_its_top_bits() {
        let f = Formats::for_resolution(64, 64);
        let top = f.derived().area_bits - 2;
        for a in [(1i128 << (top + 9)) + 12345, (3i128 << (top + 20)) - 1, 1i128 << (top + 1)] {
            let r = reciprocal(a, &f);
            let approx = r.mant as f64 * (-((f.ooa.frac + r.exp) as f64)).exp2();
            let rel = (approx * a as f64 - 1.0).abs();
            assert!(rel < 2.0 * (-(f.ooa.frac as f64)).exp2(), "1/{a}: {approx} (relative error {rel})");
        }
    }

    #[test]
    fn divider_exhaustive_w8_is_floor_division() {
        // Every signed 8-bit dividend by every 7-bit divisor: the same generic
        // code the full width runs, at a width small enough to enumerate.
        let f = Formats::for_resolution(64, 64);
        for n in -128i128..128 {
            for d in 1i128..128 {
                let o = divider(DividerIn { n, d }, &f);
                // Independent oracle: q*d <= n < (q+1)*d.
                assert!(o.q * d <= n && n < (o.q + 1) * d, "{n}/{d} gave q {}", o.q);
                assert_eq!(o.r, n - o.q * d);
            }
        }
    }

    #[test]
    fn divider_random_full_width_is_floor_division() {
        let f = Formats::for_resolution(4096, 4096);
        let dv = f.derived();
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(crate::test_seed());
        for _ in 0..crate::test_count() * 100 {
            let d = rng.gen_range(1..(1i128 << (dv.div_divisor_bits - 1)));
            let q = rng.gen_range(-(1i128 << (dv.div_quotient_bits - 2))..(1i128 << (dv.div_quotient_bits - 2)));
            let n = q * d + rng.gen_range(0..d);
            if !fx::fits_s(n, dv.div_dividend_bits) {
                continue;
            }
            let o = divider(DividerIn { n, d }, &f);
            assert_eq!((o.q, o.r), (q, n - q * d), "{n}/{d}");
        }
    }

    #[test]
    fn divider_reciprocal_error_below_1_lsb() {
        let f = Formats::for_resolution(640, 480);
        let m = f.ooa.frac;
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(crate::test_seed());
        let area_max = 1i128 << (f.derived().area_bits - 2);
        for a in (1..5000).chain((0..crate::test_count() * 10).map(|_| rng.gen_range(1..area_max))) {
            let r = reciprocal(a, &f);
            assert!(r.mant > 1 << (m - 1) && r.mant <= 1 << m, "mantissa {} of 1/{a} out of (1/2, 1]", r.mant);
            // exact = 2^(m + exp) / a, in mantissa LSBs; floor means 0 <= exact - mant < 1.
            let num = 1i128 << (m + r.exp);
            assert!(r.mant * a <= num && num < (r.mant + 1) * a, "1/{a}: mantissa {} exp {}", r.mant, r.exp);
        }
    }
}
