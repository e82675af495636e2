//! `texture_setup`: the planes of s·q, t·q and q over a triangle, in fixed point: what
//! triangle setup hands the texture unit (paper 001 §II-5: the texture coordinates are
//! interpolated as attributes and divided per pixel by eq. (3); q = w_min / w is 1/w scaled
//! so that the triangle's nearest vertex has 1).
//!
//! **Per triangle.** The vertices' s·q and t·q (format `st`) and q (format `q`) at their
//! `xy` positions ([`tex_vertices`]: the host's geometry stage forms them, as it forms x/w
//! and y/w). Twice the area exactly, its reciprocal through the shared divider (setup's
//! OneOverArea: the same operands, the same value), and by Cramer's rule each attribute's
//! gradients d/dx and d/dy, rounded once to P = F + `xy.int` + 2 fraction bits (F the
//! attribute's own). Two copies of each gradient: one wrapping in S(int + s + 1).P, the
//! plane's; one rounded and saturated to `dst` (s·q, t·q) or `dq` (q), the texture unit's
//! [`TexGrad`] for the level of detail (a sliver's gradient too steep for `dst` takes the
//! largest level, as it should).
//!
//! **Per pixel** ([`TexturePlanes::at`]). a = a0 + a_x·X + a_y·Y exactly, X and Y the pixel
//! centre's offsets from vertex 0 in sub-pixels, rounded half up once to F bits. An
//! interpolator that steps the same exact integers along edges and spans (edge walk and
//! span, or the barycentric walk of 004) gives the same value whatever its walk order, so
//! the planes are evaluated here as the hardware's incremental form would, with no error
//! accumulating along a long span. Offsets reach 2^(xy.int + 1) pixels across the guard
//! band, so the gradients' rounding moves a value by at most 2^-(F + 1): the value is
//! within 1 LSB of the exact plane through the quantized vertices.
//!
//! **Modular arithmetic.** Inside the triangle every attribute lies between its vertices'
//! values, so the sum is only needed modulo twice the format's range: the plane's
//! gradients wrap at int + s + 1 integer bits, and the rounded sum, read with one integer
//! bit more than the format, is clamped to the format's range (a value a rounding puts an
//! LSB below 0 stays 0 instead of wrapping to the top). Exact modulo that, whatever the
//! triangle's slope: a sliver gets the right coordinates.
//!
//! All three back ends (scanline, vector, SE) texture their pixels from these planes: the
//! pixel's (x, y) is all a back end hands the texture path.

use crate::divider::reciprocal;
use crate::input::{InputError, Vtx};
use crate::texture_unit::{TexGrad, TexIn};
use fx::{Fmt, Formats, TexFormats};
use scene::Triangle;

/// A vertex as the texture path takes it: its position (the hardware's `xy`, as the
/// rasterizer has it) and s·q, t·q and q, raw in `st`, `st` and `q`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TexVtx {
    pub x: i128,
    pub y: i128,
    pub a: [i128; 3],
}

/// The texture path's vertices of `tri` (whose hardware vertices are `v`: `input::to_fixed`),
/// or `None` when it is not textured. `affine`: q = 1 at every vertex (screen-linear
/// coordinates, the rubber sheet of 004 Fig. 5). An s·q or t·q beyond `st` is an error
/// naming the vertex.
pub fn tex_vertices(
    tri: &Triangle,
    v: &[Vtx; 3],
    tf: &TexFormats,
    affine: bool,
) -> Result<Option<[TexVtx; 3]>, InputError> {
    let Some(tex) = tri.map(|v| v.tex).into_iter().collect::<Option<Vec<_>>>() else { return Ok(None) };
    let w = tri.map(|v| if affine { 1.0 } else { v.w_or_one() });
    let w_min = w.iter().copied().fold(f64::INFINITY, f64::min);
    let mut out = [TexVtx::default(); 3];
    for k in 0..3 {
        let q = w_min / w[k];
        let get = |quantity: &'static str, fm: Fmt, value: f64| {
            fm.from_f64(value).ok_or(InputError { vertex: k, quantity, value, fmt: Some(fm) })
        };
        let st = tf.st.half_up();
        out[k] = TexVtx {
            x: v[k].x,
            y: v[k].y,
            a: [get("s·q", st, tex[k].s * q)?, get("t·q", st, tex[k].t * q)?, get("q", tf.q.half_up(), q)?],
        };
    }
    Ok(Some(out))
}

/// A triangle's planes of s·q, t·q and q: what `texture_setup` hands the texture path.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TexturePlanes {
    /// Vertex 0: the planes' origin (raw `xy`) and its values.
    origin: [i128; 2],
    a0: [i128; 3],
    /// Per attribute, `[d/dx, d/dy]` per pixel at [`plane_frac`] bits, wrapped.
    grad: [[i128; 2]; 3],
    /// The texture unit's gradients (`dst`, `dq`), saturated.
    lod: TexGrad,
    /// The attributes' formats (`st`, `st`, `q`), the screen's `xy` fraction bits.
    fmts: [Fmt; 3],
    s: u32,
    xy_int: u32,
}

/// The fraction bits of an attribute's plane gradients: F + `xy.int` + 2, so that the
/// rounding of both, times offsets of up to 2^(xy.int + 1) pixels, stays below 2^-(F + 1).
pub const fn plane_frac(f: &Formats, frac: u32) -> u32 {
    frac + f.xy.int + 2
}

/// The plane gradients' format for an attribute in `fm`: S(int + s + 1).P, the fewest
/// integer bits for which a wrap moves the per-pixel sum by a multiple of twice its range.
pub const fn plane_fmt(f: &Formats, fm: Fmt) -> Fmt {
    Fmt::s(fm.int + f.xy.frac + 1, plane_frac(f, fm.frac))
}

/// Twice the signed area of the triangle of `v`, in squared sub-pixels: its reciprocal
/// `divider::reciprocal(|area2|)` is triangle setup's OneOverArea, which `rtl::texture_setup`
/// takes as an input.
pub fn area2(v: &[TexVtx; 3]) -> i128 {
    (v[1].x - v[0].x) * (v[2].y - v[0].y) - (v[2].x - v[0].x) * (v[1].y - v[0].y)
}

/// The planes of a textured triangle's vertices `v` at screen formats `f` and texture
/// formats `tf`; `None` for a triangle of zero area (which draws nothing).
pub fn texture_setup(v: &[TexVtx; 3], f: &Formats, tf: &TexFormats) -> Option<TexturePlanes> {
    let s = f.xy.frac;
    let (e1, e2) = ([v[1].x - v[0].x, v[1].y - v[0].y], [v[2].x - v[0].x, v[2].y - v[0].y]);
    let area2 = area2(v);
    if area2 == 0 {
        return None;
    }
    // 1/|area2| = mant * 2^-(ooa.frac + exp).
    let r = reciprocal(area2.abs(), f);
    let fmts = [tf.st, tf.st, tf.q];
    let lod_fmts = [tf.dst, tf.dst, tf.dq];
    let mut grad = [[0; 2]; 3];
    let mut lod = [[0i64; 2]; 3];
    for k in 0..3 {
        let (d1, d2) = (v[1].a[k] - v[0].a[k], v[2].a[k] - v[0].a[k]);
        // Cramer: per sub-pixel, num / area2, at the attribute's F fraction bits.
        let num = [d1 * e2[1] - d2 * e1[1], d2 * e1[0] - d1 * e2[0]];
        let p = plane_frac(f, fmts[k].frac);
        // Per pixel at P bits: num * sign * mant * 2^(s + P - F - ooa.frac - exp).
        let shift = (s + p) as i64 - (fmts[k].frac + f.ooa.frac + r.exp) as i64;
        for (d, n) in num.into_iter().enumerate() {
            let prod = area2.signum() * n * r.mant;
            let exact = if shift >= 0 { prod << shift } else { Fmt::s(0, 0).half_up().rescale(prod, (-shift) as u32) };
            grad[k][d] = plane_fmt(f, fmts[k]).store(exact);
            let to_lod = lod_fmts[k].half_up().saturating();
            lod[k][d] = to_lod.store(to_lod.rescale(exact, p)) as i64;
        }
    }
    Some(TexturePlanes {
        origin: [v[0].x, v[0].y],
        a0: v[0].a,
        grad,
        lod: TexGrad { dsq: lod[0], dtq: lod[1], dq: lod[2] },
        fmts,
        s,
        xy_int: f.xy.int,
    })
}

impl TexturePlanes {
    /// The texture unit's gradients of s·q, t·q and q (the level of detail's inputs).
    pub fn grad(&self) -> TexGrad {
        self.lod
    }

    /// s·q, t·q and q at the centre of pixel (x, y).
    pub fn at(&self, x: u32, y: u32) -> TexIn {
        let px = 1i128 << self.s;
        let off = [i128::from(x) * px + px / 2 - self.origin[0], i128::from(y) * px + px / 2 - self.origin[1]];
        let value = |k: usize| {
            let fm = self.fmts[k];
            let p = fm.frac + self.xy_int + 2;
            // At P + s fraction bits: a0, and the gradients (per pixel) times sub-pixel offsets.
            let sum = (self.a0[k] << (p + self.s - fm.frac)) + self.grad[k][0] * off[0] + self.grad[k][1] * off[1];
            let rounded = Fmt::s(0, fm.frac).half_up().rescale(sum, p + self.s);
            // Read with one integer bit more than the format, then clamped to its range.
            let wide = Fmt { signed: true, int: fm.int + 1, frac: fm.frac, ..Fmt::s(0, 0) }.store(rounded);
            wide.clamp(fm.min_raw(), fm.max_raw()) as i64
        };
        TexIn { sq: value(0), tq: value(1), q: value(2) }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::to_fixed;
    use crate::texture_unit::input::TexPlanes;
    use rand::{Rng, SeedableRng};
    use scene::{Tex, Vertex};

    /// A random perspective triangle on a `size`-pixel screen, s and t over a few repeats.
    fn triangle(rng: &mut rand::rngs::StdRng, size: f64) -> Triangle {
        std::array::from_fn(|_| Vertex {
            w: Some(rng.gen_range(1.0..20.0)),
            tex: Some(Tex { s: rng.gen_range(-8.0..8.0), t: rng.gen_range(-8.0..8.0), texture: 0 }),
            ..Vertex::new(rng.gen_range(-0.1 * size..1.1 * size), rng.gen_range(-0.1 * size..1.1 * size), 0.5, [0.0; 3])
        })
    }

    #[test]
    fn texture_setup_planes_are_within_an_lsb_of_the_exact_planes_through_their_vertices() {
        let tf = TexFormats::DEFAULT;
        let mut rng = rand::rngs::StdRng::seed_from_u64(7);
        for size in [64u32, 320, 1024] {
            let f = Formats::for_resolution(size, size);
            for _ in 0..300 {
                let tri = triangle(&mut rng, f64::from(size));
                let v = to_fixed(&tri, &f).unwrap();
                let tv = tex_vertices(&tri, &v, &tf, false).unwrap().unwrap();
                let Some(planes) = texture_setup(&tv, &f, &tf) else { continue };
                // The exact planes through the quantized vertices.
                let xy = tv.map(|v| [f.xy.to_f64(v.x), f.xy.to_f64(v.y)]);
                let q = tv.map(|v| tf.q.to_f64(v.a[2]));
                let st = tv.map(|v| [tf.st.to_f64(v.a[0]), tf.st.to_f64(v.a[1])]);
                let exact = TexPlanes::new(xy, std::array::from_fn(|k| [st[k][0] / q[k], st[k][1] / q[k]]), q).unwrap();
                // The reciprocal of the area has ooa.frac bits: the gradients are exact to a
                // relative 2^-(ooa.frac - 1), which is a sample position off by as much.
                let rel = (1.0 - f.ooa.frac as f64).exp2();
                let (want_g, got_g) = (exact.grad(&tf), planes.grad());
                let pairs = [(want_g.dsq, got_g.dsq), (want_g.dtq, got_g.dtq), (want_g.dq, got_g.dq)];
                for (w, g) in pairs.iter().flat_map(|(w, g)| w.iter().zip(g)) {
                    assert!((w - g).abs() as f64 <= 1.0 + rel * w.abs() as f64, "gradient {w} against {g}");
                }
                for _ in 0..20 {
                    let (x, y) = (rng.gen_range(0..size), rng.gen_range(0..size));
                    let (want, got) = (exact.at(&tf, f64::from(x) + 0.5, f64::from(y) + 0.5), planes.at(x, y));
                    // Beyond the triangle, where an attribute leaves its range, the planes
                    // are only right modulo it.
                    let inside = |v: i64, fm: Fmt| v > fm.min_raw() as i64 && v < fm.max_raw() as i64;
                    if !(inside(want.sq, tf.st) && inside(want.tq, tf.st) && inside(want.q, tf.q)) {
                        continue;
                    }
                    // 1 LSB, plus the gradients' error over the offset from vertex 0.
                    let dist = (f64::from(x) - xy[0][0]).abs() + (f64::from(y) - xy[0][1]).abs() + 1.0;
                    let near = |a: i64, b: i64, g: [i64; 2], gfrac: u32, frac: u32| {
                        let slope = (g[0].abs().max(g[1].abs()) as f64) * (frac as f64 - gfrac as f64).exp2();
                        ((a - b).abs() as f64) <= 1.0 + rel * slope * dist
                    };
                    let (d, dq) = (tf.dst.frac, tf.dq.frac);
                    assert!(
                        near(want.sq, got.sq, got_g.dsq, d, tf.st.frac)
                            && near(want.tq, got.tq, got_g.dtq, d, tf.st.frac)
                            && near(want.q, got.q, got_g.dq, dq, tf.q.frac),
                        "{size}: ({x}, {y}): {want:?} {got:?}"
                    );
                }
            }
        }
    }
}
