//! The dense scene (`scenes/dense/dense.json`): a mesh of small triangles, the load that
//! sets a frame's time by the triangle rate.

use reference::{Cull, Options};
use scene::{guard_band, Scene};

/// It loads at 640 x 480 with at least 70,000 triangles, every one inside the guard band
/// (none clipped), its mesh closed and wound outward, and draws a sizeable part of the
/// frame in the reference rasterizer.
#[test]
fn dense_scene_loads_with_70k_triangles_at_640x480_and_renders() {
    let path = scene::shipped::dense();
    let s = Scene::load(&path).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!((s.width, s.height), (640, 480));
    for o in &s.objects {
        o.mesh.check_closed().unwrap_or_else(|e| panic!("{}: {:?}: {e}", path.display(), o.source));
    }
    let mesh_triangles: usize = s.objects.iter().map(|o| o.mesh.triangles.len()).sum();
    let list = s.to_trilist().unwrap();
    assert!(list.triangles.len() >= 70_000, "{} triangles", list.triangles.len());
    // Nothing crosses the guard band, so the list is the mesh, triangle for triangle.
    assert_eq!(list.triangles.len(), mesh_triangles);
    let band = guard_band(s.width, s.height);
    for v in list.triangles.iter().flatten() {
        assert!(v.w.unwrap() > 0.0 && v.x >= band.x_min && v.x <= band.x_max && v.y >= band.y_min && v.y <= band.y_max);
        assert!((0.0..=1.0).contains(&v.z), "{v:?}");
    }
    let cull = if s.cull_back { Cull::Back } else { Cull::None };
    let frame =
        reference::render(&list, &Options { cull, background: s.background, ..Options::default() }, &mut |_| {}).0;
    let share = frame.written.iter().filter(|&&b| b).count() as f64 / (s.width * s.height) as f64;
    assert!(share > 0.15, "the dense scene covers only {:.0}% of the frame", share * 100.0);
}
