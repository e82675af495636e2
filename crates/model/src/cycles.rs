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
//! * `triangle_setup` holds several triangles: it takes them on a grid of II cycles
//!   from the last one taken (or at once when empty), and while a result waits for the edge walk
//!   all of setup waits (every triangle in flight with it); its latency and II follow
//!   its schedule of 64 products on `multipliers` multipliers and the divider's
//!   latency ([`setup_timing`], the schedule its RTL runs);
//! * `edge_walk`: first span command [`edge_walk::LATENCY`] cycles after it takes
//!   a triangle, then one scanline per cycle; it stalls while the span FIFO is full;
//! * the span FIFO: a command pushed in cycle t is offered from its head register in
//!   t + [`SPAN_FIFO_LATENCY`] (`rtl::span_fifo`: no pass-through);
//! * `span`: one cycle per pixel walked, one for a dropped span, the walk starting the
//!   cycle after the command is taken; each pixel leaves [`span::LATENCY`] - 1 cycles
//!   after its walk cycle (latency 2: the pixel register);
//! * `pixel_out`: one pixel per cycle, latency 2;
//! * without `cull_sort` ([`Timing::cull_sort`]) the host sends only the triangles that
//!   pass, straight to setup; without `pixel_out` the fragments leave `span` at once;
//! * `vector` (`rtl::vector`): fed by `cull_sort`; [`VectorUnit`] (setup overlapping the
//!   scout and the walker, the scout a row ahead of the walker, two sets of constants),
//!   with the rows of `vector::vector`'s walk at the default divider; its chunks go to
//!   `pixel_out` as they leave (one lane: a pixel a cycle; more lanes count as a `pixel_out`
//!   as wide);
//! * the textured `raster_top` ([`textured`]): the same front end, `span`'s fragments taken
//!   by the texture path's cycle-for-cycle model or by `pixel_out`.

use crate::render::{SpanWork, Work};
use crate::triangle_setup::schedule::Schedule;
use crate::{cull_sort, edge_walk, pixel_out, se, se_cmd, span, vector};

pub mod textured;

/// Cycles from a span command pushed into the span FIFO to its offer from the FIFO's head
/// register (`rtl::span_fifo`, which has no pass-through).
pub const SPAN_FIFO_LATENCY: u32 = 1;

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

/// Setup's timing at `t`'s multipliers and divider ([`setup_timing`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SetupTiming {
    /// Cycles from the cycle setup takes a triangle to the cycle its result is valid.
    pub latency: u32,
    /// Cycles between two triangles taken back to back (II): setup takes triangles on a
    /// grid of II cycles (or at once when it is empty), several in flight.
    pub interval: u32,
}

/// Setup's latency and interval: those of the schedule its RTL runs
/// ([`crate::triangle_setup::schedule::Schedule`]), 64 products on `setup_multipliers`
/// multipliers (1 to 7) and the divider's `divider_latency` stages, several triangles in
/// flight. While a result waits for the edge walk, all of setup waits with it (the
/// triangles behind it too). 7 multipliers: latency 52, II 10 with the default 25-stage divider, 32 with 001's 5 stages.
pub fn setup_timing(t: &Timing) -> SetupTiming {
    let s = Schedule::new(t.setup_multipliers as usize, t.divider_latency as usize).unwrap_or_else(|e| panic!("{e}"));
    SetupTiming { latency: s.latency as u32, interval: s.interval as u32 }
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
    scanline_frame_stalled(work, t, &|_| true)
}

/// [`scanline_frame`] behind a memory ready (`raster_top`'s `mem$ready`) in the cycles
/// `ready` says (cycle 0 the one the first triangle is offered in; ready again after any
/// cycle, or the frame never ends). `pixel_out` takes a pixel only in a ready cycle and
/// moves its stages only then, so a pixel taken in cycle c is tested in the first ready
/// cycle after c and written in the next; span's pixel register holds a pixel not taken,
/// and its walk with it, unsent cycles too (`rtl::span`); the span FIFO, the edge walk and
/// setup fill behind it as the cycle model has them without stalls. Without `pixel_out`
/// ([`Timing::pixel_out`]), `ready` is the host's `out$ready`.
pub fn scanline_frame_stalled(work: &[Work], t: &Timing, ready: &dyn Fn(u64) -> bool) -> FrameCycles {
    let sink = Sink { ready, pixel_out: t.pixel_out };
    front_end_frame(work, t, &mut SpanUnit::new(sink))
}

/// Cycles of a frame through the SE back end (`rtl::raster_top` with `METHOD = 2`): the
/// scanline pipeline's front end up to the span FIFO, then `se_cmd` and the array of
/// engines `prm` (all alike but for their index: one issue reaches every engine at once);
/// `ready_after`: `se_cmd::ready_after` of the build's formats. The frame is done
/// [`se_done`] cycles after the last issue.
pub fn se_frame(work: &[Work], t: &Timing, prm: &se::SeParams, ready_after: u64) -> FrameCycles {
    front_end_frame(work, t, &mut SeIssue { prm: *prm, ready_after, free: 0, last_issue: None })
}

/// Cycles from the SE back end's last issue to the cycle its `raster_top` is done: the
/// engines' latency (their last write is in the cycle before).
pub fn se_done(prm: &se::SeParams) -> u64 {
    prm.latency() as u64
}

/// What takes the span FIFO's commands: `span` or `se_cmd`.
trait SpanTaker {
    /// The span `s` at the FIFO's head from the cycle before `avail`: the cycle after the one
    /// it is taken in. The frame lasts at least until `last`; `busy` counts the cycles the
    /// span unit (or the engines) worked.
    fn take(&mut self, avail: u64, s: &SpanWork, last: &mut u64, busy: &mut u64) -> u64;
    /// The first cycle it may take the next span.
    fn free(&self) -> u64;
    /// The first cycle triangle `index` (of the frame's work) may be taken in, the edge walk
    /// free from cycle `ew_free` (of the triangle before): 0, unless the taker holds the
    /// input back.
    fn offer(&mut self, _index: usize, _ew_free: u64, _last: &mut u64) -> u64 {
        0
    }
    /// Triangle `index` left `cull_sort` rejected in cycle `left`.
    fn rejected(&mut self, _index: usize, _left: u64) {}
    /// The cycle the edge walk takes triangle `index`, setup's result for it valid from cycle
    /// `done` and the edge walk free from `ew_free`: the later, unless the taker holds the
    /// edge walk back.
    fn hand(&mut self, done: u64, ew_free: u64, _index: usize, _last: &mut u64) -> u64 {
        done.max(ew_free)
    }
    /// After the frame's last span: the frame lasts at least until what it still holds is
    /// through.
    fn finish(&mut self, _last: &mut u64) {}
}

/// What takes `span`'s pixels.
trait PixelSink {
    /// The cycle a pixel presented from cycle `from` on is taken in; the frame lasts at
    /// least until that pixel is through (in `last`).
    fn take(&mut self, from: u64, last: &mut u64) -> u64;
    /// After the frame's last pixel: the frame lasts at least until what the sink still
    /// holds is through.
    fn finish(&mut self, _last: &mut u64) {}
}

/// What takes `span`'s pixels: `pixel_out` and its memory, ready in the cycles `ready` says
/// (or, without `pixel_out`, the host).
struct Sink<'a> {
    ready: &'a dyn Fn(u64) -> bool,
    pixel_out: bool,
}

impl Sink<'_> {
    /// The cycle a pixel presented from cycle `from` on is taken in: the first ready one.
    fn first_ready(&self, from: u64) -> u64 {
        (from..).find(|&c| (self.ready)(c)).expect("the memory is ready again")
    }

    /// The cycle the frame can be done in once the pixel taken in `taken` is through: the
    /// cycle after `pixel_out`'s write, which is in the second ready cycle after `taken`
    /// (its test in the first; `taken` + 2 without stalls: [`pixel_out::LATENCY`]); without
    /// `pixel_out`, the cycle after `taken`.
    fn through(&self, taken: u64) -> u64 {
        if self.pixel_out {
            const _: () = assert!(pixel_out::LATENCY == 2);
            self.first_ready(self.first_ready(taken + 1) + 1) + 1
        } else {
            taken + 1
        }
    }
}

impl PixelSink for Sink<'_> {
    fn take(&mut self, from: u64, last: &mut u64) -> u64 {
        let taken = self.first_ready(from);
        *last = (*last).max(self.through(taken));
        taken
    }
}

/// `span`: it takes a command when idle or in the last cycle of the walk before, and walks
/// it in the cycles from `start` (in this model's count; `FrameCycles::total` is the cycle
/// `done` rises in), a walk cycle (a pixel sent or not) in each cycle its pixel register is
/// empty or its pixel is taken; a pixel walked in cycle a is in the register from a + 1
/// ([`span::LATENCY`] = 2) until the sink takes it. Without stalls, walk cycle k is
/// start + k, its pixel taken in start + k + 1, and the frame done 3 cycles after that.
struct SpanUnit<S> {
    free: u64,
    /// The cycle from which the pixel register holds a pixel not yet taken, if it does.
    held: Option<u64>,
    /// The cycle after the last one a pixel was taken in.
    emptied: u64,
    sink: S,
}

impl<S: PixelSink> SpanUnit<S> {
    fn new(sink: S) -> Self {
        SpanUnit { free: 0, held: None, emptied: 0, sink }
    }

    /// The pixel register's pixel, if any, taken by the sink: the cycle it is taken in
    /// (the frame lasts until it is through).
    fn release(&mut self, last: &mut u64) -> Option<u64> {
        let taken = self.sink.take(self.held.take()?, last);
        self.emptied = taken + 1;
        Some(taken)
    }

    /// The first cycle `span` is idle (`rtl::span`'s `idle`) after the spans it was given:
    /// its last walked, its last pixel taken.
    fn idle(&mut self, last: &mut u64) -> u64 {
        self.release(last);
        self.free.max(self.emptied)
    }
}

impl<S: PixelSink> SpanTaker for SpanUnit<S> {
    fn take(&mut self, avail: u64, s: &SpanWork, last: &mut u64, busy: &mut u64) -> u64 {
        const _: () = assert!(span::LATENCY == 2);
        let start = avail.max(self.free);
        let (mut at, mut unsent) = (start, s.unsent.iter().peekable());
        for k in 0..s.cycles {
            // Walk cycle k: in the first cycle from `at` with the register empty, or in the
            // one its pixel is taken in.
            let walked = self.release(last).map_or(at, |taken| taken.max(at));
            if unsent.next_if_eq(&&k).is_none() {
                self.held = Some(walked + 1);
            }
            at = walked + 1;
        }
        self.free = at;
        *busy += self.free - start;
        start
    }

    fn free(&self) -> u64 {
        self.free
    }

    fn finish(&mut self, last: &mut u64) {
        self.release(last);
        self.sink.finish(last);
    }
}

/// `se_cmd` and the engines: a span off screen is dropped in the cycle it is taken; one on
/// screen is offered `ready_after` cycles after and issued when `se_cmd::issue_gap` has
/// passed since the last issue; the next is taken the cycle after.
struct SeIssue {
    prm: se::SeParams,
    ready_after: u64,
    /// The cycle after the first one `se_cmd` may take a span in.
    free: u64,
    /// The last issue: its cycle and row.
    last_issue: Option<(u64, u32)>,
}

impl SpanTaker for SeIssue {
    fn take(&mut self, avail: u64, s: &SpanWork, last: &mut u64, busy: &mut u64) -> u64 {
        let start = avail.max(self.free);
        if !s.on_screen {
            self.free = start + 1;
            return start;
        }
        let ready = start - 1 + self.ready_after;
        let issue = match self.last_issue {
            Some((c, y)) => ready.max(c + se_cmd::issue_gap(&self.prm, y == s.y)),
            None => ready,
        };
        self.last_issue = Some((issue, s.y));
        self.free = issue + 2;
        *busy += self.prm.ii() as u64;
        *last = (*last).max(issue + se_done(&self.prm));
        start
    }

    fn free(&self) -> u64 {
        self.free
    }
}

/// Cycles of a frame through `cull_sort`, setup, the edge walk and the span FIFO, its
/// commands taken by `taker`.
fn front_end_frame(work: &[Work], t: &Timing, taker: &mut impl SpanTaker) -> FrameCycles {
    let SetupTiming { latency: setup, interval, .. } = setup_timing(t);
    let (setup, interval) = (setup as u64, interval as u64);
    let fifo = t.span_fifo.max(1) as usize;
    let (mut ew_free, mut last) = (0u64, 0u64);
    // The last triangle setup took: the cycle it was taken and the cycle its result was
    // taken (setup is empty from the next one); and the spans of cycles in which setup
    // stands still (from the cycle a result is valid until the one it is taken in), those
    // that can still delay a triangle.
    let mut last_taken: Option<(u64, u64)> = None;
    let mut waits: Vec<(u64, u64)> = Vec::new();
    // The cycle setup reaches `n` cycles of running after `from`, standing still in `waits`.
    let running = |waits: &[(u64, u64)], from: u64, n: u64| {
        waits.iter().filter(|w| w.0 >= from).fold(from + n, |t, &(d, h)| if d < t { t + (h - d) } else { t })
    };
    let mut cull = CullSortStages::new(t.cull_sort);
    let mut span_starts: Vec<u64> = Vec::new();
    let mut out = FrameCycles::default();
    for (index, w) in work.iter().enumerate().filter(|(_, w)| t.cull_sort || w.passed_cull) {
        cull.not_before(taker.offer(index, ew_free, &mut last));
        let culled = match cull.passing(w.passed_cull, &mut last) {
            Ok(culled) => culled,
            Err(left) => {
                taker.rejected(index, left);
                continue;
            }
        };
        out.triangles += 1;
        // Setup takes a triangle on the grid of the last one it took (when that one has run
        // II, 2 II, ... cycles), or at once when empty. No triangle is taken while setup
        // stands still; every triangle in flight stands still with it, however many results
        // ahead of its own the wait is for.
        let mut setup_start = match last_taken {
            Some((start, handed)) if culled <= handed => {
                let grid = (1..).map(|n| running(&waits, start, n * interval)).find(|&g| g >= culled).unwrap();
                grid.min(handed + 1)
            }
            _ => culled,
        };
        for &(d, h) in &waits {
            if (d..h).contains(&setup_start) {
                setup_start = h;
            }
        }
        waits.retain(|w| w.0 >= setup_start);
        cull.leave(setup_start);
        let done = running(&waits, setup_start, setup);
        let ew_start = taker.hand(done, ew_free, index, &mut last);
        last_taken = Some((setup_start, ew_start));
        if ew_start > done {
            waits.push((done, ew_start));
        }
        let mut now = ew_start + edge_walk::LATENCY as u64;
        for scanline in &w.scanlines {
            if let Some(span) = scanline {
                // A full FIFO holds the walk until the taker takes an older command.
                if span_starts.len() >= fifo {
                    now = now.max(span_starts[span_starts.len() - fifo]);
                }
                // Pushed into the FIFO in `now`, offered from its head SPAN_FIFO_LATENCY later.
                let offered = now + SPAN_FIFO_LATENCY as u64;
                span_starts.push(taker.take(offered + 1, span, &mut last, &mut out.span_busy));
            }
            now += 1;
        }
        ew_free = now;
        last = last.max(taker.free()).max(now);
    }
    taker.finish(&mut last);
    out.total = last;
    out
}

/// Cycles from a pixel presented to `pixel_out` (or, without it, leaving the rasterizer)
/// to the cycle the frame can be done.
fn write_latency(t: &Timing) -> u64 {
    if t.pixel_out {
        1 + pixel_out::LATENCY as u64
    } else {
        1
    }
}

/// `cull_sort`'s stages as a frame sees them (none without it): `free[k]` is the cycle the
/// triangle before left stage k + 1 (the last: the output register), in which the next may
/// move into it; the next triangle is taken (without `cull_sort`: offered to the unit
/// behind) in `free[0]`.
struct CullSortStages {
    stages: usize,
    free: Vec<u64>,
    /// The cycle the triangle in flight leaves stage k (0: taken).
    leaves: Vec<u64>,
}

impl CullSortStages {
    fn new(present: bool) -> Self {
        let stages = if present { cull_sort::LATENCY as usize } else { 0 };
        CullSortStages { stages, free: vec![0; stages.max(1)], leaves: vec![0; stages.max(1)] }
    }

    /// The next triangle through the stages: its first cycle in the output register, with
    /// its verdict (without `cull_sort`, the cycle it is offered).
    fn arrive(&mut self) -> u64 {
        self.leaves[0] = self.free[0];
        for k in 1..self.stages {
            self.leaves[k] = (self.leaves[k - 1] + 1).max(self.free[k]);
        }
        if self.stages == 0 {
            self.leaves[0]
        } else {
            self.leaves[self.stages - 1] + 1
        }
    }

    /// The next triangle through the stages, its verdict `passed`: the cycle it arrives in
    /// the output register (the frame lasts at least until then, in `last`), or, when it is
    /// rejected, `Err` of that cycle, which it leaves in.
    fn passing(&mut self, passed: bool, last: &mut u64) -> Result<u64, u64> {
        let culled = self.arrive();
        *last = (*last).max(culled);
        if !passed {
            self.leave(culled);
            return Err(culled);
        }
        Ok(culled)
    }

    /// The next triangle is taken no earlier than cycle `c`.
    fn not_before(&mut self, c: u64) {
        self.free[0] = self.free[0].max(c);
    }

    /// The triangle leaves the output register in `left` (a rejected one in the cycle it
    /// arrives; a passing one when the unit behind takes it): each stage is free for the
    /// next from the cycle this one left it.
    fn leave(&mut self, left: u64) {
        let n = self.free.len();
        self.free[..n - 1].copy_from_slice(&self.leaves[1..]);
        self.free[n - 1] = left;
    }
}

/// The vector unit's timing (`rtl::vector`, `model::vector`): triangles go through its
/// setup one at a time, then through the scout, which finds each row's chunks, and the
/// walker, which walks them; setup overlaps the scout and the walker, and the scout the
/// walker. A triangle's constants are one of two sets.
#[derive(Clone, Debug)]
pub struct VectorUnit {
    setup: u64,
    pixel: u64,
    held: u64,
    /// The first cycle setup may take a triangle; the first cycle the scout is free; the
    /// walker's last chunk (it may take a row in that cycle or later); per set, the first
    /// cycle it may be loaded; the set the next triangle uses.
    setup_free: u64,
    scout_free: u64,
    walk_last: u64,
    set_free: [u64; 2],
    set: usize,
    /// The first cycle the unit is empty, after what it has been given.
    idle: u64,
}

/// When the vector unit handled one triangle ([`VectorUnit::triangle`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct VectorTimes {
    /// The cycle it was taken.
    pub taken: u64,
    /// Per row of its walk, the cycle the walker took it (its chunk `k` is in the walker's
    /// registers in the cycle `take + 1 + k`, and its pixels leave `vector::pixel_latency`
    /// cycles after); `None` for a row found empty. Empty for an empty box.
    pub takes: Vec<Option<u64>>,
}

impl VectorTimes {
    /// The walk cycle of chunk `k` of row `row`.
    pub fn chunk(&self, (row, k): (u32, u32)) -> u64 {
        self.takes[row as usize].expect("a row walked") + 1 + k as u64
    }
}

impl VectorUnit {
    /// An empty unit with a `divider_latency`-stage divider.
    pub fn new(divider_latency: u32) -> VectorUnit {
        VectorUnit {
            setup: vector::setup(divider_latency) as u64,
            pixel: vector::pixel_latency(divider_latency) as u64,
            held: vector::constants_read(divider_latency) as u64,
            setup_free: 0,
            scout_free: 0,
            walk_last: 0,
            set_free: [0; 2],
            set: 0,
            idle: 0,
        }
    }

    /// A triangle offered from cycle `offered` whose box has the rows `rows` (none: empty):
    /// taken when setup is free; set up in `vector::setup` cycles, the last of which (or a
    /// later one) hands it to the scout when the scout is free and its set of constants is
    /// read no more; setup is free from the cycle after, and the scout starts on the first
    /// row. The scout searches a row for `search` cycles from the cycle after it began it; a
    /// row found empty it leaves in its last, a row found it holds until the walker takes
    /// it (in the walker's last chunk or later), and it begins the next row in the cycle
    /// after that.
    pub fn triangle(&mut self, offered: u64, rows: &[vector::WalkRow]) -> VectorTimes {
        let taken = offered.max(self.setup_free);
        let ready = taken + self.setup - 1;
        if rows.is_empty() {
            self.setup_free = ready + 1;
            self.idle = self.idle.max(self.setup_free);
            return VectorTimes { taken, takes: Vec::new() };
        }
        let handed = ready.max(self.scout_free).max(self.set_free[self.set]);
        self.setup_free = handed + 1;
        let mut start = handed + 1;
        let mut takes = Vec::with_capacity(rows.len());
        let mut walked = false;
        for r in rows {
            let found = start + r.search as u64 - 1;
            if r.chunks == 0 {
                takes.push(None);
                start = found + 1;
                continue;
            }
            let take = found.max(self.walk_last);
            takes.push(Some(take));
            self.walk_last = take + r.chunks as u64;
            walked = true;
            start = take + 1;
        }
        self.scout_free = start;
        if walked {
            self.set_free[self.set] = self.walk_last + self.held;
            self.idle = self.idle.max(self.walk_last + self.pixel + 1);
        }
        self.set ^= 1;
        self.idle = self.idle.max(self.scout_free).max(self.setup_free);
        VectorTimes { taken, takes }
    }

    /// The first cycle the unit is empty after the triangles given.
    pub fn idle(&self) -> u64 {
        self.idle
    }
}

/// Cycles of a frame through the vector pipeline (`cull_sort` -> `vector` -> `pixel_out`,
/// `rtl::raster_top` with `METHOD = 1`): the vector unit ([`VectorUnit`], the default
/// divider) takes a passing triangle from `cull_sort`'s output register when its setup is
/// free, and sends its pixel `k` of the walk `vector::pixel_latency` cycles after the walk
/// cycle `k`; the frame is done when the unit is empty and `pixel_out` has written the last
/// pixel.
pub fn vector_frame(work: &[Work], t: &Timing) -> FrameCycles {
    let mut cull = CullSortStages::new(t.cull_sort);
    let mut unit = VectorUnit::new(crate::divider::LATENCY);
    let pixel = vector::pixel_latency(crate::divider::LATENCY) as u64;
    let mut last = 0u64;
    let mut out = FrameCycles::default();
    for w in work.iter().filter(|w| t.cull_sort || w.passed_cull) {
        let Ok(culled) = cull.passing(w.passed_cull, &mut last) else { continue };
        out.triangles += 1;
        let times = unit.triangle(culled, &w.vector_rows);
        cull.leave(times.taken);
        out.span_busy += w.vector_rows.iter().map(|r| r.chunks as u64).sum::<u64>();
        if let Some(at) = w.vector_last_sent {
            last = last.max(times.chunk(at) + pixel + write_latency(t));
        }
    }
    out.total = last.max(unit.idle());
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 001's 5-stage divider, at which the frames below are derived by hand (setup's
    /// latency 32, II 10).
    fn l5() -> Timing {
        Timing { divider_latency: 5, ..Timing::default() }
    }

    #[test]
    fn cycles_setup_timing_is_its_schedules() {
        // 001's 7 multipliers and the default divider: the schedule's latency and II
        // (`triangle_setup::schedule`, whose tests derive them).
        let s = Schedule::new(7, crate::divider::LATENCY as usize).unwrap();
        assert_eq!(
            setup_timing(&Timing::default()),
            SetupTiming { latency: s.latency as u32, interval: s.interval as u32 }
        );
        assert_eq!(setup_latency(&Timing::default()), s.latency as u32);
        assert_eq!(setup_timing(&l5()), SetupTiming { latency: 32, interval: 10 });
    }

    /// Triangles in flight: each is taken on the II grid of the one before (latency 32, II
    /// 10); while one waits for the edge walk, those taken after it wait with it.
    #[test]
    fn cycles_setup_overlaps_triangles_and_waits_as_one() {
        assert_eq!(setup_timing(&l5()), SetupTiming { latency: 32, interval: 10 });
        let walk = |n: usize| Work { passed_cull: true, scanlines: vec![None; n], ..Work::default() };
        // First: culled out at 3 (cull_sort's three stages), taken, done at 35, walked
        // 37..87. Second: culled out at 4, taken at 3 + 10 = 13 (the grid), done at 45,
        // waits for the walk until 87, walked 89..90. Third: culled out at 14 (it waited in
        // stage 2 while the second held the output register), taken at 23 (the second in its
        // cycle 10), in flight while the second waits 42 cycles: done at 23 + 32 + 42 = 97,
        // walked 99..100.
        assert_eq!(scanline_frame(&[walk(50), walk(1), walk(1)], &l5()).total, 100);
        // A triangle waits for every result ahead of it that waits. With a second long walk,
        // the second waits from 45 to 87 as above and the third from 97 to 139; the fourth,
        // taken at 33 (the third in its cycle 10), runs 12 cycles, stands still 42, runs 10,
        // stands still 42, runs 10: done at 149, walked 151..152.
        assert_eq!(scanline_frame(&[walk(50), walk(50), walk(1), walk(1)], &l5()).total, 152);
        // Without the long walk nothing waits: the third is done at 55, walked 57..58.
        assert_eq!(scanline_frame(&[walk(1), walk(1), walk(1)], &l5()).total, 58);
        // Off the grid, a triangle is taken once setup is empty: as above, the second waits
        // from 45 to 87; the third, culled out at 54 behind 40 culled ones, would be on the
        // grid at 95 (13 + 40 cycles of running, 42 standing still) and goes in at 88, the
        // cycle after the second's result is taken; done at 88 + 32 = 120, walked 122..123.
        let mut frame = vec![walk(50), walk(1)];
        frame.extend(std::iter::repeat_n(Work::default(), 40));
        frame.push(walk(1));
        assert_eq!(scanline_frame(&frame, &l5()).total, 123);
        // On the grid: the third, culled out at 14 + 10 behind 10 culled ones, waits for
        // the grid at 33 (the second in its cycle 20), not for 45 and the second's result.
        let mut frame = vec![walk(1), walk(1)];
        frame.extend(std::iter::repeat_n(Work::default(), 10));
        frame.push(walk(1));
        assert_eq!(scanline_frame(&frame, &l5()).total, 33 + 32 + 3);
    }

    /// A span of `c` cycles, each sending a pixel.
    fn full(c: u32) -> Option<SpanWork> {
        Some(SpanWork { cycles: c, ..SpanWork::default() })
    }

    #[test]
    fn cycles_one_triangle_through_the_scanline_pipeline() {
        // Taken in cycle 0, culled out at 3; setup done at 3 + 32 = 35; the walk pushes
        // into the span FIFO in 37, 38, 39, each offered from its head a cycle later; span
        // walks each from 2 cycles after its push or when free: 39..44, 44..49, 49..54; the
        // last pixel leaves span's pixel register in 54 and is written 2 cycles after, in
        // cycle 56: 57 cycles.
        let w = Work { passed_cull: true, scanlines: vec![full(5), full(5), full(5)], ..Work::default() };
        let c = scanline_frame(std::slice::from_ref(&w), &l5());
        assert_eq!((c.total, c.span_busy, c.triangles), (57, 15, 1));
        // A culled triangle ahead costs one cycle of cull_sort only.
        let culled = Work::default();
        assert_eq!(scanline_frame(&[culled.clone(), w.clone()], &l5()).total, 58);
        // Behind a triangle waiting for setup, culled ones wait too: the first triangle
        // leaves cull_sort for setup in cycle 3, the second (which crosses no scanline)
        // arrives in the output register at 4 and leaves in 13, when the first is in its
        // cycle 10 (II); the first two culled ones, taken at 2 and 3, wait in stages 1 and
        // 2 (nothing more is taken), then the 45 culled ones go through cull_sort, one per
        // cycle, the last one's verdict in cycle 13 + 45 (after the first triangle's last
        // pixel, 57).
        let mut frame = vec![w.clone(), Work { passed_cull: true, ..Work::default() }];
        frame.extend(std::iter::repeat_n(culled, 45));
        assert_eq!(scanline_frame(&frame, &l5()).total, 13 + 45);
        // With a 4-deep FIFO the walk runs ahead and span never waits: walking from 39
        // for 53 cycles, the last pixel out of the pixel register 1 later, written 2 later.
        let long = Work { scanlines: vec![full(50), full(1), full(1), None, full(1)], ..w.clone() };
        assert_eq!(scanline_frame(std::slice::from_ref(&long), &l5()).total, 39 + 53 + 1 + 2);
        // A one-deep FIFO holds the walk until span takes each command: the second, pushed
        // in 38, is taken in 88 as the first span's walk ends and walked in 89; the third can
        // be pushed only in 89 (the FIFO empties the cycle after its head is taken), offered
        // in 90 and walked in 91; the last, pushed in 91, is walked in 93: two idle cycles.
        let one_deep = Timing { span_fifo: 1, ..l5() };
        assert_eq!(scanline_frame(&[long], &one_deep).total, 39 + 53 + 2 + 1 + 2);
        // Spans that end on pixels sent nowhere (off screen, out of the depth range, or
        // dropped): the frame ends when span is done, or 4 cycles after the last pixel's
        // walk cycle (out of the pixel register, into pixel_out, written).
        let mut tail = w.clone();
        tail.scanlines[2] = Some(SpanWork { cycles: 5, unsent: vec![2, 3, 4], ..SpanWork::default() });
        assert_eq!(scanline_frame(&[tail.clone()], &l5()).total, 54);
        tail.scanlines[2] = Some(SpanWork { cycles: 1, unsent: vec![0], ..SpanWork::default() });
        // Dropped: span done at 50, the pixel walked in 48 out of span in 49, written in 51.
        assert_eq!(scanline_frame(&[tail], &l5()).total, 52);
    }

    /// The memory stalling (`mem$ready` low): `pixel_out` and span's pixel register hold,
    /// the walk with them; a stall with nothing to take costs nothing.
    #[test]
    fn cycles_scanline_frame_behind_a_stalling_memory() {
        // The frame of `cycles_one_triangle_through_the_scanline_pipeline`: spans walked in
        // 39..43, 44..48, 49..53, each pixel in the register from the cycle after its walk
        // cycle and taken there; the last tested in 55, written in 56, done in 57.
        let w = Work { passed_cull: true, scanlines: vec![full(5), full(5), full(5)], ..Work::default() };
        let stalled = |from: u64, to: u64| {
            scanline_frame_stalled(std::slice::from_ref(&w), &l5(), &move |c| !(from..=to).contains(&c)).total
        };
        assert_eq!(stalled(1, 0), 57, "never stalled: as scanline_frame");
        // Stalled before the first pixel: nothing waits for the memory.
        assert_eq!(stalled(10, 39), 57);
        // Stalled in 45..49: the second span's first pixel (in the register from 45) is
        // taken in 50, its second walk cycle with it; everything 5 cycles later.
        assert_eq!(stalled(45, 49), 62);
        // Stalled in 56 only: the last pixel, taken in 54 and tested in 55, is written in 57.
        assert_eq!(stalled(56, 56), 58);
        // Stalled in 41..43 under a first span that sends nothing: its walk goes on (the
        // register stays empty); the second span's first pixel is walked in 44 and taken in
        // 45, after the stall: 57 as without it.
        let quiet = Work {
            scanlines: vec![
                Some(SpanWork { cycles: 5, unsent: vec![0, 1, 2, 3, 4], ..SpanWork::default() }),
                full(5),
                full(5),
            ],
            ..w.clone()
        };
        assert_eq!(scanline_frame(std::slice::from_ref(&quiet), &l5()).total, 57);
        let quiet_stalled = scanline_frame_stalled(std::slice::from_ref(&quiet), &l5(), &|c| !(41..=43).contains(&c));
        assert_eq!(quiet_stalled.total, 57);
        // The same stall under a span that sends: its pixel walked in 40, in the register
        // from 41, is taken in 44, and each walk cycle after waits for the one before:
        // walked in 39, 40, 44, 45, 46 instead of 39..43: 3 cycles later.
        assert_eq!(stalled(41, 43), 60);
    }

    #[test]
    fn cycles_without_cull_sort_or_pixel_out() {
        // Without cull_sort the triangle reaches setup in cycle 0 and culled ones are not
        // sent: 3 cycles less, and nothing for the 30 culled ones.
        let w = Work { passed_cull: true, scanlines: vec![full(5), full(5), full(5)], ..Work::default() };
        let mut frame = vec![Work::default(), w.clone()];
        frame.extend(std::iter::repeat_n(Work::default(), 30));
        let no_cull = Timing { cull_sort: false, ..l5() };
        assert_eq!(scanline_frame(&frame, &no_cull).total, 54);
        // Without pixel_out the frame ends the cycle after span's last fragment (54):
        // 2 cycles less than with the depth test and write behind it.
        let no_out = Timing { pixel_out: false, ..l5() };
        assert_eq!(scanline_frame(std::slice::from_ref(&w), &no_out).total, 55);
        let neither = Timing { cull_sort: false, pixel_out: false, ..l5() };
        assert_eq!(scanline_frame(&frame, &neither).total, 52);
    }

    /// The vector unit sets the next triangle up while it walks one, its scout finds the
    /// next row while the walker walks one, and the walker takes the row in its last chunk
    /// of the row before; a triangle waits for its set of constants (two triangles before);
    /// the frame ends when the last pixel is written or the unit is empty.
    #[test]
    fn cycles_vector_frame_overlaps_setup_scout_and_walk() {
        let l = crate::divider::LATENCY;
        let (setup, pixel, held) =
            (vector::setup(l) as u64, vector::pixel_latency(l) as u64, vector::constants_read(l) as u64);
        let row = |search, chunks| vector::WalkRow { search, chunks };
        let w = |rows: Vec<vector::WalkRow>, last| Work {
            passed_cull: true,
            vector_rows: rows,
            vector_last_sent: last,
            ..Work::default()
        };
        let t = Timing::default();
        let cull = cull_sort::LATENCY as u64;
        // Taken in cycle 3 (cull_sort's latency), handed over at 3 + setup - 1; the scout
        // finds its one row in the cycle after, the walker takes it then and walks its 100
        // chunks from the cycle after; the last pixel leaves pixel_latency later and is
        // written 3 cycles on.
        let first = cull + setup;
        assert_eq!(vector_frame(&[w(vec![row(1, 100)], Some((0, 99)))], &t).total, first + 100 + pixel + 3);
        // Its last pixel earlier: done when the unit is empty (the walk's end + pixel + 1).
        assert_eq!(vector_frame(&[w(vec![row(1, 100)], Some((0, 50)))], &t).total, first + 100 + pixel + 1);
        // A second triangle is set up during the first's walk and walks right after it.
        let two = vector_frame(&[w(vec![row(1, 100)], Some((0, 99))), w(vec![row(1, 10)], Some((0, 9)))], &t).total;
        assert_eq!(two, first + 110 + pixel + 3);
        // A row the scout needs 5 cycles for (4 moves) is taken 5 cycles after the row
        // before was: 2 cycles after the walker's last chunk of a 2-chunk row.
        let mut u = VectorUnit::new(l);
        let rows = [row(1, 2), row(5, 1), row(3, 0), row(1, 4)];
        let times = u.triangle(0, &rows);
        let handed = setup - 1;
        assert_eq!(times.takes, vec![Some(handed + 1), Some(handed + 6), None, Some(handed + 10)]);
        assert_eq!(times.chunk((3, 3)), handed + 14);
        assert_eq!(u.idle(), handed + 14 + pixel + 1);
        // Short walks: the third waits for the first's constants to be read no more.
        let mut u = VectorUnit::new(l);
        let s: Vec<u64> = (0..3).map(|_| u.triangle(0, &[row(1, 1)]).chunk((0, 0))).collect();
        assert_eq!(s[1] - s[0], setup, "the second: its own setup, taken as the first was handed over");
        assert_eq!(s[2], (s[0] + held + 2).max(s[1] + setup), "the third: the first's set");
        // An empty box hands over as soon as it is set up and walks nothing.
        let mut u = VectorUnit::new(l);
        assert_eq!(u.triangle(5, &[]), VectorTimes { taken: 5, takes: Vec::new() });
        assert_eq!(u.idle(), 5 + setup);
    }
}
