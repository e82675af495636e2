//! `cull_sort`: the cull & sort unit of paper 003 (Lee 2008, §II.1.다.(1), Fig. 4).
//!
//! Computes a Cohen-Sutherland outcode per vertex against the clip volume (the
//! screen [0, W] x [0, H] in pixels, z in [0, 1]); rejects a triangle only when
//! all three vertices lie outside one plane (a shared outcode bit); optionally
//! drops back faces by the sign of the area; rejects zero-area triangles (they
//! cover no sample under the fill rule); sorts the vertices by y and passes the
//! triangle on. It makes no new vertices: a triangle that crosses the volume goes
//! on whole and is clipped by `edge_walk` (y) and `span` (x, z).
//!
//! Latency 3, one triangle per cycle (003 Table 1: clipping 1 cycle; the RTL takes three
//! pipeline stages for the clock: edge vectors, the area's products, the verdict).
//! Mirrors `rtl::cull_sort` (`hdl-out/cull_sort.v`).

use crate::input::Vtx;
use fx::Formats;

/// Cycles from a triangle in to its verdict out: the stages of `rtl::cull_sort` (003
/// Table 1 has 1 cycle); a triangle moves from stage to stage when the next is free.
pub const LATENCY: u32 = 3;
/// Cycles between triangles.
pub const II: u32 = 1;

/// Outcode bits (Cohen-Sutherland), one per clip plane.
pub mod outcode {
    /// x < 0
    pub const LEFT: u8 = 1;
    /// x > width
    pub const RIGHT: u8 = 2;
    /// y < 0 (the top row; y points down)
    pub const TOP: u8 = 4;
    /// y > height
    pub const BOTTOM: u8 = 8;
    /// z < 0
    pub const NEAR: u8 = 16;
    /// z > the largest depth value
    pub const FAR: u8 = 32;
}

/// The clip volume: the screen in pixels; z runs over the depth buffer's range.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Clip {
    pub width: u32,
    pub height: u32,
}

/// Face culling.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Cull {
    #[default]
    None,
    /// Drop triangles that run clockwise on screen (front faces are
    /// counter-clockwise as the viewer sees them).
    Back,
}

/// Why a triangle went no further.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Reject {
    /// All three vertices outside these planes (the common outcode bits).
    Outside(u8),
    BackFace,
    ZeroArea,
}

/// A triangle that passed, vertices sorted by y (ties keep input order).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Sorted {
    /// vMin, vMid, vMax (Mesa's and 001's names; vMin is the top vertex on screen).
    pub v: [Vtx; 3],
    /// OR of the three outcodes: the planes the triangle crosses.
    pub crosses: u8,
}

/// The largest depth value: `2^z.frac - 1` (1.0 itself does not fit the buffer).
pub fn z_max(f: &Formats) -> i128 {
    (1i128 << f.z.frac) - 1
}

/// The outcode of one vertex.
pub fn outcode(v: &Vtx, clip: Clip, f: &Formats) -> u8 {
    let px = 1i128 << f.xy.frac;
    let mut c = 0;
    c |= if v.x < 0 { outcode::LEFT } else { 0 };
    c |= if v.x > clip.width as i128 * px { outcode::RIGHT } else { 0 };
    c |= if v.y < 0 { outcode::TOP } else { 0 };
    c |= if v.y > clip.height as i128 * px { outcode::BOTTOM } else { 0 };
    c |= if v.z < 0 { outcode::NEAR } else { 0 };
    c |= if v.z > z_max(f) { outcode::FAR } else { 0 };
    c
}

/// Twice the signed area in submission order (exact): positive means clockwise
/// on screen (y down), i.e. a back face.
pub fn area2(v: &[Vtx; 3]) -> i128 {
    (v[1].x - v[0].x) * (v[2].y - v[0].y) - (v[2].x - v[0].x) * (v[1].y - v[0].y)
}

/// One triangle through the unit.
pub fn cull_sort(v: &[Vtx; 3], clip: Clip, cull: Cull, f: &Formats) -> Result<Sorted, Reject> {
    let oc = v.map(|v| outcode(&v, clip, f));
    let common = oc[0] & oc[1] & oc[2];
    if common != 0 {
        return Err(Reject::Outside(common));
    }
    let a = area2(v);
    if a == 0 {
        return Err(Reject::ZeroArea);
    }
    if cull == Cull::Back && a > 0 {
        return Err(Reject::BackFace);
    }
    // Sorting network on (y, input index): three compare-exchanges.
    let mut s = [(v[0], 0), (v[1], 1), (v[2], 2)];
    let before = |a: &(Vtx, u8), b: &(Vtx, u8)| (a.0.y, a.1) <= (b.0.y, b.1);
    for (i, j) in [(0, 1), (1, 2), (0, 1)] {
        if !before(&s[i], &s[j]) {
            s.swap(i, j);
        }
    }
    Ok(Sorted { v: s.map(|p| p.0), crosses: oc[0] | oc[1] | oc[2] })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn vtx(x: i128, y: i128, z: i128) -> Vtx {
        Vtx { x: x * 16, y: y * 16, z, ..Vtx::default() }
    }

    #[test]
    fn cull_sort_paper_003_fig4_rejects_only_triangles_wholly_outside_one_plane() {
        let f = Formats::for_resolution(64, 48);
        let clip = Clip { width: 64, height: 48 };
        // Wholly left of the screen: rejected.
        assert_eq!(
            cull_sort(&[vtx(-9, 1, 5), vtx(-1, 9, 5), vtx(-5, 20, 5)], clip, Cull::None, &f),
            Err(Reject::Outside(outcode::LEFT))
        );
        // Outside two different planes but not one: passes (003 sends it on whole).
        let corner = [vtx(-10, 10, 5), vtx(10, -10, 5), vtx(-10, -10, 5)];
        assert!(cull_sort(&corner, clip, Cull::None, &f).is_ok());
        // Behind the far plane.
        let far = z_max(&f) + 1;
        assert_eq!(
            cull_sort(&[vtx(1, 1, far), vtx(9, 1, far), vtx(1, 9, far)], clip, Cull::None, &f),
            Err(Reject::Outside(outcode::FAR))
        );
    }

    #[test]
    fn cull_sort_sorts_by_y_and_culls_back_faces() {
        let f = Formats::for_resolution(64, 48);
        let clip = Clip { width: 64, height: 48 };
        // Counter-clockwise on screen (front): left-top, left-bottom, right-bottom.
        let front = [vtx(1, 1, 5), vtx(1, 9, 5), vtx(9, 9, 5)];
        let s = cull_sort(&[front[2], front[0], front[1]], clip, Cull::Back, &f).unwrap();
        assert_eq!(s.v.map(|v| v.y), [16, 144, 144]);
        assert_eq!(s.v[1], front[2], "equal y keeps input order");
        let back = [front[0], front[2], front[1]];
        assert_eq!(cull_sort(&back, clip, Cull::Back, &f), Err(Reject::BackFace));
        assert!(cull_sort(&back, clip, Cull::None, &f).is_ok());
        assert_eq!(cull_sort(&[front[0], front[0], front[1]], clip, Cull::None, &f), Err(Reject::ZeroArea));
    }
}
