//! The texture coordinates and level of detail of one pixel: 001's perspective division
//! (eq. 3) and level L = log2 max(ds/dx, dt/dx, ds/dy, dt/dy) (eq. 4), or OpenGL's exact
//! rho as the alternative.
//!
//! **Divide.** q (format `q`) is normalised, q = m · 2^(E') with m in [1/2, 1), and
//! r = floor(2^recip / m), in (2^recip, 2^(recip+1)], is its reciprocal mantissa: the exact
//! quotient a pipelined restoring divider gives, one per clock. Then
//! s = floor(s·q · r · 2^(-E') / 2^recip) in `st`'s fraction bits (saturating), likewise t.
//!
//! **Derivatives.** s = (s·q) / q, so ds/dx = (d(s·q)/dx - s · dq/dx) / q (the quotient
//! rule; likewise t and y). The numerators g are formed in `dst`'s fraction bits (the
//! product s · dq/dx floored), scaled to texels of level 0 (u = s · 2^ws, v = t · 2^hs) and
//! the division by q is an addition of logarithms:
//! - [`LodRule::Max`] (001 eq. 4): lambda = log2 max(|g_u,x|, |g_v,x|, |g_u,y|, |g_v,y|) + log2(1/q);
//! - [`LodRule::Exact`] (OpenGL 4.6 eq. 8.7): lambda = log2(max(g_u,x² + g_v,x², g_u,y² + g_v,y²)) / 2 + log2(1/q).
//!
//! log2 of an integer is its leading one's position plus a table of log2(1 + f) over the
//! next `lod_frac + 4` bits of f ([`log2_table`]), each entry at the middle of its interval,
//! in `lod_frac + 3` fraction bits; the sum is rounded half up to `lod_frac` bits. A pixel
//! whose four numerators are 0 gets [`MAGNIFIED`].

use crate::texture_unit::{TexGrad, TexIn, TexState};
use fx::{shr_floor, TexFormats};
use texture::LodRule;

/// The level of detail of a pixel whose derivatives are all 0 (lambda = -inf): magnified.
pub const MAGNIFIED: i64 = -(1 << 30);

/// Guard bits of the level of detail beyond `lod_frac`, before its final rounding.
const GUARD: u32 = 3;

/// A pixel's texture coordinates and level of detail.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Coords {
    /// s and t, in `st`'s fraction bits.
    pub s: i64,
    pub t: i64,
    /// lambda in `lod_frac` fraction bits (signed), [`MAGNIFIED`] for zero derivatives.
    pub lambda: i64,
}

/// The reciprocal of q: (r, e) with 1/q = r · 2^e / 2^recip, r in (2^recip, 2^(recip+1)].
/// q <= 0 is taken as its smallest step.
pub fn reciprocal(f: &TexFormats, q: i64) -> (i64, i32) {
    let q = q.max(1) as u64;
    let bits = f.q.bits();
    let lz = bits - (64 - q.leading_zeros());
    let m = q << lz;
    let r = (1u128 << (f.recip + bits)) / m as u128;
    (r as i64, lz as i32 + f.q.frac as i32 - bits as i32)
}

/// s·q or t·q divided by q: in `st`'s fraction bits, saturated.
fn divide(f: &TexFormats, xq: i64, (r, e): (i64, i32)) -> i64 {
    let p = i128::from(xq) * i128::from(r);
    let shift = f.recip as i32 - e;
    let v = if shift >= 0 { shr_floor(p, shift as u32) } else { p << -shift };
    f.st.store(v) as i64
}

/// The entries of the log2 table: entry k = round(log2(1 + (k + 1/2) / 2^T) · 2^F) for
/// T = `lod_frac + 4` index bits and F = `lod_frac + 3` fraction bits. The RTL's ROM holds
/// the same entries.
pub fn log2_table(f: &TexFormats) -> Vec<i64> {
    let (t, frac) = (f.lod_frac + GUARD + 1, f.lod_frac + GUARD);
    (0..1u64 << t)
        .map(|k| (((k as f64 + 0.5) / (1u64 << t) as f64).ln_1p() / 2f64.ln() * (1u64 << frac) as f64).round() as i64)
        .collect()
}

/// log2(x) for x >= 1 in `frac` >= `lod_frac + GUARD` fraction bits: the leading one's
/// position and the table entry of the next bits.
pub fn log2(f: &TexFormats, table: &[i64], x: u128, frac: u32) -> i64 {
    let t = f.lod_frac + GUARD + 1;
    let p = 127 - x.leading_zeros();
    let below = x ^ (1 << p);
    let index = if p >= t { below >> (p - t) } else { below << (t - p) };
    ((i64::from(p)) << frac) + (table[index as usize] << (frac - (f.lod_frac + GUARD)))
}

/// The numerator of ds/dx (or dt/dx, ...): d(s·q)/dx - s · dq/dx in `dst`'s fraction bits.
fn numerator(f: &TexFormats, dxq: i64, x: i64, dq: i64) -> i128 {
    let product = shr_floor(i128::from(x) * i128::from(dq), f.st.frac + f.dq.frac - f.dst.frac);
    i128::from(dxq) - product
}

/// The coordinates and level of detail of pixel `p` of a triangle with gradients `g`.
pub fn coords(f: &TexFormats, state: &TexState, table: &[i64], p: &TexIn, g: &TexGrad) -> Coords {
    let recip = reciprocal(f, p.q);
    let (s, t) = (divide(f, p.sq, recip), divide(f, p.tq, recip));
    let [ws, hs] = state.size_log2;
    let axis = |k: usize| {
        let u = numerator(f, g.dsq[k], s, g.dq[k]).unsigned_abs() << ws;
        let v = numerator(f, g.dtq[k], t, g.dq[k]).unsigned_abs() << hs;
        (u, v)
    };
    let ((ux, vx), (uy, vy)) = (axis(0), axis(1));
    // The sum is formed in one bit more than the table's, so that the exact rule's halving
    // of log2(m) is exact: log2(m) in F bits is log2(m) / 2 in F + 1.
    let frac = f.lod_frac + GUARD + 1;
    let log_rho = match state.lod {
        LodRule::Max => {
            let m = ux.max(vx).max(uy).max(vy);
            (m > 0).then(|| log2(f, table, m, frac))
        }
        LodRule::Exact => {
            let m = (ux * ux + vx * vx).max(uy * uy + vy * vy);
            (m > 0).then(|| log2(f, table, m, frac - 1))
        }
    };
    let lambda = match log_rho {
        None => MAGNIFIED,
        Some(l) => {
            let scale = i64::from(recip.1) - i64::from(f.dst.frac) - i64::from(f.recip);
            let g = l + log2(f, table, recip.0 as u128, frac) + (scale << frac);
            (g + (1 << GUARD)) >> (GUARD + 1)
        }
    };
    Coords { s, t, lambda }
}
