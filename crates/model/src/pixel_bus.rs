//! `pixel_bus`: `pixel_out`'s depth test (LESS) and buffer writes with the depth and
//! colour buffers in system memory, behind AXI4 masters, cycle by cycle. Mirrors
//! `rtl::pixel_bus` on every cycle.
//!
//! **Buffers.** Pixel (x, y) has a 32-bit depth word at `depth_base + y * depth_pitch + 4x`
//! (the depth in its low bits) and a 32-bit colour word `0x00RRGGBB` at `color_base + y *
//! color_pitch + 4x`; pitches are bytes per row, below 2^16.
//!
//! **Buses.** Three single-beat, 32-bit AXI4 channels groups: depth reads (`zr`), depth
//! writes (`zw`) and colour writes (`cw`); a system puts `zr` and `zw` on one AXI4 master
//! and `cw` on another. Every transfer is offered from a register; `r_ready` and `b_ready`
//! are always high.
//!
//! **A frame.** `start` (taken only while [`Outputs::idle`]) clears the bus error and, with
//! `clear`, first writes every pixel of the `width` x `height` screen: depth `2^DEPTH - 1`
//! (the far plane, `cull_sort::z_max`) and the `background` colour, one pixel a cycle, then
//! waits for every write's response. Pixels are then taken one a cycle:
//!
//! * **In.** A pixel is taken while drawing when one of the [`INPUT`] input registers is
//!   free (`inp$ready` is a function of registers only), with its two word addresses. The
//!   oldest input enters the queue when a queue entry is free, the read-address register
//!   is free or being emptied, and no pixel in the queue has the same depth address (the
//!   hazard check: that pixel's write has not been answered yet, so a read of the word
//!   could return the old depth). Its depth word's read is offered from the next cycle.
//! * **Test.** Read data come back in order, each into the oldest entry waiting for one:
//!   the pixel passes if its depth is below the word's (and the read was not answered with
//!   an error).
//! * **Write.** The oldest tested entry not yet written writes its depth and colour words
//!   when it passed and the four write registers (address and data of each buffer) are free
//!   or being emptied, and fewer than 128 writes of either buffer are unanswered.
//! * **Out.** The oldest entry leaves the queue when it did not pass, or once a depth-write
//!   response has come for it (responses come in order).
//!
//! So a pixel's depth is read only after every earlier write of its word was answered, and
//! the buffers end as `pixel_out::Framebuffer` ends with the same pixels in order: the
//! tests check that against `WordMemory`, whose reads return a word as it was before any
//! unanswered write. With the memory answering in `latency` cycles, [`Params::entries`]
//! pixels are in flight: a pixel a cycle while a read and a write's response take fewer
//! cycles than that.

use crate::span::Pixel;
use crate::word_memory::{WordMemory, WordRequest, WordResponse};
use std::collections::VecDeque;

/// The unit's build parameters.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Params {
    /// Queue entries: pixels in flight, a power of two from 2 to 64.
    pub entries: u32,
    /// Bits of a depth value (`z.frac`, 1 to 32).
    pub depth_bits: u32,
}

impl Params {
    /// Why these parameters build no unit, if they do not.
    pub fn check(&self) -> Result<(), String> {
        if !(self.entries.is_power_of_two() && (2..=64).contains(&self.entries)) {
            return Err(format!("{} queue entries: a power of two from 2 to 64", self.entries));
        }
        if !(1..=32).contains(&self.depth_bits) {
            return Err(format!("a depth of {} bits: 1 to 32", self.depth_bits));
        }
        Ok(())
    }
}

/// Writes of one buffer left unanswered at most, before the unit waits.
pub const MAX_PENDING: u32 = 128;

/// Input registers: pixels taken and not yet in the queue. Two keep a pixel a cycle
/// coming in while `inp$ready` depends on no input: the address arithmetic and the hazard
/// check, on the oldest input's registered address, end in registers.
pub const INPUT: usize = 2;

/// Where the buffers are and what a clear writes: ports held while the unit is busy.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Config {
    pub width: u32,
    pub height: u32,
    pub background: [u8; 3],
    pub color_base: u32,
    pub color_pitch: u16,
    pub depth_base: u32,
    pub depth_pitch: u16,
}

impl Config {
    /// The depth word's and the colour word's addresses of pixel (x, y).
    pub fn addresses(&self, x: u32, y: u32) -> (u32, u32) {
        let at = |base: u32, pitch: u16| base.wrapping_add(y.wrapping_mul(pitch.into())).wrapping_add(4 * x);
        (at(self.depth_base, self.depth_pitch), at(self.color_base, self.color_pitch))
    }
}

/// A colour as its 32-bit word, `0x00RRGGBB`.
pub fn color_word(rgb: [u8; 3]) -> u32 {
    u32::from_be_bytes([0, rgb[0], rgb[1], rgb[2]])
}

/// The unit's inputs, one cycle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Inputs {
    pub start: bool,
    /// With `start`: clear the buffers first.
    pub clear: bool,
    pub config: Config,
    /// The pixel offered (`inp$valid` and its fields).
    pub pixel: Option<Pixel>,
    /// The depth buffer's memory (reads and writes) and the colour buffer's (writes).
    pub depth: WordResponse,
    pub color: WordResponse,
}

/// The unit's outputs, one cycle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Outputs {
    /// The pixel offered is taken (`inp$ready`).
    pub ready: bool,
    /// What the unit drives on the depth buffer's channels (`zr`, `zw`) and the colour
    /// buffer's (`cw`; no reads).
    pub depth: WordRequest,
    pub color: WordRequest,
    /// Nothing to do: no clear, no pixel in flight, every write answered.
    pub idle: bool,
    /// A read or write answered with an error since `start`.
    pub error: bool,
}

/// The phases of a frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Phase {
    /// Pixels are taken.
    Draw,
    /// Writing the clear values.
    Clear,
    /// Waiting for the clear's write responses.
    Settle,
}

/// A pixel in the queue or in an input register.
#[derive(Clone, Copy, Debug, Default)]
struct Entry {
    depth_addr: u32,
    color_addr: u32,
    z: u32,
    color: u32,
    pass: bool,
}

/// A write channel pair's registers: the address and the data offered.
#[derive(Clone, Copy, Debug, Default)]
struct WriteSlot {
    aw: Option<u32>,
    w: Option<u32>,
}

impl WriteSlot {
    /// Free now or after this cycle's handshakes.
    fn free(&self, r: &WordResponse) -> bool {
        (self.aw.is_none() || r.aw_ready) && (self.w.is_none() || r.w_ready)
    }

    /// The registers after this cycle: loaded with `load`, else what was not taken.
    fn next(&self, r: &WordResponse, load: Option<(u32, u32)>) -> WriteSlot {
        match load {
            Some((addr, data)) => WriteSlot { aw: Some(addr), w: Some(data) },
            None => WriteSlot { aw: self.aw.filter(|_| !r.aw_ready), w: self.w.filter(|_| !r.w_ready) },
        }
    }
}

/// The unit's registers.
pub struct PixelBus {
    params: Params,
    phase: Phase,
    /// The clear's next pixel.
    cx: u32,
    cy: u32,
    /// The input registers, oldest first (at most [`INPUT`]).
    input: VecDeque<Entry>,
    /// The queue, a ring: `head` (the oldest) <= `written` (the next to write) <= `tested`
    /// (the next to get its read data) <= `tail` (the next free), counted without wrapping.
    entries: Vec<Entry>,
    head: u64,
    written: u64,
    tested: u64,
    tail: u64,
    /// The read address offered.
    ar: Option<u32>,
    zw: WriteSlot,
    cw: WriteSlot,
    /// Writes of each buffer offered and not yet answered.
    z_pending: u32,
    c_pending: u32,
    /// Depth-write responses come while drawing and not yet matched with an entry.
    credit: u32,
    error: bool,
}

impl PixelBus {
    /// The unit just out of reset: drawing, nothing in flight.
    pub fn new(params: Params) -> Result<PixelBus, String> {
        params.check()?;
        Ok(PixelBus {
            params,
            phase: Phase::Draw,
            cx: 0,
            cy: 0,
            input: VecDeque::with_capacity(INPUT),
            entries: vec![Entry::default(); params.entries as usize],
            head: 0,
            written: 0,
            tested: 0,
            tail: 0,
            ar: None,
            zw: WriteSlot::default(),
            cw: WriteSlot::default(),
            z_pending: 0,
            c_pending: 0,
            credit: 0,
            error: false,
        })
    }

    fn entry(&self, n: u64) -> &Entry {
        &self.entries[(n % self.entries.len() as u64) as usize]
    }

    fn entry_mut(&mut self, n: u64) -> &mut Entry {
        let len = self.entries.len() as u64;
        &mut self.entries[(n % len) as usize]
    }

    fn idle(&self) -> bool {
        self.phase == Phase::Draw
            && self.input.is_empty()
            && self.head == self.tail
            && self.z_pending == 0
            && self.c_pending == 0
    }

    /// Whether both buffers' write registers can take a write this cycle.
    fn can_write(&self, i: &Inputs) -> bool {
        self.zw.free(&i.depth) && self.cw.free(&i.color) && self.z_pending < MAX_PENDING && self.c_pending < MAX_PENDING
    }

    /// `inp$ready`: a pixel offered is taken this cycle.
    fn ready(&self) -> bool {
        self.phase == Phase::Draw && self.input.len() < INPUT
    }

    /// Whether the oldest input enters the queue this cycle.
    fn enters(&self, i: &Inputs) -> bool {
        let Some(p) = self.input.front() else { return false };
        let hazard = (self.head..self.tail).any(|n| self.entry(n).depth_addr == p.depth_addr);
        self.phase == Phase::Draw
            && self.tail - self.head < self.entries.len() as u64
            && (self.ar.is_none() || i.depth.ar_ready)
            && !hazard
    }

    /// What the unit drives this cycle: its registers' outputs alone (no input reaches an
    /// output in the same cycle).
    pub fn outputs(&self) -> Outputs {
        let request =
            |ar: Option<u32>, s: &WriteSlot| WordRequest { ar, aw: s.aw, w: s.w, r_ready: true, b_ready: true };
        Outputs {
            ready: self.ready(),
            depth: request(self.ar, &self.zw),
            color: request(None, &self.cw),
            idle: self.idle(),
            error: self.error,
        }
    }

    /// The clock edge.
    pub fn clock(&mut self, i: &Inputs) {
        let c = i.config;
        let idle = self.idle();
        let can_write = self.can_write(i);
        let enters = self.enters(i);
        let taken = i.pixel.filter(|_| self.ready());
        let mut error = self.error || (i.depth.r_valid && i.depth.r_error);
        error |= (i.depth.b_valid && i.depth.b_error) || (i.color.b_valid && i.color.b_error);

        // The writes loaded this cycle: the clear's pixel, or the oldest tested entry's.
        let mut load = None;
        let mut written = self.written;
        if self.phase == Phase::Clear && can_write {
            let (z_addr, c_addr) = c.addresses(self.cx, self.cy);
            let z_max = ((1u64 << self.params.depth_bits) - 1) as u32;
            load = Some(((z_addr, z_max), (c_addr, color_word(c.background))));
        } else if self.written != self.tested {
            let e = *self.entry(self.written);
            if !e.pass || can_write {
                written += 1;
            }
            if e.pass && can_write {
                load = Some(((e.depth_addr, e.z), (e.color_addr, e.color)));
            }
        }

        // The oldest entry leaves when it did not pass, or with a depth-write response.
        let credit_mask = 2 * self.params.entries - 1;
        let mut credit = (self.credit + (self.phase == Phase::Draw && i.depth.b_valid) as u32) & credit_mask;
        let mut head = self.head;
        if self.head != self.written {
            if !self.entry(self.head).pass {
                head += 1;
            } else if credit > 0 {
                head += 1;
                credit -= 1;
            }
        }

        // The read data of the oldest entry waiting for one.
        let mut tested = self.tested;
        if i.depth.r_valid && self.tested != self.tail {
            let old = i.depth.r_data & ((1u64 << self.params.depth_bits) - 1) as u32;
            let e = self.entry_mut(tested);
            e.pass = !i.depth.r_error && e.z < old;
            tested += 1;
        }

        let mut phase = self.phase;
        match self.phase {
            Phase::Clear if load.is_some() => {
                if self.cx + 1 < c.width {
                    self.cx += 1;
                } else {
                    self.cx = 0;
                    self.cy += 1;
                    if self.cy == c.height {
                        phase = Phase::Settle;
                    }
                }
            }
            Phase::Settle if self.z_pending == 0 && self.c_pending == 0 => phase = Phase::Draw,
            _ => {}
        }
        if i.start && idle {
            error = false;
            (self.cx, self.cy) = (0, 0);
            if i.clear && c.width > 0 && c.height > 0 {
                phase = Phase::Clear;
            }
        }

        self.ar = self.ar.filter(|_| !i.depth.ar_ready);
        if enters {
            let e = self.input.pop_front().expect("an input enters");
            let n = self.tail;
            *self.entry_mut(n) = e;
            self.tail += 1;
            self.ar = Some(e.depth_addr);
        }
        if let Some(p) = taken {
            let (depth_addr, color_addr) = c.addresses(p.x, p.y);
            self.input.push_back(Entry { depth_addr, color_addr, z: p.z, color: color_word(p.rgb), pass: false });
        }
        let pending = |n: u32, load: bool, b: bool| (n + load as u32).wrapping_sub(b as u32) & 0xff;
        self.z_pending = pending(self.z_pending, load.is_some(), i.depth.b_valid);
        self.c_pending = pending(self.c_pending, load.is_some(), i.color.b_valid);
        self.zw = self.zw.next(&i.depth, load.map(|(z, _)| z));
        self.cw = self.cw.next(&i.color, load.map(|(_, c)| c));
        (self.phase, self.head, self.written, self.tested, self.credit, self.error) =
            (phase, head, written, tested, credit, error);
    }
}

/// A frame through the unit, the way the tests drive it: `start` (with the clear or not)
/// in the first cycle, then the pixels offered in order, each held until taken, a cycle
/// offering one whenever `offer` says so, with the depth and colour buffers in two
/// [`WordMemory`]s. One driver feeds the model and the RTL alike.
pub struct FrameDrive<'a, 'm> {
    pub config: Config,
    pub clear: bool,
    pub depth: &'m mut WordMemory<'a>,
    pub color: &'m mut WordMemory<'a>,
    pixels: &'m [Pixel],
    offer: Box<dyn FnMut() -> bool + 'a>,
    /// The next pixel to offer, and whether it is offered this cycle.
    next: usize,
    offered: bool,
    cycle: u64,
}

impl<'a, 'm> FrameDrive<'a, 'm> {
    pub fn new(
        config: Config,
        clear: bool,
        depth: &'m mut WordMemory<'a>,
        color: &'m mut WordMemory<'a>,
        pixels: &'m [Pixel],
        offer: impl FnMut() -> bool + 'a,
    ) -> Self {
        FrameDrive { config, clear, depth, color, pixels, offer: Box::new(offer), next: 0, offered: false, cycle: 0 }
    }

    /// This cycle's inputs.
    pub fn inputs(&mut self) -> Inputs {
        if !self.offered && self.cycle > 0 && self.next < self.pixels.len() {
            self.offered = (self.offer)();
        }
        Inputs {
            start: self.cycle == 0,
            clear: self.clear,
            config: self.config,
            pixel: self.pixels.get(self.next).filter(|_| self.offered).copied(),
            depth: self.depth.response(),
            color: self.color.response(),
        }
    }

    /// The clock edge, with this cycle's inputs and the unit's outputs. Whether the frame
    /// is done: every pixel taken and the unit idle again.
    pub fn clock(&mut self, i: &Inputs, o: &Outputs) -> bool {
        let done = self.cycle > 0 && self.next == self.pixels.len() && o.idle;
        if i.pixel.is_some() && o.ready {
            self.next += 1;
            self.offered = false;
        }
        self.depth.clock(&o.depth);
        self.color.clock(&o.color);
        self.cycle += 1;
        done
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pixel_out::Framebuffer;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    const PARAMS: Params = Params { entries: 16, depth_bits: 24 };
    const DEPTH_BASE: u32 = 0x1000;
    const COLOR_BASE: u32 = 0x8000;
    /// Words of memory before and after each buffer, to catch writes outside.
    const GUARD: u32 = 16;

    /// A `width` x `height` screen whose rows are `pad` words longer than the screen.
    fn config(width: u32, height: u32, pad: u32) -> Config {
        let pitch = (4 * (width + pad)) as u16;
        Config {
            width,
            height,
            background: [1, 2, 3],
            color_base: COLOR_BASE,
            color_pitch: pitch,
            depth_base: DEPTH_BASE,
            depth_pitch: pitch,
        }
    }

    /// A memory holding a buffer of `c`'s screen and [`GUARD`] words each side, every word
    /// `fill`.
    fn memory<'a>(c: &Config, base: u32, fill: u32, latency: u32, stall: impl FnMut() -> bool + 'a) -> WordMemory<'a> {
        let words = c.height * u32::from(c.depth_pitch) / 4 + 2 * GUARD;
        WordMemory::new(vec![fill; words as usize], base - 4 * GUARD, latency, stall)
    }

    /// What the unit drove, and how long the frame took.
    struct Run {
        cycles: u64,
        error: bool,
    }

    /// `pixels` through the model until done (at most `max` cycles).
    fn run(drive: &mut FrameDrive, max: u64) -> Run {
        let mut unit = PixelBus::new(PARAMS).expect("parameters");
        for cycle in 0..max {
            let i = drive.inputs();
            let o = unit.outputs();
            unit.clock(&i);
            if drive.clock(&i, &o) {
                return Run { cycles: cycle + 1, error: o.error };
            }
        }
        panic!("the frame did not end in {max} cycles");
    }

    /// The buffers as `Framebuffer` would leave them after `pixels`, in the memories' words.
    fn expected(c: &Config, pixels: &[Pixel]) -> (Vec<u32>, Vec<u32>) {
        let mut fb = Framebuffer::new(c.width, c.height, (1 << PARAMS.depth_bits) - 1, c.background);
        for p in pixels {
            fb.pixel_out(p, 0);
        }
        let (mut depth, mut color) =
            (memory(c, DEPTH_BASE, 0xdead, 0, || false), memory(c, COLOR_BASE, 0xdead, 0, || false));
        for y in 0..c.height {
            for x in 0..c.width {
                let (za, ca) = c.addresses(x, y);
                let i = (y * c.width + x) as usize;
                let z = depth.slot(za).expect("inside");
                depth.words[z] = fb.depth[i];
                let k = color.slot(ca).expect("inside");
                color.words[k] = color_word(fb.rgb[i]);
            }
        }
        (depth.words, color.words)
    }

    /// Random pixels on a small screen, so that many share an address.
    fn pixels(rng: &mut ChaCha8Rng, c: &Config, n: usize) -> Vec<Pixel> {
        (0..n)
            .map(|_| Pixel {
                x: rng.gen_range(0..c.width),
                y: rng.gen_range(0..c.height),
                z: rng.gen_range(0..1 << PARAMS.depth_bits),
                rgb: rng.gen(),
            })
            .collect()
    }

    /// Cleared buffers, then random pixels at several latencies and back-pressures: the
    /// memories end as `Framebuffer` does, with nothing written outside the screen (the
    /// rows' padding and the guard words keep their fill).
    #[test]
    fn random_pixels_end_as_the_framebuffer() {
        let mut rng = ChaCha8Rng::seed_from_u64(crate::test_seed());
        for (latency, stall, offer) in [(0, 0.0, 1.0), (3, 0.2, 0.8), (20, 0.5, 0.5), (40, 0.0, 1.0)] {
            let c = config(rng.gen_range(1..12), rng.gen_range(1..9), rng.gen_range(0..3));
            let ps = pixels(&mut rng, &c, crate::test_count() / 2);
            let [mut s1, mut s2, mut s3] = [0u64; 3].map(|_| ChaCha8Rng::seed_from_u64(rng.gen()));
            let mut depth = memory(&c, DEPTH_BASE, 0xdead, latency, move || s1.gen_bool(stall));
            let mut color = memory(&c, COLOR_BASE, 0xdead, latency, move || s2.gen_bool(stall));
            let mut drive = FrameDrive::new(c, true, &mut depth, &mut color, &ps, move || s3.gen_bool(offer));
            let r = run(&mut drive, 1_000_000);
            assert!(!r.error);
            let (z, rgb) = expected(&c, &ps);
            assert_eq!(depth.words, z, "depth, latency {latency}");
            assert_eq!(color.words, rgb, "colour, latency {latency}");
            assert_eq!((depth.outside_reads, depth.outside_writes, color.outside_writes), (0, 0, 0));
        }
    }

    /// Pixels of distinct addresses at latency 0 go in one a cycle: the clear (one pixel a
    /// cycle), its responses, then a pixel a cycle and the last one's read, test, write and
    /// response.
    #[test]
    fn distinct_pixels_at_latency_0_take_one_cycle_each() {
        let c = config(8, 4, 0);
        let ps: Vec<Pixel> = (0..32).map(|i| Pixel { x: i % 8, y: i / 8, z: i, rgb: [i as u8; 3] }).collect();
        let mut depth = memory(&c, DEPTH_BASE, 0, 0, || false);
        let mut color = memory(&c, COLOR_BASE, 0, 0, || false);
        let r = run(&mut FrameDrive::new(c, false, &mut depth, &mut color, &ps, || true), 1000);
        // Cycle 0 starts, pixels are taken in cycles 1..=32 and enter the queue in 2..=33;
        // the last one's read is offered in 34 and answered in 35; in 36 it fails, and
        // leaves in 37: idle is seen in 38.
        assert_eq!(r.cycles, 39);
        let before = memory(&c, DEPTH_BASE, 0, 0, || false).words;
        assert_eq!(depth.words, before, "no depth below 0: nothing passes");
        let (mut depth, mut color) =
            (memory(&c, DEPTH_BASE, 0xffff_ffff, 0, || false), memory(&c, COLOR_BASE, 0, 0, || false));
        let r = run(&mut FrameDrive::new(c, false, &mut depth, &mut color, &ps, || true), 1000);
        // When it passes, its writes are loaded in 36, offered and taken in 37, answered
        // in 38, and it leaves with the response: idle in 39.
        assert_eq!((r.cycles, depth.written.len(), color.written.len()), (40, 32, 32));
    }

    /// At latency 40, a read and a write's response take over 80 cycles: 16 entries let
    /// about 16 pixels through per round trip.
    #[test]
    fn the_queue_sets_the_rate_at_long_latency() {
        let c = config(64, 4, 0);
        let ps: Vec<Pixel> = (0..256).map(|i| Pixel { x: i % 64, y: i / 64, z: 1, rgb: [0; 3] }).collect();
        let mut depth = memory(&c, DEPTH_BASE, 0xffff_ffff, 40, || false);
        let mut color = memory(&c, COLOR_BASE, 0, 40, || false);
        let r = run(&mut FrameDrive::new(c, false, &mut depth, &mut color, &ps, || true), 100_000);
        let round_trip = 2 * (40 + 1) + 3;
        let rounds = 256 / PARAMS.entries as u64;
        assert!((rounds * round_trip..(rounds + 2) * round_trip).contains(&r.cycles), "{} cycles", r.cycles);
    }

    /// A clear writes every pixel once and nothing else, then the unit is idle; a frame
    /// without the clear and without pixels ends at once.
    #[test]
    fn a_clear_writes_each_pixel_once() {
        let c = config(5, 3, 2);
        let (mut depth, mut color) =
            (memory(&c, DEPTH_BASE, 0xdead, 2, || false), memory(&c, COLOR_BASE, 0xdead, 2, || false));
        let r = run(&mut FrameDrive::new(c, true, &mut depth, &mut color, &[], || true), 1000);
        assert_eq!((depth.written.len(), color.written.len()), (15, 15));
        assert_eq!(depth.words, expected(&c, &[]).0);
        assert_eq!(color.words, expected(&c, &[]).1);
        assert!(r.cycles >= 15 && r.cycles <= 15 + 8, "{} cycles", r.cycles);
        let r = run(&mut FrameDrive::new(c, false, &mut depth, &mut color, &[], || true), 10);
        assert_eq!(r.cycles, 2);
    }

    /// A read or a write answered with an error raises `error` until the next `start`; a
    /// pixel whose read failed writes nothing.
    #[test]
    fn errors_are_sticky_and_failed_reads_write_nothing() {
        let c = Config { depth_base: 0x100, ..config(4, 1, 0) };
        // The depth buffer lies outside its memory: every read fails.
        let mut depth = memory(&config(4, 1, 0), DEPTH_BASE, 0xffff_ffff, 0, || false);
        let mut color = memory(&c, COLOR_BASE, 0, 0, || false);
        let ps = [Pixel { x: 1, y: 0, z: 5, rgb: [9; 3] }];
        let r = run(&mut FrameDrive::new(c, false, &mut depth, &mut color, &ps, || true), 100);
        assert!(r.error);
        assert_eq!((depth.outside_reads, depth.written.len(), color.written.len()), (1, 0, 0));
    }
}
