//! The cycle model: cycles per triangle and per frame, from each unit's latency
//! and initiation interval and the work each triangle made ([`Work`]).
//!
//! Assumptions (the RTL of `raster_top` is built to them):
//! * triangles arrive back to back (each offered as soon as the one before is
//!   taken), and memory never stalls;
//! * units hand over on valid/ready with no bubble: a unit starts its next
//!   item the cycle after the previous one is taken;
//! * `cull_sort`: latency 1, one triangle per cycle; its output register holds a
//!   passing triangle until setup takes it, and takes the next triangle in the
//!   cycle one leaves (a rejected one leaves the cycle after it came in);
//! * `triangle_setup` is iterative: it holds one triangle from start to
//!   hand-over (II = latency, plus any wait for the edge walk to take it); its
//!   latency follows its schedule of 64 products on `multipliers` multipliers
//!   and the divider's latency ([`setup_latency`], the schedule its RTL runs);
//! * `edge_walk`: first span command [`edge_walk::LATENCY`] cycles after it takes
//!   a triangle, then one scanline per cycle; it stalls while the span FIFO is full;
//! * `span`: one cycle per pixel walked, one for a dropped span; latency 1;
//! * `pixel_out`: one pixel per cycle, latency 2;
//! * without `cull_sort` ([`Timing::cull_sort`]) the host sends only the triangles that
//!   pass, straight to setup; without `pixel_out` the fragments leave `span` at once;
//! * `vector`: the per-triangle cycles of `vector::vector` (lanes per cycle),
//!   fed by `cull_sort`; triangles do not overlap in the vector unit.

use crate::render::Work;
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
    /// Whether `cull_sort` is present (`raster_top`'s `CULL_SORT`); without it the host
    /// sends only the triangles that pass, sorted, straight to setup.
    pub cull_sort: bool,
    /// Whether `pixel_out` is present (`PIXEL_OUT`); without it the frame ends when the
    /// last fragment leaves `span` (taken at once).
    pub pixel_out: bool,
}

impl Default for Timing {
    fn default() -> Self {
        Timing {
            setup_multipliers: 7,
            divider_latency: crate::divider::LATENCY,
            span_fifo: 4,
            cull_sort: true,
            pixel_out: true,
        }
    }
}

/// Most multipliers setup can use: with seven, the last edge's divisions are back
/// just as its products are due (see [`setup_latency`]); more would wait for the divider.
pub const SETUP_MULTIPLIERS_MAX: u32 = 7;

/// Setup's latency, from the cycle it takes a triangle to the cycle its result is valid:
/// the schedule `rtl::triangle_setup` runs, 64 products on `multipliers` (1 to
/// [`SETUP_MULTIPLIERS_MAX`]) multipliers, each phase's products `multipliers` per cycle,
/// and the divider's `divider_latency` stages. With c(n) = ceil(n / multipliers):
///
/// | step | products | cycles | waits for |
/// |---|---|---|---|
/// | twice the area | 2 | c(2) | vertices |
/// | normalise, issue 1/area | - | 1 | area |
/// | edge start numerators (from the normalise cycle on); the 6 edge divisions, one per cycle | 6 | - | vertices |
/// | wait for 1/area and for the multipliers | - | max(L, c(6)) - 1 | the divider's L stages; the numerators' c(6) cycles |
/// | OneOverArea x edge deltas (eq. 2) | 4 | c(4) | 1/area |
/// | gradients dC/dx, dC/dy of z, R, G, B | 16 | c(16) | the four products |
/// | start values and increments of 3 edges | 36 | c(36) | gradients, edge divisions |
/// | hand-over | - | 1 | |
///
/// 7 multipliers and 001's 5-stage divider: 1 + 1 + 5 + 1 + 3 + 6 + 1 = 18. With one
/// multiplier the six numerators outlast the divider (6 > 5): 66.
pub fn setup_latency(t: &Timing) -> u32 {
    let k = t.setup_multipliers;
    assert!((1..=SETUP_MULTIPLIERS_MAX).contains(&k), "setup has 1 to {SETUP_MULTIPLIERS_MAX} multipliers, not {k}");
    let c = |n: u32| n.div_ceil(k);
    c(2) + 1 + t.divider_latency.max(c(6)) + c(4) + c(16) + c(36) + 1
}

/// The predicted cycles of one frame.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FrameCycles {
    /// Cycles from the first triangle in until the pipeline is empty again: the last
    /// pixel's depth test and write done, every unit idle (`raster_top`'s `done` rises
    /// in this cycle).
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
    // The cycle cull_sort takes the next triangle.
    let mut cull_free = 0u64;
    let mut span_starts: Vec<u64> = Vec::new();
    let mut out = FrameCycles::default();
    let cull_latency = if t.cull_sort { cull_sort::LATENCY as u64 } else { 0 };
    let write_latency = if t.pixel_out { 1 + pixel_out::LATENCY as u64 } else { 1 };
    for w in work.iter().filter(|w| t.cull_sort || w.passed_cull) {
        let culled = cull_free + cull_latency;
        last = last.max(culled);
        if !w.passed_cull {
            cull_free = culled;
            continue;
        }
        out.triangles += 1;
        let setup_start = culled.max(setup_free);
        cull_free = setup_start;
        let done = setup_start + setup;
        let ew_start = done.max(ew_free);
        setup_free = ew_start;
        let mut now = ew_start + edge_walk::LATENCY as u64;
        for scanline in &w.scanlines {
            if let Some(span) = scanline {
                // A full FIFO holds the walk until the span unit takes an older command.
                if span_starts.len() >= fifo {
                    now = now.max(span_starts[span_starts.len() - fifo]);
                }
                let start = (now + span::LATENCY as u64).max(span_free);
                span_starts.push(start);
                span_free = start + span.cycles as u64;
                out.span_busy += span.cycles as u64;
                // pixel_out is empty LATENCY cycles after the one after its last pixel.
                if let Some(k) = span.last_sent {
                    last = last.max(start + k as u64 + write_latency);
                }
            }
            now += 1;
        }
        ew_free = now;
        last = last.max(span_free).max(now);
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
    use crate::render::SpanWork;

    #[test]
    fn cycles_setup_latency_counts_its_schedule() {
        // 7 multipliers, 5-stage divider: area 1, issue 1, divider 5, eq. (2) 1,
        // gradients 3, starts and increments 6, hand-over 1.
        assert_eq!(setup_latency(&Timing::default()), 18);
        // One multiplier: the six numerators take 6 cycles, one more than the divider:
        // 2 + 1 + 6 + 4 + 16 + 36 + 1.
        assert_eq!(setup_latency(&Timing { setup_multipliers: 1, ..Timing::default() }), 66);
        // 3 multipliers, a 2-stage divider: the numerators (2 cycles) and 1/area meet:
        // 1 + 1 + 2 + 2 + 6 + 12 + 1.
        assert_eq!(setup_latency(&Timing { setup_multipliers: 3, divider_latency: 2, ..Timing::default() }), 25);
    }

    /// A span of `c` cycles whose last cycle sends a pixel.
    fn full(c: u32) -> Option<SpanWork> {
        Some(SpanWork { cycles: c, last_sent: Some(c - 1) })
    }

    #[test]
    fn cycles_one_triangle_through_the_scanline_pipeline() {
        // Culled out at 1; setup done at 1 + 18 = 19; the walk emits at 21, 22, 23;
        // span takes each 1 cycle later or when free: 22..27, 27..32, 32..37;
        // the last pixel is written 2 cycles after, in cycle 38: 39 cycles.
        let w = Work { passed_cull: true, scanlines: vec![full(5), full(5), full(5)], vector_cycles: 0 };
        let c = scanline_frame(std::slice::from_ref(&w), &Timing::default());
        assert_eq!((c.total, c.span_busy, c.triangles), (39, 15, 1));
        // A culled triangle ahead costs one cycle of cull_sort only.
        let culled = Work::default();
        assert_eq!(scanline_frame(&[culled.clone(), w.clone()], &Timing::default()).total, 40);
        // Behind a triangle waiting for setup, culled ones wait too: the first triangle
        // leaves cull_sort for setup in cycle 1, the second (which crosses no scanline)
        // in 19, when setup hands the first over; then the 30 culled ones go through
        // cull_sort, one per cycle, the last one's verdict in cycle 49.
        let mut frame = vec![w.clone(), Work { passed_cull: true, ..Work::default() }];
        frame.extend(std::iter::repeat_n(culled, 30));
        assert_eq!(scanline_frame(&frame, &Timing::default()).total, 19 + 30);
        // With a 4-deep FIFO the walk runs ahead and span never waits: busy from
        // 22 for 53 cycles, written 2 later.
        let long = Work { scanlines: vec![full(50), full(1), full(1), None, full(1)], ..w.clone() };
        assert_eq!(scanline_frame(std::slice::from_ref(&long), &Timing::default()).total, 22 + 53 + 2);
        // A one-deep FIFO holds the walk until span takes each command; the last
        // command is emitted only at 74, reaches span at 75: one idle cycle.
        assert_eq!(scanline_frame(&[long], &Timing { span_fifo: 1, ..Timing::default() }).total, 22 + 53 + 1 + 2);
        // Spans that end on pixels sent nowhere (off screen, out of the depth range, or
        // dropped): the frame ends when span is done, or 3 cycles after the last pixel.
        let mut tail = w.clone();
        tail.scanlines[2] = Some(SpanWork { cycles: 5, last_sent: Some(1) });
        assert_eq!(scanline_frame(&[tail.clone()], &Timing::default()).total, 37);
        tail.scanlines[2] = Some(SpanWork { cycles: 1, last_sent: None });
        // Dropped: span done at 33, the pixel of cycle 31 written in 33.
        assert_eq!(scanline_frame(&[tail], &Timing::default()).total, 34);
    }

    #[test]
    fn cycles_without_cull_sort_or_pixel_out() {
        // Without cull_sort the triangle reaches setup in cycle 0 and culled ones are not
        // sent: 1 cycle less, and nothing for the 30 culled ones.
        let w = Work { passed_cull: true, scanlines: vec![full(5), full(5), full(5)], vector_cycles: 0 };
        let mut frame = vec![Work::default(), w.clone()];
        frame.extend(std::iter::repeat_n(Work::default(), 30));
        let no_cull = Timing { cull_sort: false, ..Timing::default() };
        assert_eq!(scanline_frame(&frame, &no_cull).total, 38);
        // Without pixel_out the frame ends the cycle after span's last fragment (36):
        // 2 cycles less than with the depth test and write behind it.
        let no_out = Timing { pixel_out: false, ..Timing::default() };
        assert_eq!(scanline_frame(std::slice::from_ref(&w), &no_out).total, 37);
        let neither = Timing { cull_sort: false, pixel_out: false, ..Timing::default() };
        assert_eq!(scanline_frame(&frame, &neither).total, 36);
    }

    #[test]
    fn cycles_vector_frame_adds_triangles_in_turn() {
        let w = |c| Work { passed_cull: true, vector_cycles: c, ..Work::default() };
        assert_eq!(vector_frame(&[w(100)]).total, 1 + 100 + 2);
        assert_eq!(vector_frame(&[w(100), Work::default(), w(10)]).total, 1 + 100 + 10 + 2);
    }
}
