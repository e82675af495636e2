//! `vector`: per-pixel barycentric ("vector") rasterization of paper 004
//! (Lee et al. 2009, eq. 1-6). Every pixel is computed on its own, so any
//! number of lanes can work side by side.
//!
//! For each pixel centre p of the triangle's bounding box (clipped to the screen):
//! * the numerators of eq. (3) are exact edge functions; `a = w1/area`,
//!   `b = w2/area` with 1/area from the divider (the `ooa` mantissa), in `bary`;
//!   coverage uses the exact signs with the top-left rule, so the method is as
//!   watertight as the scanline one;
//! * attributes by eq. (4): `C = C0 + (C1 - C0) a + (C2 - C0) b`; depth is always
//!   screen-linear;
//! * perspective correction (eq. 5-6): with `l = (1-a-b, a, b)` and the vertices'
//!   `iw = w_min/w`, `l'_k = l_k iw_k / sum(l_j iw_j)` (one reciprocal per pixel
//!   through a divider of the lane's own), then eq. (4) with `a' = l'_1`, `b' = l'_2`.
//!   Eq. (6) solves the same system for a and b directly; the two agree exactly
//!   in real arithmetic.
//!
//! Cycle model (`rtl::vector`'s, at `lanes` = 1; a frame's: `cycles::vector_frame`): the
//! unit sets a triangle up in [`setup`] cycles while it walks the one before; the walk of
//! the clipped bounding box, `lanes` pixels of a row per cycle, rows one after another
//! ([`VectorOut::walk_cycles`]; pixel `walk[i]` in the walk's cycle `walk[i] / lanes`), begins
//! when the walk before has ended and the constants of the triangle two before are read no
//! more ([`constants_read`]); each pixel leaves [`pixel_latency`] cycles after its walk cycle.

use crate::ctx::{Ctx, Q};
use crate::cull_sort::{z_max, Clip, Sorted};
use crate::divider::{divider, recip_operands};
use crate::input::Vtx;
use crate::span::{color_of, depth_of, Pixel};

/// Stages of setup's own divider, for 1/area, when the pixels' has `divider_latency`: at
/// most 13 (93 MHz alone on ECP5, README "Units": faster than the unit's critical path), so
/// that setup is short; the pixels' divider keeps its stages (a new division every cycle).
pub const fn area_divider_latency(divider_latency: u32) -> u32 {
    if divider_latency < 13 {
        divider_latency
    } else {
        13
    }
}

/// Cycles from taking a triangle to the cycle after the earliest handover to the walk, with
/// a pixels' divider of `divider_latency` stages: the input registers, the area's products,
/// its sign (v1 and v2 swapped for a negative area), its leading one, 1/area's divisor
/// normalised into a register in cycle 6, taken by setup's divider
/// ([`area_divider_latency`] stages) in cycle 7 and back that many cycles later; the edge
/// functions at the box's first pixel are ready by cycle 11, so a divider of fewer than 4
/// stages waits for them.
pub const fn setup(divider_latency: u32) -> u32 {
    let la = area_divider_latency(divider_latency);
    8 + if la > 4 { la } else { 4 }
}

/// Cycles from a pixel's walk cycle to the cycle it leaves: coverage and a, b (eq. 3: two
/// products and a shift, 3 cycles), depth (eq. 4: two products, the sum, the rounding) and
/// beside it eq. 5's three products, their sum and leading one (5 cycles), 1/sum's divisor
/// normalised into a register and through the divider, eq. 6's two products and shift
/// (3 cycles), the colours (eq. 4: two products a channel, the sum, the rounding; 3 cycles)
/// and the output register.
pub const fn pixel_latency(divider_latency: u32) -> u32 {
    16 + divider_latency
}

/// Cycles after a pixel's walk cycle in which its triangle's constants are still read (the
/// colours' c0 at t+14+L): a triangle's constants are one of two sets, and the walk two
/// triangles on may load that set only after its last pixel got this far.
pub const fn constants_read(divider_latency: u32) -> u32 {
    pixel_latency(divider_latency) - 2
}

/// Edge function of a -> b at p (exact, subpixel units squared).
fn edge(a: &Vtx, b: &Vtx, px: i128, py: i128) -> i128 {
    (b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x)
}

/// Whether a sample exactly on edge a -> b belongs to the triangle (clockwise on
/// screen, y down): top edges run in +x, left edges in -y.
fn owns_ties(a: &Vtx, b: &Vtx) -> bool {
    let (dx, dy) = (b.x - a.x, b.y - a.y);
    dy < 0 || (dy == 0 && dx > 0)
}

/// `num / den` for two raw values of one format, to `bary` (via `1/den` from the divider).
fn ratio(num: i128, den: i128, ctx: &mut Ctx) -> i128 {
    let (op, exp) = recip_operands(den, &ctx.f);
    let mant = divider(op, &ctx.f).q;
    let shift = ctx.f.bary.frac as i64 - (ctx.f.ooa.frac + exp) as i64;
    if shift >= 0 {
        ctx.put(Q::Bary, (num * mant) << shift)
    } else {
        ctx.put_scaled(Q::Bary, num * mant, (ctx.f.bary.frac as i64 - shift) as u32)
    }
}

/// What one triangle produced, and its walk.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct VectorOut {
    pub pixels: Vec<Pixel>,
    /// Each pixel's index in the walk of the clipped bounding box (row by row from its
    /// top left): `walk[i]` for `pixels[i]`.
    pub walk: Vec<u32>,
    /// Cycles of the walk of its box: rows x ceil(columns / lanes); 0 for an empty box.
    pub walk_cycles: u32,
    pub z_clipped: u32,
}

/// Rasterizes one triangle (from `cull_sort`) with `lanes` pixels per cycle.
pub fn vector(t: &Sorted, clip: Clip, lanes: u32, perspective: bool, ctx: &mut Ctx) -> VectorOut {
    let f = ctx.f;
    let s = f.xy.frac;
    let px = 1i128 << s;
    let mut v = t.v;
    let mut area = edge(&v[0], &v[1], v[2].x, v[2].y);
    if area < 0 {
        v.swap(1, 2);
        area = -area;
    }
    let edges = [(v[1], v[2]), (v[2], v[0]), (v[0], v[1])];
    let owns = edges.map(|(a, b)| owns_ties(&a, &b));
    let one = 1i128 << f.bary.frac;
    let zmax = z_max(&f);

    // Bounding box of pixel centres, clipped to the screen.
    let lo = |c: i128| ((c - px / 2 + px - 1) >> s).max(0);
    let x0 = lo(v.iter().map(|p| p.x).min().unwrap());
    let y0 = lo(v.iter().map(|p| p.y).min().unwrap());
    let x1 = ((v.iter().map(|p| p.x).max().unwrap() - px / 2) >> s).min(clip.width as i128 - 1);
    let y1 = ((v.iter().map(|p| p.y).max().unwrap() - px / 2) >> s).min(clip.height as i128 - 1);
    let mut out = VectorOut { pixels: Vec::new(), walk: Vec::new(), walk_cycles: 0, z_clipped: 0 };
    if x0 > x1 || y0 > y1 {
        return out;
    }
    out.walk_cycles = ((y1 - y0 + 1) as u32) * ((x1 - x0 + 1) as u32).div_ceil(lanes);

    let d_attr = |k: usize| (v[k].z - v[0].z, [0, 1, 2].map(|i| v[k].c[i] - v[0].c[i]));
    let (d1, d2) = (d_attr(1), d_attr(2));
    for yy in y0..=y1 {
        let cy = yy * px + px / 2;
        for xx in x0..=x1 {
            let cx = xx * px + px / 2;
            let w = edges.map(|(a, b)| edge(&a, &b, cx, cy));
            if !(0..3).all(|k| w[k] > 0 || (w[k] == 0 && owns[k])) {
                continue;
            }
            // Eq. (3): a, b from the exact numerators and 1/area.
            let a = ratio(w[1], area, ctx);
            let b = ratio(w[2], area, ctx);
            let z = ctx.put(
                Q::ZAcc,
                f.z_acc.rescale(v[0].z, f.z.frac) + f.z_acc.rescale(d1.0 * a + d2.0 * b, f.z.frac + f.bary.frac),
            );
            // Eq. (5)-(6): perspective-corrected weights for colour.
            let (ca, cb) = if perspective {
                let l = [one - a - b, a, b];
                let q: [i128; 3] =
                    std::array::from_fn(|k| ctx.put_scaled(Q::Bary, l[k] * v[k].iw, f.bary.frac + f.inv_w.frac));
                // Every term floors to 0 only where the pixel lies on the nearest vertex's
                // opposite edge and the other two are more than 2^inv_w.frac times as far
                // (their w_min / w rounds to 0): no weight to divide, so divide by 1.
                let sum = (q[0] + q[1] + q[2]).max(1);
                (ratio(q[1], sum, ctx), ratio(q[2], sum, ctx))
            } else {
                (a, b)
            };
            let c: [i128; 3] = std::array::from_fn(|i| {
                let plane = d1.1[i] * ca + d2.1[i] * cb;
                ctx.put(
                    Q::CAcc,
                    f.c_acc.rescale(v[0].c[i], f.color.frac) + f.c_acc.rescale(plane, f.color.frac + f.bary.frac),
                )
            });
            let depth = depth_of(z, &f);
            if (0..=zmax).contains(&depth) {
                out.pixels.push(Pixel { x: xx as u32, y: yy as u32, z: depth as u32, rgb: c.map(|c| color_of(c, &f)) });
                out.walk.push(((yy - y0) * (x1 - x0 + 1) + xx - x0) as u32);
            } else {
                out.z_clipped += 1;
            }
        }
    }
    out
}
