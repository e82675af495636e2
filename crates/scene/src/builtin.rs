//! The built-in models: 001's Cube demo and 003's four test models.
//!
//! | name     | triangles | vertices sent | built as |
//! |----------|-----------|---------------|----------|
//! | `cube`   | 12        | 36            | 6 faces of 2 triangles, flat normals (001, Cube demo) |
//! | `sphere` | 168       | 504 (003)     | lathe: 12 slices x 8 stacks, pole fans |
//! | `cone`   | 168       | 504 (003)     | lathe: 42 slices; tip fan, one quad band, base fan |
//! | `torus`  | 340       | 1,020 (003)   | lathe of a circle: 17 slices x 10 profile points |
//! | `pawn`   | 506       | 1,518 (003)   | lathe: 23 slices x 13 profile points, both ends on the axis |
//!
//! Vertices are counted as sent to the rasterizer, 3 per triangle (a triangle
//! soup; 003 counts them the same way). Every model is closed, centred on the
//! origin, fits in [-1, 1]^3 and has its front faces counter-clockwise seen from
//! outside. Normals are per vertex: smooth where the surface is smooth, flat on
//! the cube's faces, the cone's base and across the pawn's creases.
//!
//! **Detail.** [`mesh_at`] builds a model at a finer tessellation, `detail` d from 1
//! (the papers' meshes above) to [`MAX_DETAIL`]: the sphere and the torus sample their
//! circles d times as finely in both directions (8d stacks x 12d slices, 10d x 17d); the
//! cube cuts each face into a d x d grid and the cone and the pawn cut each profile segment
//! into d and take d times the slices (the same shape, smaller triangles). Triangles:
//! cube 12 d^2, sphere 192 d^2 - 24 d, cone 42 d (6 d - 2), torus 340 d^2, pawn
//! 23 d (24 d - 2) ([`triangle_count`]); every detail is closed and wound outward.

use crate::math::Vec3;
use crate::mesh::{Mesh, MeshVertex};
use std::f64::consts::{PI, TAU};

/// The names [`mesh`] knows, in the order the docs list them.
pub const NAMES: [&str; 5] = ["cube", "sphere", "cone", "torus", "pawn"];

/// The finest `detail` [`mesh_at`] builds (the torus at 32 is 348,160 triangles).
pub const MAX_DETAIL: u32 = 32;

/// The built-in model called `name`, or `None` if there is none.
pub fn mesh(name: &str) -> Option<Mesh> {
    mesh_at(name, 1)
}

/// The built-in model called `name` tessellated at `detail` (1 is [`mesh`]'s; see the
/// module's docs), or `None` if there is no such model or `detail` is outside 1 to
/// [`MAX_DETAIL`].
pub fn mesh_at(name: &str, detail: u32) -> Option<Mesh> {
    if !(1..=MAX_DETAIL).contains(&detail) {
        return None;
    }
    let d = detail as usize;
    match name {
        "cube" => Some(cube(d)),
        "sphere" => Some(sphere(d)),
        "cone" => Some(cone(d)),
        "torus" => Some(torus(d)),
        "pawn" => Some(pawn(d)),
        _ => None,
    }
}

/// The number of triangles of [`mesh_at`]`(name, detail)`, without building it; `None`
/// as for [`mesh_at`].
pub fn triangle_count(name: &str, detail: u32) -> Option<usize> {
    if !(1..=MAX_DETAIL).contains(&detail) {
        return None;
    }
    let d = detail as usize;
    match name {
        "cube" => Some(12 * d * d),
        "sphere" => Some(192 * d * d - 24 * d),
        "cone" => Some(42 * d * (6 * d - 2)),
        "torus" => Some(340 * d * d),
        "pawn" => Some(23 * d * (24 * d - 2)),
        _ => None,
    }
}

/// The cube [-1, 1]^3: for each axis and sign, a face of 2 d^2 triangles (a d x d grid
/// of squares, each cut along the same diagonal).
fn cube(d: usize) -> Mesh {
    let mut triangles = Vec::with_capacity(12 * d * d);
    for axis in 0..3 {
        for sign in [1.0, -1.0] {
            let unit = |a: usize| -> Vec3 { std::array::from_fn(|k| if k == a { 1.0 } else { 0.0 }) };
            let n = unit(axis).map(|c| c * sign);
            // u x v = n, so (-u-v, u-v, u+v, -u+v) runs counter-clockwise about n.
            let (mut u, mut v) = (unit((axis + 1) % 3), unit((axis + 2) % 3));
            if sign < 0.0 {
                std::mem::swap(&mut u, &mut v);
            }
            let corner = |su: f64, sv: f64| MeshVertex {
                position: std::array::from_fn(|k| n[k] + su * u[k] + sv * v[k]),
                normal: n,
                // The whole image on each face.
                uv: [(su + 1.0) / 2.0, (sv + 1.0) / 2.0],
                texture: None,
            };
            // Grid lines at -1 + 2 i / d: the same values on every face, so that shared
            // edges match bit for bit (n[k] + s * 1 + t * 0 is s exactly).
            let at = |i: usize| if i == d { 1.0 } else { -1.0 + 2.0 * i as f64 / d as f64 };
            for i in 0..d {
                for j in 0..d {
                    let (u0, u1, v0, v1) = (at(i), at(i + 1), at(j), at(j + 1));
                    let q = [corner(u0, v0), corner(u1, v0), corner(u1, v1), corner(u0, v1)];
                    triangles.push([q[0], q[1], q[2]]);
                    triangles.push([q[0], q[2], q[3]]);
                }
            }
        }
    }
    Mesh { triangles, textures: Vec::new(), has_uv: true }
}

/// A point of a lathe profile in the half-plane through the y axis: distance
/// `r` from the axis, height `y`. At a `crease` each neighbouring segment
/// keeps its own normal; elsewhere the two are averaged.
#[derive(Clone, Copy)]
struct ProfilePoint {
    r: f64,
    y: f64,
    crease: bool,
}

const fn smooth(r: f64, y: f64) -> ProfilePoint {
    ProfilePoint { r, y, crease: false }
}

const fn crease(r: f64, y: f64) -> ProfilePoint {
    ProfilePoint { r, y, crease: true }
}

/// The point at angle `theta` about the y axis of the profile-plane vector
/// (r, y): theta = 0 is +z, and theta grows toward +x.
fn revolve(r: f64, y: f64, theta: f64) -> Vec3 {
    let (s, c) = theta.sin_cos();
    [r * s, y, r * c]
}

/// Sweeps `profile` around the y axis in `slices` steps. Segment i -> i+1 of
/// the profile becomes a band of quads (two triangles each), or a fan where
/// one end is on the axis (r = 0). A `closed` profile also joins its last
/// point to its first. With the profile running so that (dy, -dr) points out
/// of the solid (upward on the outside, as for a pawn standing on its base),
/// front faces run counter-clockwise seen from outside.
fn lathe(profile: &[ProfilePoint], slices: usize, closed: bool) -> Mesh {
    let n = profile.len();
    let segments = if closed { n } else { n - 1 };
    // Unit outward normal of each segment in the profile plane, as (r, y).
    let seg_normal: Vec<[f64; 2]> = (0..segments)
        .map(|s| {
            let (a, b) = (profile[s], profile[(s + 1) % n]);
            let (dr, dy) = (b.r - a.r, b.y - a.y);
            let len = dr.hypot(dy);
            [dy / len, -dr / len]
        })
        .collect();
    // Profile normal of point i as seen from segment s (one of its two).
    let point_normal = |i: usize, s: usize| -> [f64; 2] {
        let p = profile[i];
        // The point's other segment: the one ending at i when s starts there,
        // the one starting at i when s ends there; none at an open end.
        let other =
            if s == i { (i > 0 || closed).then(|| (i + segments - 1) % segments) } else { (i < segments).then_some(i) };
        if p.r == 0.0 && !p.crease {
            // On the axis a smooth surface is perpendicular to it.
            [0.0, seg_normal[s][1].signum()]
        } else if let (false, Some(other)) = (p.crease, other) {
            let (a, b) = (seg_normal[s], seg_normal[other]);
            let (r, y) = (a[0] + b[0], a[1] + b[1]);
            let len = r.hypot(y);
            [r / len, y / len]
        } else {
            seg_normal[s]
        }
    };
    let step = TAU / slices as f64;
    let mut triangles = Vec::new();
    for s in 0..segments {
        let (i0, i1) = (s, (s + 1) % n);
        for j in 0..slices {
            // Positions depend only on (point, slice mod slices), so shared
            // edges and the seam at 2 pi match bit for bit.
            let vertex = |i: usize, j: usize, normal_theta: f64| {
                let p = profile[i];
                let nrm = point_normal(i, s);
                MeshVertex {
                    position: revolve(p.r, p.y, (j % slices) as f64 * step),
                    normal: revolve(nrm[0], nrm[1], normal_theta),
                    // Around the axis, then along the profile: the image wrapped once.
                    // (s + 1 at the segment's far end, so that a closed profile's last
                    // segment runs to 1, not back to 0).
                    uv: [j as f64 / slices as f64, if i == s { s } else { s + 1 } as f64 / segments as f64],
                    texture: None,
                }
            };
            let at = |i: usize, j: usize| vertex(i, j, (j % slices) as f64 * step);
            // An axis point takes the normal of the slice's middle (it matters
            // only at a cone's tip).
            let mid = (j as f64 + 0.5) * step;
            let (a, b, c, d) = (at(i0, j), at(i0, j + 1), at(i1, j + 1), at(i1, j));
            if profile[i0].r == 0.0 {
                triangles.push([vertex(i0, j, mid), c, d]);
            } else if profile[i1].r == 0.0 {
                triangles.push([a, b, vertex(i1, j, mid)]);
            } else {
                triangles.push([a, b, c]);
                triangles.push([a, c, d]);
            }
        }
    }
    Mesh { triangles, textures: Vec::new(), has_uv: true }
}

/// `profile` (open) with each segment cut into `d` equal pieces; the points added are
/// smooth (the segment's normal on both sides), the original points keep their creases.
fn subdivide(profile: &[ProfilePoint], d: usize) -> Vec<ProfilePoint> {
    let mut out = Vec::with_capacity((profile.len() - 1) * d + 1);
    for w in profile.windows(2) {
        let (a, b) = (w[0], w[1]);
        out.push(a);
        for t in 1..d {
            let t = t as f64 / d as f64;
            out.push(smooth(a.r + (b.r - a.r) * t, a.y + (b.y - a.y) * t));
        }
    }
    out.extend(profile.last().copied());
    out
}

/// Unit sphere: 12 d slices x 8 d stacks (8 d + 1 profile points from pole to pole).
fn sphere(d: usize) -> Mesh {
    let stacks = 8 * d;
    let profile: Vec<ProfilePoint> = (0..=stacks)
        .map(|k| {
            let phi = -PI / 2.0 + PI * k as f64 / stacks as f64;
            // cos(+-pi/2) is not exactly 0: put the poles on the axis.
            let r = if k == 0 || k == stacks { 0.0 } else { phi.cos() };
            smooth(r, phi.sin())
        })
        .collect();
    lathe(&profile, 12 * d, false)
}

/// Cone of radius 1 and height 2 with its base at y = -1: 42 slices; the side
/// is a fan from the tip to a ring at mid-height plus one quad band, and the
/// base is a flat fan (at detail d: 42 d slices, each segment in d pieces).
fn cone(d: usize) -> Mesh {
    let profile = [smooth(0.0, -1.0), crease(1.0, -1.0), smooth(0.5, 0.0), crease(0.0, 1.0)];
    lathe(&subdivide(&profile, d), 42 * d, false)
}

/// Torus about the y axis: tube centre radius 0.7, tube radius 0.3;
/// 17 d slices x 10 d profile points.
fn torus(d: usize) -> Mesh {
    let points = 10 * d;
    let profile: Vec<ProfilePoint> = (0..points)
        .map(|k| {
            let phi = TAU * k as f64 / points as f64;
            smooth(0.7 + 0.3 * phi.cos(), 0.3 * phi.sin())
        })
        .collect();
    lathe(&profile, 17 * d, true)
}

/// A chess pawn: flat base, rounded foot, tapering body, collar, neck and a
/// round head; 23 slices x 13 profile points (at detail d: 23 d slices, each
/// profile segment in d pieces).
fn pawn(d: usize) -> Mesh {
    // The head is a sphere of radius HEAD_R centred HEAD_Y above the bottom;
    // its profile points are at these angles from its lowest point.
    const HEAD_R: f64 = 0.34;
    const HEAD_Y: f64 = 1.64;
    let head = |deg: f64, crease_here: bool| {
        let (s, c) = deg.to_radians().sin_cos();
        let r = if deg == 180.0 { 0.0 } else { HEAD_R * s };
        ProfilePoint { r, y: HEAD_Y - HEAD_R * c, crease: crease_here }
    };
    let profile = [
        smooth(0.0, 0.0),
        crease(0.8, 0.0),
        crease(0.8, 0.14),
        smooth(0.62, 0.28),
        smooth(0.4, 0.42),
        smooth(0.27, 1.04),
        crease(0.52, 1.13),
        crease(0.52, 1.21),
        head(40.0, true),
        head(80.0, false),
        head(120.0, false),
        head(155.0, false),
        head(180.0, false),
    ];
    // Centre it vertically: the top of the head is at 1.98.
    let centred: Vec<ProfilePoint> = profile.iter().map(|p| ProfilePoint { y: p.y - 0.99, ..*p }).collect();
    lathe(&subdivide(&centred, d), 23 * d, false)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::{dot, face_normal, normalize, sub};

    #[test]
    fn builtin_vertex_counts_match_003_and_001() {
        // 003: Pawn 1,518, Sphere 504, Cone 504, Torus 1,020 vertices; 001's cube: 12 triangles.
        for (name, vertices) in [("cube", 36), ("sphere", 504), ("cone", 504), ("torus", 1020), ("pawn", 1518)] {
            assert_eq!(mesh(name).unwrap().vertex_count(), vertices, "model {name}");
        }
        assert!(mesh("teapot").is_none());
        assert!(NAMES.iter().all(|n| mesh(n).is_some()));
    }

    #[test]
    fn builtin_models_are_closed_and_wound_outward() {
        for name in NAMES {
            let m = mesh(name).unwrap();
            m.check().unwrap_or_else(|e| panic!("{name}: {e}"));
            m.check_closed().unwrap_or_else(|e| panic!("{name}: {e}"));
            let extent = m.triangles.iter().flatten().flat_map(|v| v.position).fold(0.0f64, |a, c| a.max(c.abs()));
            assert!(extent <= 1.0, "{name} reaches {extent}, outside [-1, 1]^3");
        }
    }

    #[test]
    fn builtin_detail_one_is_the_papers_mesh_and_finer_details_are_closed_outward_and_counted() {
        for name in NAMES {
            assert_eq!(mesh_at(name, 1), mesh(name), "{name}");
            for detail in [2, 3] {
                let m = mesh_at(name, detail).unwrap();
                assert_eq!(Some(m.triangles.len()), triangle_count(name, detail), "{name} at detail {detail}");
                m.check().unwrap_or_else(|e| panic!("{name} at detail {detail}: {e}"));
                m.check_closed().unwrap_or_else(|e| panic!("{name} at detail {detail}: {e}"));
                let extent = m.triangles.iter().flatten().flat_map(|v| v.position).fold(0.0f64, |a, c| a.max(c.abs()));
                assert!(extent <= 1.0, "{name} at detail {detail} reaches {extent}");
                for (t, tri) in m.triangles.iter().enumerate() {
                    let f = normalize(face_normal(tri[0].position, tri[1].position, tri[2].position)).unwrap();
                    assert!(tri.iter().all(|v| dot(v.normal, f) > 0.5), "{name} at detail {detail}, triangle {t}");
                }
            }
            assert_eq!(triangle_count(name, 1), Some(mesh(name).unwrap().triangles.len()));
        }
        // The dense scene's model (scenes/dense/dense.json): the torus at 15.
        assert_eq!(triangle_count("torus", 15), Some(76_500));
        for bad in [0, MAX_DETAIL + 1, u32::MAX] {
            assert!(mesh_at("sphere", bad).is_none() && triangle_count("sphere", bad).is_none(), "{bad}");
        }
        assert!(mesh_at("teapot", 2).is_none() && triangle_count("teapot", 2).is_none());
    }

    #[test]
    fn builtin_convex_models_face_away_from_their_centroid() {
        // The cube, sphere and cone are convex and centred on the y axis.
        for name in ["cube", "sphere", "cone"] {
            let m = mesh(name).unwrap();
            let n = m.vertex_count() as f64;
            let c =
                m.triangles.iter().flatten().fold([0.0; 3], |s, v| std::array::from_fn(|k| s[k] + v.position[k] / n));
            for (t, tri) in m.triangles.iter().enumerate() {
                let f = face_normal(tri[0].position, tri[1].position, tri[2].position);
                assert!(dot(f, sub(tri[0].position, c)) > 0.0, "{name} triangle {t} faces its centroid {c:?}");
            }
        }
    }

    #[test]
    fn builtin_normals_are_unit_and_agree_with_the_faces() {
        for name in NAMES {
            for (t, tri) in mesh(name).unwrap().triangles.iter().enumerate() {
                let f = normalize(face_normal(tri[0].position, tri[1].position, tri[2].position)).unwrap();
                for v in tri {
                    assert!((dot(v.normal, v.normal) - 1.0).abs() < 1e-12, "{name} triangle {t}: {:?}", v.normal);
                    // Smooth normals lean at most a facet's angle away from the face.
                    assert!(dot(v.normal, f) > 0.5, "{name} triangle {t}: normal {:?} vs face {f:?}", v.normal);
                }
            }
        }
    }

    #[test]
    fn builtin_normals_are_flat_on_the_cube_and_the_cone_base_and_smooth_on_the_sphere() {
        for tri in mesh("cube").unwrap().triangles {
            let f = normalize(face_normal(tri[0].position, tri[1].position, tri[2].position)).unwrap();
            assert!(tri.iter().all(|v| v.normal == f), "{tri:?}");
        }
        let base: Vec<_> =
            mesh("cone").unwrap().triangles.into_iter().filter(|t| t.iter().all(|v| v.position[1] == -1.0)).collect();
        assert_eq!(base.len(), 42);
        assert!(base.iter().flatten().all(|v| v.normal == [0.0, -1.0, 0.0]));
        for v in mesh("sphere").unwrap().triangles.iter().flatten() {
            // On a unit sphere the smooth normal is the position.
            assert!((0..3).all(|k| (v.normal[k] - v.position[k]).abs() < 1e-12), "{v:?}");
        }
    }
}
