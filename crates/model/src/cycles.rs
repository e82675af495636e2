//! The cycle model: cycles per triangle and per frame, from each unit's latency
//! and initiation interval and the work each triangle made ([`Work`]).
//!
//! Assumptions (the RTL of `raster_top` is built to them):
//! * triangles arrive back to back, one per cycle, and memory never stalls;
//! * units hand over on valid/ready with no bubble: a unit starts its next
//!   item the cycle after the previous one is taken;
//! * `cull_sort`: latency 1, one triangle per cycle;
//! * `triangle_setup` is iterative: it holds one triangle from start to
//!   hand-over (II = latency, plus any wait for the edge walk to take it); its
//!   latency follows its schedule of 64 products on `multipliers` multipliers
//!   and the divider's latency ([`setup_latency`]);
//! * `edge_walk`: first span command [`edge_walk::LATENCY`] cycles after it takes
//!   a triangle, then one scanline per cycle; it stalls while the span FIFO is full;
//! * `span`: one cycle per pixel walked, one for a dropped span; latency 1;
//! * `pixel_out`: one pixel per cycle, latency 2;
//! * `vector`: the per-triangle cycles of `vector::vector` (lanes per cycle),
//!   fed by `cull_sort`; triangles do not overlap in the vector unit.

use crate::raster::Work;
use crate::{cull_sort, edge_walk, pixel_out, span};

/// Hardware parameters the cycle model depends on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Timing {
    /// Multipliers in triangle setup (001 uses 7).
    pub setup_multipliers: u32,
    /// Pipeline stages of the shared divider (001: 5).
    pub divider_latency: u32,
    /// Span commands buffered between edge walk and span.
    pub span_fifo: u32,
}

impl Default for Timing {
    fn default() -> Self {
        Timing { setup_multipliers: 7, divider_latency: crate::divider::LATENCY, span_fifo: 4 }
    }
}

/// Setup's latency: products in dependency order on `multipliers` multipliers.
///
/// | step | products | waits for |
/// |---|---|---|
/// | twice the area | 2 | vertices |
/// | normalise, issue 1/area | - | area (1 cycle) |
/// | edge start numerators; issue 6 edge divisions | 6 | vertices (overlaps the divider) |
/// | OneOverArea x edge deltas (eq. 2) | 4 | 1/area from the divider |
/// | gradients dC/dx, dC/dy of z, R, G, B | 16 | the four products |
/// | start values and increments of 3 edges | 36 | gradients, edge divisions |
/// | hand-over | - | 1 cycle |
pub fn setup_latency(t: &Timing) -> u32 {
    let k = t.setup_multipliers.max(1);
    let c = |n: u32| n.div_ceil(k);
    c(2) + 1 + t.divider_latency + c(4) + c(16) + c(36) + 1
}

/// The predicted cycles of one frame.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FrameCycles {
    /// Cycles from the first triangle in to the last pixel written.
    pub total: u64,
    /// Cycles the span unit was busy (its utilisation is busy / total).
    pub span_busy: u64,
    /// Triangles that reached setup (or the vector unit).
    pub triangles: u64,
}

/// Cycles of a frame through the scanline pipeline.
pub fn scanline_frame(work: &[Work], t: &Timing) -> FrameCycles {
    let setup = setup_latency(t) as u64;
    let fifo = t.span_fifo.max(1) as usize;
    let (mut setup_free, mut ew_free, mut span_free, mut last) = (0u64, 0u64, 0u64, 0u64);
    let mut span_starts: Vec<u64> = Vec::new();
    let mut out = FrameCycles::default();
    for (i, w) in work.iter().enumerate() {
        let culled = i as u64 + cull_sort::LATENCY as u64;
        last = last.max(culled);
        if !w.passed_cull {
            continue;
        }
        out.triangles += 1;
        let done = culled.max(setup_free) + setup;
        let ew_start = done.max(ew_free);
        setup_free = ew_start;
        let mut now = ew_start + edge_walk::LATENCY as u64;
        for cycles in &w.scanlines {
            if let Some(c) = cycles {
                // A full FIFO holds the walk until the span unit takes an older command.
                if span_starts.len() >= fifo {
                    now = now.max(span_starts[span_starts.len() - fifo]);
                }
                let start = (now + span::LATENCY as u64).max(span_free);
                span_starts.push(start);
                span_free = start + *c as u64;
                out.span_busy += *c as u64;
            }
            now += 1;
        }
        ew_free = now;
        last = last.max(span_free + pixel_out::LATENCY as u64).max(now);
    }
    out.total = last;
    out
}

/// Cycles of a frame through the vector pipeline.
pub fn vector_frame(work: &[Work]) -> FrameCycles {
    let (mut free, mut last) = (0u64, 0u64);
    let mut out = FrameCycles::default();
    for (i, w) in work.iter().enumerate() {
        let culled = i as u64 + cull_sort::LATENCY as u64;
        last = last.max(culled);
        if w.passed_cull {
            out.triangles += 1;
            free = free.max(culled) + w.vector_cycles as u64;
            out.span_busy += w.vector_cycles as u64;
            last = last.max(free + pixel_out::LATENCY as u64);
        }
    }
    out.total = last;
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cycles_setup_latency_counts_its_schedule() {
        // 7 multipliers, 5-stage divider: area 1, issue 1, divider 5, eq. (2) 1,
        // gradients 3, starts and increments 6, hand-over 1.
        assert_eq!(setup_latency(&Timing::default()), 18);
        // One multiplier: 2 + 1 + 5 + 4 + 16 + 36 + 1.
        assert_eq!(setup_latency(&Timing { setup_multipliers: 1, ..Timing::default() }), 65);
    }

    #[test]
    fn cycles_one_triangle_through_the_scanline_pipeline() {
        // Culled out at 1; setup done at 1 + 18 = 19; the walk emits at 21, 22, 23;
        // span takes each 1 cycle later or when free: 22..27, 27..32, 32..37;
        // the last pixel is written 2 cycles after: 39.
        let w = Work { passed_cull: true, scanlines: vec![Some(5), Some(5), Some(5)], vector_cycles: 0 };
        let c = scanline_frame(std::slice::from_ref(&w), &Timing::default());
        assert_eq!((c.total, c.span_busy, c.triangles), (39, 15, 1));
        // A culled triangle ahead costs one cycle of cull_sort only.
        let culled = Work::default();
        assert_eq!(scanline_frame(&[culled, w.clone()], &Timing::default()).total, 40);
        // With a 4-deep FIFO the walk runs ahead and span never waits: busy from
        // 22 for 53 cycles, written 2 later.
        let long = Work { scanlines: vec![Some(50), Some(1), Some(1), None, Some(1)], ..w };
        assert_eq!(scanline_frame(std::slice::from_ref(&long), &Timing::default()).total, 22 + 53 + 2);
        // A one-deep FIFO holds the walk until span takes each command; the last
        // command is emitted only at 74, reaches span at 75: one idle cycle.
        assert_eq!(scanline_frame(&[long], &Timing { span_fifo: 1, ..Timing::default() }).total, 22 + 53 + 1 + 2);
    }

    #[test]
    fn cycles_vector_frame_adds_triangles_in_turn() {
        let w = |c| Work { passed_cull: true, vector_cycles: c, ..Work::default() };
        assert_eq!(vector_frame(&[w(100)]).total, 1 + 100 + 2);
        assert_eq!(vector_frame(&[w(100), Work::default(), w(10)]).total, 1 + 100 + 10 + 2);
    }
}
