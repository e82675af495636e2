//! The model of `rtl::gpu_top`, a frame at a time: what the core leaves in the colour and
//! depth buffers and in its registers after a frame of a vertex buffer. Its cycles are not
//! modelled here: every unit inside is cycle-exact to its own model (`command_parser`,
//! `triangle_queue`, `cull_sort`, ..., `pixel_bus`, `gpu_regs`), and the frame's pixels are
//! [`raster_top`](crate::raster_top)'s.

use crate::command_parser::{self, Bench, Outcome, Params};
use crate::cull_sort::Cull;
use crate::pixel_bus::color_word;
use crate::raster_top::raster_top;
use crate::vertex_buffer::{words_trilist, Fault, VertexBuffer};
use fx::Build;

/// `STATUS` bits (`gpu_regs::Reg::Status`): busy, the frame failed, the parser's fault code
/// (4 bits), a pixel transfer answered with an error, the parser's state (3 bits).
pub const BUSY: u32 = 1;
pub const FAILED: u32 = 1 << 1;
pub const FAULT_SHIFT: u32 = 4;
pub const BUS_ERROR: u32 = 1 << 8;
pub const STATE_SHIFT: u32 = 9;

/// `STATUS` after a frame that ended with `fault` (none: done), the parser back in INIT
/// or stopped in Error (the state bits are left out: `status & 0x1ff`).
pub fn status(fault: Option<Fault>) -> u32 {
    fault.map_or(0, |f| FAILED | (f as u32) << FAULT_SHIFT)
}

/// The largest screen (width, height) buffers of `SCREEN` = `screen` and these pitches (bytes
/// a row, 4 a pixel) hold: the command parser's `screen` input in `gpu_top`.
pub fn screen_limit(screen: u32, color_pitch: u16, depth_pitch: u16) -> [u32; 2] {
    let width = (screen & 0xffff).min(u32::from(color_pitch / 4)).min(u32::from(depth_pitch / 4));
    [width, screen >> 16]
}

/// A frame's result.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Frame {
    /// The colour (`0x00RRGGBB`) and depth words of each pixel, row-major, as the buffers
    /// hold them after a cleared frame.
    pub color: Vec<u32>,
    pub depth: Vec<u32>,
    /// `TRIANGLES`: every triangle of the buffer goes to the rasterizer.
    pub triangles: u32,
}

/// The frame of `vb` on cleared buffers.
pub fn frame(vb: &VertexBuffer) -> Result<Frame, String> {
    let cull = if vb.cull_back { Cull::Back } else { Cull::None };
    let out = raster_top(&vb.build, &vb.to_trilist(), cull, vb.background)?;
    Ok(Frame {
        color: out.render.fb.rgb.iter().map(|&c| color_word(c)).collect(),
        depth: out.render.fb.depth,
        triangles: vb.triangles.len() as u32,
    })
}

/// What a frame of any bytes leaves behind.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Ending {
    /// `STATUS` without the state bits ([`status`]).
    pub status: u32,
    /// `TRIANGLES`: those handed to the rasterizer before the buffer ended.
    pub triangles: u32,
    /// When the header passed: its screen, and the buffers after a cleared frame of the
    /// triangles handed over (every one the parser assembled is drawn, also when a later
    /// record stops it). None: nothing is written.
    pub drawn: Option<(u32, u32, Frame)>,
}

/// A frame of `bytes` at bus address `base` on buffers holding `screen` ([`screen_limit`]),
/// as `gpu_top` of the default build draws it: the command parser's model reads the buffer,
/// and its triangles are drawn as [`frame`] draws a whole buffer's. An error if the parser
/// has not ended after `max_cycles` (it ends within a bound set by the buffer's length).
pub fn run(bytes: &[u8], base: u32, screen: [u32; 2], max_cycles: u64) -> Result<Ending, String> {
    let build = Build::default();
    let bench = Bench { base, screen, max_cycles, ..Bench::default() };
    let r = command_parser::run(Params::default(), build, bytes, bench)?;
    let fault = match r.outcome {
        Outcome::FrameDone | Outcome::BufferDone => None,
        Outcome::Fault(f) => Some(f),
        Outcome::Timeout => return Err(format!("the parser had not ended after {max_cycles} cycles")),
    };
    let triangles: Vec<_> = r.triangles.iter().map(|(_, t)| t.vertices).collect();
    let drawn = match r.header {
        Some(h) => {
            let list = words_trilist(&build.formats, h.width, h.height, &triangles);
            let cull = if h.cull_back { Cull::Back } else { Cull::None };
            let out = raster_top(&build, &list, cull, h.background)?;
            let color = out.render.fb.rgb.iter().map(|&c| color_word(c)).collect();
            let frame = Frame { color, depth: out.render.fb.depth, triangles: triangles.len() as u32 };
            Some((h.width, h.height, frame))
        }
        None => None,
    };
    Ok(Ending { status: status(fault), triangles: triangles.len() as u32, drawn })
}

/// Two overlapping triangles of opposite windings on a 16 x 16 screen, nothing culled,
/// packed for the default build: a small frame with a depth test in it (the test benches'
/// frame in both simulators).
pub fn overlap() -> VertexBuffer {
    use scene::{Trilist, Vertex};
    let v = |x, y, z, c: [f64; 3]| Vertex::new(x, y, z, c);
    let triangles = vec![
        [
            v(1.0, 1.0, 0.5, [250.0, 0.0, 0.0]),
            v(15.0, 2.0, 0.5, [0.0, 250.0, 0.0]),
            v(7.0, 15.0, 0.5, [0.0, 0.0, 250.0]),
        ],
        [
            v(3.0, 12.0, 0.2, [90.0, 90.0, 0.0]),
            v(14.0, 14.0, 0.7, [0.0, 90.0, 90.0]),
            v(10.0, 3.0, 0.4, [90.0, 0.0, 90.0]),
        ],
    ];
    let list = Trilist { width: 16, height: 16, triangles, textures: Vec::new() };
    crate::vertex_buffer::pack(&list, &fx::Build::default(), false, [1, 2, 3]).expect("the overlap packs").0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_overlap_draws_both_triangles_over_the_background() {
        let vb = overlap();
        let f = frame(&vb).expect("draws");
        let background = color_word(vb.background);
        let drawn = f.color.iter().filter(|&&c| c != background).count();
        assert_eq!(f.triangles, 2);
        assert!(drawn > 60 && drawn < 256, "{drawn} pixels drawn");
        assert_eq!(f.color[0], background, "the corner");
        let far = f.depth[0];
        assert!(f.depth.iter().filter(|&&z| z < far).count() == drawn);
    }

    #[test]
    fn run_draws_a_whole_buffer_as_frame_does_and_nothing_on_a_refused_screen() {
        let vb = overlap();
        let bytes = vb.encode();
        let whole = run(&bytes, 0x1000, [16, 16], 100_000).expect("ends");
        assert_eq!(whole.drawn, Some((16, 16, frame(&vb).expect("draws"))));
        assert_eq!((whole.status, whole.triangles), (0, 2));
        let refused = run(&bytes, 0x1000, screen_limit(16 << 16 | 16, 60, 64), 100_000).expect("ends");
        assert_eq!(refused, Ending { status: status(Some(Fault::Screen)), triangles: 0, drawn: None });
    }

    #[test]
    fn run_draws_the_triangles_before_a_broken_record() {
        let fan = crate::vertex_buffer::broken::fan();
        let (what, bytes, fault) = crate::vertex_buffer::broken::cases()
            .into_iter()
            .find(|c| c.0 == "a texture index")
            .expect("the case breaking triangle 2");
        let e = run(&bytes, 0x1000, [16, 16], 100_000).expect("ends");
        assert_eq!((e.status, e.triangles), (status(Some(fault)), 2), "{what}");
        let mut first_two = fan.clone();
        first_two.triangles.truncate(2);
        let (w, h, f) = e.drawn.expect("the header passed");
        assert_eq!((w, h), (16, 16));
        assert_eq!((f.color, f.depth), {
            let g = frame(&first_two).expect("draws");
            (g.color, g.depth)
        });
    }

    #[test]
    fn screen_limit_takes_the_narrowest_of_screen_and_pitches() {
        assert_eq!(screen_limit(480 << 16 | 640, 2560, 2560), [640, 480]);
        assert_eq!(screen_limit(480 << 16 | 640, 2556, 4096), [639, 480]);
        assert_eq!(screen_limit(480 << 16 | 640, 4096, 1024), [256, 480]);
    }

    #[test]
    fn status_codes_a_fault() {
        assert_eq!(status(None), 0);
        assert_eq!(status(Some(Fault::Bus)), FAILED | (Fault::Bus as u32) << 4);
    }
}
