//! The model of `rtl::gpu_top`, a frame at a time: what the core leaves in the colour and
//! depth buffers and in its registers after a frame of a vertex buffer. Its cycles are not
//! modelled here: every unit inside is cycle-exact to its own model (`command_parser`,
//! `cull_sort`, ..., `pixel_bus`, `gpu_regs`), and the frame's pixels are
//! [`raster_top`](crate::raster_top)'s.

use crate::cull_sort::Cull;
use crate::pixel_bus::color_word;
use crate::raster_top::raster_top;
use crate::vertex_buffer::{Fault, VertexBuffer};

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
    let list = Trilist { width: 16, height: 16, triangles };
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
    fn status_codes_a_fault() {
        assert_eq!(status(None), 0);
        assert_eq!(status(Some(Fault::Bus)), FAILED | (Fault::Bus as u32) << 4);
    }
}
