//! The bit-serial z compare of one pixel, LSB first: paper 000 (Bang, Bae, Kyung 1990),
//! Fig. 10 "Z-depth comparison logic for one pixel". Mirrors `rtl::se::zcmp::Zcmp`.
//!
//! One bit of the new z (`nz`, from the interpolator) and of the stored z (`oz`, from the
//! old-z block) per clock, bit 0 first (`first` high with it). After the clock of the MSB,
//! `flag` is "new z < old z", unsigned; AND the EPT mask, it is the pixel's write enable.
//! One bit per clock: W clocks for a W-bit z.
//!
//! **Reading of Fig. 10 (erratum).** The text says flag 1 becomes 1 where NZ_i < OZ_i and
//! *holds* where NZ_i >= OZ_i, starting at 0. Taken literally ([`step_literal`]) a later,
//! more significant bit where NZ_i > OZ_i cannot clear the flag, so 0b10 would be "less"
//! than 0b01. LSB first, the most significant differing bit must decide, so [`step`] sets
//! the flag where NZ_i < OZ_i, *clears* it where NZ_i > OZ_i and holds it where they are
//! equal. Tests: `zcmp_exhaustive_w1_to_w8` (the reading is `<`) and
//! `zcmp_paper_000_literal_reading_is_wrong` (the literal text is not).

/// The flag after one clock of Fig. 10 as built: a differing bit decides (`oz` = 1 there
/// means NZ_i < OZ_i), an equal bit keeps the flag; `first` (bit 0) starts from 0.
pub fn step(flag: bool, first: bool, nz: bool, oz: bool) -> bool {
    let held = flag && !first; // RTL: held = flag & ~first
    if nz != oz {
        oz
    } else {
        held
    }
}

/// The flag after one clock of Fig. 10 as its text reads: set where NZ_i < OZ_i, held
/// otherwise. Not built; kept to show why it is wrong.
pub fn step_literal(flag: bool, first: bool, nz: bool, oz: bool) -> bool {
    let held = flag && !first;
    (!nz && oz) || held
}

/// Runs `w` clocks of `step_fn`, LSB first, from a flag left over from a previous compare
/// (`stale`): the flag after the MSB.
pub fn run(step_fn: fn(bool, bool, bool, bool) -> bool, nz: u64, oz: u64, w: u32, stale: bool) -> bool {
    (0..w).fold(stale, |flag, i| step_fn(flag, i == 0, (nz >> i) & 1 == 1, (oz >> i) & 1 == 1))
}

/// Whether `nz` < `oz` (unsigned, `w` bits), as Fig. 10 computes it.
pub fn zcmp(nz: u64, oz: u64, w: u32) -> bool {
    run(step, nz, oz, w, false)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every pair of operands from 1 to 8 bits, from either stale flag: the flag is `<`.
    #[test]
    fn zcmp_exhaustive_w1_to_w8() {
        for w in 1..=8u32 {
            for nz in 0..1u64 << w {
                for oz in 0..1u64 << w {
                    for stale in [false, true] {
                        assert_eq!(run(step, nz, oz, w, stale), nz < oz, "w={w} nz={nz:#b} oz={oz:#b} stale={stale}");
                    }
                }
            }
        }
    }

    /// 000 Fig. 10 read literally ("holds where NZ_i >= OZ_i") calls 0b10 less than 0b01:
    /// bit 0 sets the flag (0 < 1) and bit 1 (1 > 0) cannot clear it.
    #[test]
    fn zcmp_paper_000_literal_reading_is_wrong() {
        assert!(run(step_literal, 0b10, 0b01, 2, false), "the literal reading says 2 < 1");
        assert!(!zcmp(0b10, 0b01, 2), "the built reading says 2 >= 1");
        // It fails on exactly the pairs whose lower bits say "less" and a higher bit "more".
        let wrong = (0..16u64).flat_map(|a| (0..16u64).map(move |b| (a, b)));
        let wrong = wrong.filter(|&(nz, oz)| run(step_literal, nz, oz, 4, false) != (nz < oz)).count();
        assert!(wrong > 0);
    }
}
