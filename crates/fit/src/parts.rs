//! Which optional parts of the scanline pipeline (`rtl::switch::Parts`) a workload uses:
//! the bit-exact model draws every scene at the fitted formats and counts what each part
//! would act on. A part nothing acts on is left out of the fitted design.
//!
//! | part | needed when some scene has |
//! |---|---|
//! | `cull` (`cull_sort`'s reject and cull) | a triangle rejected outside a plane, of zero area, or culled as a back face |
//! | `clip_y` (`edge_walk`) | a triangle drawn across the top or bottom of the screen (outcode TOP or BOTTOM) |
//! | `clip_x` (`span`) | a triangle drawn across the left or right edge (outcode LEFT or RIGHT) |
//! | `clip_z` (`span`) | a vertex drawn in front of 0 or beyond the largest depth (NEAR or FAR), or a pixel Z-clipped |
//! | `depth_test` (`pixel_out`) | a fragment on a pixel already written, or one that fails the test |
//!
//! A triangle within the screen gives spans within its columns and rows (a pixel belongs to
//! a triangle when its centre does), so the outcodes decide X and Y exactly; for depth,
//! the interpolated values are checked as well, since rounding could carry a pixel past a
//! vertex's depth. The fitted design is then proven on the workload in Verilator.

use model::cull_sort::outcode::{BOTTOM, FAR, LEFT, NEAR, RIGHT, TOP};
use model::cull_sort::Cull;
use model::render::{render, Method, Options, Stats};
use rtl::switch::Parts;
use sweep::run::Input;

/// The parts the workload needs, and for each one, the first scene that needs it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Needed {
    pub parts: Parts,
    /// (`PARAMS` name, scene) for each part present.
    pub why: Vec<(&'static str, String)>,
}

/// Whether each part acts in a render with `stats`, in `Parts::PARAMS`' order.
fn acts(s: &Stats) -> [bool; 5] {
    [
        s.culled_outside + s.culled_back + s.degenerate > 0,
        s.crosses & (TOP | BOTTOM) != 0,
        s.crosses & (LEFT | RIGHT) != 0,
        s.crosses & (NEAR | FAR) != 0 || s.z_clipped > 0,
        s.overdraw > 0 || s.pixels_written < s.fragments,
    ]
}

/// The parts `inputs` need at `formats` (the scanline method, each scene's culling).
pub fn needed(inputs: &[Input], formats: &fx::Formats) -> Needed {
    let mut why: Vec<(&'static str, String)> = Vec::new();
    for input in inputs {
        let opts = Options {
            method: Method::Scanline,
            cull: if input.cull_back { Cull::Back } else { Cull::None },
            analysis: false,
            background: [0; 3],
        };
        let stats = render(&input.trilist, formats, &opts, &mut |_| {}).stats;
        for (i, on) in acts(&stats).into_iter().enumerate() {
            let name = Parts::PARAMS[i].0;
            if on && !why.iter().any(|(n, _)| *n == name) {
                why.push((name, input.name.clone()));
            }
        }
    }
    let has = |name: &str| why.iter().any(|(n, _)| *n == name);
    let parts = Parts {
        cull: has("CULL"),
        clip_y: has("CLIP_Y"),
        clip_x: has("CLIP_X"),
        clip_z: has("CLIP_Z"),
        depth_test: has("DEPTH_TEST"),
    };
    why.sort_by_key(|(n, _)| Parts::PARAMS.iter().position(|(p, _)| p == n));
    Needed { parts, why }
}
