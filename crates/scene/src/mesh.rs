//! Triangle meshes in object space, and loading them from Wavefront OBJ files.

use crate::error::{Error, Result};
use crate::math::{add, cross, dot, face_normal, normalize, Vec3};
use std::collections::HashMap;
use std::path::{Path, PathBuf};

/// One mesh vertex: object-space position, unit normal and texture coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MeshVertex {
    pub position: Vec3,
    pub normal: Vec3,
    /// Texture coordinates (s, t): OpenGL's, (0, 0) the image's bottom-left corner, as an
    /// OBJ file's `vt`; (0, 0) where the mesh has none.
    pub uv: [f64; 2],
    /// The index in [`Mesh::textures`] of the image its triangle's material maps (the
    /// three vertices of a triangle agree); `None` for an untextured triangle.
    pub texture: Option<u16>,
}

/// A triangle soup: every triangle carries its own three vertices, the way the
/// geometry stage sends them to the rasterizer. Front faces run counter-clockwise
/// seen from outside (OpenGL's default).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Mesh {
    pub triangles: Vec<[MeshVertex; 3]>,
    /// The images its materials map onto it (an OBJ material's `map_Kd`, resolved against
    /// the MTL file's folder), each once.
    pub textures: Vec<PathBuf>,
    /// Whether its vertices carry texture coordinates of their own (every built-in model;
    /// an OBJ whose faces all give `vt`).
    pub has_uv: bool,
}

impl Mesh {
    /// Vertices as sent to the rasterizer: 3 per triangle.
    pub fn vertex_count(&self) -> usize {
        3 * self.triangles.len()
    }

    /// Checks that the mesh has triangles and only finite positions and normals.
    pub fn check(&self) -> std::result::Result<(), String> {
        if self.triangles.is_empty() {
            return Err("has no triangles".into());
        }
        for (t, tri) in self.triangles.iter().enumerate() {
            for (k, v) in tri.iter().enumerate() {
                if v.position.iter().chain(&v.normal).any(|c| !c.is_finite()) {
                    return Err(format!(
                        "triangle {t} vertex {k} is not finite (position {:?}, normal {:?})",
                        v.position, v.normal
                    ));
                }
            }
        }
        Ok(())
    }

    /// Checks that the mesh is a closed surface wound consistently outward:
    /// every edge (by vertex position) is run once in each direction by two
    /// triangles, and the enclosed volume is positive. The error says which
    /// edge or that the surface is inside out.
    pub fn check_closed(&self) -> std::result::Result<(), String> {
        let key = |p: &Vec3| p.map(|c| (c + 0.0).to_bits());
        let mut edges: HashMap<([u64; 3], [u64; 3]), usize> = HashMap::new();
        for tri in &self.triangles {
            for k in 0..3 {
                let (a, b) = (&tri[k].position, &tri[(k + 1) % 3].position);
                *edges.entry((key(a), key(b))).or_default() += 1;
            }
        }
        let at = |k: &[u64; 3]| k.map(f64::from_bits);
        for ((a, b), n) in &edges {
            let back = edges.get(&(*b, *a)).copied().unwrap_or(0);
            if *n != 1 || back != 1 {
                return Err(format!(
                    "edge {:?} -> {:?} is run {n} time(s) that way and {back} time(s) back (want 1 and 1)",
                    at(a),
                    at(b)
                ));
            }
        }
        // Divergence theorem: the volume is the sum of the tetrahedra the
        // faces make with the origin; outward winding makes it positive.
        let volume: f64 =
            self.triangles.iter().map(|t| dot(t[0].position, cross(t[1].position, t[2].position))).sum::<f64>() / 6.0;
        if volume <= 0.0 {
            return Err(format!("encloses volume {volume}: the faces are wound inward"));
        }
        Ok(())
    }

    /// Loads an OBJ file: polygons are triangulated as fans, every object and
    /// group in the file goes into the one mesh. Normals come from the file (`vn`,
    /// referenced by every face); a file without them gets smooth normals, see
    /// [`smooth_normals`]. Texture coordinates (`vt`) are kept when every face has
    /// them; each material's `map_Kd` (the MTL files, `mtllib`, relative to the OBJ's
    /// folder, the image relative to the MTL's) textures the faces that use it, the faces
    /// of a material without one are drawn untextured; a textured mesh whose faces do not
    /// all give `vt` is an error. Errors name the file and say what is wrong.
    pub fn load_obj(path: &Path) -> Result<Mesh> {
        let text = std::fs::read_to_string(path).map_err(|e| Error::io(path, e))?;
        let dir = path.parent().unwrap_or(Path::new("."));
        Self::parse_obj(&text, Some(dir)).map_err(|msg| Error::invalid(msg).in_file(path))
    }

    /// Parses OBJ text without its materials (see [`Mesh::load_obj`]); the error is the
    /// message alone.
    pub fn from_obj_text(text: &str) -> std::result::Result<Mesh, String> {
        Self::parse_obj(text, None)
    }

    /// Parses OBJ text, its MTL files read from `dir` (none without it).
    fn parse_obj(text: &str, dir: Option<&Path>) -> std::result::Result<Mesh, String> {
        let opts =
            tobj::LoadOptions { triangulate: true, ignore_points: true, ignore_lines: true, ..Default::default() };
        let mtl = |p: &Path| match dir {
            Some(d) => tobj::load_mtl(d.join(p)),
            None => Ok((Vec::new(), Default::default())),
        };
        let (models, materials) =
            tobj::load_obj_buf(&mut text.as_bytes(), &opts, mtl).map_err(|e| format!("not a valid OBJ file: {e}"))?;
        let materials = materials.map_err(|e| format!("its material library cannot be read: {e}"))?;
        let mut positions: Vec<[Vec3; 3]> = Vec::new();
        let mut normals: Vec<[Vec3; 3]> = Vec::new();
        let mut uvs: Vec<[[f64; 2]; 3]> = Vec::new();
        let (mut all_have_normals, mut all_have_uv) = (true, true);
        let mut textures: Vec<PathBuf> = Vec::new();
        let mut texture_of: Vec<Option<u16>> = Vec::new();
        // tobj gives a face without `vt` a neighbour's coordinates when the file has some:
        // ask the text whether every face names its own.
        all_have_uv &= every_face_has_vt(text);
        for model in &models {
            let m = &model.mesh;
            let at = |data: &[f32], i: u32| -> Vec3 { std::array::from_fn(|c| data[3 * i as usize + c] as f64) };
            let has_normals = m.normal_indices.len() == m.indices.len();
            let has_uv = m.texcoord_indices.len() == m.indices.len();
            all_have_normals &= has_normals;
            all_have_uv &= has_uv;
            let image = m.material_id.and_then(|i| materials.get(i)).and_then(|mat| mat.diffuse_texture.as_ref());
            let texture = match (image, dir) {
                (Some(image), Some(dir)) => {
                    let image = dir.join(image);
                    let at = textures.iter().position(|t| *t == image).unwrap_or(textures.len());
                    if at == textures.len() {
                        textures.push(image);
                    }
                    Some(u16::try_from(at).map_err(|_| format!("its materials map more than {} images", u16::MAX))?)
                }
                _ => None,
            };
            for (t, tri) in m.indices.chunks_exact(3).enumerate() {
                positions.push(std::array::from_fn(|k| at(&m.positions, tri[k])));
                if has_normals {
                    normals.push(std::array::from_fn(|k| at(&m.normals, m.normal_indices[3 * t + k])));
                }
                let uv = |k: usize| {
                    let i = 2 * m.texcoord_indices[3 * t + k] as usize;
                    [m.texcoords[i] as f64, m.texcoords[i + 1] as f64]
                };
                uvs.push(if has_uv { std::array::from_fn(uv) } else { [[0.0; 2]; 3] });
                texture_of.push(texture);
            }
        }
        if positions.is_empty() {
            return Err("has no faces (a mesh needs at least one triangle)".into());
        }
        if let Some(p) = positions.iter().flatten().find(|p| p.iter().any(|c| !c.is_finite())) {
            return Err(format!("vertex position {p:?} is not finite"));
        }
        if let Some(uv) = uvs.iter().flatten().find(|uv| uv.iter().any(|c| !c.is_finite())) {
            return Err(format!("texture coordinate {uv:?} is not finite"));
        }
        if let (Some(image), false) = (textures.first(), all_have_uv) {
            return Err(format!(
                "its material maps {} but not every face has texture coordinates (vt)",
                image.display()
            ));
        }
        let normals = if all_have_normals {
            let mut unit = Vec::with_capacity(normals.len());
            for tri in &normals {
                let mut out = [[0.0; 3]; 3];
                for (o, n) in out.iter_mut().zip(tri) {
                    *o = unit_normal(*n)?;
                }
                unit.push(out);
            }
            unit
        } else {
            smooth_normals(&positions)
        };
        let triangles = positions
            .iter()
            .zip(&normals)
            .zip(&uvs)
            .zip(&texture_of)
            .map(|(((p, n), uv), &texture)| {
                std::array::from_fn(|k| MeshVertex { position: p[k], normal: n[k], uv: uv[k], texture })
            })
            .collect();
        let mesh = Mesh { triangles, textures, has_uv: all_have_uv };
        mesh.check()?;
        Ok(mesh)
    }
}

/// Whether every face (`f`) of OBJ `text` gives each of its vertices a texture
/// coordinate (`v/vt` or `v/vt/vn`).
fn every_face_has_vt(text: &str) -> bool {
    text.lines()
        .filter_map(|l| l.trim_start().strip_prefix("f "))
        .flat_map(str::split_whitespace)
        .all(|vertex| vertex.split('/').nth(1).is_some_and(|vt| !vt.is_empty()))
}

/// A normal from a file, made unit length.
fn unit_normal(n: Vec3) -> std::result::Result<Vec3, String> {
    if n.iter().any(|c| !c.is_finite()) {
        return Err(format!("normal {n:?} is not finite"));
    }
    normalize(n).ok_or_else(|| format!("normal {n:?} has zero length"))
}

/// Per-vertex normals for a triangle soup that has none: at each vertex, the
/// average of the unit normals of the faces sharing its position (paper 000,
/// "the average of the normal vectors of the faces that share the vertex").
/// A vertex whose neighbours cancel out, and any vertex of a zero-area
/// triangle, falls back to its own face's normal, or to +z if that has none.
pub fn smooth_normals(triangles: &[[Vec3; 3]]) -> Vec<[Vec3; 3]> {
    // `+ 0.0` merges -0.0 into 0.0, which compare equal but differ in bits.
    let key = |p: &Vec3| p.map(|c| (c + 0.0).to_bits());
    let unit_faces: Vec<Option<Vec3>> = triangles.iter().map(|t| normalize(face_normal(t[0], t[1], t[2]))).collect();
    let mut sums: HashMap<[u64; 3], Vec3> = HashMap::new();
    for (tri, n) in triangles.iter().zip(&unit_faces) {
        for p in tri {
            let sum = sums.entry(key(p)).or_insert([0.0; 3]);
            *sum = add(*sum, n.unwrap_or([0.0; 3]));
        }
    }
    triangles
        .iter()
        .zip(&unit_faces)
        .map(|(tri, face)| {
            tri.map(|p| {
                let fallback = face.unwrap_or([0.0, 0.0, 1.0]);
                face.and(normalize(sums[&key(&p)])).unwrap_or(fallback)
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    const TETRA: &str = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

    #[test]
    fn obj_without_normals_gets_face_averaged_normals() {
        let mesh = Mesh::from_obj_text(TETRA).unwrap();
        assert_eq!(mesh.vertex_count(), 12);
        // The origin corner is shared by the faces with normals -x, -y, -z.
        let origin = mesh.triangles[0][0];
        assert_eq!(origin.position, [0.0; 3]);
        let k = -1.0 / 3f64.sqrt();
        for c in 0..3 {
            assert!((origin.normal[c] - k).abs() < 1e-12, "{:?}", origin.normal);
        }
    }

    #[test]
    fn mesh_check_closed_finds_holes_flips_and_inside_out_surfaces() {
        let mesh = Mesh::from_obj_text(TETRA).unwrap();
        mesh.check_closed().unwrap();
        let mut open = mesh.clone();
        open.triangles.pop();
        assert!(open.check_closed().unwrap_err().contains("0 time(s) back"));
        let mut flipped = mesh.clone();
        flipped.triangles[1].swap(0, 1);
        assert!(flipped.check_closed().unwrap_err().contains("run 2 time(s)"));
        let mut inside_out = mesh;
        inside_out.triangles.iter_mut().for_each(|t| t.swap(0, 1));
        assert!(inside_out.check_closed().unwrap_err().contains("wound inward"));
    }

    #[test]
    fn obj_normals_and_quads_come_from_the_file() {
        let quad = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 2\nf 1//1 2//1 3//1 4//1\n";
        let mesh = Mesh::from_obj_text(quad).unwrap();
        assert_eq!(mesh.triangles.len(), 2);
        assert!(mesh.triangles.iter().flatten().all(|v| v.normal == [0.0, 0.0, 1.0]));
    }

    #[test]
    fn obj_rejects_empty_and_non_finite_meshes() {
        let err = Mesh::from_obj_text("v 0 0 0\n").unwrap_err();
        assert!(err.contains("has no faces"), "{err}");
        let err = Mesh::from_obj_text("v 0 0 0\nv 1 0 0\nv 0 nan 0\nf 1 2 3\n").unwrap_err();
        assert!(err.contains("not finite"), "{err}");
        let err = Mesh::from_obj_text("v 0 0 0\nv 1 0 0\nv 0 inf 0\nf 1 2 3\n").unwrap_err();
        assert!(err.contains("not finite"), "{err}");
        let err = Mesh::from_obj_text("v 0 0 0\nf 1 2 3\n").unwrap_err();
        assert!(err.contains("not a valid OBJ file"), "{err}");
    }
}
