//! Scene files: what to draw, from where, under which lights.
//!
//! A scene is a JSON object. Unknown keys are errors everywhere, and every
//! value is checked when the scene is read; the message names the key
//! (`objects[2].transform.scale: ...`) and the caller adds the file.
//!
//! ```json
//! {
//!   "width": 320, "height": 240,
//!   "background": [20, 24, 32],
//!   "camera": {"eye": [0, 1.5, 4], "target": [0, 0, 0], "up": [0, 1, 0],
//!              "fov_y_deg": 45, "near": 0.5, "far": 20},
//!   "lights": {"ambient": [0.15, 0.15, 0.15],
//!              "directional": [{"direction": [-1, -1, -1], "color": [0.9, 0.9, 0.8]}]},
//!   "objects": [
//!     {"model": "torus", "color": [230, 120, 40],
//!      "transform": {"translate": [0, 0, 0], "rotate_deg": [60, 0, 0], "scale": 1.2}},
//!     {"obj": "house.obj", "color": [200, 200, 200]}
//!   ],
//!   "cull": "none"
//! }
//! ```
//!
//! | key | type | default | meaning |
//! |---|---|---|---|
//! | `width`, `height` | integers | required | resolution in pixels, 1 to [`MAX_RESOLUTION`](crate::MAX_RESOLUTION) |
//! | `background` | [r, g, b] in 0..255 | [0, 0, 0] | colour of pixels no triangle covers |
//! | `camera.eye` | [x, y, z] | required | where the camera is (world space; units are free, the built-in models fit in [-1, 1]^3) |
//! | `camera.target` | [x, y, z] | required | the point at the centre of the image; not `eye` |
//! | `camera.up` | [x, y, z] | [0, 1, 0] | which way is up on screen; not parallel to `target - eye` |
//! | `camera.fov_y_deg` | number in (0, 180) | required | vertical field of view, degrees |
//! | `camera.near`, `camera.far` | numbers, 0 < near < far | required | distances along the view direction that map to depth 0 and 1 |
//! | `lights.ambient` | [r, g, b] in 0..1 | [0, 0, 0] | light reaching every surface |
//! | `lights.directional` | array | [] | distant lights: |
//! | &nbsp; `.direction` | [x, y, z], not zero | required | the direction the light *travels* (world space): [0, -1, 0] shines straight down |
//! | &nbsp; `.color` | [r, g, b] in 0..1 | [1, 1, 1] | its intensity per channel |
//! | `objects` | array | required | what to draw, each object with: |
//! | &nbsp; `.model` | name | one of `model`, `obj` | a built-in model: `cube`, `sphere`, `cone`, `torus`, `pawn` (see [`builtin`]) |
//! | &nbsp; `.detail` | integer, 1 to [`MAX_DETAIL`](builtin::MAX_DETAIL) | 1 | with `model` only: the built-in model tessellated that much finer ([`builtin::mesh_at`]; the torus at 15 is 76,500 triangles) |
//! | &nbsp; `.obj` | path | one of `model`, `obj` | a Wavefront OBJ file, relative to the scene file's folder (see [`Mesh::load_obj`]): polygons are triangulated; its normals (`vn`) are used when every face has them, else each vertex gets the average of the normals of the faces sharing its position |
//! | &nbsp; `.transform.translate` | [x, y, z] | [0, 0, 0] | |
//! | &nbsp; `.transform.rotate_deg` | [rx, ry, rz] | [0, 0, 0] | degrees about the world x, then y, then z axis, each counter-clockwise seen from the positive end of the axis (right-hand rule) |
//! | &nbsp; `.transform.scale` | number or [x, y, z], no zero | 1 | a negative factor mirrors the object (its faces stay front faces) |
//! | &nbsp; `.color` | [r, g, b] in 0..255 | [255, 255, 255] | the surface's colour |
//! | &nbsp; `.texture` | object | each OBJ material's `map_Kd`, else none | a texture mapped by the mesh's texture coordinates (an OBJ's `vt`; a built-in model's own, see [`builtin`]), modulating the lit colour by default: |
//! | &nbsp;&nbsp; `.image` | path | the materials' `map_Kd` | a PNG file relative to the scene file's folder, its sides powers of two, on every triangle of the object (in place of its materials' images) |
//! | &nbsp;&nbsp; `.levels` | [path, ...] | | instead of `image`: each mip level's own PNG, base first, down to 1x1 (each level half the one before) |
//! | &nbsp;&nbsp; `.sampler` | object | bilinear, nearest mip level, repeat | `texture::Sampler`: `min`, `mag` (`nearest`, `linear`), `mip` (`none`, `nearest`, `linear`), `wrap_s`, `wrap_t` (`repeat`, `mirrored_repeat`, `clamp_to_edge`) |
//! | &nbsp;&nbsp; `.env` | name | `modulate` | the texture environment: `replace`, `modulate`, `decal`, `blend`, `add` (OpenGL's) |
//! | &nbsp;&nbsp; `.format` | name | `rgba8888` | the texel format the image and its mip levels are stored in (001's five colour modes): `rgb565`, `rgba5551`, `rgba4444`, `rgb888`, `rgba8888` |
//! | &nbsp; `.blend` | name | `opaque` | framebuffer blending of the object's fragments onto the colour already drawn, in draw order (paper 001's six blend modes, OpenGL 4.6 section 17.3.6; the source alpha is the texture environment's, 1 untextured): `opaque` (no blending: replace), `alpha`, `additive`, `multiply`, `premultiplied_alpha`, `alpha_additive` (`texture::BlendMode`) |
//! | `cull` | `"none"` or `"back"` | `"none"` | whether the renderer drops back faces ([`Scene::cull_back`]) |
//!
//! An object's vertices go to world space by `translate * Rz * Ry * Rx * scale`
//! and are lit there (Lambert, per vertex; normals by the inverse transpose):
//! `color * (ambient + sum over lights of max(0, N.L) * light color)`, clamped
//! to [0, 255] per channel, with L the unit vector toward the light. What
//! happens next is the [`geometry`](crate::geometry) stage.

use crate::builtin;
use crate::error::{parse_json, Error, Result};
use crate::geometry::{emit_clipped, ObjectTransform, Projection};
use crate::math::{Mat3, Vec3};
use crate::mesh::Mesh;
use crate::trilist::{check_resolution, TextureRef, TextureSpec, Trilist};
use serde::Deserialize;
use std::path::{Path, PathBuf};
use texture::BlendMode;

/// A scene: resolution, background, camera, lights and objects, checked.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    pub width: u32,
    pub height: u32,
    /// Background colour in [0, 255].
    pub background: [f64; 3],
    /// Whether the scene asks for back faces to be culled (`"cull": "back"`).
    pub cull_back: bool,
    pub camera: Camera,
    pub lights: Lights,
    pub objects: Vec<Object>,
}

/// The camera: a perspective look-at view.
#[derive(Clone, Copy, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Camera {
    pub eye: Vec3,
    pub target: Vec3,
    #[serde(default = "y_up")]
    pub up: Vec3,
    /// Vertical field of view in degrees, in (0, 180).
    pub fov_y_deg: f64,
    /// Distance along the view direction of depth 0; > 0.
    pub near: f64,
    /// Distance along the view direction of depth 1; > near.
    pub far: f64,
}

/// Ambient and directional lights.
#[derive(Clone, Debug, Default, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Lights {
    /// Intensity per channel in [0, 1].
    #[serde(default)]
    pub ambient: [f64; 3],
    #[serde(default)]
    pub directional: Vec<DirectionalLight>,
}

/// A light at infinity.
#[derive(Clone, Copy, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DirectionalLight {
    /// The direction the light travels, world space; not zero.
    pub direction: Vec3,
    /// Intensity per channel in [0, 1].
    #[serde(default = "white_light")]
    pub color: [f64; 3],
}

/// Where an object's mesh came from.
#[derive(Clone, Debug, PartialEq)]
pub enum ModelSource {
    /// A [`builtin`] model, by name.
    Builtin(String),
    /// An OBJ file (the path as resolved against the scene's folder).
    Obj(PathBuf),
}

/// One object of the scene, its mesh loaded.
#[derive(Clone, Debug, PartialEq)]
pub struct Object {
    pub source: ModelSource,
    pub mesh: Mesh,
    pub transform: Transform,
    /// Surface colour in [0, 255].
    pub color: [f64; 3],
    /// The textures its triangles name (`MeshVertex::texture` indexes them), loaded.
    pub textures: Vec<TextureRef>,
    /// How its fragments blend onto the framebuffer (`blend`; opaque by default).
    pub blend: BlendMode,
}

/// Object to world: scale, then rotate about x, y, z (in that order), then translate.
#[derive(Clone, Copy, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Transform {
    #[serde(default)]
    pub translate: Vec3,
    /// Degrees about the world x, then y, then z axis.
    #[serde(default)]
    pub rotate_deg: Vec3,
    /// Per-axis factors; none zero. The file may give one number for all three.
    #[serde(default = "unit_scale", deserialize_with = "scale_from_file")]
    pub scale: Vec3,
}

impl Default for Transform {
    fn default() -> Self {
        Transform { translate: [0.0; 3], rotate_deg: [0.0; 3], scale: unit_scale() }
    }
}

impl Transform {
    /// The linear part `Rz * Ry * Rx * S` (the translation is added apart).
    fn linear(&self) -> Mat3 {
        let [rx, ry, rz] = self.rotate_deg;
        Mat3::rotation(2, rz).mul(&Mat3::rotation(1, ry)).mul(&Mat3::rotation(0, rx)).mul(&Mat3::diagonal(self.scale))
    }
}

fn y_up() -> Vec3 {
    [0.0, 1.0, 0.0]
}

fn white_light() -> [f64; 3] {
    [1.0; 3]
}

fn white() -> [f64; 3] {
    [255.0; 3]
}

fn unit_scale() -> Vec3 {
    [1.0; 3]
}

fn scale_from_file<'de, D: serde::Deserializer<'de>>(d: D) -> std::result::Result<Vec3, D::Error> {
    #[derive(Deserialize)]
    #[serde(untagged, expecting = "expected a number or [x, y, z]")]
    enum Scale {
        Uniform(f64),
        Axes(Vec3),
    }
    Ok(match Scale::deserialize(d)? {
        Scale::Uniform(s) => [s; 3],
        Scale::Axes(v) => v,
    })
}

/// The file's form of a scene, before meshes are loaded.
#[derive(Deserialize)]
#[serde(deny_unknown_fields, expecting = "a scene: an object with width, height, camera, lights and objects")]
struct SceneFile {
    width: u32,
    height: u32,
    #[serde(default)]
    background: [f64; 3],
    camera: Camera,
    lights: Lights,
    objects: Vec<ObjectFile>,
    #[serde(default)]
    cull: Cull,
}

#[derive(Default, Deserialize)]
#[serde(rename_all = "lowercase")]
enum Cull {
    #[default]
    None,
    Back,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ObjectFile {
    model: Option<String>,
    obj: Option<PathBuf>,
    detail: Option<u32>,
    #[serde(default)]
    transform: Transform,
    #[serde(default = "white")]
    color: [f64; 3],
    texture: Option<TextureSpec>,
    #[serde(default)]
    blend: BlendMode,
}

impl ObjectFile {
    /// Loads the mesh; `at` names the object in messages.
    fn load(self, base_dir: &Path, at: &str) -> Result<Object> {
        let (source, mut mesh) = match (self.model, self.obj) {
            (Some(name), None) => {
                let detail = self.detail.unwrap_or(1);
                if !(1..=builtin::MAX_DETAIL).contains(&detail) {
                    return Err(Error::invalid(format!(
                        "{at}.detail = {detail} is outside 1 to {} (1 is the papers' mesh)",
                        builtin::MAX_DETAIL
                    )));
                }
                let mesh = builtin::mesh_at(&name, detail).ok_or_else(|| {
                    Error::invalid(format!(
                        "{at}.model: unknown model \"{name}\" (the built-in models are {})",
                        builtin::NAMES.join(", ")
                    ))
                })?;
                (ModelSource::Builtin(name), mesh)
            }
            (None, Some(_)) if self.detail.is_some() => {
                return Err(Error::invalid(format!(
                    "{at}.detail: only a built-in model (\"model\") has a detail; an OBJ mesh is drawn as the file gives it"
                )))
            }
            (None, Some(obj)) => {
                let path = base_dir.join(obj);
                let mesh = Mesh::load_obj(&path).map_err(|e| Error::invalid(format!("{at}.obj: {e}")))?;
                (ModelSource::Obj(path), mesh)
            }
            (Some(_), Some(_)) => {
                return Err(Error::invalid(format!("{at}: has both \"model\" and \"obj\"; give exactly one")))
            }
            (None, None) => {
                return Err(Error::invalid(format!(
                    "{at}: has neither \"model\" nor \"obj\"; give exactly one (a built-in model name or an OBJ path)"
                )))
            }
        };
        let keyed = self.texture.is_some();
        let spec = self.texture.unwrap_or_default();
        let given = spec.files(base_dir).map_err(|e| Error::invalid(format!("{at}.texture: {e}")))?;
        let textures: Vec<Vec<PathBuf>> = match given {
            Some(files) => {
                if !mesh.has_uv {
                    return Err(Error::invalid(format!(
                        "{at}.texture: the mesh has no texture coordinates (an OBJ needs vt on every face)"
                    )));
                }
                mesh.triangles.iter_mut().flatten().for_each(|v| v.texture = Some(0));
                vec![files]
            }
            None if keyed && mesh.textures.is_empty() => {
                return Err(Error::invalid(format!(
                    "{at}.texture: no image: give \"image\" or \"levels\", or an OBJ whose materials have map_Kd"
                )))
            }
            None => mesh.textures.iter().map(|image| vec![image.clone()]).collect(),
        };
        let textures = textures
            .iter()
            .map(|files| TextureRef::load(files, &spec).map_err(|e| Error::invalid(format!("{at}.texture: {e}"))))
            .collect::<Result<Vec<_>>>()?;
        Ok(Object { source, mesh, transform: self.transform, color: self.color, textures, blend: self.blend })
    }
}

impl Scene {
    /// Reads and validates a scene file; OBJ paths are relative to its folder.
    pub fn load(path: &Path) -> Result<Scene> {
        let text = std::fs::read_to_string(path).map_err(|e| Error::io(path, e))?;
        let raw: serde_json::Value = parse_json(&text).map_err(|e| e.in_file(path))?;
        Scene::from_value(&raw, path.parent().unwrap_or(Path::new("."))).map_err(|e| e.in_file(path))
    }

    /// Builds and validates a scene from parsed JSON; OBJ paths are relative to `base_dir`.
    pub fn from_value(raw: &serde_json::Value, base_dir: &Path) -> Result<Scene> {
        let file: SceneFile = serde_path_to_error::deserialize(raw).map_err(|e| {
            let at = e.path().to_string();
            let inner = e.into_inner();
            Error::invalid(if at == "." { inner.to_string() } else { format!("{at}: {inner}") })
        })?;
        let objects = file
            .objects
            .into_iter()
            .enumerate()
            .map(|(i, o)| o.load(base_dir, &format!("objects[{i}]")))
            .collect::<Result<Vec<_>>>()?;
        let scene = Scene {
            width: file.width,
            height: file.height,
            background: file.background,
            cull_back: matches!(file.cull, Cull::Back),
            camera: file.camera,
            lights: file.lights,
            objects,
        };
        scene.validate()?;
        Ok(scene)
    }

    /// The same scene drawn at another resolution (the field of view stays vertical).
    pub fn with_size(self, width: u32, height: u32) -> Result<Scene> {
        check_resolution(width, height)?;
        Ok(Scene { width, height, ..self })
    }

    /// Checks every value (the serde types alone allow out-of-range ones).
    pub fn validate(&self) -> Result<()> {
        check_resolution(self.width, self.height)?;
        check_vec("background", self.background, Some((0.0, 255.0)))?;
        let cam = &self.camera;
        for (name, v) in [("camera.eye", cam.eye), ("camera.target", cam.target), ("camera.up", cam.up)] {
            check_vec(name, v, None)?;
        }
        Projection::new(cam, self.width, self.height).map_err(Error::invalid)?;
        check_vec("lights.ambient", self.lights.ambient, Some((0.0, 1.0)))?;
        for (i, light) in self.lights.directional.iter().enumerate() {
            let at = format!("lights.directional[{i}]");
            check_vec(&format!("{at}.direction"), light.direction, None)?;
            if light.direction == [0.0; 3] {
                return Err(Error::invalid(format!("{at}.direction is [0, 0, 0]: a light needs a direction")));
            }
            check_vec(&format!("{at}.color"), light.color, Some((0.0, 1.0)))?;
        }
        for (i, o) in self.objects.iter().enumerate() {
            let at = format!("objects[{i}]");
            let t = &o.transform;
            check_vec(&format!("{at}.transform.translate"), t.translate, None)?;
            check_vec(&format!("{at}.transform.rotate_deg"), t.rotate_deg, None)?;
            check_vec(&format!("{at}.transform.scale"), t.scale, None)?;
            if t.scale.contains(&0.0) {
                return Err(Error::invalid(format!(
                    "{at}.transform.scale = {:?} has a zero factor: the object would be flat",
                    t.scale
                )));
            }
            check_vec(&format!("{at}.color"), o.color, Some((0.0, 255.0)))?;
            o.mesh.check().map_err(|msg| Error::invalid(format!("{at}: the mesh {msg}")))?;
        }
        Ok(())
    }

    /// Runs the geometry stage: the screen-space triangles, each vertex with its
    /// clip-space w. See [`geometry`](crate::geometry).
    pub fn to_trilist(&self) -> Result<Trilist> {
        self.validate()?;
        let projection = Projection::new(&self.camera, self.width, self.height).map_err(Error::invalid)?;
        let mut list = Trilist::new(self.width, self.height)?;
        for (i, o) in self.objects.iter().enumerate() {
            let xf = ObjectTransform::new(&projection, &o.transform.linear(), o.transform.translate)
                .map_err(|msg| Error::invalid(format!("objects[{i}].transform: {msg}")))?;
            // The object's textures as the list's.
            let mut index = Vec::with_capacity(o.textures.len());
            for t in &o.textures {
                let at = list.textures.iter().position(|u| u == t).unwrap_or(list.textures.len());
                if at == list.textures.len() {
                    list.textures.push(t.clone());
                }
                index.push(u16::try_from(at).map_err(|_| {
                    Error::invalid(format!("objects[{i}].texture: more than {} textures in the scene", u16::MAX))
                })?);
            }
            let first = list.triangles.len();
            for tri in &o.mesh.triangles {
                let texture = tri[0].texture.and_then(|k| index.get(k as usize).copied());
                emit_clipped(xf.vertices(tri, o.color, &self.lights), &projection, texture, &mut list.triangles);
            }
            list.triangles[first..].iter_mut().flatten().for_each(|v| v.blend = o.blend);
        }
        Ok(list)
    }
}

/// Checks that `v` is finite and, when `range` is given, each component inside it.
fn check_vec(name: &str, v: Vec3, range: Option<(f64, f64)>) -> Result<()> {
    if v.iter().any(|c| !c.is_finite()) {
        return Err(Error::invalid(format!("{name} = {v:?} is not finite")));
    }
    if let Some((lo, hi)) = range {
        if v.iter().any(|c| !(lo..=hi).contains(c)) {
            return Err(Error::invalid(format!("{name} = {v:?} is outside [{lo}, {hi}]")));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::{json, Value};

    fn valid() -> Value {
        json!({
            "width": 64, "height": 48,
            "camera": {"eye": [0, 0, 5], "target": [0, 0, 0], "fov_y_deg": 45, "near": 1, "far": 10},
            "lights": {"ambient": [0.2, 0.2, 0.2], "directional": [{"direction": [0, 0, -1]}]},
            "objects": [{"model": "cube"}]
        })
    }

    fn error_of(v: &Value) -> String {
        Scene::from_value(v, Path::new(".")).map(|_| ()).unwrap_err().to_string()
    }

    #[test]
    fn scene_defaults_fill_in_what_the_file_leaves_out() {
        let s = Scene::from_value(&valid(), Path::new(".")).unwrap();
        assert_eq!(s.background, [0.0; 3]);
        assert!(!s.cull_back);
        assert_eq!(s.camera.up, [0.0, 1.0, 0.0]);
        assert_eq!(s.lights.directional[0].color, [1.0; 3]);
        assert_eq!(s.objects[0].transform, Transform::default());
        assert_eq!(s.objects[0].color, [255.0; 3]);
        assert_eq!(s.objects[0].source, ModelSource::Builtin("cube".into()));
        assert_eq!(s.objects[0].blend, BlendMode::Opaque);
        assert!(!s.to_trilist().unwrap().is_blended());
        let mut v = valid();
        v["cull"] = json!("back");
        v["objects"][0]["transform"] = json!({"scale": [1, 2, 3]});
        let s = Scene::from_value(&v, Path::new(".")).unwrap();
        assert!(s.cull_back);
        assert_eq!(s.objects[0].transform.scale, [1.0, 2.0, 3.0]);
        assert_eq!(s.objects[0].mesh, builtin::mesh("cube").unwrap());
        v["objects"][0]["detail"] = json!(3);
        let s = Scene::from_value(&v, Path::new(".")).unwrap();
        assert_eq!(s.objects[0].mesh.triangles.len(), 12 * 3 * 3);
        assert_eq!(s.objects[0].source, ModelSource::Builtin("cube".into()));
    }

    #[test]
    fn scene_blend_goes_to_every_triangle_of_its_object_and_to_the_trilist() {
        let mut v = valid();
        v["objects"] = json!([
            {"model": "cube"},
            {"model": "cube", "blend": "alpha", "transform": {"scale": 0.5}},
            {"model": "cube", "blend": "multiply", "transform": {"translate": [0, 0, 1]}}
        ]);
        let s = Scene::from_value(&v, Path::new(".")).unwrap();
        let modes: Vec<BlendMode> = s.objects.iter().map(|o| o.blend).collect();
        assert_eq!(modes, [BlendMode::Opaque, BlendMode::Alpha, BlendMode::Multiply]);
        let list = s.to_trilist().unwrap();
        assert!(list.is_blended());
        // The cube is 12 triangles, none of them clipped here: 12 of each mode, in draw order.
        assert_eq!(list.triangles.len(), 36);
        for (k, want) in modes.iter().enumerate() {
            for t in &list.triangles[12 * k..12 * (k + 1)] {
                assert_eq!(t.map(|v| v.blend), [*want; 3]);
            }
        }
        // The screen-space file keeps it.
        assert_eq!(Trilist::from_json(&list.to_json()).unwrap(), list);
    }

    #[test]
    fn scene_bad_blend_names_the_scene_file_and_the_key() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("s.json");
        let mut v = valid();
        v["objects"][0]["blend"] = json!("Alpha");
        std::fs::write(&path, v.to_string()).unwrap();
        let err = Scene::load(&path).unwrap_err().to_string();
        let want = format!("{}: objects[0].blend: unknown variant `Alpha`", path.display());
        assert!(err.starts_with(&want), "got {err:?}, want {want:?}");
    }

    #[test]
    fn scene_with_size_changes_the_resolution_and_checks_it() {
        let s = Scene::from_value(&valid(), Path::new(".")).unwrap();
        let big = s.clone().with_size(640, 480).unwrap();
        assert_eq!((big.width, big.height), (640, 480));
        assert_eq!(big.to_trilist().unwrap().width, 640);
        let err = s.with_size(0, 480).unwrap_err().to_string();
        assert!(err.contains("width 0 is out of range"), "{err}");
    }

    #[test]
    fn scene_rejects_bad_values_saying_what_is_wrong() {
        let cases: &[(&str, Value, &str)] = &[
            ("/width", json!(0), "width 0 is out of range"),
            ("/height", json!(100000), "height 100000 is out of range"),
            ("/width", json!(-3), "width: invalid value: integer `-3`"),
            ("/background", json!([0, 256, 0]), "background = [0.0, 256.0, 0.0] is outside [0, 255]"),
            ("/camera/target", json!([0, 0, 5]), "camera.eye and camera.target are the same point"),
            ("/camera/up", json!([0, 0, 3]), "camera.up = [0.0, 0.0, 3.0] is parallel to the view direction"),
            ("/camera/fov_y_deg", json!(0), "camera.fov_y_deg = 0 is outside (0, 180)"),
            ("/camera/fov_y_deg", json!(180), "camera.fov_y_deg = 180 is outside (0, 180)"),
            ("/camera/near", json!(0), "camera.near = 0 must be greater than 0"),
            ("/camera/near", json!(-1), "camera.near = -1 must be greater than 0"),
            ("/camera/far", json!(1), "camera.far = 1 must be greater than camera.near = 1"),
            ("/camera/eye", json!([0, 0]), "camera.eye: invalid length 2"),
            ("/lights/ambient", json!([0.2, 1.5, 0]), "lights.ambient = [0.2, 1.5, 0.0] is outside [0, 1]"),
            ("/lights/directional/0/direction", json!([0, 0, 0]), "lights.directional[0].direction is [0, 0, 0]"),
            (
                "/lights/directional/0/color",
                json!([2, 0, 0]),
                "lights.directional[0].color = [2.0, 0.0, 0.0] is outside [0, 1]",
            ),
            ("/objects/0/color", json!([0, 0, -1]), "objects[0].color = [0.0, 0.0, -1.0] is outside [0, 255]"),
            (
                "/objects/0/transform",
                json!({"scale": 0}),
                "objects[0].transform.scale = [0.0, 0.0, 0.0] has a zero factor",
            ),
            ("/objects/0/transform", json!({"scale": [1, 0, 1]}), "has a zero factor"),
            (
                "/objects/0/transform",
                json!({"scale": "big"}),
                "objects[0].transform.scale: expected a number or [x, y, z]",
            ),
            (
                "/objects/0/transform",
                json!({"rotate": [0, 1, 0]}),
                "objects[0].transform.rotate: unknown field `rotate`",
            ),
            (
                "/objects/0/model",
                json!("teapot"),
                "objects[0].model: unknown model \"teapot\" (the built-in models are cube, sphere, cone, torus, pawn)",
            ),
            ("/objects/0", json!({"model": "cube", "obj": "a.obj"}), "objects[0]: has both \"model\" and \"obj\""),
            ("/objects/0/detail", json!(0), "objects[0].detail = 0 is outside 1 to 32"),
            ("/objects/0/detail", json!(33), "objects[0].detail = 33 is outside 1 to 32"),
            ("/objects/0/detail", json!(-2), "objects[0].detail: invalid value: integer `-2`"),
            ("/objects/0/detail", json!(1.5), "objects[0].detail: invalid type: floating point `1.5`"),
            ("/objects/0/detail", json!("fine"), "objects[0].detail: invalid type: string \"fine\""),
            (
                "/objects/0",
                json!({"obj": "a.obj", "detail": 2}),
                "objects[0].detail: only a built-in model (\"model\") has a detail",
            ),
            ("/objects/0", json!({"color": [1, 2, 3]}), "objects[0]: has neither \"model\" nor \"obj\""),
            ("/objects/0/colour", json!([1, 2, 3]), "objects[0].colour: unknown field `colour`"),
            ("/cull", json!("front"), "cull: unknown variant `front`, expected `none` or `back`"),
            (
                "/objects/0/blend",
                json!("screen"),
                "objects[0].blend: unknown variant `screen`, expected one of `opaque`, `alpha`, `additive`, \
                 `multiply`, `premultiplied_alpha`, `alpha_additive`",
            ),
            ("/objects/0/blend", json!(1), "objects[0].blend: invalid type: integer `1`"),
            ("/fog", json!(true), "fog: unknown field `fog`"),
        ];
        for (pointer, value, want) in cases {
            let mut v = valid();
            let (parent, key) = pointer.rsplit_once('/').unwrap();
            let target = v.pointer_mut(parent).unwrap_or_else(|| panic!("{pointer}"));
            match target {
                Value::Array(a) => a[key.parse::<usize>().unwrap()] = value.clone(),
                Value::Object(o) => {
                    o.insert(key.to_string(), value.clone());
                }
                _ => panic!("{pointer}"),
            }
            let err = error_of(&v);
            assert!(err.contains(want), "{pointer} = {value}: got {err:?}, want {want:?}");
        }
        let err = error_of(&json!([1, 2]));
        assert!(err.contains("expected a scene: an object with width"), "{err}");
        let mut v = valid();
        v.as_object_mut().unwrap().remove("camera");
        assert!(error_of(&v).contains("missing field `camera`"), "{}", error_of(&v));
    }

    #[test]
    fn scene_obj_errors_name_the_obj_and_the_scene_file() {
        let dir = tempfile::tempdir().unwrap();
        let scene_path = dir.path().join("s.json");
        let write_scene = |obj: &str| {
            let mut v = valid();
            v["objects"][0] = json!({ "obj": obj });
            std::fs::write(&scene_path, v.to_string()).unwrap();
        };
        let cases = [
            ("missing.obj", None, "missing.obj: no such file"),
            (
                "nan.obj",
                Some("v 0 0 0\nv 1 0 0\nv 0 NaN 0\nf 1 2 3\n"),
                "nan.obj: vertex position [0.0, NaN, 0.0] is not finite",
            ),
            ("empty.obj", Some("# nothing\n"), "empty.obj: has no faces"),
            ("bad.obj", Some("v 0 0 0\nf 1 2 3\n"), "bad.obj: not a valid OBJ file: face vertex index out of bounds"),
        ];
        for (name, content, want) in cases {
            if let Some(text) = content {
                std::fs::write(dir.path().join(name), text).unwrap();
            }
            write_scene(name);
            let err = Scene::load(&scene_path).unwrap_err().to_string();
            let scene_named = err.starts_with(&format!("{}: objects[0].obj: ", scene_path.display()));
            assert!(scene_named && err.contains(want), "{name}: got {err:?}, want the scene file and {want:?}");
        }
        // A good OBJ beside the scene loads, relative to the scene's folder.
        std::fs::write(dir.path().join("tri.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").unwrap();
        write_scene("tri.obj");
        let s = Scene::load(&scene_path).unwrap();
        assert_eq!(s.objects[0].source, ModelSource::Obj(dir.path().join("tri.obj")));
        assert_eq!(s.objects[0].mesh.vertex_count(), 3);
    }
}
