//! `triangle_setup`: fixed-point triangle setup of paper 001 (Woo 2004,
//! §II.2.나-라, eq. 2), with the names of Mesa's setup code (`sp_setup.c`):
//! vertices sorted by y into vMin, vMid, vMax; `e_maj` runs vMin -> vMax,
//! `e_bot` vMin -> vMid, `e_top` vMid -> vMax. (Mesa's y points up, ours down,
//! so on screen `e_bot` is the *upper* short edge; the names are kept.)
//!
//! It produces, for the edge walker:
//! * **OneOverArea** through the shared `divider`, and the attribute gradients
//!   by the reordered products of 001 eq. (2):
//!   `dC/dy = (OOA * e_maj.dx) * e_bot.dC - (OOA * e_bot.dx) * e_maj.dC`,
//!   `dC/dx = (OOA * e_bot.dy) * e_maj.dC - (OOA * e_maj.dy) * e_bot.dC`,
//!   where the four `OOA * e.d` products are shared by z, R, G and B.
//! * per edge, the state of an **exact edge walker**: at each scanline centre
//!   the first pixel whose centre is at or right of the edge, `x`, and the
//!   remainder `r = x*D - num` in [0, D) of the exact rational, with the step
//!   `dx/dy = q + rho/D`. Walking either way reproduces the exact positions, so
//!   two triangles sharing an edge agree on every scanline whatever their walk
//!   direction: meshes stay watertight in fixed point. Two divisions per edge
//!   (start and step) plus OneOverArea: the seven divisions of 001.
//! * the **walk direction** for 003's Y clipping (see `edge_walk`), the
//!   attribute values where each edge's walk starts, and their per-scanline
//!   increments for steps of q and q + 1 pixels.
//!
//! Fill rule: scanline j (centre `y = j + 1/2`) belongs to the triangle when
//! `y_min <= centre < y_max`; on it, pixels from the left edge's `x` to the right
//! edge's `x - 1`. A centre on a left or top edge is inside, on a right or bottom
//! edge outside: the top-left rule, exactly.
//!
//! Mirrors `rtl::triangle_setup` (`hdl-out/triangle_setup.v`), which runs [`schedule`].

pub mod schedule;

use crate::ctx::{Ctx, Q};
use crate::cull_sort::Sorted;
use crate::divider::{divider, recip_operands, DividerIn, Recip};
use crate::input::Vtx;

/// z and R, G, B, as raw values in the formats the context names.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Attrs {
    pub z: i128,
    pub c: [i128; 3],
}

impl Attrs {
    /// `self + k * o`, stored as the accumulators (`z_acc`, `c_acc`) wrap.
    pub fn step(self, o: &Attrs, k: i128, ctx: &mut Ctx) -> Attrs {
        Attrs {
            z: ctx.put(Q::ZAcc, self.z + k * o.z),
            c: std::array::from_fn(|i| ctx.put(Q::CAcc, self.c[i] + k * o.c[i])),
        }
    }
}

/// Which way `edge_walk` goes (paper 003, §II.1.다.(2)).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Walk {
    /// From vMin down (increasing y), stopping at the bottom row or vMax.
    Down,
    /// From vMax up, stopping at row 0: the triangle crosses the top boundary only.
    Up,
}

/// One edge prepared for the exact walker, at the scanline its walk starts on.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Edge {
    /// First scanline walked on this edge, and how many.
    pub j: i32,
    pub count: u32,
    /// First pixel with its centre at or right of the edge on scanline `j`.
    pub x: i128,
    /// `x*D - num` in [0, D): how far the edge lies left of that centre.
    pub r: i128,
    /// Step per scanline down: `q + rho/D` pixels (rho in [0, D)).
    pub q: i128,
    pub rho: i128,
    /// `D = 2^s * dy`.
    pub d: i128,
    /// Attributes at the pixel this side tracks on scanline `j`: `x` on the
    /// left side, `x - 1` (the last pixel inside) on the right.
    pub at: Attrs,
    /// Change of `at` per scanline down when x moves q (inc0) or q+1 (inc1) pixels.
    pub inc0: Attrs,
    pub inc1: Attrs,
}

/// What setup hands the edge walker.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TriangleSetupOut {
    pub walk: Walk,
    /// Whether e_maj is the left side.
    pub maj_left: bool,
    pub maj: Edge,
    /// Short edges in walk order: e_bot, e_top walking down; e_top, e_bot walking up.
    pub short: [Edge; 2],
    /// d/dx of z (`dz`) and R, G, B (`dc`): the span's per-pixel steps.
    pub ddx: Attrs,
    /// The seven divisions issued to the divider, in issue order.
    pub divisions: [DividerIn; 7],
    /// OneOverArea, the reciprocal of |twice the area| from the divider
    /// (`divider::reciprocal`): the texture path's (`texture_path::Draw::tex`) for its own
    /// setup, so that one divider serves both.
    pub recip: Recip,
}

/// `ceil((v - half)/px)` for a subpixel coordinate: the first scanline (or
/// pixel) whose centre is at or below (right of) `v`.
fn first_centre_at_or_after(v: i128, s: u32) -> i128 {
    (v + (1 << (s - 1)) - 1) >> s
}

/// The product `OOA * delta` in the `ooa_d` format (one of the four first
/// products of eq. 2): `delta * 2^s / area2` per pixel, i.e.
/// `sign * delta * mant * 2^(ooa_d.frac + s - ooa.frac - exp)`.
fn ooa_times(delta: i128, sign: i128, r: Recip, ctx: &mut Ctx) -> i128 {
    let (f, s) = (ctx.f, ctx.f.xy.frac);
    let prod = sign * delta * r.mant;
    let shift = (f.ooa_d.frac + s) as i64 - (f.ooa.frac + r.exp) as i64;
    if shift >= 0 {
        ctx.put(Q::OoaD, prod << shift)
    } else {
        ctx.put_scaled(Q::OoaD, prod, (f.ooa_d.frac as i64 - shift) as u32)
    }
}

/// Runs setup on a sorted triangle. `height` is the screen height, which the
/// walk direction depends on.
pub fn triangle_setup(t: &Sorted, ctx: &mut Ctx) -> TriangleSetupOut {
    let f = ctx.f;
    let s = f.xy.frac;
    let px = 1i128 << s;
    let [v0, v1, v2] = t.v;
    let delta = |a: &Vtx, b: &Vtx| (b.x - a.x, b.y - a.y);
    let (maj, bot) = (delta(&v0, &v2), delta(&v0, &v1));

    // Twice the area (Mesa: eMaj.dx * eBot.dy - eBot.dx * eMaj.dy), exact.
    let area2 = maj.0 * bot.1 - bot.0 * maj.1;
    debug_assert!(area2 != 0, "cull_sort rejects zero-area triangles");
    let (recip_in, exp) = recip_operands(area2.abs(), &f);
    let ooa = Recip { mant: divider(recip_in, &f).q, exp };
    let sign = area2.signum();
    // The four products of eq. (2) that every attribute shares.
    let p_maj_dx = ooa_times(maj.0, sign, ooa, ctx);
    let p_bot_dx = ooa_times(bot.0, sign, ooa, ctx);
    let p_maj_dy = ooa_times(maj.1, sign, ooa, ctx);
    let p_bot_dy = ooa_times(bot.1, sign, ooa, ctx);

    // Gradients. An attribute difference carries its own fraction bits (z: z.frac,
    // colour: color.frac), so a product has ooa_d.frac + those.
    let grad = |d_maj: i128, d_bot: i128, from: u32, q: Q, ctx: &mut Ctx| {
        let dx = p_bot_dy * d_maj - p_maj_dy * d_bot;
        let dy = p_maj_dx * d_bot - p_bot_dx * d_maj;
        (ctx.put_scaled(q, dx, f.ooa_d.frac + from), ctx.put_scaled(q, dy, f.ooa_d.frac + from))
    };
    let (dzdx, dzdy) = grad(v2.z - v0.z, v1.z - v0.z, f.z.frac, Q::Dz, ctx);
    let mut ddx = Attrs { z: dzdx, c: [0; 3] };
    let mut ddy = Attrs { z: dzdy, c: [0; 3] };
    for i in 0..3 {
        (ddx.c[i], ddy.c[i]) = grad(v2.c[i] - v0.c[i], v1.c[i] - v0.c[i], f.color.frac, Q::Dc, ctx);
    }

    // Scanlines: [j_first, j_mid) on e_bot, [j_mid, j_end) on e_top.
    let j_first = first_centre_at_or_after(v0.y, s) as i32;
    let j_mid = first_centre_at_or_after(v1.y, s) as i32;
    let j_end = first_centre_at_or_after(v2.y, s) as i32;
    use crate::cull_sort::outcode::{BOTTOM, TOP};
    let walk = if t.crosses & TOP != 0 && t.crosses & BOTTOM == 0 { Walk::Up } else { Walk::Down };
    // 003: walking up starts at the last scanline and each edge at its lower end.
    let maj_left = area2 < 0;
    let span = |a: i32, b: i32| (b - a).max(0) as u32;
    let edges: [(Vtx, Vtx, i32, u32, bool); 3] = match walk {
        Walk::Down => [
            (v0, v2, j_first, span(j_first, j_end), maj_left),
            (v0, v1, j_first, span(j_first, j_mid), !maj_left),
            (v1, v2, j_mid, span(j_mid, j_end), !maj_left),
        ],
        Walk::Up => [
            (v0, v2, j_end - 1, span(j_first, j_end), maj_left),
            (v1, v2, j_end - 1, span(j_mid, j_end), !maj_left),
            (v0, v1, j_mid - 1, span(j_first, j_mid), !maj_left),
        ],
    };

    let mut divisions = [recip_in; 7];
    let mut out = [Edge::default(); 3];
    for (k, &(a, b, j, count, left)) in edges.iter().enumerate() {
        let (dx, dy) = (b.x - a.x, b.y - a.y);
        // Unused divisions are issued as 0/1 (see `divider`).
        let step_in = if count >= 2 { DividerIn { n: dx, d: dy } } else { DividerIn { n: 0, d: 1 } };
        // Start from the end the walk begins at: a walking down, b walking up,
        // so that |t| < 2^s and the quotient stays small.
        let base = if walk == Walk::Down { a } else { b };
        let centre_y = (j as i128) * px + px / 2;
        let t_off = centre_y - base.y;
        let xb = base.x - px / 2;
        let (xi, xf) = (xb >> s, xb & (px - 1));
        let start_in =
            if count >= 1 { DividerIn { n: xf * dy + dx * t_off, d: px * dy } } else { DividerIn { n: 0, d: 1 } };
        divisions[1 + 2 * k] = start_in;
        divisions[2 + 2 * k] = step_in;
        let st = divider(start_in, &f);
        let sp = divider(step_in, &f);
        let d = px * dy;
        let x = xi + st.q + (st.r > 0) as i128;
        let r = if st.r > 0 { d - st.r } else { 0 };
        // Attribute value at the tracked pixel, from the plane through vMin.
        let tracked = x - (!left) as i128;
        let off_x = tracked * px + px / 2 - v0.x;
        let off_y = centre_y - v0.y;
        let at = Attrs {
            z: ctx.put(
                Q::ZAcc,
                ctx.f.z_acc.rescale(v0.z, f.z.frac) + ctx.f.z_acc.rescale(ddx.z * off_x + ddy.z * off_y, f.dz.frac + s),
            ),
            c: std::array::from_fn(|i| {
                let base = ctx.f.c_acc.rescale(v0.c[i], f.color.frac);
                let plane = ctx.f.c_acc.rescale(ddx.c[i] * off_x + ddy.c[i] * off_y, f.dc.frac + s);
                ctx.put(Q::CAcc, base + plane)
            }),
        };
        let inc0 = Attrs {
            z: ctx.put(Q::Dz, ddy.z + sp.q * ddx.z),
            c: std::array::from_fn(|i| ctx.put(Q::Dc, ddy.c[i] + sp.q * ddx.c[i])),
        };
        let inc1 = Attrs {
            z: ctx.put(Q::Dz, inc0.z + ddx.z),
            c: std::array::from_fn(|i| ctx.put(Q::Dc, inc0.c[i] + ddx.c[i])),
        };
        out[k] = Edge { j, count, x, r, q: sp.q, rho: px * sp.r, d, at, inc0, inc1 };
    }
    TriangleSetupOut { walk, maj_left, maj: out[0], short: [out[1], out[2]], ddx, divisions, recip: ooa }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cull_sort::{cull_sort, Clip, Cull};
    use crate::input::to_fixed;
    use fx::Formats;
    use scene::Vertex;

    /// The triangle `t` (screen pixels), sorted for setup on a `w` x `h` screen at `f`.
    fn sorted(t: &[Vertex; 3], w: u32, h: u32, f: &Formats) -> Sorted {
        let clip = Clip { width: w, height: h };
        cull_sort(&to_fixed(t, f).unwrap(), clip, Cull::None, f).unwrap()
    }

    #[test]
    fn triangle_setup_paper_001_eq2_fits_where_eq1_overflows() {
        // 001's worst case: an 800-pixel base (e_maj.dx = 800) and a colour
        // difference of 255 (e_bot.dC), at 800x600.
        let f = Formats::for_resolution(800, 600);
        let t = [
            Vertex::new(0.0, 0.0, 0.5, [0.0; 3]),
            Vertex::new(0.0, 599.0, 0.5, [255.0; 3]),
            Vertex::new(800.0, 600.0, 0.5, [0.0; 3]),
        ];
        let sorted = sorted(&t, 800, 600, &f);
        // Eq. (1) forms e_maj.dx * e_bot.dC first: 800 * 255 = 204000 needs 18 integer
        // bits, more than a gradient register (dc) has.
        let s = f.xy.frac;
        let eq1 = (sorted.v[2].x - sorted.v[0].x) * (sorted.v[1].c[0] - sorted.v[0].c[0]);
        assert_eq!(f.xy.to_f64(eq1), 204000.0);
        assert!(!f.dc.fits(f.dc.rescale(eq1, s + f.color.frac)), "eq. (1)'s product fits {}", f.dc);
        assert!(fx::signed_bits(204000) - 1 > f.dc.int);
        // Eq. (2) forms OneOverArea * e_maj.dx first (~1/600): no register of setup wraps.
        let mut ctx = Ctx::new(f);
        let o = triangle_setup(&sorted, &mut ctx);
        assert_eq!(ctx.overflowed(), vec![], "a register of setup wrapped");
        // dC/dy = 255/599 per pixel along x = 0, within an LSB of its format.
        let dcdy = (255.0 / 599.0) * (1.0 - 0.0) - 0.0;
        let got = f.dc.to_f64(o.short[0].inc0.c[0] - o.short[0].q * o.ddx.c[0]);
        assert!((got - dcdy).abs() < 1e-5, "dC/dy {got} vs {dcdy}");
    }

    #[test]
    fn triangle_setup_issues_seven_divisions_and_unused_ones_as_0_over_1() {
        let f = Formats::for_resolution(64, 64);
        // A flat-topped triangle: e_bot is horizontal and crosses no scanline.
        let t = [
            Vertex::new(2.0, 2.0, 0.5, [0.0; 3]),
            Vertex::new(40.0, 2.0, 0.5, [0.0; 3]),
            Vertex::new(20.0, 50.0, 0.5, [0.0; 3]),
        ];
        let o = triangle_setup(&sorted(&t, 64, 64, &f), &mut Ctx::new(f));
        assert_eq!(o.divisions.len(), 7);
        assert_eq!(o.short[0].count, 0);
        assert_eq!(o.divisions[3], DividerIn { n: 0, d: 1 });
        assert_eq!(o.divisions[4], DividerIn { n: 0, d: 1 });
        assert!(o.divisions.iter().all(|d| d.d > 0));
    }
}
