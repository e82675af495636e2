//! The `edgepaint` command line, run as a process: good input renders, bad input
//! fails with a non-zero exit and a message naming the file and the problem,
//! never a panic.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn edgepaint(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_edgepaint")).args(args).output().expect("edgepaint runs")
}

/// A scratch folder for one test, under the target directory.
fn scratch(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("cli").join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn write(dir: &Path, name: &str, text: &str) -> String {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p.to_str().unwrap().to_string()
}

/// Runs `args`, expects failure, and checks stderr mentions every word of `want`.
fn fails_with(args: &[&str], want: &[&str]) {
    let out = edgepaint(args);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success(), "{args:?} should fail; stderr: {err}");
    assert!(!err.contains("panicked"), "{args:?} panicked: {err}");
    for w in want {
        assert!(err.contains(w), "{args:?}: stderr {err:?} should mention {w:?}");
    }
}

const SCENE_HEAD: &str = r#""camera": {"eye": [0, 0, 5], "target": [0, 0, 0], "fov_y_deg": 45, "near": 0.5, "far": 20},
    "lights": {"ambient": [0.2, 0.2, 0.2], "directional": [{"direction": [0, 0, -1]}]}"#;

#[test]
fn cli_bad_input_is_a_clear_error_naming_the_file() {
    let d = scratch("bad");
    let png = d.join("out.png");
    let out = png.to_str().unwrap();
    let tri = |v: &str| format!(r#"{{"width": 8, "height": 8, "triangles": [[{v}]]}}"#);
    let cases: Vec<(String, Vec<&str>)> = vec![
        (
            write(&d, "malformed.json", "{\"width\": 8, \"height\": "),
            vec!["malformed.json", "malformed JSON", "line 1"],
        ),
        (
            write(&d, "nan.json", &tri("[NaN,0,0,0,0,0],[1,0,0,0,0,0],[0,1,0,0,0,0]")),
            vec!["nan.json", "NaN is not a number"],
        ),
        (
            write(&d, "inf.json", &tri("[1e999,0,0,0,0,0],[1,0,0,0,0,0],[0,1,0,0,0,0]")),
            vec!["inf.json", "must be finite"],
        ),
        (
            write(&d, "arity.json", &tri("[0,0,0,0,0,0],[1,0,0,0,0,0]")),
            vec!["arity.json", "triangle 0", "has 2 vertices"],
        ),
        (
            write(&d, "values.json", &tri("[0,0,0,0,0],[1,0,0,0,0,0],[0,1,0,0,0,0]")),
            vec!["values.json", "vertex 0", "has 5 values"],
        ),
        (
            write(&d, "zero.json", r#"{"width": 0, "height": 8, "triangles": []}"#),
            vec!["zero.json", "width 0 is out of range"],
        ),
        (
            write(&d, "huge.json", r#"{"width": 100000, "height": 8, "triangles": []}"#),
            vec!["huge.json", "width 100000 is out of range"],
        ),
        (
            write(
                &d,
                "missing_obj.json",
                &format!(r#"{{"width": 64, "height": 64, {SCENE_HEAD}, "objects": [{{"obj": "nowhere.obj"}}]}}"#),
            ),
            vec!["missing_obj.json", "nowhere.obj", "no such file"],
        ),
        (
            write(
                &d,
                "scene_res.json",
                &format!(r#"{{"width": 100000, "height": 64, {SCENE_HEAD}, "objects": [{{"model": "cube"}}]}}"#),
            ),
            vec!["scene_res.json", "100000"],
        ),
        (
            write(
                &d,
                "nan_obj.json",
                &format!(r#"{{"width": 64, "height": 64, {SCENE_HEAD}, "objects": [{{"obj": "nan.obj"}}]}}"#),
            ),
            vec!["nan_obj.json", "nan.obj"],
        ),
        (write(&d, "neither.json", r#"{"width": 8, "height": 8}"#), vec!["neither.json", "neither a scene"]),
        (d.join("absent.json").to_str().unwrap().to_string(), vec!["absent.json", "no such file"]),
    ];
    write(&d, "nan.obj", "v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n");
    for (input, want) in &cases {
        fails_with(&["render", input, "-o", out], want);
        fails_with(&["render", input, "-o", out, "--engine", "scanline"], want);
    }
    // A trilist cannot be resized; a size must be sane.
    let ok = write(&d, "ok.json", &tri("[0,0,0,0,0,0],[8,0,0,0,0,0],[0,8,0,0,0,0]"));
    fails_with(&["render", &ok, "-o", out, "--size", "64x48"], &["ok.json", "--size applies to scenes"]);
    fails_with(
        &["render", concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/cube.json"), "-o", out, "--size", "0x48"],
        &["width 0 is out of range"],
    );
    // Impossible formats.
    let narrow = write(&d, "narrow.json", r#"{"xy": "S3.4"}"#);
    fails_with(
        &["render", &ok, "-o", out, "--engine", "scanline", "--formats", &narrow],
        &["narrow.json", "guard band"],
    );
    fails_with(&["render", &ok, "-o", out, "--engine", "vector", "--formats", "nope.json"], &["nope.json"]);
    // An unwritable output names the output.
    fails_with(&["render", &ok, "-o", d.join("no/such/dir/x.png").to_str().unwrap()], &["no/such/dir/x.png"]);
}

/// A textured scene (OBJ + MTL + PNG) draws on the float reference, its trilist (version
/// 2) draws the same image; the scanline and vector models texture it through
/// `texture_setup` and the texture unit, close to the reference; the engines that cannot
/// texture refuse it by name.
#[test]
fn cli_draws_textured_scenes_on_the_float_scanline_and_vector_engines() {
    let d = scratch("textured");
    let scene = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/textured/crate.json");
    let (a, b, tris) = (d.join("scene.png"), d.join("tris.png"), d.join("tris.json"));
    let o = edgepaint(&["render", scene, "--engine", "float", "-o", a.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let o = edgepaint(&["trilist", scene, "-o", tris.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(std::fs::read_to_string(&tris).unwrap().starts_with(r#"{"version":2,"#));
    let o = edgepaint(&["render", tris.to_str().unwrap(), "-o", b.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let (ia, ib) = (image::open(&a).unwrap().to_rgb8(), image::open(&b).unwrap().to_rgb8());
    // The crate's planks: many colours, not the flat lit colour of an untextured cube.
    let colours: std::collections::HashSet<[u8; 3]> = ia.pixels().map(|p| p.0).collect();
    assert!(colours.len() > 500, "{} colours", colours.len());
    // The trilist has no background: compare where the crate is.
    let bg = ia.get_pixel(0, 0).0;
    for (p, q) in ia.pixels().zip(ib.pixels()) {
        if p.0 != bg {
            assert_eq!(p, q);
        }
    }
    // The fixed-point engines: the same planks, within a few LSB on average where both drew
    // the crate (edges differ by the vertices' snapping).
    for engine in ["scanline", "vector"] {
        close_to_the_reference(&d, scene, engine, &ia, Some(bg), 15_000);
    }
    let out = d.join("x.out");
    let out = out.to_str().unwrap();
    for (cmd, what) in [
        (vec!["render", scene, "--engine", "se", "-o", out], "--engine se cannot texture or blend: 000's shading"),
        (vec!["render", scene, "--engine", "rtl", "--method", "vector", "-o", out], "the scanline method only"),
        (vec!["pack", scene, "-o", out], "gpu_top's command parser has no texture path"),
    ] {
        fails_with(&cmd, &["crate.json", what]);
    }
}

/// `scene` drawn by `engine` is `reference` within a few LSB on average where both drew
/// (every pixel when `bg` is `None`) and far from it on few channels; at least `pixels`
/// pixels compared.
fn close_to_the_reference(
    d: &Path,
    scene: &str,
    engine: &str,
    reference: &image::RgbImage,
    bg: Option<[u8; 3]>,
    pixels: usize,
) {
    let c = d.join(format!("{engine}.png"));
    let o = edgepaint(&["render", scene, "--engine", engine, "-o", c.to_str().unwrap()]);
    assert!(o.status.success(), "{engine}: {}", String::from_utf8_lossy(&o.stderr));
    let ic = image::open(&c).unwrap().to_rgb8();
    let both: Vec<(u8, u8)> = reference
        .pixels()
        .zip(ic.pixels())
        .filter(|(p, q)| bg.is_none_or(|bg| p.0 != bg && q.0 != bg))
        .flat_map(|(p, q)| p.0.into_iter().zip(q.0))
        .collect();
    let mean = both.iter().map(|&(p, q)| f64::from(p.abs_diff(q))).sum::<f64>() / both.len() as f64;
    let far = both.iter().filter(|&&(p, q)| p.abs_diff(q) > 32).count();
    println!("{scene} {engine}: {} channels, mean difference {mean:.3}, {far} beyond 32", both.len());
    assert!(both.len() > 3 * pixels && mean < 1.5 && far * 200 < both.len(), "{engine}: mean {mean}, {far} far");
}

/// The blend-mode scene (a textured badge by each of 001's six modes over two backdrops)
/// draws on the fixed-point engines as on the reference: they blend after the depth test.
#[test]
fn cli_blends_on_the_fixed_point_engines() {
    let d = scratch("blend");
    let scene = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/blend/blend-modes.json");
    let a = d.join("float.png");
    let o = edgepaint(&["render", scene, "--engine", "float", "-o", a.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let reference = image::open(&a).unwrap().to_rgb8();
    for engine in ["scanline", "vector"] {
        close_to_the_reference(&d, scene, engine, &reference, None, 40_000);
    }
}

#[test]
fn cli_accuracy_measures_the_texture_unit_on_a_textured_scene() {
    let d = scratch("texture-accuracy");
    let scene = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/textured/crate.json");
    let json = d.join("acc.json");
    let o = edgepaint(&["accuracy", scene, "--json", json.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(
        out.contains("(textured, Max level of detail)") && out.contains("| out of conformance tolerance | 0 |"),
        "{out}"
    );
    let report: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    assert_eq!(report["texture"]["failures"], 0);
    assert!(report["texture"]["pixels"].as_u64().unwrap() > 10_000);
    assert!(report["texture"]["psnr_db"].as_f64().unwrap() >= 40.0);
    // The pipelines measured on the lit colours: their coverage equals the reference's.
    assert_eq!(report["engines"][0]["method"], "scanline");
    // A formats file's texture object sets the unit's precisions; an impossible one is named.
    let coarse = d.join("coarse.json");
    std::fs::write(&coarse, r#"{"texture": {"subtexel": 2, "weight": 2}}"#).unwrap();
    let o = edgepaint(&["accuracy", scene, "--formats", coarse.to_str().unwrap(), "--lod", "exact"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(
        out.contains("(textured, Exact level of detail)") && !out.contains("| out of conformance tolerance | 0 |"),
        "{out}"
    );
    std::fs::write(&coarse, r#"{"texture": {"subtexel": 0}}"#).unwrap();
    fails_with(&["accuracy", scene, "--formats", coarse.to_str().unwrap()], &["coarse.json: texture: subtexel = 0"]);
}

#[test]
fn cli_renders_a_scene_and_its_trilist_to_the_same_image() {
    let d = scratch("good");
    let scene = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/sphere.json");
    let tris = d.join("tris.json");
    let o = edgepaint(&["trilist", scene, "-o", tris.to_str().unwrap(), "--size", "96x72"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    for engine in ["float", "scanline", "vector", "se"] {
        let (a, b) = (d.join(format!("{engine}-scene.png")), d.join(format!("{engine}-tris.png")));
        let mask = d.join(format!("{engine}-mask.png"));
        let o = edgepaint(&[
            "render",
            scene,
            "--size",
            "96x72",
            "-o",
            a.to_str().unwrap(),
            "--engine",
            engine,
            "--mask",
            mask.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let summary = String::from_utf8_lossy(&o.stdout);
        assert!(summary.contains("168 triangles in") && summary.contains("pixels written"), "{summary}");
        // The trilist carries no scene background or cull setting; sphere.json uses neither default-changing option.
        let o = edgepaint(&["render", tris.to_str().unwrap(), "-o", b.to_str().unwrap(), "--engine", engine]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let (ia, ib) = (image::open(&a).unwrap().to_rgb8(), image::open(&b).unwrap().to_rgb8());
        assert_eq!(ia.dimensions(), (96, 72));
        let m = image::open(&mask).unwrap().to_luma8();
        let covered = m.pixels().filter(|p| p.0[0] == 255).count();
        assert!(covered > 1000, "{engine}: the sphere should cover the middle of the frame, covered {covered}");
        // Same triangles, same engine: identical where the sphere is drawn.
        for (p, q) in m.pixels().zip(ia.pixels().zip(ib.pixels())) {
            if p.0[0] == 255 {
                assert_eq!(q.0, q.1, "{engine}");
            }
        }
    }
}

#[test]
fn cli_accuracy_writes_a_table_and_json() {
    let d = scratch("accuracy");
    let json = d.join("acc.json");
    let scene = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/cube.json");
    let o = edgepaint(&[
        "accuracy",
        scene,
        "--engine",
        "scanline,vector",
        "--size",
        "80x60",
        "--json",
        json.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let table = String::from_utf8_lossy(&o.stdout);
    assert!(table.contains("PSNR") && table.contains("vector (4 lanes)"), "{table}");
    let v: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    assert_eq!(v.as_array().unwrap().len(), 2);
    assert_eq!(v[0]["coverage_unexplained"], 0);
    assert!(v[1]["cycles"].as_u64().unwrap() > 0);
}

/// `render --engine rtl`'s frame time: (cycles, ms, MHz, where the clock comes from), read
/// off the summary's "N cycles (model::cycles[::se_frame]: N), frame time T ms at F MHz
/// (SOURCE)".
fn frame_time(summary: &str) -> (u64, f64, f64, String) {
    let (before, after) = summary.split_once(" cycles (model::cycles").expect("the cycles");
    let cycles = before.rsplit(' ').next().unwrap().parse().unwrap();
    let (_, t) = after.split_once("frame time ").expect("the frame time");
    let (ms, t) = t.split_once(" ms at ").unwrap();
    let (mhz, t) = t.split_once(" MHz (").unwrap();
    let source = t.split_once(')').unwrap().0;
    (cycles, ms.parse().unwrap(), mhz.parse().unwrap(), source.to_string())
}

/// `render --engine rtl --top raster_top` gives the frame's time beside its cycles: at the
/// default design, at raster_top's routed ECP5 clock (`sweep::clock::PIPELINE_MHZ`), cycles /
/// MHz.
#[test]
fn cli_render_rtl_reports_the_frame_time_at_the_routed_clock() {
    let d = scratch("rtl-frame-time");
    let png = d.join("rtl.png");
    let cube = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/cube.json");
    let args = ["render", cube, "--size", "64x48", "--engine", "rtl", "--top", "raster_top", "-o"];
    let out = edgepaint(&[&args[..], &[png.to_str().unwrap()]].concat());
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let (cycles, ms, mhz, source) = frame_time(&stdout);
    assert!(cycles > 1000, "{stdout}");
    assert_eq!((mhz, source.as_str()), (sweep::clock::PIPELINE_MHZ, "routed, ECP5"), "{stdout}");
    let want = cycles as f64 / (sweep::clock::PIPELINE_MHZ * 1000.0);
    assert!((ms - want).abs() <= 0.0005 + 1e-12, "{ms} ms reported, {cycles} cycles at {mhz} MHz are {want} ms");
}

/// `render` of the cube at 64 x 48 into `png` with `more` arguments, which must succeed:
/// the PNG's bytes and the summary.
fn render_cube(png: &std::path::Path, more: &[&str]) -> (Vec<u8>, String) {
    let cube = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/cube.json");
    let args = [&["render", cube, "--size", "64x48", "-o", png.to_str().unwrap()][..], more].concat();
    let out = edgepaint(&args);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    (std::fs::read(png).unwrap(), String::from_utf8_lossy(&out.stdout).to_string())
}

/// `render --engine rtl` draws a textured or blended scene through the textured
/// `raster_top` (`TEXTURE = 1`) and checks it against the textured scanline model: its PNG
/// is the scanline engine's. A top, method or parameter without a texture path is a clear
/// error.
#[test]
fn cli_render_rtl_draws_textured_and_blended_scenes() {
    let d = scratch("rtl-textured");
    let (rtl, model) = (d.join("rtl.png"), d.join("scanline.png"));
    for scene in ["textured/checker", "blend/blend-modes"] {
        let path = format!("{}/scenes/{scene}.json", env!("CARGO_MANIFEST_DIR"));
        let render = |png: &Path, engine: &str| {
            let out = edgepaint(&["render", &path, "--size", "96x64", "--engine", engine, "-o", png.to_str().unwrap()]);
            assert!(out.status.success(), "{scene}: {}", String::from_utf8_lossy(&out.stderr));
            (std::fs::read(png).unwrap(), String::from_utf8_lossy(&out.stdout).to_string())
        };
        let (got, summary) = render(&rtl, "rtl");
        assert!(summary.contains("with TEXTURE = 1"), "{summary}");
        assert!(summary.contains("image and depth equal to the textured scanline model's"), "{summary}");
        assert!(summary.contains("texture cache hit rate"), "{summary}");
        assert!(got == render(&model, "scanline").0, "{scene}: the rtl PNG is the scanline model's");
    }
    let checker = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/textured/checker.json");
    let o = rtl.to_str().unwrap();
    let base = ["render", checker, "-o", o, "--engine", "rtl"];
    fails_with(
        &[&base[..], &["--top", "gpu_top"]].concat(),
        &["checker.json", "--top gpu_top has no texture path yet"],
    );
    fails_with(&[&base[..], &["--method", "se"]].concat(), &["checker.json", "the scanline method only"]);
    fails_with(&[&base[..], &["--param", "K=3"]].concat(), &["checker.json", "default parameters (no --param)"]);
}

/// `render --engine rtl` draws through `gpu_top` by default: the scene packed into a vertex
/// buffer in memory, the core driven through its registers; its PNG is the scanline
/// model's and `raster_top`'s, its summary gives the bus traffic and the frame's cycles
/// from START to the interrupt (the clear's pixel writes among them). `--top gpu_top` where
/// gpu_top does not apply, and `--top` without `--engine rtl`, are clear errors.
#[test]
fn cli_render_rtl_draws_through_gpu_top() {
    let d = scratch("rtl-gpu-top");
    let cube = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/cube.json");
    let render = |name: &str, more: &[&str]| render_cube(&d.join(name), more);
    let (gpu, summary) = render("gpu.png", &["--engine", "rtl"]);
    assert!(summary.contains("rtl (gpu_top of size class 10"), "{summary}");
    assert!(summary.contains("STATUS, TRIANGLES, image and depth equal to model::gpu_top's"), "{summary}");
    assert!(summary.contains("3072 each among them"), "the clear of 64 x 48: {summary}");
    let cycles: u64 = summary.split(" cycles from START").next().unwrap().rsplit(' ').next().unwrap().parse().unwrap();
    assert!(cycles > 3072, "{summary}");
    let mhz = sweep::clock::GPU_TOP_MHZ;
    let at = format!("frame time {:.3} ms at {mhz:.1} MHz (gpu_top routed, ECP5)", cycles as f64 / (mhz * 1000.0));
    assert!(summary.contains(&at), "{at}: {summary}");
    let (scan, _) = render("scan.png", &["--engine", "scanline"]);
    let (raster, _) = render("raster.png", &["--engine", "rtl", "--top", "raster_top"]);
    assert!(gpu == scan && raster == scan, "gpu_top's, raster_top's and the model's PNG are one");
    let png = d.join("x.png");
    let o = png.to_str().unwrap();
    let base = ["render", cube, "--size", "64x48", "-o", o, "--engine", "rtl", "--top", "gpu_top"];
    fails_with(&[&base[..], &["--param", "K=3"]].concat(), &["--top gpu_top", "--param K", "--top raster_top"]);
    let custom = concat!(env!("CARGO_MANIFEST_DIR"), "/crates/rtl/custom-formats.json");
    fails_with(&[&base[..], &["--formats", custom]].concat(), &["--top gpu_top", "default formats"]);
    fails_with(&["render", cube, "-o", o, "--top", "gpu_top"], &["--top", "needs --engine rtl"]);
}

/// `render --engine rtl --method vector` draws through `raster_top` with `METHOD = 1` (004's
/// barycentric unit) with `--lanes` lanes (default 4, as the vector model's): its PNG is the
/// vector model's (perspective-correct here; with `--linear` screen-linear in
/// [`cli_render_rtl_draws_with_the_vector_method_linear`]), and its frame time at the routed
/// ECP5 clock of its lanes (`sweep::clock::vector_pipeline_mhz`: one and four routed); what
/// does not apply to it is a clear error.
#[test]
fn cli_render_rtl_draws_with_the_vector_method() {
    vector_frame_equals_the_model("rtl-vector", false, None);
    let d = scratch("rtl-vector-errors");
    let cube = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/cube.json");
    let png = d.join("x.png");
    let o = png.to_str().unwrap();
    let base = ["render", cube, "--size", "64x48", "-o", o, "--engine", "rtl", "--method", "vector"];
    fails_with(&[&base[..], &["--lanes", "16"]].concat(), &["--lanes 16", "1, 2, 4 or 8"]);
    fails_with(&[&base[..], &["--top", "gpu_top"]].concat(), &["gpu_top holds the scanline method"]);
    fails_with(&[&base[..], &["--param", "K=3"]].concat(), &["--param K", "no triangle_setup"]);
    fails_with(&["render", cube, "-o", o, "--method", "vector"], &["--method", "needs --engine rtl"]);
    let scanline = ["render", cube, "--size", "64x48", "-o", o, "--engine", "rtl", "--top", "raster_top"];
    fails_with(&[&scanline[..], &["--lanes", "4"]].concat(), &["--lanes", "the vector unit's (--method vector)"]);
    // The vector walk's chunks are aligned to the lanes: a power of two.
    fails_with(&["render", cube, "-o", o, "--engine", "vector", "--lanes", "3"], &["--lanes 3", "1, 2, 4"]);
}

/// `render --engine rtl --method vector` of the cube (`linear`: `--linear`; `lanes`: `--lanes`,
/// default 4) against the vector model's PNG, with the summary's method and frame time.
fn vector_frame_equals_the_model(dir: &str, linear: bool, lanes: Option<&str>) {
    let d = scratch(dir);
    let render = |name: &str, more: &[&str]| render_cube(&d.join(name), more);
    let mut more: Vec<&str> = if linear { vec!["--linear"] } else { vec![] };
    more.extend(lanes.map(|l| ["--lanes", l]).into_iter().flatten());
    let n = lanes.unwrap_or("4");
    let (rtl, summary) = render("rtl.png", &[&["--engine", "rtl", "--method", "vector"][..], &more].concat());
    assert!(summary.contains(&format!("METHOD = 1: cull_sort, vector with {n} lanes, pixel_out")), "{summary}");
    let model_name = if n == "1" { "vector (1 lane)".to_owned() } else { format!("vector ({n} lanes)") };
    assert!(summary.contains(&format!("image, depth and cycles equal to the {model_name} model's")), "{summary}");
    let (cycles, ms, mhz, source) = frame_time(&summary);
    let want_mhz = if n == "1" { sweep::clock::VECTOR_PIPELINE_MHZ } else { sweep::clock::VECTOR_PIPELINE_4_MHZ };
    assert_eq!((mhz, source.as_str()), (want_mhz, "routed, ECP5"), "{summary}");
    assert!((ms - cycles as f64 / (mhz * 1000.0)).abs() <= 0.0005 + 1e-12, "{summary}");
    let (model, _) = render(
        "model.png",
        &[&["--engine", "vector", "--lanes", n][..], if linear { &["--linear"][..] } else { &[] }].concat(),
    );
    assert!(rtl == model, "raster_top's vector PNG is the vector model's (linear: {linear}, {n} lanes)");
}

/// [`cli_render_rtl_draws_with_the_vector_method`] without perspective at one lane (the
/// soak's: the vector unit's own tests run without perspective in the test command, and this
/// is one more Verilated build of `raster_top`).
#[test]
#[ignore = "soak: scripts/soak.sh"]
fn cli_render_rtl_draws_with_the_vector_method_linear() {
    vector_frame_equals_the_model("rtl-vector-linear", true, Some("1"));
}

/// `render --engine rtl --method se` draws through `raster_top`'s SE back end (`METHOD =
/// 2`: 000's shading engines behind the scanline front end) in Verilator: its PNG is the SE
/// model's (`--engine se`), its summary says the cycles equal `model::cycles::se_frame`'s
/// and gives the frame time at the clock routed at one engine
/// (`sweep::clock::SE_PIPELINE_MHZ`). (Its Verilated model is the soak's; the errors are
/// [`cli_render_rtl_se_errors_are_clear`].)
#[test]
#[ignore = "long: scripts/soak.sh runs it"]
fn cli_render_rtl_draws_with_the_se_back_end() {
    let d = scratch("rtl-se");
    let render = |name: &str, more: &[&str]| render_cube(&d.join(name), more);
    // Five engines: the Verilated model the raster_top tests build.
    let (rtl, summary) = render("rtl.png", &["--engine", "rtl", "--method", "se", "--param", "ENGINES=5"]);
    assert!(summary.contains("METHOD = 2: the scanline front end, se_cmd and 5 shading engines"), "{summary}");
    assert!(summary.contains("image, depth and cycles equal to the se model's"), "{summary}");
    let (cycles, ms, mhz, source) = frame_time(&summary);
    assert_eq!((mhz, source.as_str()), (sweep::clock::SE_PIPELINE_MHZ, "one engine's, routed, ECP5"), "{summary}");
    assert!((ms - cycles as f64 / (mhz * 1000.0)).abs() <= 0.0005 + 1e-12, "{summary}");
    let (model, _) = render("model.png", &["--engine", "se"]);
    assert!(rtl == model, "raster_top's SE back end PNG is the se model's");
}

/// What does not apply to `render --engine rtl --method se` is a clear error.
#[test]
fn cli_render_rtl_se_errors_are_clear() {
    let d = scratch("rtl-se-errors");
    let cube = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/cube.json");
    let png = d.join("x.png");
    let o = png.to_str().unwrap();
    let base = ["render", cube, "--size", "64x48", "-o", o, "--engine", "rtl", "--method", "se"];
    fails_with(&[&base[..], &["--param", "ENGINES=3"]].concat(), &["3 engines", "1, 5 or 16"]);
    fails_with(&[&base[..], &["--param", "K=3"]].concat(), &["--param K", "ENGINES"]);
    fails_with(&[&base[..], &["--lanes", "4"]].concat(), &["--method se", "--lanes"]);
    let wide = ["render", cube, "--size", "1100x48", "-o", o, "--engine", "rtl", "--method", "se"];
    fails_with(&wide, &["size class 10", "1100x48"]);
    let five =
        ["render", cube, "--size", "400x48", "-o", o, "--engine", "rtl", "--method", "se", "--param", "ENGINES=5"];
    fails_with(&five, &["5 engines for a screen 400 columns wide"]);
}

/// Formats other than a size class's defaults: `emit --formats` writes the scanline units
/// at them (the manifest records them, the ports follow them), `render --engine rtl
/// --formats` draws through them, equal to the scanline model at those formats.
/// (`crates/rtl/custom-formats.json` is `rtl::custom`'s build, so nothing is recompiled
/// here; the test command builds without it, so this is the soak's.)
#[test]
#[cfg_attr(not(feature = "custom-formats"), ignore = "needs rtl::custom (feature custom-formats): scripts/soak.sh")]
fn cli_emits_and_renders_at_other_formats() {
    let d = scratch("formats");
    let custom = concat!(env!("CARGO_MANIFEST_DIR"), "/crates/rtl/custom-formats.json");
    let dir = d.join("hdl");
    let out = edgepaint(&["emit", "--unit", "raster_top", "--formats", custom, "-o", dir.to_str().unwrap()]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let manifest: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("manifest.json")).unwrap()).unwrap();
    let unit = &manifest["units"][0];
    assert_eq!(unit["formats"]["z"], "S1.24 [26] half-up", "{unit}");
    assert_eq!(unit["formats"]["xy"], "S11.3 [15] half-up", "{unit}");
    let width = |port: &str| {
        unit["ports"].as_array().unwrap().iter().find(|p| p["name"] == port).map(|p| p["width"].clone()).unwrap()
    };
    assert_eq!((width("mem$wr_z"), width("inp$v0_x"), width("inp$v0_c0")), (24.into(), 15.into(), 10.into()));

    let png = d.join("rtl.png");
    let cube = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/cube.json");
    let args = ["render", cube, "--size", "32x24", "--engine", "rtl", "--formats", custom, "-o"];
    let out = edgepaint(&[&args[..], &[png.to_str().unwrap()]].concat());
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(
        stdout.contains("formats of --formats")
            && stdout.contains("image, depth and cycles equal to the scanline model's"),
        "{stdout}"
    );
    // Formats that were never routed: the clock model's figure (printed to 0.1 MHz).
    let (cycles, ms, mhz, source) = frame_time(&stdout);
    assert_eq!(source, "modelled, ECP5", "{stdout}");
    let rel = ms * mhz * 1000.0 / cycles as f64 - 1.0;
    assert!(rel.abs() <= 0.05 / mhz + 0.0005 / ms, "{ms} ms at {mhz} MHz for {cycles} cycles");
    let scan = d.join("scanline.png");
    let args = ["render", cube, "--size", "32x24", "--engine", "scanline", "--formats", custom, "-o"];
    assert!(edgepaint(&[&args[..], &[scan.to_str().unwrap()]].concat()).status.success());
    assert_eq!(std::fs::read(&png).unwrap(), std::fs::read(&scan).unwrap(), "the RTL's PNG is the model's");
}

/// Formats the RTL cannot take, and units without formats, are clear errors; formats no
/// build holds, asked of an edgepaint already rebuilt for them, end without a loop.
#[test]
fn cli_formats_the_rtl_cannot_take_are_clear_errors() {
    let d = scratch("bad-formats");
    let custom = concat!(env!("CARGO_MANIFEST_DIR"), "/crates/rtl/custom-formats.json");
    let dir = d.join("hdl");
    let o = dir.to_str().unwrap();
    let saturating = write(&d, "saturating.json", r#"{"dz": "S5.34 saturate"}"#);
    fails_with(
        &["emit", "--unit", "raster_top", "--formats", &saturating, "-o", o],
        &["saturating.json", "truncate and wrap"],
    );
    let narrow = write(&d, "narrow.json", r#"{"xy": "S3.4"}"#);
    fails_with(&["emit", "--unit", "span", "--formats", &narrow, "-o", o], &["narrow.json", "guard band"]);
    fails_with(&["emit", "--unit", "ept", "--formats", custom, "-o", o], &["ept has no number formats"]);
    fails_with(&["emit", "--formats", custom, "-o", o], &["need --unit"]);
    // Formats no build holds, when the rebuilt edgepaint still lacks them: no loop.
    let z24 = write(&d, "z24.json", r#"{"z": "S1.24 half-up", "ooa_d": "S29.35"}"#);
    let out = Command::new(env!("CARGO_BIN_EXE_edgepaint"))
        .args(["emit", "--unit", "raster_top", "--formats", &z24, "-o", o])
        .env("EDGEPAINT_REBUILT", "1")
        .output()
        .expect("edgepaint runs");
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success() && err.contains("does not hold that build"), "{err}");
}

/// `edgepaint sweep`: each row's accuracy is `edgepaint accuracy`'s at the row's formats;
/// the charts, the report and both tables are written; shards merge; a grid with an
/// impossible point fails naming the file and the point.
#[test]
fn cli_sweep_rows_equal_accuracy_and_bad_grids_fail() {
    let d = scratch("sweep");
    let cube = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/cube.json");
    let grid = write(
        &d,
        "grid.json",
        r#"{"sensitivity": {"xy.frac": [3], "bary.frac": [12]}, "joint": {"samples": 1, "seed": 1}}"#,
    );
    let dir = d.join("out");
    let out =
        edgepaint(&["sweep", cube, "--size", "40x30", "--grid", &grid, "--jobs", "2", "-o", dir.to_str().unwrap()]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    for f in ["results.jsonl", "results.csv", "report.md", "error_vs_cycles.png", "error_vs_cycles.svg"] {
        assert!(dir.join(f).is_file(), "{f} written");
    }
    let rows: Vec<serde_json::Value> = std::fs::read_to_string(dir.join("results.jsonl"))
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(rows.len(), 10, "default, xy.frac=3 and a joint point per method, and bary.frac=12 for vector");
    assert_eq!(std::fs::read_to_string(dir.join("skipped.txt")).unwrap(), "", "the shading engines draw every point");
    for row in &rows {
        let formats = write(&d, "formats.json", &row["formats"].to_string());
        let json = d.join("accuracy.json");
        let engine = row["method"].as_str().unwrap();
        let args = ["accuracy", cube, "--size", "40x30", "--engine", engine, "--formats", &formats, "--json"];
        let out = edgepaint(&[&args[..], &[json.to_str().unwrap()]].concat());
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        let acc: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
        let acc = &acc[0];
        assert_eq!(row["psnr_db"], acc["errors"]["psnr_db"], "{}", row["point"]);
        assert_eq!(row["color_max_lsb"], acc["errors"]["color_max"], "{}", row["point"]);
        assert_eq!(row["depth_max_lsb"], acc["depth_max_lsb"], "{}", row["point"]);
        assert_eq!(row["coverage_differs"], acc["coverage_differs"], "{}", row["point"]);
        assert_eq!(row["cycles"], acc["cycles"], "{}", row["point"]);
    }

    let shards: Vec<String> = (0..2)
        .map(|i| {
            let s = d.join(format!("shard{i}"));
            let shard = format!("{i}/2");
            let args =
                ["sweep", cube, "--size", "40x30", "--grid", &grid, "--shard", &shard, "-o", s.to_str().unwrap()];
            assert!(edgepaint(&args).status.success());
            s.to_str().unwrap().to_owned()
        })
        .collect();
    let merged = d.join("merged");
    let out = edgepaint(&["sweep", "merge", &shards[0], &shards[1], "-o", merged.to_str().unwrap()]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let read = |p: &Path| std::fs::read_to_string(p.join("results.jsonl")).unwrap();
    assert_eq!(read(&merged), read(&dir), "the merged shards are the whole sweep");

    let bad = write(&d, "bad-grid.json", r#"{"methods": ["scanline"], "sensitivity": {"z.frac": [40]}}"#);
    fails_with(
        &["sweep", cube, "--grid", &bad, "-o", d.join("bad").to_str().unwrap()],
        &["cube", "scanline z.frac=40", "depth buffer"],
    );
    let unknown = write(&d, "unknown-grid.json", r#"{"sensitivity": {"w.frac": [4]}}"#);
    fails_with(
        &["sweep", cube, "--grid", &unknown, "-o", d.join("bad").to_str().unwrap()],
        &["unknown-grid.json", "w.frac"],
    );
}

#[test]
fn cli_stability_maps_families_and_bad_arguments_fail() {
    let d = scratch("stability");
    let narrow = write(&d, "xy2.json", r#"{"xy": "S11.2 half-up"}"#);
    let dir = d.join("out");
    let args =
        ["stability", "--family", "depth,sliver-h", "--method", "scanline,se", "--formats", &narrow, "--jobs", "2"];
    let out = edgepaint(&[&args[..], &["-o", dir.to_str().unwrap()]].concat());
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let cells = stability::report::read_cells(&dir.join("cells.json")).unwrap();
    // depth: 23 separations x 2 rows; sliver-h: 10 thicknesses x 11 lengths; 2 methods, 2 points.
    assert_eq!(cells.len(), (23 * 2 + 10 * 11) * 2 * 2);
    let verdict = |family: &str, method: &str, formats: &str, x: f64, y: f64| {
        let c = cells
            .iter()
            .find(|c| {
                (c.family.name(), c.method.name(), c.formats.as_str(), c.x, c.y)
                    == (family, method, formats, x, Some(y))
            })
            .unwrap_or_else(|| panic!("no cell {family} {method} {formats} {x} {y}"));
        c.passes()
    };
    // A 16-bit depth buffer orders depths a full LSB apart, not a quarter of one; 4 subpixel
    // bits keep a 1/16-px needle, 2 bits lose it and keep a 1/4-px one.
    for m in ["scanline", "se"] {
        assert_eq!(verdict("depth", m, "default", (-16f64).exp2(), 0.0), Some(true));
        assert_eq!(verdict("depth", m, "default", (-18f64).exp2(), 0.0), Some(false));
        assert_eq!(verdict("sliver-h", m, "default", 0.0625, 64.0), Some(true));
        assert_eq!(verdict("sliver-h", m, "xy2", 0.0625, 64.0), Some(false));
        assert_eq!(verdict("sliver-h", m, "xy2", 0.25, 64.0), Some(true));
    }
    let report = std::fs::read_to_string(dir.join("report.md")).unwrap();
    assert!(
        report.contains("| scanline | default | every length L (px): passes at 2^-4, fails from 2^-5 |"),
        "{report}"
    );
    for f in ["depth_scanline_default", "sliver-h_se_xy2", "depth_se_xy2"] {
        assert!(dir.join(format!("{f}.png")).is_file() && dir.join(format!("{f}.svg")).is_file(), "{f}");
        assert!(report.contains(&format!("({f}.svg)")), "{f} in the report");
    }

    let o = d.join("bad").to_str().unwrap().to_string();
    fails_with(
        &["stability", "--family", "slivers", "-o", &o],
        &["--family", "unknown family \"slivers\"", "sliver-h"],
    );
    fails_with(&["stability", "--method", "raster", "-o", &o], &["--method", "raster", "scanline"]);
    let no_subpixel = write(&d, "no-subpixel.json", r#"{"xy": "S11.0 half-up"}"#);
    fails_with(&["stability", "--formats", &no_subpixel, "-o", &o], &["no-subpixel.json", "xy", "subpixel bit"]);
    let unknown = write(&d, "unknown.json", r#"{"w": "S11.4"}"#);
    fails_with(&["stability", "--formats", &unknown, "-o", &o], &["unknown.json", "unknown quantity \"w\""]);
    let malformed = write(&d, "malformed.json", r#"{"xy": "#);
    fails_with(&["stability", "--formats", &malformed, "-o", &o], &["malformed.json", "malformed JSON"]);
    fails_with(&["stability", "--formats", "/nonexistent/f.json", "-o", &o], &["f.json", "cannot read"]);
    assert!(!Path::new(&o).exists(), "nothing written on bad arguments");
}

/// `edgepaint fit` refuses a bad target or objective and a target no design of the method
/// meets, naming each design's miss; `render --param` is for the RTL engine only. (A whole
/// scanline fit rebuilds edgepaint at the fitted formats: `crates/fit/tests` runs the
/// search, the soak the command; `cli_fit_chooses_the_barycentric_back_end_and_proves_it`
/// runs one whose design is built at the default formats.)
#[test]
fn cli_fit_and_render_param_errors_are_clear() {
    let d = scratch("fit");
    let cube = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/cube.json");
    let o = d.join("out");
    let o = o.to_str().unwrap();
    fn fit<'a>(cube: &'a str, o: &'a str, target: &'a str, more: &[&'a str]) -> Vec<&'a str> {
        [&["fit", cube, "--size", "32x24", "--target", target, "-o", o][..], more].concat()
    }
    let fit = |target: &'static str, more: &[&'static str]| fit(cube, o, target, more);
    fails_with(&fit("psnr>=40,,problems=0", &[]), &["empty term"]);
    fails_with(&fit("psnr<=40", &[]), &["\"psnr<=40\"", "larger is better"]);
    fails_with(&fit("sharpness>=2", &[]), &["unknown measure \"sharpness\""]);
    fails_with(
        &fit("colour_max_lsb<=0,coverage_differs=0", &["--method", "vector"]),
        &["no design of --method vector meets the target", "vector lanes=1: cube: colour_max_lsb is", "vector lanes=8"],
    );
    fails_with(
        &fit("colour_max_lsb<=0,coverage_differs=0", &["--no-synth", "--no-proof"]),
        &["no design of --method auto", "not met even with every knob at its ceiling", "se engines=1: cube: "],
    );
    fails_with(&fit("psnr>=40", &["--objective", "speed"]), &["'speed'", "area*time"]);
    let png = d.join("p.png");
    let args = ["render", cube, "--size", "32x24", "--param", "K=3", "-o", png.to_str().unwrap()];
    fails_with(&args, &["--param", "needs --engine rtl"]);
    let args = ["render", cube, "--size", "32x24", "--engine", "rtl", "--param", "P=3", "-o", png.to_str().unwrap()];
    fails_with(&args, &["--param P", "takes N", "K (setup's multipliers)", "CLIP_Y"]);
}

/// `fit --method vector` runs the barycentric back end at each lane count it is built with,
/// chooses the lanes for the objective (area: one lane, the fewest gates), emits raster_top
/// at them, and proves the workload in Verilator: the proof's PNG is the vector model's; the
/// manifest and the report name every design compared.
#[test]
fn cli_fit_chooses_the_barycentric_back_end_and_proves_it() {
    let d = scratch("fit-vector");
    let cube = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/cube.json");
    let o = d.join("out");
    let target = "psnr>=40,colour_max_lsb<=8,depth_order=exact,coverage_unexplained=0";
    let args = ["fit", cube, "--size", "64x48", "--target", target, "--method", "vector", "--no-synth"];
    let out = edgepaint(&[&args[..], &["-o", o.to_str().unwrap()]].concat());
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let read =
        |p: PathBuf| -> serde_json::Value { serde_json::from_str(&std::fs::read_to_string(p).unwrap()).unwrap() };
    let m = read(o.join("manifest.json"));
    assert_eq!((m["method"].as_str(), m["params"]["lanes"].as_u64()), (Some("vector"), Some(1)));
    let compared = m["methods_compared"].as_array().unwrap();
    let lanes: Vec<u64> = compared.iter().map(|c| c["params"]["lanes"].as_u64().unwrap()).collect();
    assert_eq!(lanes, [1, 2, 4, 8]);
    assert!(compared.iter().all(|c| c["passes"] == true), "{compared:?}");
    assert_eq!(m["proven_in_verilator"], serde_json::json!(["cube"]));
    let hdl = read(o.join("hdl").join("manifest.json"));
    let p = &hdl["units"][0]["parameters"];
    assert_eq!((p["METHOD"].as_u64(), p["LANES"].as_u64()), (Some(1), Some(1)), "{p}");
    let (model, _) = render_cube(&d.join("model.png"), &["--engine", "vector", "--lanes", "1"]);
    assert!(std::fs::read(o.join("proof").join("cube.png")).unwrap() == model, "the proof's PNG is the vector model's");
    let report = std::fs::read_to_string(o.join("report.md")).unwrap();
    assert!(report.contains("| vector lanes=1 (chosen) | yes |"), "{report}");
    assert!(report.contains("Method: `vector`, **vector lanes=1**"), "{report}");
}

/// `pack` writes a scene's vertex buffer (shared vertices once), `inspect` prints it, and
/// `render` draws it: the scanline model's image of the buffer is the scene's, pixel for
/// pixel (the same words), and `--engine rtl` draws the file's bytes through `gpu_top`
/// equal to the model. Broken buffers
/// and arguments are clear errors naming the file.
#[test]
fn cli_packs_inspects_and_renders_a_vertex_buffer() {
    let d = scratch("vertex-buffer");
    let scene = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/sphere.json");
    let vb = d.join("sphere.vb");
    let vb_s = vb.to_str().unwrap();
    let o = edgepaint(&["pack", scene, "--size", "96x72", "-o", vb_s]);
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(stdout.contains("168 triangles in, 168 packed"), "{stdout}");
    let bytes = std::fs::read(&vb).unwrap();
    let buffer = model::vertex_buffer::VertexBuffer::decode(&bytes).expect("pack writes a readable buffer");
    assert!(buffer.vertices.len() < buffer.triangles.len(), "a sphere's vertices are shared: {stdout}");

    let o = edgepaint(&["inspect", vb_s]);
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(text.contains("vertex buffer v1: 96x72 screen, size class 10"), "{text}");
    assert!(text.contains(&format!("{} triangles from byte 96", buffer.triangles.len())), "{text}");
    // The command parser's vertex fetches: the sphere is index-ordered, so each vertex is
    // fetched about once (0.5 per triangle), far from a soup's 3.
    let fetches = text.split("vertex cache, latency 0): ").nth(1).and_then(|s| s.split(' ').next());
    let fetches: f64 = fetches.and_then(|f| f.parse().ok()).unwrap_or_else(|| panic!("{text}"));
    assert!(fetches > 0.0 && fetches <= 1.2, "{text}");
    fails_with(&["inspect", vb_s, "--cache", "3"], &["--cache", "power of two"]);

    let (a, b) = (d.join("scene.png"), d.join("vb.png"));
    let render = |input: &str, out: &Path, engine: &str| {
        let o = edgepaint(&["render", input, "-o", out.to_str().unwrap(), "--engine", engine]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        String::from_utf8_lossy(&o.stdout).to_string()
    };
    let o = edgepaint(&["render", scene, "--size", "96x72", "-o", a.to_str().unwrap(), "--engine", "scanline"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    render(vb_s, &b, "scanline");
    assert_eq!(image::open(&a).unwrap().to_rgb8(), image::open(&b).unwrap().to_rgb8(), "the same words draw the same");
    let rtl = render(vb_s, &d.join("rtl.png"), "rtl");
    assert!(
        rtl.contains(&format!("gpu_top of size class 10, in Verilator, from a vertex buffer of {} bytes", bytes.len())),
        "{rtl}"
    );
    assert!(rtl.contains("equal to model::gpu_top's"), "{rtl}");
    assert_eq!(image::open(d.join("rtl.png")).unwrap().to_rgb8(), image::open(&b).unwrap().to_rgb8());

    let png = d.join("x.png");
    let out = png.to_str().unwrap();
    let truncated = d.join("truncated.vb");
    std::fs::write(&truncated, &bytes[..bytes.len() - 32]).unwrap();
    let t = truncated.to_str().unwrap();
    fails_with(&["render", t, "-o", out], &["truncated.vb", "offset 32", "length"]);
    fails_with(&["inspect", t], &["truncated.vb", "offset 32"]);
    fails_with(&["inspect", scene], &["sphere.json", "offset 0", "not a vertex buffer"]);
    fails_with(&["render", vb_s, "-o", out, "--engine", "scanline", "--formats", "wide"], &["--formats wide"]);
    fails_with(&["render", vb_s, "-o", out, "--size", "32x32"], &["sphere.vb", "--size"]);
    fails_with(&["pack", vb_s, "-o", out], &["sphere.vb", "already a vertex buffer"]);
}
