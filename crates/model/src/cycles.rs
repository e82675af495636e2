//! The cycle model: cycles per triangle and per frame, from each unit's latency
//! and initiation interval and the work each triangle made ([`Work`]).
//!
//! Assumptions (the RTL of `raster_top` is built to them):
//! * triangles arrive back to back (each offered as soon as the one before is
//!   taken), and memory never stalls;
//! * units hand over on valid/ready with no bubble: a unit starts its next
//!   item the cycle after the previous one is taken;
//! * `cull_sort`: [`cull_sort::LATENCY`] stages, one triangle per cycle; a triangle
//!   moves to the next stage in the cycle the one before leaves it (or the cycle after
//!   it came in, if later), and its output register holds a passing triangle until
//!   setup takes it (a rejected one leaves the cycle it arrives);
//! * `triangle_setup` holds several triangles: it takes the next one II cycles
//!   after the last (or when idle), and while a result waits for the edge walk
//!   all of setup waits (every triangle in flight with it); its latency and II follow
//!   its schedule of 64 products on `multipliers` multipliers and the divider's
//!   latency ([`setup_timing`], the schedule its RTL runs);
//! * `edge_walk`: first span command [`edge_walk::LATENCY`] cycles after it takes
//!   a triangle, then one scanline per cycle; it stalls while the span FIFO is full;
//! * `span`: one cycle per pixel walked, one for a dropped span, the walk starting the
//!   cycle after the command is taken; each pixel leaves [`span::LATENCY`] - 1 cycles
//!   after its walk cycle (latency 2: the pixel register);
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

/// Cycles from a division's issue in setup into the divider: the operands are registered.
pub const SETUP_DIVIDER_OPERANDS: u32 = 1;

/// Most copies of a triangle's registers setup holds (see [`setup_timing`]): II is at least
/// a quarter of the latency.
pub const SETUP_COPIES_MAX: u32 = 4;

/// Setup's timing at `t`'s multipliers and divider ([`setup_timing`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SetupTiming {
    /// Cycles from the cycle setup takes a triangle to the cycle its result is valid.
    pub latency: u32,
    /// Cycles between two triangles taken back to back (II): setup takes the next one
    /// while the last is in its second part, so II < latency.
    pub interval: u32,
    /// Whether one multiplier does twice the area and the edge numerators while the other
    /// `multipliers - 1` do eq. (2), the gradients and the starts (the split schedule), or
    /// every phase uses all of them in turn (the sequential one).
    pub split: bool,
}

/// Setup's latency and interval: the schedule `rtl::triangle_setup` runs, 64 products on
/// `multipliers` (1 to [`SETUP_MULTIPLIERS_MAX`]) multipliers and the divider's
/// `divider_latency` stages, with several triangles in flight.
///
/// Setup takes a triangle in the cycle the one before it reaches cycle II of its own
/// schedule (or when it is idle), so triangles II cycles apart overlap. Nothing they use may
/// overlap: each multiplier and the divider are busy for at most II consecutive cycles of a
/// triangle, and no register is written by the later triangle before the earlier one has
/// read it. The triangle's own registers (vertices, crossings, the area's sign and exponent)
/// are copied every II cycles, ceil(latency / II) copies, each part of the schedule reading
/// the copy of its cycle. While a result waits for the edge walk, all of setup waits with it
/// (the triangles behind it too).
///
/// Two schedules, the one with the lower II taken (then the lower latency). Twice the area
/// is normalised into a register in the cycle after its last product and 1/area is issued
/// the cycle after that. A division's operands are registered ([`SETUP_DIVIDER_OPERANDS`]):
/// its result is back 1 + L cycles after its issue. With c(n) = ceil(n / multipliers):
///
/// * **sequential**: each phase on all the multipliers in turn: twice the area c(2) cycles,
///   normalise 1, the edge numerators (from the normalise cycle) and 1/area
///   max(L + 2, c(6)), eq. (2) c(4), gradients c(16), starts and increments c(36), hand-over
///   1; every multiplier is busy from cycle 1 to the last start, so II = latency - 2.
///   7 multipliers and 001's 5-stage divider: 1 + 1 + 7 + 1 + 3 + 6 + 1 = 20, II 18; one
///   multiplier, 2 + 1 + 7 + 4 + 16 + 36 + 1 = 67, II 65.
/// * **split** (2 multipliers or more): with b(n) = ceil(n / (multipliers - 1)), one
///   multiplier does the area (cycles 1, 2) and the six numerators (3 to 8), the divisions
///   are issued at 4 (1/area) and 5 to 10 (each edge's start once its two numerators are
///   summed, then its step); the others do eq. (2) from 5 + L (1/area back), b(4) cycles, the
///   gradients b(16) and the starts b(36), then hand-over 1: latency 6 + L + b(4) + b(16) +
///   b(36), II = max(8, b(4) + b(16) + b(36), ceil(latency / [`SETUP_COPIES_MAX`])). 7
///   multipliers and the 5-stage divider: 6 + 5 + 1 + 3 + 6 = 21, II = 10 (the six
///   multipliers' 60 slots hold the 56 products), at any divider depth to 24 stages (latency
///   40; 25 stages: latency 41, II 11).
pub fn setup_timing(t: &Timing) -> SetupTiming {
    let k = t.setup_multipliers;
    assert!((1..=SETUP_MULTIPLIERS_MAX).contains(&k), "setup has 1 to {SETUP_MULTIPLIERS_MAX} multipliers, not {k}");
    let l = t.divider_latency;
    let c = |n: u32| n.div_ceil(k);
    let latency = c(2) + 1 + (l + 1 + SETUP_DIVIDER_OPERANDS).max(c(6)) + c(4) + c(16) + c(36) + 1;
    let sequential = SetupTiming { latency, interval: latency - 2, split: false };
    if k == 1 {
        return sequential;
    }
    let b = |n: u32| n.div_ceil(k - 1);
    let late = b(4) + b(16) + b(36);
    let latency = 5 + SETUP_DIVIDER_OPERANDS + l + late;
    let split = SetupTiming { latency, interval: 8.max(late).max(latency.div_ceil(SETUP_COPIES_MAX)), split: true };
    if (split.interval, split.latency) < (sequential.interval, sequential.latency) {
        split
    } else {
        sequential
    }
}

/// Setup's latency ([`setup_timing`]).
pub fn setup_latency(t: &Timing) -> u32 {
    setup_timing(t).latency
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
    let SetupTiming { latency: setup, interval, .. } = setup_timing(t);
    let (setup, interval) = (setup as u64, interval as u64);
    let fifo = t.span_fifo.max(1) as usize;
    let (mut ew_free, mut span_free, mut last) = (0u64, 0u64, 0u64);
    // The cycle setup may take the next triangle (the last one reaches cycle II of its
    // schedule), and the spans of cycles in which setup stands still (from the cycle a
    // result is valid until the one it is taken in), those that can still delay a triangle.
    let mut setup_free = 0u64;
    let mut waits: Vec<(u64, u64)> = Vec::new();
    // The cycle setup reaches `n` cycles of running after `from`, standing still in `waits`.
    let running = |waits: &[(u64, u64)], from: u64, n: u64| {
        waits.iter().filter(|w| w.0 >= from).fold(from + n, |t, &(d, h)| if d < t { t + (h - d) } else { t })
    };
    // cull_sort's stages (none without it): `stage_free[k]` is the cycle the triangle before
    // left stage k + 1 (the last: the output register), in which the next may move into it;
    // the next triangle is taken (without cull_sort: offered to setup) in `stage_free[0]`.
    let stages = if t.cull_sort { cull_sort::LATENCY as usize } else { 0 };
    let mut stage_free = vec![0u64; stages.max(1)];
    let mut leaves = vec![0u64; stages.max(1)];
    let mut span_starts: Vec<u64> = Vec::new();
    let mut out = FrameCycles::default();
    let write_latency = if t.pixel_out { 1 + pixel_out::LATENCY as u64 } else { 1 };
    for w in work.iter().filter(|w| t.cull_sort || w.passed_cull) {
        // `leaves[k]`: the cycle the triangle leaves stage k (0: taken); `culled`: its first
        // cycle in the output register, with its verdict.
        leaves[0] = stage_free[0];
        for k in 1..stages {
            leaves[k] = (leaves[k - 1] + 1).max(stage_free[k]);
        }
        let culled = if stages == 0 { leaves[0] } else { leaves[stages - 1] + 1 };
        // Once the triangle leaves the output register (in `left`), each stage is free for
        // the next one from the cycle this one left it.
        fn moved_on(stage_free: &mut [u64], leaves: &[u64], left: u64) {
            let n = stage_free.len();
            stage_free[..n - 1].copy_from_slice(&leaves[1..]);
            stage_free[n - 1] = left;
        }
        last = last.max(culled);
        if !w.passed_cull {
            moved_on(&mut stage_free, &leaves, culled);
            continue;
        }
        out.triangles += 1;
        // No triangle is taken while setup stands still; every triangle in flight stands
        // still with it, however many results ahead of its own the wait is for.
        let mut setup_start = culled.max(setup_free);
        for &(d, h) in &waits {
            if (d..h).contains(&setup_start) {
                setup_start = h;
            }
        }
        waits.retain(|w| w.0 >= setup_start);
        moved_on(&mut stage_free, &leaves, setup_start);
        let done = running(&waits, setup_start, setup);
        setup_free = running(&waits, setup_start, interval);
        let ew_start = done.max(ew_free);
        if ew_start > done {
            waits.push((done, ew_start));
        }
        let mut now = ew_start + edge_walk::LATENCY as u64;
        for scanline in &w.scanlines {
            if let Some(span) = scanline {
                // A full FIFO holds the walk until the span unit takes an older command.
                if span_starts.len() >= fifo {
                    now = now.max(span_starts[span_starts.len() - fifo]);
                }
                // The walk's first cycle: span takes the command when idle or in the last
                // cycle of the walk before; walk cycle k's pixel leaves span in
                // start + k + LATENCY - 1 (its pixel register).
                let start = (now + 1).max(span_free);
                span_starts.push(start);
                span_free = start + span.cycles as u64;
                out.span_busy += span.cycles as u64;
                // pixel_out is empty LATENCY cycles after the one after its last pixel.
                if let Some(k) = span.last_sent {
                    last = last.max(start + k as u64 + (span::LATENCY as u64 - 1) + write_latency);
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
    fn cycles_setup_timing_counts_its_schedule() {
        let timing = |k, l| setup_timing(&Timing { setup_multipliers: k, divider_latency: l, ..Timing::default() });
        // 7 multipliers, 5-stage divider, split: area 2 on one multiplier, normalised in
        // 3, 1/area issued at 4, into the divider at 5 and back at 10; eq. (2) 1 cycle,
        // gradients 3, starts 6, hand-over 1: 21. The six multipliers are busy 10 cycles: II 10.
        assert_eq!(setup_timing(&Timing::default()), SetupTiming { latency: 21, interval: 10, split: true });
        // One multiplier: 1/area's operand register and the divider take 6 cycles, one more
        // than the six numerators: 2 + 1 + 7 + 4 + 16 + 36 + 1; the multiplier is busy from
        // cycle 1 to 65.
        assert_eq!(timing(1, 5), SetupTiming { latency: 67, interval: 65, split: false });
        // 3 multipliers, a 2-stage divider: sequential, 1 + 1 + 4 + 2 + 6 + 12 + 1 = 27, II
        // 25; split, the two others would take 2 + 8 + 18 cycles for eq. (2) to the starts.
        assert_eq!(timing(3, 2), SetupTiming { latency: 27, interval: 25, split: false });
        // 4 multipliers, a 9-stage divider: split, 6 + 9 + 2 + 6 + 12 = 35, II 20 (the
        // sequential one: 28, II 26).
        assert_eq!(timing(4, 9), SetupTiming { latency: 35, interval: 20, split: true });
        // Four copies of the triangle's registers keep II 10 up to a 24-stage divider
        // (latency 40); at 25 stages the latency is 41 and II ceil(41 / 4) = 11.
        assert_eq!(timing(7, 24), SetupTiming { latency: 40, interval: 10, split: true });
        assert_eq!(timing(7, 25), SetupTiming { latency: 41, interval: 11, split: true });
        // A 1-stage divider: split, 6 + 1 + 10 = 17, II 10 (sequential: 16, II 14).
        assert_eq!(timing(7, 1), SetupTiming { latency: 17, interval: 10, split: true });
        assert_eq!(setup_latency(&Timing::default()), 21);
    }

    /// Two triangles in flight: the second is taken II cycles after the first; while the
    /// second waits for the edge walk, the third (taken before) waits with it.
    #[test]
    fn cycles_setup_overlaps_triangles_and_waits_as_one() {
        let walk = |n: usize| Work { passed_cull: true, scanlines: vec![None; n], vector_cycles: 0 };
        // First: culled out at 3 (cull_sort's three stages), taken, done at 24, walked
        // 26..76. Second: culled out at 4, taken at 3 + 10 = 13, done at 34, waits for the
        // walk until 76, walked 78..79. Third: culled out at 14 (it waited in stage 2 while
        // the second held the output register), taken at 23 (the second in its cycle 10),
        // in flight while the second waits 42 cycles: done at 23 + 21 + 42 = 86, walked
        // 88..89.
        assert_eq!(scanline_frame(&[walk(50), walk(1), walk(1)], &Timing::default()).total, 89);
        // Three in flight: a triangle waits for every result ahead of it that waits. With a
        // second long walk, the second waits from 34 to 76 as above and the third from 86
        // (23 + 21 + 42) to 128; the fourth, taken at 33 (the third in its cycle 10), runs 1
        // cycle, stands still 42, runs 10, stands still 42, runs 10: done at 138, walked
        // 140..141.
        assert_eq!(scanline_frame(&[walk(50), walk(50), walk(1), walk(1)], &Timing::default()).total, 141);
        // Without the long walk nothing waits: the third is done at 44, walked 46..47.
        assert_eq!(scanline_frame(&[walk(1), walk(1), walk(1)], &Timing::default()).total, 47);
        // A triangle offered while setup waits is taken when the result is handed over: as
        // above, the second waits from 34 to 76; the third, culled out at 54 behind 40
        // culled ones, goes in at 76; done at 76 + 21 = 97, walked 99..100.
        let mut frame = vec![walk(50), walk(1)];
        frame.extend(std::iter::repeat_n(Work::default(), 40));
        frame.push(walk(1));
        assert_eq!(scanline_frame(&frame, &Timing::default()).total, 100);
    }

    /// A span of `c` cycles whose last cycle sends a pixel.
    fn full(c: u32) -> Option<SpanWork> {
        Some(SpanWork { cycles: c, last_sent: Some(c - 1) })
    }

    #[test]
    fn cycles_one_triangle_through_the_scanline_pipeline() {
        // Taken in cycle 0, culled out at 3; setup done at 3 + 21 = 24; the walk emits at
        // 26, 27, 28; span walks each from 1 cycle later or when free: 27..32, 32..37,
        // 37..42; the last pixel leaves span's pixel register in 42 and is written 2 cycles
        // after, in cycle 44: 45 cycles.
        let w = Work { passed_cull: true, scanlines: vec![full(5), full(5), full(5)], vector_cycles: 0 };
        let c = scanline_frame(std::slice::from_ref(&w), &Timing::default());
        assert_eq!((c.total, c.span_busy, c.triangles), (45, 15, 1));
        // A culled triangle ahead costs one cycle of cull_sort only.
        let culled = Work::default();
        assert_eq!(scanline_frame(&[culled.clone(), w.clone()], &Timing::default()).total, 46);
        // Behind a triangle waiting for setup, culled ones wait too: the first triangle
        // leaves cull_sort for setup in cycle 3, the second (which crosses no scanline)
        // arrives in the output register at 4 and leaves in 13, when the first is in its
        // cycle 10 (II); the first two culled ones, taken at 2 and 3, wait in stages 1 and
        // 2 (nothing more is taken), then the 40 culled ones go through cull_sort, one per
        // cycle, the last one's verdict in cycle 13 + 40 (after the first triangle's last
        // pixel, 45).
        let mut frame = vec![w.clone(), Work { passed_cull: true, ..Work::default() }];
        frame.extend(std::iter::repeat_n(culled, 40));
        assert_eq!(scanline_frame(&frame, &Timing::default()).total, 13 + 40);
        // With a 4-deep FIFO the walk runs ahead and span never waits: walking from 27
        // for 53 cycles, the last pixel out of the pixel register 1 later, written 2 later.
        let long = Work { scanlines: vec![full(50), full(1), full(1), None, full(1)], ..w.clone() };
        assert_eq!(scanline_frame(std::slice::from_ref(&long), &Timing::default()).total, 27 + 53 + 1 + 2);
        // A one-deep FIFO holds the walk until span takes each command; the last
        // command is emitted only at 79, reaches span at 80: one idle cycle.
        let one_deep = Timing { span_fifo: 1, ..Timing::default() };
        assert_eq!(scanline_frame(&[long], &one_deep).total, 27 + 53 + 1 + 1 + 2);
        // Spans that end on pixels sent nowhere (off screen, out of the depth range, or
        // dropped): the frame ends when span is done, or 4 cycles after the last pixel's
        // walk cycle (out of the pixel register, into pixel_out, written).
        let mut tail = w.clone();
        tail.scanlines[2] = Some(SpanWork { cycles: 5, last_sent: Some(1) });
        assert_eq!(scanline_frame(&[tail.clone()], &Timing::default()).total, 42);
        tail.scanlines[2] = Some(SpanWork { cycles: 1, last_sent: None });
        // Dropped: span done at 38, the pixel walked in 36 out of span in 37, written in 39.
        assert_eq!(scanline_frame(&[tail], &Timing::default()).total, 40);
    }

    #[test]
    fn cycles_without_cull_sort_or_pixel_out() {
        // Without cull_sort the triangle reaches setup in cycle 0 and culled ones are not
        // sent: 3 cycles less, and nothing for the 30 culled ones.
        let w = Work { passed_cull: true, scanlines: vec![full(5), full(5), full(5)], vector_cycles: 0 };
        let mut frame = vec![Work::default(), w.clone()];
        frame.extend(std::iter::repeat_n(Work::default(), 30));
        let no_cull = Timing { cull_sort: false, ..Timing::default() };
        assert_eq!(scanline_frame(&frame, &no_cull).total, 42);
        // Without pixel_out the frame ends the cycle after span's last fragment (42):
        // 2 cycles less than with the depth test and write behind it.
        let no_out = Timing { pixel_out: false, ..Timing::default() };
        assert_eq!(scanline_frame(std::slice::from_ref(&w), &no_out).total, 43);
        let neither = Timing { cull_sort: false, pixel_out: false, ..Timing::default() };
        assert_eq!(scanline_frame(&frame, &neither).total, 40);
    }

    #[test]
    fn cycles_vector_frame_adds_triangles_in_turn() {
        let w = |c| Work { passed_cull: true, vector_cycles: c, ..Work::default() };
        let cull = cull_sort::LATENCY as u64;
        assert_eq!(vector_frame(&[w(100)]).total, cull + 100 + 2);
        assert_eq!(vector_frame(&[w(100), Work::default(), w(10)]).total, cull + 100 + 10 + 2);
    }
}
