//! The reference's texturing against values worked out by hand from OpenGL's rules:
//! texel addressing under magnification, the perspective-correct coordinates of a plane
//! seen at an angle (and the rubber sheet without the correction), their derivatives, the
//! level of detail under minification, and the texture environment.

use reference::{fragments, render, Fragment, Options};
use scene::{Tex, TextureRef, Triangle, Trilist, Vertex};
use std::sync::Arc;
use texture::{EnvMode, Filter, MipChain, Sampler, Texture};

/// A texture `w` x `h` whose texel (i, j) is `f(i, j)` (RGB in 0..255), with `sampler`
/// and `env`.
fn texture(w: u32, h: u32, f: impl Fn(u32, u32) -> [u8; 3], sampler: Sampler, env: EnvMode) -> TextureRef {
    let f = &f;
    let bytes: Vec<u8> = (0..h).flat_map(|j| (0..w).flat_map(move |i| f(i, j))).collect();
    let rgba: Vec<u8> = bytes.chunks(3).flat_map(|c| [c[0], c[1], c[2], 255]).collect();
    let mips = MipChain::new(Texture::from_rgba8(w, h, &rgba).unwrap()).unwrap();
    TextureRef { images: vec!["test".into()], sampler, env, format: Default::default(), mips: Arc::new(mips) }
}

/// The screen-aligned square [0, n) x [0, n) mapped to the whole texture (s right, t up),
/// in vertex colour `rgb`, as two triangles.
fn square(n: f64, rgb: [f64; 3]) -> Vec<Triangle> {
    let v = |x: f64, y: f64| Vertex {
        tex: Some(Tex { s: x / n, t: 1.0 - y / n, texture: 0 }),
        ..Vertex::new(x, y, 0.5, rgb)
    };
    vec![[v(0.0, 0.0), v(n, 0.0), v(n, n)], [v(0.0, 0.0), v(n, n), v(0.0, n)]]
}

fn draw(n: u32, triangles: Vec<Triangle>, t: TextureRef) -> reference::Frame {
    let list = Trilist { width: n, height: n, triangles, textures: vec![t] };
    render(&list, &Options::default(), &mut |_| {}).0
}

fn pattern(i: u32, j: u32) -> [u8; 3] {
    [(i * 37 % 256) as u8, (j * 53 % 256) as u8, ((i * j + 7) % 256) as u8]
}

#[test]
fn magnified_nearest_texels_cover_two_by_two_pixels() {
    let sampler = Sampler { mag: Filter::Nearest, ..Sampler::default() };
    let frame = draw(8, square(8.0, [255.0; 3]), texture(4, 4, pattern, sampler, EnvMode::Replace));
    for py in 0..8 {
        for px in 0..8 {
            // s = (px + 0.5) / 8, u = 4 s: texel px / 2; t runs up, pixel rows down.
            let want = pattern(px / 2, 3 - py / 2).map(f64::from);
            assert_eq!(frame.color[(py * 8 + px) as usize], want, "pixel ({px}, {py})");
        }
    }
}

#[test]
fn modulate_multiplies_the_lit_colour_by_the_texel() {
    let sampler = Sampler { mag: Filter::Nearest, ..Sampler::default() };
    let frame = draw(8, square(8.0, [255.0, 102.0, 0.0]), texture(4, 4, pattern, sampler, EnvMode::Modulate));
    let texel = pattern(1, 3).map(f64::from);
    let got = frame.color[2];
    let want = [texel[0], texel[1] * 102.0 / 255.0, 0.0];
    assert!(got.iter().zip(want).all(|(g, w)| (g - w).abs() < 1e-9), "{got:?} against {want:?}");
}

#[test]
fn minified_squares_take_the_level_their_scale_selects() {
    // 64 x 64 texels on 8 x 8 pixels: rho = 8, lambda = 3, level 3 (8 x 8), whose texels
    // are the means of 8 x 8 blocks of the base; pixel centres fall on its texel centres,
    // so the bilinear filter returns them alone.
    let frame = draw(8, square(8.0, [255.0; 3]), texture(64, 64, pattern, Sampler::default(), EnvMode::Replace));
    for py in 0..8u32 {
        for px in 0..8u32 {
            let (bi, bj) = (8 * px, 8 * (7 - py));
            let mut mean = [0.0; 3];
            for j in bj..bj + 8 {
                for i in bi..bi + 8 {
                    for (m, c) in mean.iter_mut().zip(pattern(i, j)) {
                        *m += f64::from(c) / 64.0;
                    }
                }
            }
            let got = frame.color[(py * 8 + px) as usize];
            assert!(got.iter().zip(mean).all(|(g, w)| (g - w).abs() < 1e-9), "({px}, {py}): {got:?} against {mean:?}");
        }
    }
}

/// A floor seen from a pinhole camera on a 64 x 64 screen: the camera-space point
/// (X, -1, Z) projects to x = 32 + 32 X / Z, y = 32 + 32 / Z with w = Z; its texture
/// coordinates are s = (X + 2) / 4, t = (Z - 1) / 8.
fn floor_vertex(x: f64, z: f64) -> Vertex {
    let tex = Some(Tex { s: (x + 2.0) / 4.0, t: (z - 1.0) / 8.0, texture: 0 });
    Vertex { w: Some(z), tex, ..Vertex::new(32.0 + 32.0 * x / z, 32.0 + 32.0 / z, 0.5, [255.0; 3]) }
}

/// The texture coordinates of the floor at screen point (x, y): the ray through it meets
/// the plane Y = -1 at Z = 32 / (y - 32).
fn floor_st(x: f64, y: f64) -> [f64; 2] {
    let z = 32.0 / (y - 32.0);
    let big_x = (x - 32.0) * z / 32.0;
    [(big_x + 2.0) / 4.0, (z - 1.0) / 8.0]
}

fn floor_fragments(ignore_w: bool) -> Vec<Fragment> {
    let tri = [floor_vertex(-2.0, 1.5), floor_vertex(2.0, 1.5), floor_vertex(2.0, 9.0)];
    let mut out = Vec::new();
    let opts = Options { ignore_w, ..Options::default() };
    fragments(&tri, 64, 64, &opts, |f| out.push(f));
    out
}

#[test]
fn perspective_correct_coordinates_follow_the_plane_and_affine_ones_do_not() {
    let frags = floor_fragments(false);
    assert!(frags.len() > 300, "{}", frags.len());
    for f in &frags {
        let want = floor_st(f.x as f64 + 0.5, f.y as f64 + 0.5);
        assert!((f.st[0] - want[0]).abs() < 1e-9 && (f.st[1] - want[1]).abs() < 1e-9, "{f:?} against {want:?}");
    }
    // Screen-linear interpolation of the same triangle: the rubber sheet.
    let worst = floor_fragments(true)
        .iter()
        .map(|f| {
            let want = floor_st(f.x as f64 + 0.5, f.y as f64 + 0.5);
            (f.st[1] - want[1]).abs()
        })
        .fold(0.0, f64::max);
    assert!(worst > 0.1, "affine t is at most {worst} from the plane's");
}

#[test]
fn coordinate_derivatives_are_the_planes_own() {
    let h = 1e-4;
    for f in floor_fragments(false) {
        let (x, y) = (f.x as f64 + 0.5, f.y as f64 + 0.5);
        let dx = std::array::from_fn::<f64, 2, _>(|c| (floor_st(x + h, y)[c] - floor_st(x - h, y)[c]) / (2.0 * h));
        let dy = std::array::from_fn::<f64, 2, _>(|c| (floor_st(x, y + h)[c] - floor_st(x, y - h)[c]) / (2.0 * h));
        for (got, want) in f.dst.iter().zip([dx, dy]) {
            for c in 0..2 {
                assert!((got[c] - want[c]).abs() <= 1e-6 * want[c].abs().max(1e-3), "{f:?}: {got:?} against {want:?}");
            }
        }
    }
}

#[test]
fn each_level_given_shows_where_lambda_selects_it() {
    // Levels of one colour each (64 x 64 down to 1 x 1) on a square of n pixels: rho =
    // 64 / n, lambda = log2(64 / n), and GL_*_MIPMAP_NEAREST takes level
    // ceil(lambda + 1/2) - 1 (magnification, level 0, at lambda <= 0).
    const COLOURS: [[u8; 3]; 7] =
        [[255, 0, 0], [255, 128, 0], [255, 255, 0], [0, 255, 0], [0, 255, 255], [0, 0, 255], [255, 0, 255]];
    let levels: Vec<Texture> = (0..7)
        .map(|k| {
            let side = 64 >> k;
            let rgba: Vec<u8> =
                (0..side * side).flat_map(|_| [COLOURS[k][0], COLOURS[k][1], COLOURS[k][2], 255]).collect();
            Texture::from_rgba8(side, side, &rgba).unwrap()
        })
        .collect();
    let mips = Arc::new(MipChain::from_levels(levels).unwrap());
    let sampler = Sampler { min: Filter::Nearest, ..Sampler::default() };
    for (n, level) in [(64, 0), (46, 0), (45, 1), (32, 1), (16, 2), (12, 2), (11, 3), (8, 3), (2, 5)] {
        let t = TextureRef {
            images: vec!["levels".into()],
            sampler,
            env: EnvMode::Replace,
            format: Default::default(),
            mips: mips.clone(),
        };
        let frame = draw(n, square(n as f64, [255.0; 3]), t);
        let want = COLOURS[level].map(f64::from);
        assert!(frame.color.iter().all(|c| *c == want), "{n} pixels: want level {level}, got {:?}", &frame.color[..1]);
    }
}
