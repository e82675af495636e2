//! The model of `rtl::raster_top`, the whole scanline rasterizer of papers 001 and 003
//! (`cull_sort` -> `triangle_setup` with the `divider` -> `edge_walk` -> `span` ->
//! `pixel_out`) at the formats its RTL is built with, [`formats`]: a frame as the hardware
//! sees it. Its triangles as the input words the hardware takes, the memory writes it makes
//! in order, its image ([`raster::render`], `Method::Scanline`) and its cycle count
//! ([`cycles::scanline_frame`]).

use crate::cull_sort::{z_max, Clip, Cull};
use crate::cycles::{self, Timing};
use crate::input::{to_fixed, InputError, Vtx};
use crate::pixel_out::Framebuffer;
use crate::raster::{self, triangle, Method, Options, Render};
use crate::span::Pixel;
use fx::{Formats, RTL_CLASS};
use scene::Trilist;

/// The formats `raster_top` is built with: the defaults of size class [`RTL_CLASS`]
/// (screens up to 1024 x 1024).
pub const fn formats() -> Formats {
    Formats::for_n(RTL_CLASS)
}

/// Largest screen side `raster_top` draws: its pixel coordinates are `RTL_CLASS` bits.
pub const MAX_SIDE: u32 = 1 << RTL_CLASS;

/// One frame through `raster_top`, as the model draws it.
pub struct Frame {
    /// The triangles sent, as input words (`model::input::to_fixed`), in input order.
    pub triangles: Vec<[Vtx; 3]>,
    /// Triangles left out because their vertices do not fit the input formats, by index.
    pub skipped: Vec<(usize, InputError)>,
    /// The render: image, depth buffer, statistics, per-triangle work.
    pub render: Render,
    /// Per triangle sent, the pixels it sends to `pixel_out` (depth reads).
    pub fragments: Vec<usize>,
    /// The memory writes, in the order `pixel_out` makes them.
    pub writes: Vec<Pixel>,
}

impl Frame {
    /// The frame's cycles, from the first triangle offered to `done`
    /// ([`cycles::scanline_frame`], triangles back to back, memory always ready).
    pub fn cycles(&self) -> u64 {
        cycles::scanline_frame(&self.render.work, &Timing::default()).total
    }
}

/// `list` drawn with `cull` on `background` by `raster_top`; an error for a screen larger
/// than [`MAX_SIDE`].
pub fn frame(list: &Trilist, cull: Cull, background: [u8; 3]) -> Result<Frame, String> {
    if list.width > MAX_SIDE || list.height > MAX_SIDE {
        return Err(format!(
            "raster_top draws screens up to {MAX_SIDE}x{MAX_SIDE}, not {}x{}",
            list.width, list.height
        ));
    }
    let f = formats();
    let opts = Options { method: Method::Scanline, cull, analysis: false, background };
    let clip = Clip { width: list.width, height: list.height };
    let (mut triangles, mut skipped, mut fragments, mut writes) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    let mut fb = Framebuffer::new(list.width, list.height, z_max(&f) as u32, background);
    for (i, t) in list.triangles.iter().enumerate() {
        match to_fixed(t, &f) {
            Ok(v) => {
                triangles.push(v);
                let pixels = triangle(t, clip, &f, &opts).0.map_or(Vec::new(), |t| t.pixels);
                fragments.push(pixels.len());
                writes.extend(pixels.into_iter().filter(|p| fb.pixel_out(p, i as u32)));
            }
            Err(e) => skipped.push((i, e)),
        }
    }
    let render = raster::render(list, &f, &opts, &mut |_| {});
    debug_assert!(render.fb == fb, "the same pixels, through the same depth test");
    Ok(Frame { triangles, skipped, render, fragments, writes })
}

#[cfg(test)]
mod tests {
    use super::*;
    use scene::{Triangle, Vertex};

    fn tri(p: [(f64, f64, f64); 3]) -> Triangle {
        p.map(|(x, y, z)| Vertex::new(x, y, z, [200.0, 100.0, 50.0]))
    }

    #[test]
    fn raster_top_frame_writes_in_order_and_counts_fragments() {
        // Two overlapping triangles, the second nearer: every pixel of the overlap is
        // written twice, the first triangle's pixels first.
        let far = tri([(1.0, 1.0, 0.6), (15.0, 1.0, 0.6), (1.0, 15.0, 0.6)]);
        let near = tri([(2.0, 2.0, 0.2), (14.0, 2.0, 0.2), (2.0, 14.0, 0.2)]);
        let list = Trilist { width: 16, height: 16, triangles: vec![far, near] };
        let f = frame(&list, Cull::None, [0; 3]).expect("a 16 x 16 frame");
        assert_eq!(f.triangles.len(), 2);
        assert!(f.skipped.is_empty());
        assert_eq!(f.fragments.iter().sum::<usize>() as u64, f.render.stats.fragments);
        assert_eq!(f.writes.len() as u64, f.render.stats.pixels_written);
        // All of the near triangle's pixels pass the depth test; they come last.
        assert_eq!(f.writes.len(), f.fragments[0] + f.fragments[1]);
        let mut replay = Framebuffer::new(16, 16, z_max(&formats()) as u32, [0; 3]);
        for w in &f.writes {
            assert!(replay.pixel_out(w, 0), "each write passes the depth test in order: {w:?}");
        }
        assert_eq!(replay.rgb, f.render.fb.rgb);
        assert!(f.cycles() > f.writes.len() as u64);
    }

    #[test]
    fn raster_top_frame_rejects_large_screens_and_skips_unrepresentable_triangles() {
        let list = Trilist { width: MAX_SIDE + 1, height: 16, triangles: vec![] };
        let err = frame(&list, Cull::None, [0; 3]).err().expect("a 1025-pixel-wide screen is refused");
        assert!(err.contains("up to 1024x1024"), "{err}");
        // x beyond the S11.4 vertex format's range: skipped, the other one drawn.
        let huge = tri([(5000.0, 1.0, 0.5), (1.0, 1.0, 0.5), (1.0, 9.0, 0.5)]);
        let ok = tri([(1.0, 1.0, 0.5), (9.0, 1.0, 0.5), (1.0, 9.0, 0.5)]);
        let f = frame(&Trilist { width: 16, height: 16, triangles: vec![huge, ok] }, Cull::None, [0; 3])
            .expect("a 16 x 16 frame");
        assert_eq!((f.triangles.len(), f.skipped.len(), f.skipped[0].0), (1, 1, 0));
        assert!(!f.writes.is_empty());
    }
}
