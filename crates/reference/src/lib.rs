//! The f64 reference rasterizer: the image every fixed-point unit is measured against.
//!
//! * samples at pixel centres with the top-left fill rule ([`raster`]);
//! * depth test LESS against a depth buffer cleared to 1.0;
//! * Gouraud colour, screen-linear by default and perspective-correct when the
//!   trilist carries w (unless [`Options::ignore_w`]);
//! * textures as OpenGL 4.6 samples them (section 8.14: the scale factor rho exactly,
//!   level selection, wrap per texel, nearest and bilinear filters; the `texture` crate)
//!   at the texture coordinates interpolated as the colour is, their derivatives exact,
//!   through the texture environment with the lit colour as the fragment's;
//! * framebuffer blending in draw order, per triangle ([`Frame::write_blended`]: paper
//!   001's six blend modes as OpenGL 4.6 section 17.3.6 blends, the `texture` crate's
//!   [`texture::blend()`]);
//! * no culling by default, back faces on request;
//! * clipped to the screen, and per pixel to z in [0, 1]; triangles with a
//!   vertex behind the eye are clipped in homogeneous space first ([`clip`]).
//!
//! It shares no code with the fixed-point models (`model`): the two meet only in
//! tests and in the accuracy harness, so a mistake in one cannot hide in the other.

pub mod clip;
pub mod raster;

pub use raster::{Fragment, RasterVertex};
use scene::{TextureRef, Triangle, Trilist};
use texture::BlendMode;

/// How colours are interpolated across a triangle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Interpolation {
    /// Linear in screen space (classic Gouraud).
    Linear,
    /// Linear in clip space: attribute/w and 1/w interpolated, then divided.
    Perspective,
}

/// Which faces are culled.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Cull {
    /// Draw both faces.
    #[default]
    None,
    /// Drop triangles that run clockwise on screen (front faces run
    /// counter-clockwise as the viewer sees them, OpenGL's default).
    Back,
}

/// Rendering options.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Options {
    pub cull: Cull,
    /// Interpolate colour screen-linearly even when the input carries w.
    pub ignore_w: bool,
    /// Colour of pixels no triangle writes.
    pub background: [f64; 3],
}

impl Default for Options {
    fn default() -> Self {
        Options { cull: Cull::None, ignore_w: false, background: [0.0; 3] }
    }
}

/// What happened to the triangles and samples of one render.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Stats {
    pub triangles_in: u64,
    /// Triangles that reached the rasterizer (whether or not they cover a sample).
    pub drawn: u64,
    /// Back faces dropped by [`Cull::Back`].
    pub culled_back: u64,
    /// Zero-area triangles and triangles with no position in front of the eye.
    pub degenerate: u64,
    /// Covered samples on screen (before the z range and depth tests).
    pub fragments: u64,
    /// Samples dropped because z was outside [0, 1].
    pub z_clipped: u64,
    /// Samples that passed the depth test and were written.
    pub pixels_written: u64,
}

impl Stats {
    /// Triangles that never reached the rasterizer.
    pub fn culled(&self) -> u64 {
        self.culled_back + self.degenerate
    }
}

/// A rendered frame in full precision.
#[derive(Clone, Debug, PartialEq)]
pub struct Frame {
    pub width: u32,
    pub height: u32,
    /// Colour per pixel, row-major from the top-left, in [0, 255].
    pub color: Vec<[f64; 3]>,
    /// Depth per pixel, 1.0 where nothing was written.
    pub depth: Vec<f64>,
    /// Whether any triangle wrote the pixel.
    pub written: Vec<bool>,
    /// Which triangle (index in the list) wrote it last; `u32::MAX` if none.
    /// For analysis: the accuracy harness compares pixels drawn by the same triangle.
    pub writer: Vec<u32>,
}

impl Frame {
    /// A frame cleared to `background` and depth 1.0.
    pub fn new(width: u32, height: u32, background: [f64; 3]) -> Self {
        let n = width as usize * height as usize;
        Frame {
            width,
            height,
            color: vec![background; n],
            depth: vec![1.0; n],
            written: vec![false; n],
            writer: vec![u32::MAX; n],
        }
    }

    /// Depth test LESS, then write a sample of triangle `tri`. Returns whether it was written.
    pub fn write(&mut self, f: &Fragment, tri: u32) -> bool {
        self.write_blended(f, 1.0, BlendMode::Opaque, tri)
    }

    /// Depth test LESS, then blend sample `f` of triangle `tri`, its colour `f.rgb` with
    /// alpha `alpha` in [0, 1], onto the pixel's colour by `mode` (OpenGL 4.6 section
    /// 17.3.6, blend equation FUNC_ADD, [`texture::blend()`]); returns whether it passed.
    /// The frame holds no alpha: the destination's alpha is 1, as GL reads it from a colour
    /// buffer without alpha, and the blended alpha is dropped. [`BlendMode::Opaque`] is
    /// blending disabled: the fragment's colour is stored as it is.
    ///
    /// Depth is written as without blending: blending happens after the depth test and
    /// does not change it or the depth write (section 17.3.4; the depth mask is on), so a
    /// blended fragment that passes stores its z, and later fragments behind it fail
    /// even where it was transparent (alpha 0).
    pub fn write_blended(&mut self, f: &Fragment, alpha: f64, mode: BlendMode, tri: u32) -> bool {
        let i = f.y as usize * self.width as usize + f.x as usize;
        if f.z < self.depth[i] {
            self.depth[i] = f.z;
            self.color[i] = match mode {
                BlendMode::Opaque => f.rgb,
                _ => {
                    let (src, dst) = (f.rgb.map(|c| c / 255.0), self.color[i].map(|c| c / 255.0));
                    let c = texture::blend(mode, [src[0], src[1], src[2], alpha], [dst[0], dst[1], dst[2], 1.0]);
                    [c[0] * 255.0, c[1] * 255.0, c[2] * 255.0]
                }
            };
            self.written[i] = true;
            self.writer[i] = tri;
            true
        } else {
            false
        }
    }

    /// Colour rounded to the nearest 8-bit value.
    pub fn rgb8(&self) -> Vec<[u8; 3]> {
        self.color.iter().map(|c| c.map(|v| v.round().clamp(0.0, 255.0) as u8)).collect()
    }

    /// Depth as 16-bit values: round(depth * 65535).
    pub fn depth16(&self) -> Vec<u16> {
        self.depth.iter().map(|d| (d.clamp(0.0, 1.0) * 65535.0).round() as u16).collect()
    }
}

/// What the reference does with one input triangle.
pub enum Prepared {
    /// Screen-space triangles to rasterize, and the interpolation to use.
    Draw(Vec<[RasterVertex; 3]>, Interpolation),
    /// Dropped before rasterization.
    Culled,
    /// Nothing drawable (zero area, w = 0, wholly behind the eye).
    Degenerate,
}

/// Clip, orient and cull one triangle.
pub fn prepare(tri: &Triangle, opts: &Options) -> Prepared {
    let Ok(parts) = clip::to_screen(tri) else {
        return Prepared::Degenerate;
    };
    // All parts of a clipped triangle share its plane and winding.
    let area2: f64 = parts.iter().map(raster::signed_area2).sum();
    if area2 == 0.0 || !area2.is_finite() {
        return Prepared::Degenerate;
    }
    if opts.cull == Cull::Back && area2 > 0.0 {
        return Prepared::Culled;
    }
    let has_w = tri.iter().any(|v| v.w.is_some());
    let interp = if has_w && !opts.ignore_w { Interpolation::Perspective } else { Interpolation::Linear };
    Prepared::Draw(parts, interp)
}

/// What became of one triangle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Outcome {
    Drawn,
    Culled,
    Degenerate,
}

/// Every covered on-screen sample of one triangle, before the z range and depth
/// tests. The frame-independent half of [`render`]: tests count hits per pixel with it.
pub fn fragments(tri: &Triangle, width: u32, height: u32, opts: &Options, mut emit: impl FnMut(Fragment)) -> Outcome {
    match prepare(tri, opts) {
        Prepared::Culled => Outcome::Culled,
        Prepared::Degenerate => Outcome::Degenerate,
        Prepared::Draw(parts, interp) => {
            for part in &parts {
                raster::rasterize(part, width, height, interp, &mut emit);
            }
            Outcome::Drawn
        }
    }
}

/// Renders a whole triangle list. `progress` is called with the number of
/// triangles done so far, every few hundred triangles and at the end. Each fragment that
/// passes the depth test is blended onto the frame by its triangle's blend mode
/// ([`Frame::write_blended`]), with the texture environment's alpha where the triangle is
/// textured ([`textured`]) and alpha 1 where it is not.
pub fn render(list: &Trilist, opts: &Options, progress: &mut dyn FnMut(usize)) -> (Frame, Stats) {
    let mut frame = Frame::new(list.width, list.height, opts.background);
    let mut stats = Stats { triangles_in: list.triangles.len() as u64, ..Stats::default() };
    for (i, tri) in list.triangles.iter().enumerate() {
        let tex = tri[0].tex.and_then(|x| list.textures.get(x.texture as usize));
        let outcome = fragments(tri, list.width, list.height, opts, |f| {
            let (f, alpha) = match tex {
                Some(t) => {
                    let c = textured(&f, t);
                    (Fragment { rgb: [c[0] * 255.0, c[1] * 255.0, c[2] * 255.0], ..f }, c[3])
                }
                None => (f, 1.0),
            };
            stats.fragments += 1;
            if !(0.0..=1.0).contains(&f.z) {
                stats.z_clipped += 1;
            } else if frame.write_blended(&f, alpha, tri[0].blend, i as u32) {
                stats.pixels_written += 1;
            }
        });
        match outcome {
            Outcome::Drawn => stats.drawn += 1,
            Outcome::Culled => stats.culled_back += 1,
            Outcome::Degenerate => stats.degenerate += 1,
        }
        if i % 256 == 255 {
            progress(i + 1);
        }
    }
    progress(list.triangles.len());
    (frame, stats)
}

/// The colour and alpha, in [0, 1], of fragment `f` of a triangle textured by `t`: what
/// `t`'s sampler gives at the fragment's texture coordinates and level of detail
/// (lambda = log2 rho, rho exact from the coordinates' derivatives in texels of level 0:
/// OpenGL 4.6 section 8.14.1), through `t`'s texture environment with the lit colour as the
/// fragment's (alpha 1, the environment colour GL's default, transparent black).
pub fn textured(f: &Fragment, t: &TextureRef) -> texture::Rgba {
    let base = t.mips.base();
    let (w, h) = (base.width() as f64, base.height() as f64);
    let [[sx, tx], [sy, ty]] = f.dst;
    let lambda = texture::lambda(texture::rho_exact(sx * w, tx * h, sy * w, ty * h));
    let cs = texture::sample(&t.mips, &t.sampler, f.st[0], f.st[1], lambda);
    let cf = [f.rgb[0] / 255.0, f.rgb[1] / 255.0, f.rgb[2] / 255.0, 1.0];
    texture::environment(t.env, cf, cs, [0.0; 4])
}
