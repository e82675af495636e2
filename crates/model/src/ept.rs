//! The edge painting tree (EPT), bit-exact: mirrors `rtl::ept` (`hdl-out/ept.v`).
//!
//! Paper 002 (Choi, Kim, Eo, Kyung, KAIST), section 3: a binary tree of processing
//! elements (PEs, Fig. 3) over P pixels, XL and XR entering MSB first, one bit per level;
//! each leaf PE drives 4 pixels. Pixel i is painted iff XL <= i <= XR. Combinational:
//! [`LATENCY`] 0 clocks, [`II`] 1 (a new command every clock).
//!
//! The model walks the same tree as the RTL, PE by PE ([`pe`] is Fig. 3 as the RTL's `Pe`
//! implements it), so a wrong case in the PE shows here as in the RTL. Its tests compare it
//! with the interval rule `XL <= i <= XR`, which shares nothing with the tree.

/// Clocks from command to mask: none, the tree is combinational (002, section 3).
pub const LATENCY: u32 = 0;
/// Clocks between commands.
pub const II: u32 = 1;

/// One scanline command, as the RTL's input ports `xl`, `xr`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct EptIn {
    /// XL: left end of the span, inclusive; pixel index U{B}.0 [B], B = log2 P.
    pub xl: u32,
    /// XR: right end of the span, inclusive; U{B}.0 [B].
    pub xr: u32,
}

/// The paint mask, as the RTL's output port `px`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct EptOut {
    /// `px[i]`: pixel i is painted (RTL `px` bit i), P entries.
    pub px: Vec<bool>,
    /// Clocks taken: [`LATENCY`].
    pub cycles: u32,
}

/// The inputs of one PE, named as in 002 Fig. 3.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PeIn {
    /// LI: left-bound bit routed by the parent (root: MSB of XL).
    pub li: bool,
    /// RI: right-bound bit routed by the parent (root: MSB of XR).
    pub ri: bool,
    /// This level's bit of XL.
    pub xl: bool,
    /// This level's bit of XR.
    pub xr: bool,
    /// LCS: forces XL to 0.
    pub lcs: bool,
    /// RCS: forces XR to 1.
    pub rcs: bool,
}

/// The outputs of one PE, named as in 002 Fig. 3.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PeOut {
    /// LLC, RLC: (left, right) signal of the left child.
    pub llc: bool,
    pub rlc: bool,
    /// LRC, RRC: (left, right) signal of the right child.
    pub lrc: bool,
    pub rrc: bool,
    /// LCSO: the left child's LCS.
    pub lcso: bool,
    /// LRCSO: the left child's RCS and the right child's LCS.
    pub lrcso: bool,
    /// RCSO: the right child's RCS.
    pub rcso: bool,
}

/// One PE, 002 Fig. 3, in the reading documented on `rtl::ept::Pe`: by (LI, RI),
/// (0,0) routes (XL, XR) left, (1,1) right, (0,1) splits into (XL, 1) and (0, XR) with
/// LRCSO high, and (1,0) (also every child not chosen) is the inactive pair (1, 0).
pub fn pe(i: PeIn) -> PeOut {
    let xl = i.xl && !i.lcs; // RTL: xl_f = xl & ~lcs
    let xr = i.xr || i.rcs; // RTL: xr_f = xr | rcs
    const INACTIVE: (bool, bool) = (true, false);
    let (left, right, lrcso) = match (i.li, i.ri) {
        (false, false) => ((xl, xr), INACTIVE, false),
        (true, true) => (INACTIVE, (xl, xr), false),
        (false, true) => ((xl, true), (false, xr), true),
        (true, false) => (INACTIVE, INACTIVE, false),
    };
    PeOut { llc: left.0, rlc: left.1, lrc: right.0, rrc: right.1, lcso: i.lcs, lrcso, rcso: i.rcs }
}

/// The EPT for `p` pixels (a power of two, 8 to 1024): `px[i]` iff XL <= i <= XR.
/// Panics on an unsupported `p` or a bound that does not fit in log2(p) bits.
pub fn ept(p: usize, cmd: EptIn) -> EptOut {
    EptOut { px: tree(pe, p, cmd), cycles: LATENCY }
}

/// The tree of 002 Fig. 4 with `pe` at every node.
fn tree(pe: fn(PeIn) -> PeOut, p: usize, cmd: EptIn) -> Vec<bool> {
    assert!(p.is_power_of_two() && (8..=1024).contains(&p), "P = {p}: a power of two from 8 to 1024");
    let b = p.trailing_zeros();
    assert!((cmd.xl as usize) < p && (cmd.xr as usize) < p, "{cmd:?} does not fit in {b} bits");
    let msb = |v: u32| (v >> (b - 1)) & 1 == 1;
    let mut px = vec![false; p];
    // RTL `Ept<P>`: the MSBs are the root's (LI, RI); LCS = RCS = 0.
    subtree(pe, &mut px, 0, p, msb(cmd.xl), msb(cmd.xr), false, false, cmd);
    px
}

/// A subtree over pixels `base .. base + n` (RTL `Tree<n>`); its PE takes bit
/// log2(n) - 2 of XL and XR.
#[allow(clippy::too_many_arguments)]
fn subtree(
    pe: fn(PeIn) -> PeOut,
    px: &mut [bool],
    base: usize,
    n: usize,
    li: bool,
    ri: bool,
    lcs: bool,
    rcs: bool,
    cmd: EptIn,
) {
    let bit = n.trailing_zeros() - 2;
    let o = pe(PeIn { li, ri, xl: (cmd.xl >> bit) & 1 == 1, xr: (cmd.xr >> bit) & 1 == 1, lcs, rcs });
    if n == 4 {
        // RTL `Tree4`: pixel pair (L, R) paints its left pixel iff L = 0, its right iff R = 1.
        px[base] = !o.llc;
        px[base + 1] = o.rlc;
        px[base + 2] = !o.lrc;
        px[base + 3] = o.rrc;
    } else {
        subtree(pe, px, base, n / 2, o.llc, o.rlc, o.lcso, o.lrcso, cmd);
        subtree(pe, px, base + n / 2, n / 2, o.lrc, o.rrc, o.lrcso, o.rcso, cmd);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    /// The oracle: the interval rule of 002 section 3, not the tree.
    fn interval(p: usize, xl: u32, xr: u32) -> Vec<bool> {
        (0..p as u32).map(|i| xl <= i && i <= xr).collect()
    }

    fn mask_bits(px: &[bool]) -> u64 {
        px.iter().enumerate().map(|(i, &b)| (b as u64) << i).sum()
    }

    /// 002 Fig. 5: 8 pixels, XL = 000, XR = 101 -> PX0..PX5 = 1, PX6 = PX7 = 0.
    #[test]
    fn ept_model_paper_002_fig5() {
        let out = ept(8, EptIn { xl: 0b000, xr: 0b101 });
        assert_eq!(mask_bits(&out.px), 0b0011_1111);
        assert_eq!(out.cycles, 0);
    }

    /// 002 Fig. 3, the four (LI, RI) cases as the text states them (the (0, 1) case read as
    /// its LRCSO sentence requires). XL = 0, XR = 1 tells a routed pair from the inactive
    /// (1, 0); XL = 1, XR = 0 tells a routed bit from a constant.
    #[test]
    fn ept_pe_paper_002_fig3_cases() {
        let at = |li, ri, xl, xr| pe(PeIn { li, ri, xl, xr, lcs: false, rcs: false });
        let out = |llc, rlc, lrc, rrc, lrcso| PeOut { llc, rlc, lrc, rrc, lcso: false, lrcso, rcso: false };
        let (t, f) = (true, false);
        assert_eq!(at(f, f, f, t), out(f, t, t, f, f), "(0,0): LLC=XL RLC=XR, right child (1,0)");
        assert_eq!(at(t, t, f, t), out(t, f, f, t, f), "(1,1): LRC=XL RRC=XR, left child (1,0)");
        assert_eq!(at(f, t, f, t), out(f, t, f, t, t), "(0,1): LLC=XL RLC=1 LRC=0 RRC=XR LRCSO=1");
        assert_eq!(at(f, t, t, f), out(t, t, f, f, t), "(0,1): RLC and LRC are constants");
        assert_eq!(at(t, f, f, t), out(t, f, t, f, f), "(1,0): both children (1,0)");
        // LCS forces XL to 0, RCS forces XR to 1, and both pass on to the outer children.
        let forced = pe(PeIn { li: f, ri: f, xl: t, xr: f, lcs: t, rcs: t });
        assert_eq!((forced.llc, forced.rlc, forced.lcso, forced.rcso), (f, t, t, t));
    }

    /// The (0, 1) case as printed ("LRC = XL, RRC = 1, LLC = 0, RLC = XR") does not give
    /// Fig. 5; this pins the reading `pe` implements.
    #[test]
    fn ept_paper_002_text_case01_literal_breaks_fig5() {
        fn pe_as_printed(i: PeIn) -> PeOut {
            let o = pe(i);
            if !i.li && i.ri {
                let (xl, xr) = (i.xl && !i.lcs, i.xr || i.rcs);
                return PeOut { llc: false, rlc: xr, lrc: xl, rrc: true, ..o };
            }
            o
        }
        let cmd = EptIn { xl: 0b000, xr: 0b101 };
        assert_ne!(mask_bits(&tree(pe_as_printed, 8, cmd)), 0b0011_1111);
        assert_eq!(mask_bits(&tree(pe, 8, cmd)), 0b0011_1111);
    }

    #[test]
    fn ept_model_exhaustive_p8_p16_p64() {
        for p in [8, 16, 64] {
            for xl in 0..p as u32 {
                for xr in 0..p as u32 {
                    assert_eq!(ept(p, EptIn { xl, xr }).px, interval(p, xl, xr), "P={p} xl={xl} xr={xr}");
                }
            }
        }
    }

    #[test]
    fn ept_model_random_p1024() {
        let (seed, n) = (crate::test_seed(), crate::test_count());
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        for _ in 0..n {
            let (xl, xr) = (rng.gen_range(0..1024), rng.gen_range(0..1024));
            assert_eq!(
                ept(1024, EptIn { xl, xr }).px,
                interval(1024, xl, xr),
                "seed {seed}: EptIn {{ xl: {xl}, xr: {xr} }}"
            );
        }
    }
}
