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
//! Cycle model (`rtl::vector`'s; a frame's: `cycles::vector_frame`): the unit sets a
//! triangle up in [`setup`] cycles while it walks the ones before, and hands it to the walk's
//! scout when the scout is done with the one before and the triangle's set of constants is
//! read no more ([`constants_read`]); the scout finds each row's chunks ahead of the walker,
//! which walks a chunk of `lanes` pixels a cycle ([`vector`], [`WalkRow`]); each pixel leaves
//! [`pixel_latency`] cycles after its chunk's walk cycle (`cycles::VectorUnit`).

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
/// functions at the first row's start chunk are ready by cycle 11, so a divider of fewer than 4
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

/// One row of a triangle's walk: the scout's cycles on it and the chunks the walker
/// walks in it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct WalkRow {
    /// Cycles the scout spends on the row: one, and one more per chunk its probes move.
    pub search: u32,
    /// Chunks of `lanes` pixels walked, a cycle each: 0 for a row found empty.
    pub chunks: u32,
}

/// What one triangle produced, and its walk.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct VectorOut {
    pub pixels: Vec<Pixel>,
    /// Each pixel's place in the walk: its row (index in `rows`) and its chunk's offset from
    /// the row's first chunk, for `pixels[i]`.
    pub at: Vec<(u32, u32)>,
    /// The rows of the box, top to bottom; none for an empty box.
    pub rows: Vec<WalkRow>,
    pub z_clipped: u32,
}

/// Whether the walk takes `lanes` lanes: a power of two, at most 64 (chunks are aligned to
/// multiples of `lanes`; `rtl::vector` is built with 1, 2, 4 or 8).
pub fn lanes_supported(lanes: u32) -> bool {
    lanes.is_power_of_two() && lanes <= 64
}

/// Rasterizes one triangle (from `cull_sort`) with `lanes` pixels per cycle ([`lanes_supported`]).
///
/// **The walk** (`rtl::vector`'s scout and walker). The box's rows are walked top to bottom
/// in chunks of `lanes` pixels aligned to multiples of `lanes` (pixel x goes to lane
/// x mod `lanes`), only from the row's first chunk that may hold a pixel inside to its last:
/// * an edge whose function rises to the right (dy < 0) bounds the row on the left: a chunk
///   whose last pixel it rejects, and every chunk left of it, holds none; one that falls
///   (dy > 0) bounds it on the right, from the first pixel of a chunk it rejects; a
///   horizontal edge that rejects one pixel of the row rejects all of it;
/// * a scout finds each row's first and last chunk ahead of the walker with two probes that
///   start where they ended on the row before (on the first row, at the chunk of the
///   vertex with the least y, the first of equals, clamped to the box), each moving a chunk
///   a cycle towards its bound: a row costs it one cycle and one more per move of the probe
///   that moves more ([`WalkRow::search`]);
/// * the walker takes a row the scout found from the cycle in its last chunk of the row
///   before, and walks a chunk a cycle; the scout then searches the next row. A row found
///   empty is not walked.
pub fn vector(t: &Sorted, clip: Clip, lanes: u32, perspective: bool, ctx: &mut Ctx) -> VectorOut {
    assert!(lanes_supported(lanes), "vector: {lanes} lanes");
    let f = ctx.f;
    let s = f.xy.frac;
    let px = 1i128 << s;
    let top = *t.v.iter().min_by_key(|p| p.y).expect("three vertices");
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
    let mut out = VectorOut::default();
    if x0 > x1 || y0 > y1 {
        return out;
    }

    // The walk: chunks by their first x.
    let n = lanes as i128;
    let (c0, c1) = (x0 & !(n - 1), x1 & !(n - 1));
    let at = |k: usize, x: i128, y: i128| edge(&edges[k].0, &edges[k].1, x * px + px / 2, y * px + px / 2);
    let pass = |k: usize, e: i128| e > 0 || (e == 0 && owns[k]);
    let dy = edges.map(|(a, b)| b.y - a.y);
    let mut sl = (top.x >> s).clamp(x0, x1) & !(n - 1);
    let mut sr = sl;

    let d_attr = |k: usize| (v[k].z - v[0].z, [0, 1, 2].map(|i| v[k].c[i] - v[0].c[i]));
    let (d1, d2) = (d_attr(1), d_attr(2));
    for yy in y0..=y1 {
        let left_out = |c: i128| (0..3).any(|k| dy[k] < 0 && !pass(k, at(k, c + n - 1, yy)));
        let right_out = |c: i128| (0..3).any(|k| dy[k] > 0 && !pass(k, at(k, c, yy)));
        let dead = (0..3).any(|k| dy[k] == 0 && !pass(k, at(k, sl, yy)));
        let mut search = 1;
        // The probes move a chunk a cycle towards their bounds (none on a dead row).
        loop {
            let ml = if dead {
                0
            } else if left_out(sl) && sl < c1 {
                n
            } else if !left_out(sl - n) && sl > c0 {
                -n
            } else {
                0
            };
            let mr = if dead {
                0
            } else if right_out(sr) && sr > c0 {
                -n
            } else if !right_out(sr + n) && sr < c1 {
                n
            } else {
                0
            };
            if ml == 0 && mr == 0 {
                break;
            }
            (sl, sr, search) = (sl + ml, sr + mr, search + 1);
        }
        let empty = dead || left_out(sl) || right_out(sr) || sl > sr;
        let row = out.rows.len() as u32;
        out.rows.push(WalkRow { search, chunks: if empty { 0 } else { ((sr - sl) / n + 1) as u32 } });
        if empty {
            continue;
        }
        let cy = yy * px + px / 2;
        for xx in sl.max(x0)..=(sr + n - 1).min(x1) {
            let cx = xx * px + px / 2;
            let w = edges.map(|(a, b)| edge(&a, &b, cx, cy));
            if !(0..3).all(|k| pass(k, w[k])) {
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
                out.at.push((row, ((xx & !(n - 1)) - sl) as u32 / lanes));
            } else {
                out.z_clipped += 1;
            }
        }
    }
    out
}
