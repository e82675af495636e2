//! The model of `rtl::raster_top`, the whole rasterizer: the scanline method of papers 001
//! and 003 (`cull_sort` -> `triangle_setup` with the `divider` -> `edge_walk` -> `span` ->
//! `pixel_out`), or with `METHOD = 1` the barycentric method of 004 (`cull_sort` -> `vector`
//! -> `pixel_out`), at a build of its RTL (`fx::Build`: size class and formats): a frame as
//! the hardware sees it. Its triangles as the input words the hardware takes, the memory
//! writes it makes in order, its image ([`render::render`]) and its cycle count
//! ([`cycles::scanline_frame`], [`cycles::vector_frame`]).

use crate::cull_sort::{cull_sort, z_max, Clip, Cull, Sorted};
use crate::cycles::{self, Timing};
use crate::guard_band;
use crate::input::{to_fixed, InputError, Vtx};
use crate::pixel_out::Framebuffer;
use crate::render::{self, triangle, Method, Options, Render};
use crate::span::Pixel;
use fx::{Build, SMALLEST_CLASS};
use scene::Trilist;

/// The largest size class `raster_top` is built for (`rtl::CLASSES`: 10 to 12; a custom
/// build may have a class from `fx::SMALLEST_CLASS`, 8, up).
pub const MAX_CLASS: u32 = 12;

/// The lanes `raster_top`'s vector unit is built with (`rtl::vector`'s `LANES`).
pub const LANES: [u32; 4] = [1, 2, 4, 8];

/// One frame through `raster_top`, as the model draws it.
pub struct RasterTopOut {
    /// The size class of the `raster_top` drawing it and the formats it is built at.
    pub build: Build,
    /// Its method: `Scanline`, or `Vector` with 1, 2, 4 or 8 lanes ([`LANES`]).
    pub method: Method,
    /// The triangles sent, as input words (`model::input::to_fixed`), in input order: the
    /// front end's pieces (`model::guard_band`).
    pub triangles: Vec<[Vtx; 3]>,
    /// Triangles left out because their vertices do not fit the input formats, by index.
    pub skipped: Vec<(usize, InputError)>,
    /// The render: image, depth buffer, statistics, per-triangle work.
    pub render: Render,
    /// The triangles `cull_sort` passes, in order: what a host that culls and sorts sends
    /// to a `raster_top` without `cull_sort` (`CULL_SORT = 0`).
    pub sorted: Vec<Sorted>,
    /// Per triangle sent, the pixels it sends to `pixel_out` (depth reads).
    pub fragments: Vec<usize>,
    /// Every fragment `span` sends, in order: the output of a `raster_top` without
    /// `pixel_out` (`PIXEL_OUT = 0`).
    pub pixels: Vec<Pixel>,
    /// The memory writes, in the order `pixel_out` makes them.
    pub writes: Vec<Pixel>,
}

impl RasterTopOut {
    /// The frame's cycles, from the first triangle offered to `done`
    /// ([`cycles::scanline_frame`] or [`cycles::vector_frame`], triangles back to back,
    /// memory always ready).
    pub fn cycles(&self) -> u64 {
        self.cycles_with(&Timing::default())
    }

    /// The frame's cycles with the units and parameters of `timing`.
    pub fn cycles_with(&self, timing: &Timing) -> u64 {
        match self.method {
            Method::Scanline => cycles::scanline_frame(&self.render.work, timing).total,
            Method::Vector { .. } => cycles::vector_frame(&self.render.work, timing).total,
        }
    }

    /// The frame's cycles with the memory ready in the cycles `ready` says
    /// ([`cycles::scanline_frame_stalled`]); the scanline method only: an error for the
    /// vector method, whose cycle model assumes a memory that never stalls.
    pub fn cycles_stalled(&self, timing: &Timing, ready: &dyn Fn(u64) -> bool) -> Result<u64, String> {
        match self.method {
            Method::Scanline => Ok(cycles::scanline_frame_stalled(&self.render.work, timing, ready).total),
            Method::Vector { .. } => Err("the vector method's cycle model has a memory that never stalls".into()),
        }
    }
}

/// `list` drawn with `cull` on `background` by the scanline `raster_top` of `build`
/// ([`raster_top_by`] with `Method::Scanline`).
pub fn raster_top(build: &Build, list: &Trilist, cull: Cull, background: [u8; 3]) -> Result<RasterTopOut, String> {
    raster_top_by(build, list, cull, background, Method::Scanline)
}

/// `list` drawn with `cull` on `background` by the `raster_top` of `build` and `method`
/// (the vector method at the lanes `rtl::vector` is built with, [`LANES`]): a size class
/// (which may be larger than the screen needs; `Build::for_screen` gives the smallest) and
/// the formats it is built at (the class's defaults, or those of `rtl::custom`); an error
/// for a class not built, a screen larger than 2^class, or formats that do not work on a
/// 2^class screen.
pub fn raster_top_by(
    build: &Build,
    list: &Trilist,
    cull: Cull,
    background: [u8; 3],
    method: Method,
) -> Result<RasterTopOut, String> {
    if let Method::Vector { lanes, .. } = method {
        if !LANES.contains(&lanes) {
            return Err(format!("raster_top's vector unit has 1, 2, 4 or 8 lanes, not {lanes}"));
        }
    }
    let Build { class, formats: f } = *build;
    if !(SMALLEST_CLASS..=MAX_CLASS).contains(&class) {
        let side = 1u64 << class.min(63);
        return Err(format!(
            "a {}x{} screen needs size class {class} ({side}x{side}); raster_top is built for classes \
             {SMALLEST_CLASS} to {MAX_CLASS} (screens up to {m}x{m})",
            list.width,
            list.height,
            m = 1u32 << MAX_CLASS
        ));
    }
    let side = 1u32 << class;
    if list.width > side || list.height > side {
        return Err(format!(
            "raster_top of size class {class} draws screens up to {side}x{side}, not {}x{}",
            list.width, list.height
        ));
    }
    f.check(side, side)?;
    let opts = Options { method, cull, analysis: false, background };
    let clip = Clip { width: list.width, height: list.height };
    let (mut triangles, mut skipped, mut sorted) = (Vec::new(), Vec::new(), Vec::new());
    let (mut fragments, mut pixels, mut writes) = (Vec::new(), Vec::new(), Vec::new());
    let mut fb = Framebuffer::new(list.width, list.height, z_max(&f) as u32, background);
    let pieces = guard_band::pieces(list, &f, false);
    for (t, &i) in pieces.triangles.iter().zip(&pieces.source) {
        match to_fixed(t, &f) {
            Ok(v) => {
                sorted.extend(cull_sort(&v, clip, cull, &f));
                triangles.push(v);
                let drawn = triangle(t, clip, &f, &opts).0.map_or(Vec::new(), |t| t.pixels);
                fragments.push(drawn.len());
                writes.extend(drawn.iter().filter(|p| fb.pixel_out(p, i as u32)));
                pixels.extend(drawn);
            }
            Err(e) => skipped.push((i, e)),
        }
    }
    let render = render::render(list, &f, &opts, &mut |_| {});
    debug_assert!(render.fb == fb, "the same pixels, through the same depth test");
    Ok(RasterTopOut { build: *build, method, triangles, skipped, sorted, render, fragments, pixels, writes })
}

/// One frame through `raster_top`'s SE back end (`METHOD = 2`).
pub struct RasterTopSeOut {
    /// The scanline front end's frame: the input words sent, the triangles culled, the
    /// work of each (its spans' rows and whether they meet the screen).
    pub front: RasterTopOut,
    /// The image and depth the engines draw (`se::array::render`).
    pub fb: Framebuffer,
    /// Pixels the engines wrote.
    pub pixels_written: u64,
    /// The frame's cycles ([`cycles::se_frame`], triangles back to back).
    pub cycles: u64,
}

/// `list` drawn with `cull` on `background` by the SE back end of `build` (the class's
/// default formats; an error where the engine array cannot draw the screen).
pub fn raster_top_se(build: &Build, list: &Trilist, cull: Cull, background: [u8; 3]) -> Result<RasterTopSeOut, String> {
    let front = raster_top_by(build, list, cull, background, Method::Scanline)?;
    let f = &build.formats;
    let se = crate::se::array::render(list, f, cull, background)?;
    let prm = crate::se::array::array_params(list.width, f)?;
    let cycles = cycles::se_frame(&front.render.work, &Timing::default(), &prm, crate::se_cmd::ready_after(f)).total;
    Ok(RasterTopSeOut { front, fb: se.fb, pixels_written: se.pixels_written, cycles })
}

#[cfg(test)]
mod tests {
    use super::*;
    use scene::{Triangle, Vertex};

    fn tri(p: [(f64, f64, f64); 3]) -> Triangle {
        p.map(|(x, y, z)| Vertex::new(x, y, z, [200.0, 100.0, 50.0]))
    }

    #[test]
    fn raster_top_writes_in_order_and_counts_fragments() {
        // Two overlapping triangles, the second nearer: every pixel of the overlap is
        // written twice, the first triangle's pixels first.
        let far = tri([(1.0, 1.0, 0.6), (15.0, 1.0, 0.6), (1.0, 15.0, 0.6)]);
        let near = tri([(2.0, 2.0, 0.2), (14.0, 2.0, 0.2), (2.0, 14.0, 0.2)]);
        let list = Trilist { width: 16, height: 16, triangles: vec![far, near], textures: Vec::new() };
        let f = raster_top(&Build::for_screen(16, 16), &list, Cull::None, [0; 3]).expect("a 16 x 16 frame");
        assert_eq!(f.triangles.len(), 2);
        assert!(f.skipped.is_empty());
        assert_eq!(f.fragments.iter().sum::<usize>() as u64, f.render.stats.fragments);
        assert_eq!(f.writes.len() as u64, f.render.stats.pixels_written);
        // All of the near triangle's pixels pass the depth test; they come last.
        assert_eq!(f.writes.len(), f.fragments[0] + f.fragments[1]);
        let mut replay = Framebuffer::new(16, 16, z_max(&fx::Formats::for_n(fx::RTL_CLASS)) as u32, [0; 3]);
        for w in &f.writes {
            assert!(replay.pixel_out(w, 0), "each write passes the depth test in order: {w:?}");
        }
        assert_eq!(replay.rgb, f.render.fb.rgb);
        assert!(f.cycles() > f.writes.len() as u64);
        // Both pass cull_sort; every fragment is sent, the writes are those that pass.
        assert_eq!(f.sorted.len(), 2);
        assert_eq!(f.pixels.len(), f.fragments[0] + f.fragments[1]);
        assert_eq!(f.pixels, f.writes);
    }

    #[test]
    fn raster_top_picks_the_size_class_and_rejects_larger_screens() {
        let screen = |width, height| Trilist { width, height, triangles: vec![], textures: Vec::new() };
        assert_eq!([(320, 240), (1025, 16), (16, 4096)].map(|(w, h)| Build::for_screen(w, h).class), [10, 11, 12]);
        let err = raster_top(&Build::for_screen(4097, 16), &screen(4097, 16), Cull::None, [0; 3])
            .err()
            .expect("a 4097-pixel-wide screen is refused");
        assert!(err.contains("classes 8 to 12 (screens up to 4096x4096)"), "{err}");
        let err = raster_top(&Build::of_class(10), &screen(1025, 16), Cull::None, [0; 3])
            .err()
            .expect("too wide for class 10");
        assert!(err.contains("up to 1024x1024, not 1025x16"), "{err}");
        assert!(raster_top(&Build::of_class(7), &screen(16, 16), Cull::None, [0; 3]).is_err(), "class 7 is not built");
        assert!(
            raster_top(&Build::of_class(9), &screen(320, 240), Cull::None, [0; 3]).is_ok(),
            "a custom build's class"
        );
        assert!(raster_top(&Build::of_class(12), &screen(1025, 16), Cull::None, [0; 3]).is_ok());
        // x beyond the S11.4 vertex format's range: clipped to it (`guard_band`), sent as
        // its pieces. A colour beyond U8.0 cannot be represented: skipped, the rest drawn.
        let huge = tri([(5000.0, 1.0, 0.5), (1.0, 1.0, 0.5), (1.0, 9.0, 0.5)]);
        let mut bright = tri([(1.0, 1.0, 0.4), (9.0, 1.0, 0.4), (1.0, 9.0, 0.4)]);
        bright[0].r = 300.0;
        let list = Trilist { width: 16, height: 16, triangles: vec![huge, bright], textures: Vec::new() };
        let f = raster_top(&Build::for_screen(16, 16), &list, Cull::None, [0; 3]).expect("a 16 x 16 frame");
        assert_eq!((f.triangles.len(), f.skipped.len(), f.skipped[0].0), (2, 1, 1));
        assert_eq!((f.skipped[0].1.vertex, f.skipped[0].1.quantity), (0, "r"));
        assert!(f.writes.len() > 100, "the huge triangle's pieces cover most of the screen");
    }
}
