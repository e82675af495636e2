//! The geometry stage end to end: scenes drawn by the reference rasterizer.

use reference::{Cull, Frame, Options};
use scene::{guard_band, Scene};
use serde_json::{json, Value};
use std::path::{Path, PathBuf};

fn scene(v: &Value) -> Scene {
    Scene::from_value(v, Path::new(".")).unwrap_or_else(|e| panic!("{e}\n{v:#}"))
}

fn render(s: &Scene) -> Frame {
    let list = s.to_trilist().unwrap();
    let cull = if s.cull_back { Cull::Back } else { Cull::None };
    reference::render(&list, &Options { cull, background: s.background, ..Options::default() }, &mut |_| {}).0
}

fn at(f: &Frame, x: u32, y: u32) -> usize {
    (y * f.width + x) as usize
}

/// The unit cube [-1, 1]^3 seen head-on from (0, 0, L): its front face z = 1,
/// at distance d = L - 1, is a square of half-size s = cot(fov/2) H / (2 d)
/// pixels about the screen centre; the side faces project inside it.
#[test]
fn cube_head_on_covers_the_analytic_square() {
    let (w, h, fov, l) = (200u32, 150u32, 40.0f64, 6.0f64);
    let s = scene(&json!({
        "width": w, "height": h,
        "camera": {"eye": [0, 0, l], "target": [0, 0, 0], "fov_y_deg": fov, "near": 1, "far": 20},
        "lights": {"ambient": [0.25, 0.25, 0.25], "directional": [{"direction": [0, 0, -1], "color": [0.5, 0.5, 0.5]}]},
        "objects": [{"model": "cube", "color": [200, 100, 40]}]
    }));
    let frame = render(&s);
    let half = (fov.to_radians() / 2.0).tan().recip() * h as f64 / (2.0 * (l - 1.0));
    let side = 2.0 * half;
    let count = frame.written.iter().filter(|&&b| b).count() as f64;
    // Within one pixel row along each of the four edges.
    assert!((count - side * side).abs() <= 4.0 * side, "covered {count}, analytic area {}", side * side);
    // Exactly: the pixels whose centres lie inside the square (none lies on an edge here).
    let centres = |c: f64| ((c - half - 0.5).ceil() as u32, (c + half - 0.5).floor() as u32);
    let ((x0, x1), (y0, y1)) = (centres(w as f64 / 2.0), centres(h as f64 / 2.0));
    for y in 0..h {
        for x in 0..w {
            let want = (x0..=x1).contains(&x) && (y0..=y1).contains(&y);
            assert_eq!(frame.written[at(&frame, x, y)], want, "pixel ({x}, {y}); square [{x0}, {x1}] x [{y0}, {y1}]");
        }
    }
    // The face looks straight at the light: colour * (0.25 + 0.5).
    let c = frame.rgb8()[at(&frame, w / 2, h / 2)];
    assert_eq!(c, [150, 75, 30]);
}

fn mirror_scene(model: &str, rotate_y: f64) -> Value {
    json!({
        "width": 160, "height": 120,
        "background": [10, 20, 30],
        "camera": {"eye": [0, 2.5, 6], "target": [0, 0, 0], "fov_y_deg": 40, "near": 1, "far": 20},
        "lights": {"ambient": [0.2, 0.2, 0.2], "directional": [{"direction": [0, -1, -1], "color": [0.8, 0.7, 0.6]}]},
        "objects": [{"model": model, "color": [220, 180, 90], "transform": {"rotate_deg": [0, rotate_y, 0], "scale": 1.3}}]
    })
}

/// Pixels (x, y) and (W-1-x, y) whose coverage differs, and the largest colour
/// difference (8-bit) between mirrored written pixels.
fn asymmetry(f: &Frame) -> (usize, u8) {
    let rgb = f.rgb8();
    let (mut coverage, mut colour) = (0, 0u8);
    for y in 0..f.height {
        for x in 0..f.width / 2 {
            let (a, b) = (at(f, x, y), at(f, f.width - 1 - x, y));
            if f.written[a] != f.written[b] {
                coverage += 1;
            } else if f.written[a] {
                colour = colour.max((0..3).map(|c| rgb[a][c].abs_diff(rgb[b][c])).max().unwrap());
            }
        }
    }
    (coverage, colour)
}

/// A scene symmetric about the plane x = 0 (camera and light in it, the cube
/// turned 45 degrees to show two faces) renders as its own mirror image.
#[test]
fn symmetric_scene_renders_symmetric() {
    let frame = render(&scene(&mirror_scene("cube", 45.0)));
    let written = frame.written.iter().filter(|&&b| b).count();
    assert!(written > 2000, "the cube covers only {written} pixels");
    assert_eq!(asymmetry(&frame), (0, 0), "coverage mismatches, largest colour difference");
    // The lathe models are mirror-symmetric as surfaces (their quads are split
    // along one diagonal, so Gouraud colours need not be): coverage must be.
    for model in ["sphere", "cone", "torus", "pawn"] {
        let (coverage, _) = asymmetry(&render(&scene(&mirror_scene(model, 0.0))));
        assert_eq!(coverage, 0, "{model}: pixels whose mirror image differs in coverage");
    }
}

/// A mirroring transform keeps front faces front: with back faces culled, the
/// cube mirrored in x and turned -30 degrees draws the mirror image of the cube
/// turned +30 degrees (camera and light are symmetric about x = 0). Reversed
/// winding would leave the back faces, which cover the same silhouette of a
/// convex solid but are lit differently.
#[test]
fn mirrored_object_keeps_its_front_faces() {
    let mut v = mirror_scene("cube", 30.0);
    v["cull"] = json!("back");
    let plain = render(&scene(&v));
    v["objects"][0]["transform"]["scale"] = json!([-1.3, 1.3, 1.3]);
    v["objects"][0]["transform"]["rotate_deg"] = json!([0, -30, 0]);
    let mirrored = render(&scene(&v));
    assert!(plain.written.iter().filter(|&&b| b).count() > 2000);
    let (plain_rgb, mirrored_rgb) = (plain.rgb8(), mirrored.rgb8());
    for y in 0..plain.height {
        for x in 0..plain.width {
            let (a, b) = (at(&plain, x, y), at(&mirrored, plain.width - 1 - x, y));
            assert_eq!(plain.written[a], mirrored.written[b], "pixel ({x}, {y})");
            let diff = (0..3).map(|c| plain_rgb[a][c].abs_diff(mirrored_rgb[b][c])).max().unwrap();
            assert!(diff <= 1, "pixel ({x}, {y}): {:?} vs mirrored {:?}", plain_rgb[a], mirrored_rgb[b]);
        }
    }
}

/// A ground slab 100 units wide passes under and behind the camera: the
/// geometry stage clips it to the guard band and the reference draws a clean
/// floor below the horizon, one colour, nothing above.
#[test]
fn ground_passing_under_the_camera_renders_without_garbage() {
    let s = scene(&json!({
        "width": 160, "height": 120,
        "camera": {"eye": [0, 0, 0], "target": [0, 0, -1], "fov_y_deg": 60, "near": 0.1, "far": 100},
        "lights": {"ambient": [0.2, 0.2, 0.2], "directional": [{"direction": [0, -1, 0]}]},
        "objects": [{"model": "cube", "color": [100, 150, 200], "transform": {"translate": [0, -1, 0], "scale": [50, 0.01, 50]}}]
    }));
    let list = s.to_trilist().unwrap();
    let band = guard_band(s.width, s.height);
    for v in list.triangles.iter().flatten() {
        assert!(v.w.unwrap() > 0.0, "{v}");
        assert!(v.x >= band.x_min && v.x <= band.x_max && v.y >= band.y_min && v.y <= band.y_max, "{v}");
        assert!(v.z >= band.z_min && v.z <= band.z_max, "{v}");
    }
    let frame = render(&s);
    let rgb = frame.rgb8();
    // The top face at y = -0.99 meets the far edge z = -50 at y_ndc = -0.99/50 * cot(30 deg):
    // about 1.5 pixels under the centre row; every row from 4 below it on is all floor.
    for y in 0..frame.height {
        for x in 0..frame.width {
            let i = at(&frame, x, y);
            if y < frame.height / 2 {
                assert!(!frame.written[i], "sky pixel ({x}, {y}) written");
            }
            if y >= frame.height / 2 + 4 {
                assert!(frame.written[i], "floor pixel ({x}, {y}) missing");
            }
            if frame.written[i] {
                assert_eq!(rgb[i], [120, 180, 240], "pixel ({x}, {y})");
            }
        }
    }
}

fn shipped_scenes() -> Vec<PathBuf> {
    scene::shipped::all().unwrap_or_else(|e| panic!("{}: {e}", scene::shipped::dir().display()))
}

/// Every shipped scene loads, stays in the guard band, and draws something
/// sizeable; its OBJ meshes are closed and wound outward.
#[test]
fn shipped_scenes_load_and_render() {
    let names: Vec<String> =
        shipped_scenes().iter().map(|p| p.file_stem().unwrap().to_string_lossy().into_owned()).collect();
    for want in ["all", "clip", "cone", "cube", "house", "knot", "pawn", "sphere", "torus"] {
        assert!(names.iter().any(|n| n == want), "scenes/{want}.json missing: {names:?}");
    }
    for path in shipped_scenes() {
        let s = Scene::load(&path).unwrap_or_else(|e| panic!("{e}"));
        for o in &s.objects {
            o.mesh.check_closed().unwrap_or_else(|e| panic!("{}: {:?}: {e}", path.display(), o.source));
        }
        let list = s.to_trilist().unwrap();
        let band = guard_band(s.width, s.height);
        for v in list.triangles.iter().flatten() {
            assert!(
                v.w.unwrap() > 0.0 && v.x >= band.x_min && v.x <= band.x_max && v.y >= band.y_min && v.y <= band.y_max
            );
        }
        let frame = render(&s);
        let written = frame.written.iter().filter(|&&b| b).count();
        let share = written as f64 / (s.width * s.height) as f64;
        assert!(share > 0.15, "{}: objects cover only {:.0}% of the frame", path.display(), share * 100.0);
    }
    let all = Scene::load(&scene::shipped::path("all")).unwrap();
    assert_eq!((all.width, all.height), (640, 480));
}
