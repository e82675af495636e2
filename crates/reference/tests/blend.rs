//! Framebuffer blending in the reference (paper 001 section II-5's six blend modes, OpenGL
//! 4.6 section 17.3.6): fragments that pass the depth test blend onto the colour already
//! drawn, in draw order; depth is written as without blending. Expected colours are worked
//! by hand from GL's equations.

use reference::{render, Cull, Frame, Options};
use scene::{Scene, Triangle, Trilist, Vertex};
use texture::BlendMode;

/// A triangle covering the whole 8 x 8 screen at depth `z`, colour `rgb`, blended by `mode`.
fn cover(z: f64, rgb: [f64; 3], mode: BlendMode) -> Triangle {
    let v = |x: f64, y: f64| Vertex { blend: mode, ..Vertex::new(x, y, z, rgb) };
    [v(-1.0, -1.0), v(30.0, -1.0), v(-1.0, 30.0)]
}

fn draw(triangles: Vec<Triangle>, background: [f64; 3]) -> Frame {
    let list = Trilist { width: 8, height: 8, triangles, ..Trilist::new(8, 8).unwrap() };
    render(&list, &Options { background, ..Options::default() }, &mut |_| {}).0
}

fn assert_close(got: [f64; 3], want: [f64; 3], what: &str) {
    assert!(got.iter().zip(want).all(|(g, w)| (g - w).abs() < 1e-9), "{what}: got {got:?}, want {want:?}");
}

#[test]
fn untextured_fragments_blend_in_draw_order_with_alpha_one() {
    let (bg, a, b) = ([10.0, 20.0, 30.0], [200.0, 100.0, 50.0], [100.0, 200.0, 102.0]);
    let cases: [(BlendMode, [f64; 3]); 6] = [
        (BlendMode::Opaque, b),
        // As = 1: b · 1 + a · 0.
        (BlendMode::Alpha, b),
        (BlendMode::Additive, [255.0, 255.0, 152.0]),
        (BlendMode::Multiply, [100.0 * 200.0 / 255.0, 200.0 * 100.0 / 255.0, 102.0 * 50.0 / 255.0]),
        (BlendMode::PremultipliedAlpha, b),
        (BlendMode::AlphaAdditive, [255.0, 255.0, 152.0]),
    ];
    for (mode, want) in cases {
        // a, opaque; then b, nearer, in `mode` onto it.
        let f = draw(vec![cover(0.5, a, BlendMode::Opaque), cover(0.25, b, mode)], bg);
        assert_close(f.color[9], want, &format!("{mode:?}"));
        assert_eq!((f.depth[9], f.writer[9]), (0.25, 1), "{mode:?}: the blended fragment writes depth");
    }
    // The first, additive onto the background.
    let f = draw(vec![cover(0.5, a, BlendMode::Additive)], bg);
    assert_close(f.color[0], [210.0, 120.0, 80.0], "additive onto the background");
}

#[test]
fn blended_fragments_pass_the_depth_test_first_and_write_depth() {
    let (bg, near, far) = ([0.0; 3], [40.0, 50.0, 60.0], [100.0, 100.0, 100.0]);
    // The nearer additive triangle first: it stores 40, 50, 60 and z 0.25, and the farther
    // one drawn after it fails LESS: neither blended nor written.
    let f = draw(vec![cover(0.25, near, BlendMode::Additive), cover(0.5, far, BlendMode::Additive)], bg);
    assert_close(f.color[20], near, "far after near");
    assert_eq!((f.depth[20], f.writer[20]), (0.25, 0));
    // Farther first: the nearer blends onto it.
    let f = draw(vec![cover(0.5, far, BlendMode::Opaque), cover(0.25, near, BlendMode::Additive)], bg);
    assert_close(f.color[20], [140.0, 150.0, 160.0], "near after far");
    // Equal depth fails LESS: no blending of a second pass at the same z.
    let f = draw(vec![cover(0.5, far, BlendMode::Opaque), cover(0.5, near, BlendMode::Additive)], bg);
    assert_close(f.color[20], far, "same depth");
}

/// The pixel whose centre is nearest the projection of world point (x, y, z) in
/// `scenes/blend/blend-modes.json`'s camera: eye (0, 0, 6) looking down -z, fov_y 30
/// degrees, 480 x 128.
fn pixel(x: f64, y: f64, z: f64) -> usize {
    let half_h = (6.0 - z) * 15f64.to_radians().tan();
    let (w, h) = (480.0, 128.0);
    let px = (x / (half_h * w / h) + 1.0) / 2.0 * w;
    let py = (1.0 - y / half_h) / 2.0 * h;
    py.floor() as usize * 480 + px.floor() as usize
}

#[test]
fn blend_modes_scene_draws_each_mode_as_gl_blends() {
    // Every mode over the two backdrops (upper (60, 120, 200), lower (235, 225, 200)); each
    // square shows badge.png by REPLACE: its disc (250, 220, 40) opaque, its ring
    // (200, 30, 160) at alpha 128/255, transparent black (alpha 0) outside the ring. The
    // square's side is 1.4 (a texel 1.4 / 64), its front at z = 0.02: the disc's texels lie
    // within 0.4375 of its centre, the ring's between 0.4375 and 0.6125.
    let path = scene::shipped::dir().join("blend/blend-modes.json");
    let s = Scene::load(&path).unwrap_or_else(|e| panic!("{e}"));
    let list = s.to_trilist().unwrap();
    assert!(list.is_blended() && list.is_textured());
    let opts = Options { cull: Cull::Back, ignore_w: false, background: s.background };
    let frame = render(&list, &opts, &mut |_| {}).0;

    let (up, low) = ([60.0, 120.0, 200.0], [235.0, 225.0, 200.0]);
    let (disc, ring) = ([250.0, 220.0, 40.0], [200.0, 30.0, 160.0]);
    let a = 128.0 / 255.0;
    // Per mode: the disc over the upper backdrop, the ring over the lower, the corner (alpha
    // 0, black) over the upper; GL's equations worked per channel.
    let add = |s: [f64; 3], d: [f64; 3]| -> [f64; 3] { std::array::from_fn(|k| (s[k] + d[k]).min(255.0)) };
    let cases: [(BlendMode, [[f64; 3]; 3]); 6] = [
        (BlendMode::Opaque, [disc, ring, [0.0; 3]]),
        // src As + dst (1 - As): the disc replaces, the corner leaves the backdrop.
        (
            BlendMode::Alpha,
            [disc, [(25600.0 + 29845.0) / 255.0, (3840.0 + 28575.0) / 255.0, (20480.0 + 25400.0) / 255.0], up],
        ),
        (BlendMode::Additive, [[255.0, 255.0, 240.0], [255.0, 255.0, 255.0], up]),
        // src dst.
        (
            BlendMode::Multiply,
            [
                [250.0 * 60.0 / 255.0, 220.0 * 120.0 / 255.0, 40.0 * 200.0 / 255.0],
                [200.0 * 235.0 / 255.0, 30.0 * 225.0 / 255.0, 160.0 * 200.0 / 255.0],
                [0.0; 3],
            ],
        ),
        // src + dst (1 - As).
        (BlendMode::PremultipliedAlpha, [disc, [255.0, 30.0 + 225.0 * 127.0 / 255.0, 255.0], up]),
        // src As + dst.
        (BlendMode::AlphaAdditive, [add(disc, up), [255.0, 30.0 * a + 225.0, 255.0], up]),
    ];
    let xs = [-4.75, -2.85, -0.95, 0.95, 2.85, 4.75];
    for ((mode, [on_disc, on_ring, on_corner]), x) in cases.into_iter().zip(xs) {
        for (what, (px, py), want) in
            [("disc", (x, 0.2), on_disc), ("ring", (x, -0.525), on_ring), ("corner", (x + 0.62, 0.62), on_corner)]
        {
            let i = pixel(px, py, 0.02);
            assert_close(frame.color[i], want, &format!("{mode:?} {what} at pixel {i}"));
        }
    }
    // The backdrops themselves, where no square is.
    assert_close(frame.color[pixel(-3.8, 1.0, -0.9)], up, "upper backdrop");
    assert_close(frame.color[pixel(-3.8, -1.0, -0.9)], low, "lower backdrop");
}
