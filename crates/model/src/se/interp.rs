//! The bit-serial midpoint-subdivision interpolator: paper 000, Figs. 8 and 9 (after PIPE).
//! Mirrors `rtl::se::interp::Interp`.
//!
//! From the two ends of the engine's region, e0 = f(0) and e1 = f(P) (P = 64: XL_i and
//! XR_i, rounded integers from the multipliers), it fills all P + 1 points. Level 1 gives
//! f(P/2) = (f(0) + f(P))/2, level 2 f(P/4) and f(3P/4), and so on: level L makes the
//! points x = (2k + 1) P / 2^L from their neighbours x -+ P/2^L, K = log2 P levels in all.
//!
//! **Delay-based halving.** In a bit-serial stream, delaying a value by one clock doubles
//! it. Instead of shifting each sum right (PIPE's add and shift right, which truncates), a
//! level-L point is carried at scale 2^L, `V_x = 2^L * g(x)`, exactly; a parent from a
//! shallower level is delayed by the difference of levels to bring it to scale. No bit is
//! ever dropped, so no truncation error builds up down the tree.
//!
//! **Rounding.** Every pixel leaves rounded to the nearest integer, half up. The ends enter
//! with one more bit, the half: g = f + 1/2 is a line too, g(0) = e0 + 1/2 and
//! g(P) = e1 + 1/2, so floor(g(x)) = round(f(x)) falls out of the exact values by dropping
//! their fraction bits: no incrementer per pixel.
//!
//! **Sign extension (Fig. 9).** Ends of different signs (or both negative) need their sign
//! bit repeated past the MSB while the deeper levels still add: K clocks of it.

/// Level of point `x` of `0..=p` in the subdivision tree: 0 for the ends, K for odd x.
pub fn level(x: u32, p: u32) -> u32 {
    if x == 0 || x == p {
        0
    } else {
        p.trailing_zeros() - x.trailing_zeros()
    }
}

/// The `p` pixels' values round(f(x)), x = 0..p-1, from the region's ends `e0` = f(0) and
/// `e1` = f(p), by the tree of Fig. 8 with delay-based halving.
pub fn interp(e0: i128, e1: i128, p: u32) -> Vec<i128> {
    let k = p.trailing_zeros();
    // v[x] = 2^level(x) * (2 f(x) + 1): the stream of point x, exact. The ends carry the half.
    let mut v = vec![0i128; p as usize + 1];
    v[0] = 2 * e0 + 1;
    v[p as usize] = 2 * e1 + 1;
    for l in 1..=k {
        let s = p >> l;
        for x in (s..p).step_by(2 * s as usize) {
            // RTL `Level`: each parent delayed (doubled) up to level l - 1, then one adder.
            let scaled = |y: u32| v[y as usize] << (l - 1 - level(y, p));
            v[x as usize] = scaled(x - s) + scaled(x + s);
        }
    }
    // Drop the level's fraction bits and the half's: floor(f(x) + 1/2).
    (0..p).map(|x| v[x as usize] >> (level(x, p) + 1)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    /// The oracle: the straight line through the ends, rounded half up, by one division.
    fn line(e0: i128, e1: i128, p: u32, x: u32) -> i128 {
        let (p, x) = (p as i128, x as i128);
        (((p - x) * e0 + x * e1) * 2 + p).div_euclid(2 * p)
    }

    /// 000 Fig. 11: region (0, 64), z ends -272 and 8935 give the printed z from x = 2 to 9.
    #[test]
    fn se_interp_paper_000_fig11_z() {
        let z = interp(-272, 8935, 64);
        assert_eq!(&z[2..10], &[0x010, 0x0a0, 0x12f, 0x1bf, 0x24f, 0x2df, 0x36f, 0x3ff]);
    }

    #[test]
    fn se_interp_is_the_rounded_line() {
        let mut rng = ChaCha8Rng::seed_from_u64(crate::test_seed());
        for p in [8, 16, 32, 64] {
            for _ in 0..crate::test_count() {
                let w = rng.gen_range(2..=32);
                let (e0, e1) =
                    (rng.gen_range(-(1i128 << (w - 1))..1 << (w - 1)), rng.gen_range(-(1 << (w - 1))..1 << (w - 1)));
                let got = interp(e0, e1, p);
                for x in 0..p {
                    assert_eq!(
                        got[x as usize],
                        line(e0, e1, p, x),
                        "seed {}: p={p} e0={e0} e1={e1} x={x}",
                        crate::test_seed()
                    );
                }
            }
        }
    }

    #[test]
    fn se_interp_levels() {
        let l: Vec<u32> = (0..=8).map(|x| level(x, 8)).collect();
        assert_eq!(l, [0, 3, 2, 3, 1, 3, 2, 3, 0]);
    }
}
