//! The L and R serial multipliers with their rounding: paper 000, Fig. 7. Mirrors
//! `rtl::se::mul::SerialMul`.
//!
//! Each evaluates the span's line `f(X) = A*X + B` at one end of the engine's region (L at
//! XL_i, R at XR_i): A and B enter serially, LSB first, X is held in parallel in its 11
//! stages (one per bit of X, screens up to 1024 wide). Only the low `n + frac` bits of the
//! product are formed, so A and B may be given modulo 2^(n + frac): the result is right
//! whenever the true f(X) fits the SE word. The result is rounded half up to an integer
//! by a serial incrementer that adds bit `frac - 1` into bit `frac` (000's Fig. 11 values
//! follow from f(XL_i), f(XR_i) rounded to integers).

use fx::{shr_half_up, wrap_s};

/// round(A*X + B) as an `n`-bit two's complement integer, for A and B with `frac` fraction
/// bits held in `n + frac` bits (wrapped, as the RTL's shift registers hold them).
pub fn endpoint(a: i128, b: i128, x: i128, n: u32, frac: u32) -> i128 {
    let w = n + frac;
    // RTL: carry-save cells over the bits of X, then a serial adder for B, modulo 2^w.
    let y = wrap_s(wrap_s(a, w) * x + wrap_s(b, w), w);
    // RTL: the incrementer's carry is loaded with bit frac-1, then e_k = y_(frac+k) ^ carry.
    wrap_s(shr_half_up(y, frac), n)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 000 Fig. 11's z line (through (2, 0x010) and (9, 0x3FF), 16 fraction bits) gives the
    /// endpoints the papers' digest derives: -272 at 0 and 8935 at 64.
    #[test]
    fn se_mul_paper_000_fig11_endpoints() {
        let a = ((0x3ff - 0x010) << 16) / 7 + 1; // 143.857 rounded to 16 fraction bits
        let b = (0x010 << 16) - 2 * a;
        assert_eq!((endpoint(a, b, 0, 24, 16), endpoint(a, b, 64, 24, 16)), (-272, 8935));
    }

    /// A and B given modulo 2^(n + frac) give the same endpoint when f(X) fits n bits.
    #[test]
    fn se_mul_is_modular_in_a_and_b() {
        let (n, frac) = (12, 8);
        let (a, b) = (-3 * 256 - 17, 3000 * 256 + 99);
        let x = 1000;
        let exact = (a * x + b + 128) >> 8;
        assert!(fits(exact, n), "{exact}");
        let m = 1i128 << (n + frac);
        assert_eq!(endpoint(a + 5 * m, b - 3 * m, x, n, frac), exact);
    }

    fn fits(v: i128, n: u32) -> bool {
        wrap_s(v, n) == v
    }
}
