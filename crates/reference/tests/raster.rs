//! Interpolation, depth, clipping and culling of the float reference.

use reference::{fragments, render, Cull, Options, Outcome};
use scene::{Triangle, Trilist, Vertex};

fn vz(x: f64, y: f64, z: f64, rgb: [f64; 3]) -> Vertex {
    Vertex::new(x, y, z, rgb)
}

/// The plane through three (x, y, value) points, by Cramer's rule, evaluated at (x, y).
fn plane(p: [(f64, f64, f64); 3], x: f64, y: f64) -> f64 {
    let [(x0, y0, f0), (x1, y1, f1), (x2, y2, f2)] = p;
    let det = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
    let a = ((f1 - f0) * (y2 - y0) - (f2 - f0) * (y1 - y0)) / det;
    let b = ((x1 - x0) * (f2 - f0) - (x2 - x0) * (f1 - f0)) / det;
    f0 + a * (x - x0) + b * (y - y0)
}

#[test]
fn reference_linear_colour_and_depth_follow_the_plane_equation() {
    let t = [
        vz(3.2, 5.1, 0.1, [10.0, 200.0, 30.0]),
        vz(610.7, 40.3, 0.9, [250.0, 0.0, 128.0]),
        vz(150.4, 470.9, 0.4, [0.0, 90.0, 255.0]),
    ];
    let mut n = 0;
    fragments(&t, 640, 480, &Options::default(), |f| {
        let (x, y) = (f.x as f64 + 0.5, f.y as f64 + 0.5);
        let z = plane(t.map(|v| (v.x, v.y, v.z)), x, y);
        assert!((f.z - z).abs() < 1e-9, "z at ({x},{y}): {} vs plane {z}", f.z);
        for c in 0..3 {
            let want = plane(t.map(|v| (v.x, v.y, v.rgb()[c])), x, y);
            assert!((f.rgb[c] - want).abs() < 1e-9, "channel {c} at ({x},{y}): {} vs plane {want}", f.rgb[c]);
        }
        n += 1;
    });
    assert!(n > 100_000, "the triangle should cover most of the screen, covered {n}");
}

#[test]
fn reference_perspective_colour_is_the_ratio_of_two_planes() {
    let mk = |x, y, z, w, c| Vertex { w: Some(w), ..vz(x, y, z, [c, 0.0, 0.0]) };
    let t = [mk(10.0, 10.0, 0.2, 1.0, 0.0), mk(300.0, 20.0, 0.5, 4.0, 255.0), mk(40.0, 230.0, 0.7, 2.0, 100.0)];
    fragments(&t, 320, 240, &Options::default(), |f| {
        let (x, y) = (f.x as f64 + 0.5, f.y as f64 + 0.5);
        let num = plane(t.map(|v| (v.x, v.y, v.r / v.w.unwrap())), x, y);
        let den = plane(t.map(|v| (v.x, v.y, 1.0 / v.w.unwrap())), x, y);
        assert!((f.rgb[0] - num / den).abs() < 1e-9, "at ({x},{y})");
    });
    // With --linear semantics the same triangle follows the screen plane instead.
    let opts = Options { ignore_w: true, ..Options::default() };
    fragments(&t, 320, 240, &opts, |f| {
        let want = plane(t.map(|v| (v.x, v.y, v.r)), f.x as f64 + 0.5, f.y as f64 + 0.5);
        assert!((f.rgb[0] - want).abs() < 1e-9);
    });
}

fn one(tris: Vec<Triangle>, opts: &Options) -> reference::Frame {
    render(&Trilist { width: 16, height: 16, triangles: tris, textures: Vec::new() }, opts, &mut |_| {}).0
}

#[test]
fn reference_depth_test_is_less_and_order_independent() {
    let near = [
        vz(0.0, 0.0, 0.25, [255.0, 0.0, 0.0]),
        vz(16.0, 0.0, 0.25, [255.0, 0.0, 0.0]),
        vz(0.0, 16.0, 0.25, [255.0, 0.0, 0.0]),
    ];
    let far = [
        vz(0.0, 0.0, 0.75, [0.0, 255.0, 0.0]),
        vz(16.0, 0.0, 0.75, [0.0, 255.0, 0.0]),
        vz(0.0, 16.0, 0.75, [0.0, 255.0, 0.0]),
    ];
    let a = one(vec![near, far], &Options::default());
    let b = one(vec![far, near], &Options::default());
    assert_eq!((&a.color, &a.depth, &a.written), (&b.color, &b.depth, &b.written));
    assert_eq!(a.rgb8()[0], [255, 0, 0]);
    // The near triangle wrote every covered pixel, whichever came first.
    assert!(a.writer.iter().zip(&a.written).all(|(&w, &wr)| !wr || w == 0));
    assert!(b.writer.iter().zip(&b.written).all(|(&w, &wr)| !wr || w == 1));
    // Equal depth: LESS keeps the first.
    let same = one(vec![near, near.map(|v| Vertex { g: 255.0, ..v })], &Options::default());
    assert_eq!(same.rgb8()[0], [255, 0, 0]);
}

#[test]
fn reference_clips_samples_outside_z_0_1() {
    // z runs from -1 at the left edge to 2 at the right: only samples with z in [0, 1] remain.
    let t = [vz(0.0, 0.0, -1.0, [9.0; 3]), vz(16.0, 0.0, 2.0, [9.0; 3]), vz(0.0, 16.0, -1.0, [9.0; 3])];
    let (frame, stats) = render(
        &Trilist { width: 16, height: 16, triangles: vec![t], textures: Vec::new() },
        &Options::default(),
        &mut |_| {},
    );
    for (i, &wrote) in frame.written.iter().enumerate() {
        let x = (i % 16) as f64 + 0.5;
        let z = -1.0 + 3.0 * x / 16.0;
        if wrote {
            assert!((0.0..=1.0).contains(&z), "pixel {i} written at z {z}");
        }
    }
    assert!(stats.z_clipped > 0 && stats.pixels_written > 0);
    assert_eq!(stats.fragments, stats.z_clipped + stats.pixels_written);
}

#[test]
fn reference_back_face_cull_drops_clockwise_triangles_only() {
    // Counter-clockwise as the viewer sees it (y down): left-top, left-bottom, right-bottom.
    let ccw = [vz(1.0, 1.0, 0.5, [1.0; 3]), vz(1.0, 9.0, 0.5, [1.0; 3]), vz(9.0, 9.0, 0.5, [1.0; 3])];
    let cw = [ccw[0], ccw[2], ccw[1]];
    let back = Options { cull: Cull::Back, ..Options::default() };
    assert_eq!(fragments(&ccw, 16, 16, &back, |_| {}), Outcome::Drawn);
    assert_eq!(fragments(&cw, 16, 16, &back, |_| {}), Outcome::Culled);
    assert_eq!(fragments(&cw, 16, 16, &Options::default(), |_| {}), Outcome::Drawn);
    let flat = [ccw[0], ccw[0], ccw[2]];
    assert_eq!(fragments(&flat, 16, 16, &Options::default(), |_| {}), Outcome::Degenerate);
}

/// A triangle in eye space (x, y, z_eye with the eye looking down -z), projected
/// with a plain pinhole onto a `size` x `size` screen: the trilist vertex a
/// geometry stage would write, including one behind the eye (w < 0).
fn project(p: [f64; 3], size: f64) -> Vertex {
    let w = -p[2];
    let (xn, yn) = (p[0] / w, p[1] / w);
    let (n, f) = (1.0, 100.0);
    let z = f / (f - n) * (1.0 - n / w);
    Vertex { w: Some(w), ..vz((xn + 1.0) * size / 2.0, (1.0 - yn) * size / 2.0, z, [200.0, 100.0, 50.0]) }
}

#[test]
fn reference_draws_a_triangle_through_the_eye_plane_like_an_eye_space_clip() {
    // A long triangle from in front of the camera to behind it, at generic
    // coordinates so that no pixel centre lies exactly on one of its edges (the
    // two clipping paths round differently).
    let tri = [[-3.1, -1.0, -4.3], [2.9, -1.0, -3.7], [0.3, -1.0, 6.1]];
    let size = 64.0;
    let got = one_sized(vec![tri.map(|p| project(p, size))], size as u32);
    // Independent path: clip in eye space at z_eye = -1e-6 (in front), then project.
    let mut poly: Vec<[f64; 3]> = Vec::new();
    for i in 0..3 {
        let (a, b) = (tri[i], tri[(i + 1) % 3]);
        let (da, db) = (-a[2] - 1e-6, -b[2] - 1e-6);
        if da >= 0.0 {
            poly.push(a);
        }
        if (da >= 0.0) != (db >= 0.0) {
            let t = da / (da - db);
            poly.push(std::array::from_fn(|k| a[k] + t * (b[k] - a[k])));
        }
    }
    let fan: Vec<Triangle> =
        (1..poly.len() - 1).map(|i| [poly[0], poly[i], poly[i + 1]].map(|p| project(p, size))).collect();
    let want = one_sized(fan, size as u32);
    let differ = got.written.iter().zip(&want.written).filter(|(a, b)| a != b).count();
    assert_eq!(differ, 0, "coverage differs from the eye-space clip in {differ} pixels");
    assert!(got.written.iter().filter(|&&w| w).count() > 200, "the visible part should be drawn");
    // Nothing was painted above the horizon: the floor (y = -1) lies below the eye.
    for (i, &wrote) in got.written.iter().enumerate() {
        assert!(!(wrote && i / 64 < 32), "pixel ({}, {}) above the horizon was painted", i % 64, i / 64);
    }
}

fn one_sized(tris: Vec<Triangle>, size: u32) -> reference::Frame {
    render(
        &Trilist { width: size, height: size, triangles: tris, textures: Vec::new() },
        &Options::default(),
        &mut |_| {},
    )
    .0
}

/// A golden reference reproduces a constant attribute exactly: a triangle at z = 1 never
/// passes LESS against the 1.0 clear, one at z = 0 writes depth 0 exactly, and of two
/// overlapping triangles at one z the first keeps every pixel; a constant colour comes out
/// exactly, screen-linear or perspective-correct.
#[test]
fn reference_constant_attributes_are_exact() {
    let odd = [(3.3, 1.7), (637.9, 13.1), (91.1, 478.3)];
    let at = |z: f64, rgb: [f64; 3]| -> Triangle { odd.map(|(x, y)| vz(x, y, z, rgb)) };
    let draw = |tris: Vec<Triangle>| {
        let list = Trilist { width: 640, height: 480, triangles: tris, textures: Vec::new() };
        render(&list, &Options::default(), &mut |_| {})
    };
    let (frame, stats) = draw(vec![at(1.0, [1.0; 3])]);
    assert!(stats.fragments > 100_000);
    assert_eq!(stats.pixels_written, 0, "z = 1 is never less than the 1.0 clear");
    assert!(frame.depth.iter().all(|&d| d == 1.0));

    let grey = [100.3, 7.7, 255.0];
    let (frame, stats) = draw(vec![at(0.0, grey), at(0.0, [0.0; 3])]);
    assert_eq!(stats.pixels_written, stats.fragments / 2, "the second triangle at the same z loses everywhere");
    for i in (0..frame.depth.len()).filter(|&i| frame.written[i]) {
        assert_eq!(frame.depth[i], 0.0);
        assert_eq!(frame.color[i], grey);
        assert_eq!(frame.writer[i], 0);
    }

    // Perspective-correct: w differs per vertex, colour and z constant.
    let mut t = at(0.5, grey);
    for (v, w) in t.iter_mut().zip([1.0, 7.0, 300.0]) {
        v.w = Some(w);
    }
    fragments(&t, 640, 480, &Options::default(), |f| {
        assert_eq!((f.z, f.rgb), (0.5, grey), "at ({}, {})", f.x, f.y);
    });
}
