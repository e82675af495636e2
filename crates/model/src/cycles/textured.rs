//! The cycle model of the textured `raster_top` (`rtl::raster_top_textured`, `TEXTURE = 1`):
//! the scanline front end of [`super`] (`cull_sort`, setup, the edge walk, the span FIFO
//! and `span`), whose fragments a textured triangle sends through the texture path of
//! paper 001 §II-5, stepped cycle for cycle ([`TexturePath`], behind its texture memory),
//! and an untextured one straight to the blending `pixel_out`:
//!
//! * the edge walk takes a triangle only once `span` is idle, every fragment of the one
//!   before taken, and an untextured one only once the texture path is idle too (the RTL's
//!   `hold`); the triangle is the path's from the cycle after;
//! * a textured fragment is taken in the cycle the path takes it (its first with `new`:
//!   the path sets the triangle up first); the path's output goes to `pixel_out`, which
//!   takes it in a ready cycle (the memory's `ready`; the path's output is ready only while
//!   the current triangle is textured);
//! * an untextured fragment is taken by `pixel_out` as in [`super::scanline_frame_stalled`];
//! * the frame is done once the last pixel is written and the path is idle;
//! * the triangles' texture words wait in [`SLOTS`] slots, one per triangle taken, from its
//!   taking until `cull_sort` rejects it, or until the edge walk has walked it (`span` idle
//!   after it), and no slot is freed before an older one: a triangle is taken only while
//!   a slot beyond the next is free (15 triangles in use at most).
//!
//! The path is stepped from cycle 0 (the cache's power-up Clear included), one cycle at a
//! time and only forward: the front end asks for its cycles in order.

use super::{front_end_frame, FrameCycles, PixelSink, Sink, SpanTaker, SpanUnit, Timing};
use crate::render::{SpanWork, Work};
use crate::span::Pixel;
use crate::texture_memory::ReadPort;
use crate::texture_path::{Fragment, PathIn, SentWork, TexTriangle, TexturePath};

/// The slots of texture words (`rtl::raster_top_textured`'s RAM).
pub const SLOTS: usize = 16;

/// A textured frame's cycles and the texture cache's counters when it is done.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TexturedCycles {
    pub frame: FrameCycles,
    /// The cache's hits, misses and fills (`texture_path`'s counters).
    pub counters: [u64; 3],
}

/// Cycles of a frame of `tris` (the triangles sent, `texture_path::sent_work`) through the
/// textured `raster_top` with the units of `t`: its texture path `path` (at power-up),
/// behind texture memory `memory`, which takes a request in the cycles `ack` says (asked once
/// a cycle, in order from cycle 0), and a framebuffer memory ready in the cycles `ready`
/// says. Panics when `t` leaves out `cull_sort` or `pixel_out` (the textured `raster_top`
/// has both), or a triangle's fragments are not as many as its work sends.
pub fn textured_frame(
    tris: &[SentWork],
    t: &Timing,
    path: TexturePath,
    memory: &mut ReadPort,
    ack: &mut dyn FnMut(u64) -> bool,
    ready: &dyn Fn(u64) -> bool,
) -> TexturedCycles {
    assert!(t.cull_sort && t.pixel_out, "the textured raster_top has cull_sort and pixel_out");
    let work: Vec<Work> = tris.iter().map(|s| s.work.clone()).collect();
    let sink = PathSink {
        tris,
        path,
        memory,
        ack,
        out: Sink { ready, pixel_out: t.pixel_out },
        now: 0,
        cur: None,
        first: false,
        pixels: [].iter(),
        counters: [0; 3],
    };
    let mut taker = TexturedTaker { span: SpanUnit::new(sink), freed: Vec::new(), walking: false, after: Vec::new() };
    let frame = front_end_frame(&work, t, &mut taker);
    TexturedCycles { frame, counters: taker.span.sink.counters }
}

/// `span` and its sink, the edge walk held back as the module documentation says, and the
/// slots.
struct TexturedTaker<'a> {
    span: SpanUnit<PathSink<'a>>,
    /// Per triangle sent, in order, the cycle from which its slot is free and every older
    /// one (known for the triangles before the one last handed to the edge walk).
    freed: Vec<u64>,
    /// Whether a triangle was handed to the edge walk and not yet walked, and the rejected
    /// ones after it: the cycles after their verdicts. Their slots are freed once it is
    /// walked.
    walking: bool,
    after: Vec<u64>,
}

impl TexturedTaker<'_> {
    /// The triangle last handed is walked in cycle `idle` (the first with `span` idle after
    /// it): its slot is free from the next, and the rejected ones' after it from then or
    /// the cycle after their verdicts.
    fn walked(&mut self, idle: u64) {
        if std::mem::take(&mut self.walking) {
            self.free_from(idle + 1);
            for v in std::mem::take(&mut self.after) {
                self.free_from(v);
            }
        }
    }

    /// The next triangle's slot is free from cycle `c` (or when the one before is).
    fn free_from(&mut self, c: u64) {
        let c = c.max(self.freed.last().copied().unwrap_or(0));
        self.freed.push(c);
    }
}

impl SpanTaker for TexturedTaker<'_> {
    fn take(&mut self, avail: u64, s: &SpanWork, last: &mut u64, busy: &mut u64) -> u64 {
        self.span.take(avail, s, last, busy)
    }

    fn free(&self) -> u64 {
        self.span.free()
    }

    fn offer(&mut self, index: usize, ew_free: u64, last: &mut u64) -> u64 {
        // Taken once the triangle SLOTS - 1 before it has left its slot: SLOTS - 1 in use
        // with it at most (the RTL's `wi + 1 != base`).
        let Some(oldest) = (index + 1).checked_sub(SLOTS) else { return 0 };
        if oldest >= self.freed.len() {
            let idle = ew_free.max(self.span.idle(last));
            self.walked(idle);
        }
        self.freed[oldest]
    }

    fn rejected(&mut self, _index: usize, left: u64) {
        if self.walking {
            self.after.push(left + 1);
        } else {
            self.free_from(left + 1);
        }
    }

    fn hand(&mut self, done: u64, ew_free: u64, index: usize, last: &mut u64) -> u64 {
        // The triangle before is walked once the edge walk and span are idle.
        let idle = ew_free.max(self.span.idle(last));
        self.walked(idle);
        self.walking = true;
        self.span.sink.hand(done.max(idle), index, last)
    }

    fn finish(&mut self, last: &mut u64) {
        self.span.finish(last);
    }
}

/// `span`'s pixels taken by the texture path (the current triangle textured) or by
/// `pixel_out`.
struct PathSink<'a> {
    tris: &'a [SentWork],
    path: TexturePath,
    memory: &'a mut ReadPort,
    ack: &'a mut dyn FnMut(u64) -> bool,
    /// `pixel_out` and its memory.
    out: Sink<'a>,
    /// The path's next cycle.
    now: u64,
    /// The triangle whose fragments come, when textured; whether its first is still to
    /// come; its fragments still to come.
    cur: Option<TexTriangle>,
    first: bool,
    pixels: std::slice::Iter<'a, Pixel>,
    /// The counters after the last cycle stepped.
    counters: [u64; 3],
}

impl PathSink<'_> {
    /// One cycle of the path, `frag` offered when given: whether it is taken. Its output
    /// taken by `pixel_out` makes the frame last until that is written.
    fn step(&mut self, frag: Option<Fragment>, last: &mut u64) -> bool {
        let c = self.now;
        let m = self.memory.answer(c, (self.ack)(c));
        let i = PathIn {
            inp_valid: frag.is_some(),
            frag: frag.unwrap_or_default(),
            flush: false,
            out_ready: self.cur.is_some() && (self.out.ready)(c),
        };
        let o = self.path.step(&i, m);
        self.memory.ask(c, &m, o.mem);
        if o.out_valid && i.out_ready {
            *last = (*last).max(self.out.through(c));
        }
        self.counters = [o.counters.hits, o.counters.misses, o.counters.fills].map(u64::from);
        self.now += 1;
        o.inp_ready
    }

    /// The path stepped with nothing offered up to cycle `to`, not included.
    fn advance(&mut self, to: u64, last: &mut u64) {
        while self.now < to {
            self.step(None, last);
        }
    }

    /// The path stepped with nothing offered until it is idle: that cycle.
    fn drain(&mut self, last: &mut u64) -> u64 {
        while !self.path.is_idle() {
            self.step(None, last);
        }
        self.now
    }
}

impl PathSink<'_> {
    /// The cycle the edge walk takes triangle `index`, `span` idle and setup's result valid
    /// from cycle `idle`: then if it is textured, else once the path is idle too.
    fn hand(&mut self, idle: u64, index: usize, last: &mut u64) -> u64 {
        assert!(self.pixels.next().is_none(), "as many fragments as the work sends");
        debug_assert!(self.now <= idle, "the path is stepped only forward");
        let s = &self.tris[index];
        self.advance(idle, last);
        let handed = if s.sent.tex.is_some() { idle } else { self.drain(last) };
        self.advance(handed + 1, last);
        (self.cur, self.first, self.pixels) = (s.sent.tex, true, s.pixels.iter());
        handed
    }
}

impl PixelSink for PathSink<'_> {
    fn take(&mut self, from: u64, last: &mut u64) -> u64 {
        let pixel = *self.pixels.next().expect("as many fragments as the work sends");
        let Some(tri) = self.cur else { return self.out.take(from, last) };
        let frag = Fragment { pixel, new: self.first, tri };
        self.first = false;
        self.advance(from, last);
        loop {
            let c = self.now;
            if self.step(Some(frag), last) {
                return c;
            }
        }
    }

    fn finish(&mut self, last: &mut u64) {
        let idle = self.drain(last);
        *last = (*last).max(idle);
    }
}
