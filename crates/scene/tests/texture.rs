//! Textured scenes: an OBJ's `vt` and its material's `map_Kd`, a scene object's
//! `texture`, the trilist's version 2, and their errors, each naming the file and the rule.

use scene::{Input, Mesh, Scene, Trilist};
use std::path::{Path, PathBuf};

fn textured_dir() -> PathBuf {
    PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../../scenes/textured"))
}

/// Writes `files` (name, bytes) into a fresh scratch folder.
fn scratch(files: &[(&str, &[u8])]) -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    for (name, bytes) in files {
        std::fs::write(dir.path().join(name), bytes).unwrap();
    }
    dir
}

/// A PNG of `w` x `h` grey texels.
fn png(w: u32, h: u32) -> Vec<u8> {
    let img = image::RgbImage::from_pixel(w, h, image::Rgb([128, 128, 128]));
    let mut bytes = std::io::Cursor::new(Vec::new());
    img.write_to(&mut bytes, image::ImageOutputFormat::Png).unwrap();
    bytes.into_inner()
}

const QUAD: &str =
    "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 2 0\nvt 2 1\nvt 0 1\nusemtl a\nf 1/1 2/2 3/3 4/4\n";

#[test]
fn an_obj_takes_its_coordinates_from_vt_and_its_image_from_map_kd() {
    let mesh = Mesh::load_obj(&textured_dir().join("crate.obj")).unwrap();
    assert_eq!(mesh.textures, [textured_dir().join("crate.png")]);
    assert!(mesh.has_uv && mesh.triangles.iter().flatten().all(|v| v.texture == Some(0)));
    mesh.check_closed().unwrap();
    // The front face (+z): f 5/1/1 6/2/1 7/3/1 8/4/1, a fan of two triangles.
    let front = mesh.triangles[0];
    assert_eq!(front.map(|v| v.position), [[-1.0, -1.0, 1.0], [1.0, -1.0, 1.0], [1.0, 1.0, 1.0]]);
    assert_eq!(front.map(|v| v.uv), [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]]);
    // Coordinates beyond [0, 1] are kept (the sampler wraps them).
    let d = scratch(&[("q.obj", QUAD.as_bytes()), ("m.mtl", b"newmtl a\nmap_Kd t.png\n"), ("t.png", &png(4, 4))]);
    let quad = Mesh::load_obj(&d.path().join("q.obj")).unwrap();
    assert_eq!(quad.triangles[0][1].uv, [2.0, 0.0]);
    // Without materials (from text) the coordinates stay, with no image.
    let text = Mesh::from_obj_text(QUAD).unwrap();
    assert_eq!((text.textures.len(), text.triangles[1][2].uv, text.triangles[1][2].texture), (0, [0.0, 1.0], None));
    // Materials with their own images texture their own faces; one without draws plain.
    let three = format!("{QUAD}usemtl b\nf 1/1 3/3 4/4\nusemtl c\nf 1/1 2/2 4/4\n");
    let mtl = b"newmtl a\nmap_Kd t.png\nnewmtl b\nmap_Kd u.png\nnewmtl c\nKd 1 0 0\n";
    let d = scratch(&[("q.obj", three.as_bytes()), ("m.mtl", mtl)]);
    let mesh = Mesh::load_obj(&d.path().join("q.obj")).unwrap();
    assert_eq!(mesh.textures, [d.path().join("t.png"), d.path().join("u.png")]);
    let of: Vec<Option<u16>> = mesh.triangles.iter().map(|t| t[0].texture).collect();
    assert_eq!(of, [Some(0), Some(0), Some(1), None]);
}

#[test]
fn obj_texture_errors_name_the_file_and_the_rule() {
    let no_vt = QUAD.replace("f 1/1 2/2 3/3 4/4", "f 1 2 3 4");
    let d = scratch(&[("q.obj", no_vt.as_bytes()), ("m.mtl", b"newmtl a\nmap_Kd t.png\n")]);
    let e = Mesh::load_obj(&d.path().join("q.obj")).unwrap_err().to_string();
    assert!(e.contains("q.obj") && e.contains("not every face has texture coordinates (vt)"), "{e}");
    let d = scratch(&[("q.obj", QUAD.as_bytes())]);
    let e = Mesh::load_obj(&d.path().join("q.obj")).unwrap_err().to_string();
    assert!(e.contains("q.obj") && e.contains("material library cannot be read"), "{e}");
}

/// A scene of one object, `object` its JSON, in `dir`.
fn scene_in(dir: &Path, object: &str) -> Result<Scene, String> {
    let text = format!(
        r#"{{"width": 32, "height": 24, "camera": {{"eye": [0, 0, 5], "target": [0, 0, 0], "fov_y_deg": 45, "near": 1, "far": 10}},
        "lights": {{"ambient": [1, 1, 1]}}, "objects": [{object}]}}"#
    );
    let path = dir.join("s.json");
    std::fs::write(&path, text).unwrap();
    Scene::load(&path).map_err(|e| e.to_string())
}

#[test]
fn a_scene_object_names_its_texture_and_state() {
    let d = scratch(&[("t.png", &png(8, 4)), ("odd.png", &png(3, 4))]);
    let s = scene_in(d.path(), r#"{"model": "cube", "texture": {"image": "t.png", "sampler": {"wrap_s": "clamp_to_edge", "mip": "linear"}, "env": "decal"}}"#).unwrap();
    let t = &s.objects[0].textures[0];
    assert_eq!(
        (t.sampler.wrap_s, t.sampler.mip, t.env),
        (texture::Wrap::ClampToEdge, texture::MipMode::Linear, texture::EnvMode::Decal)
    );
    assert_eq!((t.mips.levels().len(), t.mips.base().width()), (4, 8));
    assert_eq!(t.format, texture::TexelFormat::Rgba8888);
    // RGB565 stores grey 128 as 16 of 31 red and blue and 32 of 63 green.
    let s = scene_in(d.path(), r#"{"model": "cube", "texture": {"image": "t.png", "format": "rgb565"}}"#).unwrap();
    let texel = s.objects[0].textures[0].mips.base().texel(0, 0);
    assert_eq!(texel, [16.0 / 31.0, 32.0 / 63.0, 16.0 / 31.0, 1.0]);
    // Every vertex of the trilist names the one texture; s, t within the face's [0, 1].
    let list = s.to_trilist().unwrap();
    assert_eq!(list.textures.len(), 1);
    assert!(list
        .triangles
        .iter()
        .flatten()
        .all(|v| v.tex.is_some_and(|x| x.texture == 0 && (0.0..=1.0).contains(&x.s))));
    for (object, want) in [
        (r#"{"model": "cube", "texture": {"sampler": {}}}"#, &["objects[0].texture: no image"][..]),
        (r#"{"model": "cube", "texture": {"image": "none.png"}}"#, &["objects[0].texture", "none.png"]),
        (r#"{"model": "cube", "texture": {"image": "odd.png"}}"#, &["odd.png", "powers of two", "3x4"]),
        (
            r#"{"model": "cube", "texture": {"image": "t.png", "sampler": {"wrap": "repeat"}}}"#,
            &["unknown field `wrap`"],
        ),
        (r#"{"model": "cube", "texture": {"image": "t.png", "env": "glow"}}"#, &["unknown variant `glow`"]),
    ] {
        let e = scene_in(d.path(), object).unwrap_err();
        assert!(e.contains("s.json"), "{e}");
        for w in want {
            assert!(e.contains(w), "{object}: {e} should name {w}");
        }
    }
}

#[test]
fn each_material_textures_its_own_faces_through_the_geometry_stage() {
    let three = format!("{QUAD}usemtl b\nf 1/1 3/3 4/4\nusemtl c\nf 1/1 2/2 4/4\n");
    let mtl = b"newmtl a\nmap_Kd t.png\nnewmtl b\nmap_Kd u.png\nnewmtl c\nKd 1 0 0\n";
    let d = scratch(&[("q.obj", three.as_bytes()), ("m.mtl", mtl), ("t.png", &png(4, 4)), ("u.png", &png(2, 8))]);
    let s = scene_in(d.path(), r#"{"obj": "q.obj", "transform": {"translate": [-0.5, -0.5, 0]}}"#).unwrap();
    assert_eq!(s.objects[0].textures.len(), 2);
    let list = s.to_trilist().unwrap();
    assert_eq!(list.textures.iter().map(|t| t.mips.base().height()).collect::<Vec<_>>(), [4, 8]);
    let units: Vec<Option<u16>> = list.triangles.iter().map(|t| t[0].tex.map(|x| x.texture)).collect();
    assert_eq!(units, [Some(0), Some(0), Some(1), None]);
    // The scene's image in place of the materials': every triangle, one texture.
    let s = scene_in(d.path(), r#"{"obj": "q.obj", "texture": {"image": "u.png"}}"#).unwrap();
    let list = s.to_trilist().unwrap();
    assert_eq!(list.textures.len(), 1);
    assert!(list.triangles.iter().all(|t| t[0].tex.is_some_and(|x| x.texture == 0)));
    // ... which needs the mesh's own coordinates.
    let flat = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    std::fs::write(d.path().join("flat.obj"), flat).unwrap();
    let e = scene_in(d.path(), r#"{"obj": "flat.obj", "texture": {"image": "u.png"}}"#).unwrap_err();
    assert!(e.contains("objects[0].texture: the mesh has no texture coordinates"), "{e}");
}

#[test]
fn mip_levels_given_one_by_one_load_and_travel_in_the_trilist() {
    let s = Scene::load(&textured_dir().join("mip-levels.json")).unwrap();
    let list = s.to_trilist().unwrap();
    // Five cubes, one texture of seven levels.
    assert_eq!(list.textures.len(), 1);
    assert_eq!(list.textures[0].images.len(), 7);
    assert_eq!(list.textures[0].mips.levels()[3].width(), 8);
    let json = list.to_json();
    assert!(json.contains(r#""levels":["#) && !json.contains(r#""image""#));
    let back = Trilist::from_value(&serde_json::from_str(&json).unwrap(), Path::new(".")).unwrap();
    assert_eq!(back, list);
    let d = scratch(&[("a.png", &png(4, 4)), ("b.png", &png(2, 2)), ("c.png", &png(1, 1)), ("x.png", &png(2, 1))]);
    for (texture, want) in [
        (r#"{"image": "a.png", "levels": ["a.png"]}"#, "not both"),
        (r#"{"levels": []}"#, "\"levels\" is empty"),
        (r#"{"levels": ["a.png", "x.png", "c.png"]}"#, "mip level 1 is 2x1; level 1 of a 4x4 texture is 2x2"),
        (r#"{"levels": ["a.png", "b.png"]}"#, "2 mip levels given; a 4x4 texture has 3"),
    ] {
        let e = scene_in(d.path(), &format!(r#"{{"model": "cube", "texture": {texture}}}"#)).unwrap_err();
        assert!(e.contains("objects[0].texture") && e.contains(want), "{texture}: {e}");
    }
    scene_in(d.path(), r#"{"model": "cube", "texture": {"levels": ["a.png", "b.png", "c.png"]}}"#).unwrap();
}

#[test]
fn trilist_version_2_carries_textures_and_version_1_still_reads() {
    let s = Scene::load(&textured_dir().join("crate.json")).unwrap();
    let list = s.to_trilist().unwrap();
    assert!(list.is_textured());
    let json = list.to_json();
    assert!(json.starts_with(r#"{"version":2,"#), "{}", &json[..40]);
    let back = Trilist::from_value(&serde_json::from_str(&json).unwrap(), Path::new(".")).unwrap();
    assert_eq!(back, list);
    // An untextured list stays version 1.
    let v1 = Trilist::from_json(r#"{"width":4,"height":4,"triangles":[[[0,0,0,0,0,0],[4,0,0,0,0,0],[0,4,0,0,0,0]]]}"#)
        .unwrap();
    assert!(!v1.is_textured() && !v1.to_json().contains("version"));
    let d = scratch(&[("t.png", &png(2, 2))]);
    let head = r#"{"version":2,"width":4,"height":4,"textures":[{"image":"t.png"}],"triangles":"#;
    let file = |tris: &str| {
        let path = d.path().join("l.json");
        std::fs::write(&path, format!("{head}{tris}}}")).unwrap();
        Input::load(&path).map(|_| ()).map_err(|e| e.to_string())
    };
    file("[[[0,0,0,0,0,0,1,0,0,0],[4,0,0,0,0,0,1,1,0,0],[0,4,0,0,0,0,1,0,1,0]]]").unwrap();
    for (tris, want) in [
        (
            "[[[0,0,0,0,0,0,1,0,0,1],[4,0,0,0,0,0,1,1,0,1],[0,4,0,0,0,0,1,0,1,1]]]",
            "texture 1 is not one of the file's 1 textures",
        ),
        ("[[[0,0,0,0,0,0,1,0,0,0],[4,0,0,0,0,0],[0,4,0,0,0,0,1,0,1,0]]]", "the three name the same texture"),
        ("[[[0,0,0,0,0,0,1,0,0],[4,0,0,0,0,0],[0,4,0,0,0,0]]]", "has 9 values"),
    ] {
        let e = file(tris).unwrap_err();
        assert!(e.contains("l.json") && e.contains(want), "{tris}: {e}");
    }
    let e = Trilist::from_json(r#"{"version":3,"width":4,"height":4,"triangles":[]}"#).unwrap_err().to_string();
    assert!(e.contains("versions 1 and 2"), "{e}");
    let e = Trilist::from_json(r#"{"width":4,"height":4,"textures":[],"triangles":[]}"#).unwrap_err().to_string();
    assert!(e.contains("unknown key \"textures\""), "{e}");
}

#[test]
fn every_shipped_textured_scene_draws_textured() {
    let scenes = scene::shipped::textured().unwrap();
    assert!(scenes.len() >= 2, "{scenes:?}");
    for path in scenes {
        let list = Scene::load(&path).unwrap().to_trilist().unwrap();
        assert!(list.is_textured(), "{}", path.display());
        let draw = |list: &Trilist| reference::render(list, &reference::Options::default(), &mut |_| {}).0;
        let textured = draw(&list);
        // The same triangles untextured: the texture changes most pixels drawn.
        let mut plain = list.clone();
        plain.triangles.iter_mut().flatten().for_each(|v| v.tex = None);
        let plain = draw(&plain);
        let written = textured.written.iter().filter(|&&w| w).count();
        let changed =
            (0..textured.color.len()).filter(|&i| textured.written[i] && textured.color[i] != plain.color[i]).count();
        assert!(written > 1000 && changed > written / 2, "{}: {changed} of {written} pixels textured", path.display());
    }
}

#[test]
fn each_texture_environment_combines_the_lit_colour_and_the_texel_as_opengl_does() {
    // A cube face-on, lit fully (ambient 0.55 and a head-on light 0.45): the fragment colour
    // Cf is the object's colour; at the screen's centre the texture's yellow disc, alpha 1.
    let badge = std::fs::read(textured_dir().join("badge.png")).unwrap();
    let d = scratch(&[("badge.png", &badge)]);
    let cf: [f64; 3] = [90.0, 140.0, 230.0];
    let cs: [f64; 3] = [250.0, 220.0, 40.0];
    let want = |mode: &str| -> [f64; 3] {
        std::array::from_fn(|c| match mode {
            "replace" | "decal" => cs[c],
            "modulate" => cf[c] * cs[c] / 255.0,
            "blend" => cf[c] * (1.0 - cs[c] / 255.0),
            _ => (cf[c] + cs[c]).min(255.0),
        })
    };
    for mode in ["replace", "modulate", "decal", "blend", "add"] {
        let text = format!(
            r#"{{"width": 32, "height": 24, "camera": {{"eye": [0, 0, 5], "target": [0, 0, 0], "fov_y_deg": 45, "near": 1, "far": 10}},
            "lights": {{"ambient": [0.55, 0.55, 0.55], "directional": [{{"direction": [0, 0, -1], "color": [0.45, 0.45, 0.45]}}]}},
            "objects": [{{"model": "cube", "color": [90, 140, 230], "texture": {{"image": "badge.png", "env": "{mode}"}}}}]}}"#
        );
        let path = d.path().join("s.json");
        std::fs::write(&path, text).unwrap();
        let list = Scene::load(&path).unwrap().to_trilist().unwrap();
        let frame = reference::render(&list, &reference::Options::default(), &mut |_| {}).0;
        let got = frame.color[12 * 32 + 16];
        assert!(
            got.iter().zip(want(mode)).all(|(g, w)| (g - w).abs() < 1e-9),
            "{mode}: {got:?} against {:?}",
            want(mode)
        );
    }
}
