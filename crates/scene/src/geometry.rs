//! The software geometry stage, as paper 001 runs it on the CPU: model
//! transform, per-vertex Lambert lighting (Gouraud), view and perspective
//! projection, guard-band clipping, perspective divide and viewport mapping.
//!
//! # Spaces
//! * **world**: the scene file's coordinates.
//! * **eye**: axes right, up and forward from the camera (`camera.up` made
//!   perpendicular to the view direction); `d`, the forward coordinate, is the
//!   distance along the view direction, positive in front of the eye (OpenGL's
//!   eye-space z is `-d`).
//! * **clip**: `(x_c, y_c, z_c, w_c)` with `w_c = d` and
//!   `z_c = f (d - n) / (f - n)`, so after the divide `z = f (d - n) / (d (f - n))`:
//!   0 at the near plane, 1 at the far plane (n, f: the camera's `near`, `far`).
//! * **screen**: `x = (x_c / w_c + 1) W / 2` (right), `y = (1 - y_c / w_c) H / 2`
//!   (down), pixel (i, j) covering [i, i+1) x [j, j+1); `z = z_c / w_c`.
//!
//! Every emitted vertex carries its `w_c` (= d) as the trilist's 7th value.
//! Winding is kept: a front face (counter-clockwise seen from outside) comes
//! out counter-clockwise as the viewer sees the screen, which with y down is a
//! negative `(x1-x0)(y2-y0) - (x2-x0)(y1-y0)`. Mirroring transforms (negative
//! determinant) have their triangles' vertex order reversed to keep this.
//!
//! # Guard band instead of view-volume clipping
//! The rasterizers clip x and y to the screen and z to [0, 1] per pixel (paper
//! 003 splits clipping between edge walk and span processing), so this stage
//! does not clip to the view volume. Fixed-point hardware still needs bounded
//! coordinates, so triangles are clipped (Sutherland-Hodgman, in homogeneous
//! clip space, colour and w interpolated linearly there) against the
//! [`GuardBand`] only when they cross it; triangles wholly outside one of its
//! planes are dropped (003's cull & sort does the same with outcodes), and
//! triangles inside it but off screen are passed on for the hardware to reject.
//! The plane `z = GUARD_Z_MIN` lies at `d = n f / (1.5 f - 0.5 n)`, which is
//! positive for every `0 < n < f`: whatever survives has `w > 0`.

use crate::math::{cross, dot, length, normalize, sub, Mat3, Mat4, Vec3, Vec4};
use crate::mesh::MeshVertex;
use crate::scene::{Camera, Lights};
use crate::trilist::{Tex, Triangle, Vertex};

/// Nearest screen depth a vertex may have after clipping (before it, 0 is the near plane).
pub const GUARD_Z_MIN: f64 = -0.5;
/// Farthest screen depth a vertex may have after clipping (1 is the far plane).
pub const GUARD_Z_MAX: f64 = 1.5;

/// The region of screen space (pixels and depth) every emitted vertex lies in.
/// For a `W` x `H` screen and `D = max(W, H)`: x in [-D/2, W + D/2],
/// y in [-D/2, H + D/2], z in [[`GUARD_Z_MIN`], [`GUARD_Z_MAX`]]. The
/// fixed-point coordinate formats are sized from these bounds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GuardBand {
    pub x_min: f64,
    pub x_max: f64,
    pub y_min: f64,
    pub y_max: f64,
    pub z_min: f64,
    pub z_max: f64,
}

/// The guard band of a `width` x `height` screen.
pub fn guard_band(width: u32, height: u32) -> GuardBand {
    let margin = width.max(height) as f64 / 2.0;
    GuardBand {
        x_min: -margin,
        x_max: width as f64 + margin,
        y_min: -margin,
        y_max: height as f64 + margin,
        z_min: GUARD_Z_MIN,
        z_max: GUARD_Z_MAX,
    }
}

impl GuardBand {
    /// The band's six planes as clip-space half-spaces `dot(plane, v) >= 0`,
    /// the near one (z >= z_min, which keeps w > 0) first.
    fn clip_planes(&self, width: u32, height: u32) -> [Vec4; 6] {
        // Inverse viewport: screen x = (ndc + 1) W / 2, y = (1 - ndc) H / 2.
        let ndc_x = |x: f64| 2.0 * x / width as f64 - 1.0;
        let ndc_y = |y: f64| 1.0 - 2.0 * y / height as f64;
        [
            [0.0, 0.0, 1.0, -self.z_min],
            [0.0, 0.0, -1.0, self.z_max],
            [1.0, 0.0, 0.0, -ndc_x(self.x_min)],
            [-1.0, 0.0, 0.0, ndc_x(self.x_max)],
            [0.0, -1.0, 0.0, ndc_y(self.y_min)],
            [0.0, 1.0, 0.0, -ndc_y(self.y_max)],
        ]
    }

    fn clamp(&self, x: f64, y: f64, z: f64) -> (f64, f64, f64) {
        (x.clamp(self.x_min, self.x_max), y.clamp(self.y_min, self.y_max), z.clamp(self.z_min, self.z_max))
    }
}

/// Smallest sine of the angle between `camera.up` and the view direction.
const MIN_UP_SINE: f64 = 1e-6;

/// World to clip space, and clip to screen space, for one camera and screen size.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Projection {
    clip_from_world: Mat4,
    width: u32,
    height: u32,
    band: GuardBand,
    /// The band's planes in clip space, from [`GuardBand::clip_planes`].
    planes: [Vec4; 6],
}

impl Projection {
    /// Checks the camera and builds its view-projection matrix. The error
    /// says what is wrong with the camera.
    pub fn new(camera: &Camera, width: u32, height: u32) -> Result<Projection, String> {
        let Camera { eye, target, up, fov_y_deg, near, far } = *camera;
        if !(fov_y_deg > 0.0 && fov_y_deg < 180.0) {
            return Err(format!("camera.fov_y_deg = {fov_y_deg} is outside (0, 180) degrees"));
        }
        if !(near > 0.0 && near.is_finite()) {
            return Err(format!("camera.near = {near} must be greater than 0"));
        }
        if !(far > near && far.is_finite()) {
            return Err(format!("camera.far = {far} must be greater than camera.near = {near}"));
        }
        let forward = normalize(sub(target, eye))
            .ok_or_else(|| format!("camera.eye and camera.target are the same point {eye:?}: no view direction"))?;
        let up_dir = normalize(up).ok_or_else(|| format!("camera.up = {up:?} has no direction"))?;
        // Right = forward x up, of length sin(angle between them); below
        // MIN_UP_SINE the screen's orientation is lost in rounding.
        let right = cross(forward, up_dir);
        if length(right) < MIN_UP_SINE {
            return Err(format!("camera.up = {up:?} is parallel to the view direction {forward:?}"));
        }
        let right = normalize(right).expect("checked above");
        let true_up = cross(right, forward);
        let rot = Mat3([right, true_up, forward]);
        let view = Mat4::affine(&rot, rot.apply(eye).map(|c| -c));
        let sy = 1.0 / (fov_y_deg.to_radians() / 2.0).tan();
        let sx = sy * height as f64 / width as f64;
        let a = far / (far - near);
        let proj = Mat4([[sx, 0.0, 0.0, 0.0], [0.0, sy, 0.0, 0.0], [0.0, 0.0, a, -a * near], [0.0, 0.0, 1.0, 0.0]]);
        let band = guard_band(width, height);
        let planes = band.clip_planes(width, height);
        Ok(Projection { clip_from_world: proj.mul(&view), width, height, band, planes })
    }

    /// Clip-space image of a world-space point.
    pub fn to_clip(&self, world: Vec3) -> Vec4 {
        self.clip_from_world.apply_point(world)
    }

    /// Perspective divide and viewport mapping: screen (x, y, z) of a clip-space point with w != 0.
    pub fn to_screen(&self, clip: Vec4) -> (f64, f64, f64) {
        let [x, y, z, w] = clip;
        let (w_px, h_px) = (self.width as f64, self.height as f64);
        ((x / w + 1.0) * w_px / 2.0, (1.0 - y / w) * h_px / 2.0, z / w)
    }
}

/// Lambert's law at one vertex: `color * (ambient + sum max(0, N.L) * light)`
/// per channel, clamped to [0, 255]. `normal` is a unit world-space normal;
/// L is the unit vector toward the light, the opposite of the direction it
/// travels.
pub fn lambert(color: [f64; 3], normal: Vec3, lights: &Lights) -> [f64; 3] {
    let mut intensity = lights.ambient;
    for light in &lights.directional {
        if let Some(to_light) = normalize(light.direction.map(|c| -c)) {
            let k = dot(normal, to_light).max(0.0);
            for (i, c) in intensity.iter_mut().zip(light.color) {
                *i += k * c;
            }
        }
    }
    std::array::from_fn(|c| (color[c] * intensity[c]).clamp(0.0, 255.0))
}

/// A vertex in clip space with its lit colour: what the clipper interpolates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClipVertex {
    pub clip: Vec4,
    pub rgb: [f64; 3],
    /// Texture coordinates (s, t).
    pub st: [f64; 2],
}

impl ClipVertex {
    fn lerp(&self, o: &ClipVertex, t: f64) -> ClipVertex {
        ClipVertex {
            clip: std::array::from_fn(|k| self.clip[k] + t * (o.clip[k] - self.clip[k])),
            rgb: std::array::from_fn(|k| self.rgb[k] + t * (o.rgb[k] - self.rgb[k])),
            st: std::array::from_fn(|k| self.st[k] + t * (o.st[k] - self.st[k])),
        }
    }
}

fn plane_distance(plane: &Vec4, v: &ClipVertex) -> f64 {
    (0..4).map(|k| plane[k] * v.clip[k]).sum()
}

/// One object's transform as the geometry stage uses it.
pub struct ObjectTransform {
    clip_from_object: Mat4,
    normal_matrix: Mat3,
    mirrored: bool,
}

impl ObjectTransform {
    /// `world_from_object = T * R * S` given as its linear part and translation.
    pub fn new(projection: &Projection, linear: &Mat3, translate: Vec3) -> Result<ObjectTransform, String> {
        let normal_matrix = linear.inverse_transpose().ok_or("the transform is singular (a zero scale?)")?;
        Ok(ObjectTransform {
            clip_from_object: projection.clip_from_world.mul(&Mat4::affine(linear, translate)),
            normal_matrix,
            mirrored: linear.determinant() < 0.0,
        })
    }

    /// Transforms and lights one mesh triangle, in the order that keeps its winding.
    pub fn vertices(&self, tri: &[MeshVertex; 3], color: [f64; 3], lights: &Lights) -> [ClipVertex; 3] {
        let order = if self.mirrored { [0, 2, 1] } else { [0, 1, 2] };
        order.map(|k| {
            let v = &tri[k];
            // Only underflow can make a unit normal vanish under an invertible
            // matrix; such a vertex gets the ambient light alone.
            let n_world = normalize(self.normal_matrix.apply(v.normal)).unwrap_or([0.0; 3]);
            ClipVertex {
                clip: self.clip_from_object.apply_point(v.position),
                rgb: lambert(color, n_world, lights),
                st: v.uv,
            }
        })
    }
}

/// Clips one clip-space triangle to the guard band and emits the screen-space
/// triangles that remain (none, the triangle itself, or a fan of up to 7), their vertices
/// textured by texture `texture` when given.
pub fn emit_clipped(tri: [ClipVertex; 3], projection: &Projection, texture: Option<u16>, out: &mut Vec<Triangle>) {
    let (band, planes) = (&projection.band, &projection.planes);
    // Outcodes as in 003's cull & sort: bit p set when outside plane p.
    let outcode = |v: &ClipVertex| -> u8 {
        planes.iter().enumerate().filter(|(_, p)| plane_distance(p, v) < 0.0).fold(0, |m, (i, _)| m | 1 << i)
    };
    let codes = tri.map(|v| outcode(&v));
    if codes[0] & codes[1] & codes[2] != 0 {
        return;
    }
    let crossing = codes[0] | codes[1] | codes[2];
    let mut poly: Vec<ClipVertex> = tri.to_vec();
    for (i, plane) in planes.iter().enumerate() {
        if crossing & (1 << i) == 0 {
            continue;
        }
        let mut next = Vec::with_capacity(poly.len() + 1);
        for (k, a) in poly.iter().enumerate() {
            let b = &poly[(k + 1) % poly.len()];
            let (da, db) = (plane_distance(plane, a), plane_distance(plane, b));
            if da >= 0.0 {
                next.push(*a);
            }
            if (da >= 0.0) != (db >= 0.0) {
                next.push(a.lerp(b, da / (da - db)));
            }
        }
        poly = next;
        if poly.len() < 3 {
            return;
        }
    }
    let screen: Vec<Vertex> = poly
        .iter()
        .map(|v| {
            let (x, y, z) = projection.to_screen(v.clip);
            // Clipped vertices lie on a band plane up to rounding: clamp that
            // rounding away so every vertex is provably inside the band.
            let (x, y, z) = band.clamp(x, y, z);
            let tex = texture.map(|texture| Tex { s: v.st[0], t: v.st[1], texture });
            Vertex { w: Some(v.clip[3]), tex, ..Vertex::new(x, y, z, v.rgb.map(|c| c.clamp(0.0, 255.0))) }
        })
        .collect();
    out.extend((1..screen.len() - 1).map(|i| [screen[0], screen[i], screen[i + 1]]));
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::DirectionalLight;

    /// Camera at (0, 0, 5) looking at the origin: 90 degrees vertical FOV on a
    /// 200 x 100 screen, near 1, far 9. The visible half-height at distance d
    /// is d * tan(45 deg) = d, the half-width 2d.
    fn axis_camera() -> Projection {
        Projection::new(&axis_cam(), 200, 100).unwrap()
    }

    /// The camera of [`axis_camera`].
    fn axis_cam() -> Camera {
        Camera { eye: [0.0, 0.0, 5.0], target: [0.0; 3], up: [0.0, 1.0, 0.0], fov_y_deg: 90.0, near: 1.0, far: 9.0 }
    }

    fn screen(p: &Projection, world: Vec3) -> (f64, f64, f64, f64) {
        let c = p.to_clip(world);
        let (x, y, z) = p.to_screen(c);
        (x, y, z, c[3])
    }

    fn close(a: (f64, f64, f64, f64), b: (f64, f64, f64, f64)) -> bool {
        [a.0 - b.0, a.1 - b.1, a.2 - b.2, a.3 - b.3].iter().all(|d| d.abs() < 1e-9)
    }

    /// z_screen = f (d - n) / (d (f - n)) for the axis camera.
    fn depth(d: f64) -> f64 {
        9.0 * (d - 1.0) / (d * 8.0)
    }

    #[test]
    fn projection_maps_known_points() {
        let p = axis_camera();
        let cases = [
            ([0.0, 0.0, 0.0], (100.0, 50.0, depth(5.0), 5.0)), // target: screen centre
            ([0.0, 0.0, 4.0], (100.0, 50.0, 0.0, 1.0)),        // on the near plane: z = 0
            ([0.0, 0.0, -4.0], (100.0, 50.0, 1.0, 9.0)),       // on the far plane: z = 1
            ([0.0, 5.0, 0.0], (100.0, 0.0, depth(5.0), 5.0)),  // top edge, y down
            ([0.0, -5.0, 0.0], (100.0, 100.0, depth(5.0), 5.0)),
            ([10.0, 0.0, 0.0], (200.0, 50.0, depth(5.0), 5.0)), // right edge
            ([-1.0, 0.5, 3.0], (75.0, 37.5, depth(2.0), 2.0)),  // d = 2: x a quarter of the half-width 4
        ];
        for (world, want) in cases {
            let got = screen(&p, world);
            assert!(close(got, want), "world {world:?}: got {got:?}, want {want:?}");
        }
    }

    #[test]
    fn projection_of_an_oblique_camera_centres_the_target_at_its_distance() {
        let cam = Camera {
            eye: [3.0, 4.0, -2.0],
            target: [-1.0, 0.5, 1.0],
            up: [0.0, 1.0, 0.0],
            fov_y_deg: 50.0,
            near: 0.5,
            far: 40.0,
        };
        let p = Projection::new(&cam, 320, 240).unwrap();
        let (x, y, _, w) = screen(&p, cam.target);
        let dist = crate::math::length(sub(cam.target, cam.eye));
        assert!((x - 160.0).abs() < 1e-9 && (y - 120.0).abs() < 1e-9 && (w - dist).abs() < 1e-12, "{x} {y} {w}");
        // A point straight above the target (world up) appears above it on screen.
        let (_, y_above, _, _) = screen(&p, [-1.0, 1.5, 1.0]);
        assert!(y_above < 120.0, "{y_above}");
    }

    #[test]
    fn projection_rejects_bad_cameras() {
        let good = Camera { fov_y_deg: 60.0, ..axis_cam() };
        let cases = [
            (Camera { target: good.eye, ..good }, "are the same point"),
            (Camera { up: [0.0, 0.0, -2.0], ..good }, "parallel to the view direction"),
            (Camera { up: [0.0; 3], ..good }, "has no direction"),
            (Camera { fov_y_deg: 0.0, ..good }, "outside (0, 180)"),
            (Camera { fov_y_deg: 180.0, ..good }, "outside (0, 180)"),
            (Camera { near: 0.0, ..good }, "near = 0 must be greater than 0"),
            (Camera { far: 1.0, ..good }, "far = 1 must be greater than camera.near = 1"),
        ];
        for (cam, want) in cases {
            let err = Projection::new(&cam, 64, 64).unwrap_err();
            assert!(err.contains(want), "{cam:?}: got {err:?}, want {want:?}");
        }
    }

    fn lights(ambient: f64, color: [f64; 3]) -> Lights {
        Lights { ambient: [ambient; 3], directional: vec![DirectionalLight { direction: [0.0, -2.0, 0.0], color }] }
    }

    #[test]
    fn lambert_lights_known_normals() {
        let l = lights(0.25, [0.5, 0.5, 1.0]);
        let c = [200.0, 100.0, 40.0];
        // Facing the light (which travels down): ambient + full light.
        assert_eq!(lambert(c, [0.0, 1.0, 0.0], &l), [150.0, 75.0, 50.0]);
        // At 60 degrees: N.L = 1/2.
        let n60 = [60f64.to_radians().sin(), 60f64.to_radians().cos(), 0.0];
        let got = lambert(c, n60, &l);
        let want = [100.0, 50.0, 30.0];
        assert!((0..3).all(|k| (got[k] - want[k]).abs() < 1e-12), "{got:?}");
        // Edge-on and facing away: ambient only.
        assert_eq!(lambert(c, [1.0, 0.0, 0.0], &l), [50.0, 25.0, 10.0]);
        assert_eq!(lambert(c, [0.0, -1.0, 0.0], &l), [50.0, 25.0, 10.0]);
        // Two full lights on white saturate at 255.
        let mut bright = lights(1.0, [1.0; 3]);
        bright.directional.push(bright.directional[0]);
        assert_eq!(lambert([255.0; 3], [0.0, 1.0, 0.0], &bright), [255.0; 3]);
    }

    fn cv(p: &Projection, world: Vec3, rgb: [f64; 3]) -> ClipVertex {
        ClipVertex { clip: p.to_clip(world), rgb, st: [0.0; 2] }
    }

    fn clipped(p: &Projection, tri: [ClipVertex; 3]) -> Vec<Triangle> {
        let mut out = Vec::new();
        emit_clipped(tri, p, None, &mut out);
        out
    }

    fn inside(band: &GuardBand, v: &Vertex) -> bool {
        (band.x_min..=band.x_max).contains(&v.x)
            && (band.y_min..=band.y_max).contains(&v.y)
            && (band.z_min..=band.z_max).contains(&v.z)
    }

    fn signed_area2(t: &Triangle) -> f64 {
        (t[1].x - t[0].x) * (t[2].y - t[0].y) - (t[2].x - t[0].x) * (t[1].y - t[0].y)
    }

    #[test]
    fn guard_band_is_half_the_larger_side_around_the_screen() {
        let b = guard_band(640, 480);
        assert_eq!((b.x_min, b.x_max, b.y_min, b.y_max, b.z_min, b.z_max), (-320.0, 960.0, -320.0, 800.0, -0.5, 1.5));
    }

    #[test]
    fn geometry_passes_triangles_inside_the_band_unchanged_with_w() {
        let p = axis_camera();
        // Wholly off screen to the right (x > 200) but inside the band (x <= 300,
        // x_world <= 20 at d = 5).
        let world = [[11.0, 0.0, 0.0], [14.0, 0.0, 0.0], [12.0, 1.0, 0.0]];
        let tri = world.map(|w| cv(&p, w, [1.0, 2.0, 3.0]));
        let out = clipped(&p, tri);
        assert_eq!(out.len(), 1);
        for (v, w) in out[0].iter().zip(world) {
            let (x, y, z, d) = screen(&p, w);
            assert_eq!((v.x, v.y, v.z, v.w), (x, y, z, Some(d)));
            assert!(x > 200.0);
        }
    }

    #[test]
    fn geometry_keeps_front_faces_counter_clockwise_on_screen() {
        let p = axis_camera();
        // Counter-clockwise seen from the camera on +z.
        let tri = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]].map(|w| cv(&p, w, [0.0; 3]));
        let out = clipped(&p, tri);
        assert!(signed_area2(&out[0]) < 0.0, "{:?}", out[0]);
    }

    #[test]
    fn geometry_clips_a_triangle_crossing_the_near_guard_plane() {
        let p = axis_camera();
        let band = guard_band(200, 100);
        // A floor triangle facing up at the camera above it, one vertex 3 behind
        // the eye (d = -3): it crosses z = -0.5 (d = 9/13).
        let tri = [
            cv(&p, [-1.0, -1.0, 0.0], [255.0, 0.0, 0.0]),
            cv(&p, [0.0, -1.0, 8.0], [0.0, 0.0, 255.0]),
            cv(&p, [1.0, -1.0, 0.0], [0.0, 255.0, 0.0]),
        ];
        let out = clipped(&p, tri);
        assert!(!out.is_empty());
        let d_min = 9.0 / 13.0; // n f / (1.5 f - 0.5 n)
        for v in out.iter().flatten() {
            let w = v.w.unwrap();
            assert!(w >= d_min - 1e-12, "{v}");
            assert!(inside(&band, v), "{v} outside {band:?}");
            assert!(v.rgb().iter().all(|c| (0.0..=255.0).contains(c)), "{v}");
        }
        assert!(out.iter().flatten().any(|v| (v.z - GUARD_Z_MIN).abs() < 1e-12), "no vertex on the cut");
        assert!(out.iter().all(|t| signed_area2(t) < 0.0), "winding lost: {out:?}");
    }

    #[test]
    fn geometry_drops_triangles_wholly_outside_one_plane() {
        let p = axis_camera();
        let behind = [[0.0, 0.0, 6.0], [1.0, 0.0, 7.0], [0.0, 1.0, 8.0]].map(|w| cv(&p, w, [0.0; 3]));
        assert!(clipped(&p, behind).is_empty());
        // Beyond the right band edge x = 300 (ndc 2), i.e. x_world > 20 at d = 5.
        let right = [[21.0, 0.0, 0.0], [25.0, 0.0, 0.0], [22.0, 1.0, 0.0]].map(|w| cv(&p, w, [0.0; 3]));
        assert!(clipped(&p, right).is_empty());
    }

    #[test]
    fn geometry_clips_to_the_side_band_interpolating_colour_in_clip_space() {
        let p = axis_camera();
        let band = guard_band(200, 100);
        // From the centre to x_world = 30 at d = 5 (screen x = 400): cut at x = 300.
        let tri = [
            cv(&p, [0.0, -1.0, 0.0], [0.0, 0.0, 0.0]),
            cv(&p, [30.0, -1.0, 0.0], [240.0, 0.0, 0.0]),
            cv(&p, [0.0, 1.0, 0.0], [0.0, 0.0, 0.0]),
        ];
        let out = clipped(&p, tri);
        assert_eq!(out.len(), 2, "a quad after one cut");
        let cut: Vec<&Vertex> = out.iter().flatten().filter(|v| v.x == band.x_max).collect();
        assert!(!cut.is_empty());
        // All at d = 5, so clip-space and screen-space interpolation agree:
        // x = 300 of 400 is 2/3 of the way from the centre (x = 100): red = 160.
        let bottom = cut.iter().find(|v| (v.y - 60.0).abs() < 1e-9).expect("cut on the bottom edge");
        assert!((bottom.r - 160.0).abs() < 1e-9 && bottom.w == Some(5.0), "{bottom}");
        assert!(out.iter().flatten().all(|v| inside(&band, v)));
    }
}
