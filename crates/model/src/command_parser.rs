//! The command parser of 001 (§II.1, Fig. 4), cycle by cycle: it waits for a vertex buffer
//! (INIT), reads and checks its header (Header), then for each record of the triangle index
//! list (Tri Index) fetches the three vertices (vertex fetch), waits until the rasterizer
//! takes the triangle (CP Ready) and goes on, until the record that ends the buffer; the
//! buffer's format is `vertex_buffer`'s (Fig. 5).
//!
//! It reads memory through one AXI4 read master (`read_memory` answers it in the tests):
//! a burst per header (96 bytes), per index record and per vertex record (32 bytes each),
//! one burst outstanding at a time, every beat taken (`r_ready` is always high). A
//! post-transform vertex cache of [`Params::cache`] entries, direct-mapped by vertex
//! index, keeps shared vertices from being fetched again (001 keeps indices and vertex
//! data apart for this reuse); it is emptied when a buffer starts.
//!
//! Every rule a record breaks (`vertex_buffer::read_header`, `read_index_record`,
//! `read_vertex_record`, the same checks as reading a file) stops the parser in
//! [`State::Error`] with the rule's class as its error code ([`Fault`]), as do a buffer
//! built for other hardware (size class or formats), a buffer address off a record
//! boundary and a read the memory answers with an error. Every read lies inside
//! `[address, address + length)` of a header that passed, so a hostile buffer reads
//! nothing else, and every state leaves within a bounded number of cycles of the memory
//! answering and the rasterizer taking triangles.
//!
//! Timing (the RTL follows it on every cycle): a read address is offered the cycle after
//! the parser decides on it; a record is checked the cycle after its last beat; each
//! vertex takes a cycle of cache lookup (a hit also copies it), a miss adds its burst and
//! the check; the triangle goes to the output register in the cycle of its last vertex if
//! the register is free or being taken (else it waits in CP Ready).
//!
//! The next index record is read ahead: record `t + 1` is asked for in the cycle record
//! `t` is checked (or taken from ahead), so that its burst overlaps triangle `t`'s
//! lookups; a lookup that misses is repeated until the bus is free. Record `t + 1` is checked when it comes in (in CP
//! Ready that cycle holds the hand-over back), and its verdict waits until triangle `t`
//! has been handed over: a rule it breaks stops the parser then, after triangle `t`, as
//! when records were read one after another.

use crate::input::Vtx;
use crate::read_memory::{ReadRequest, ReadResponse};
use crate::vertex_buffer::{
    read_header, read_index_record, read_vertex_record, Broken, Fault, Header, IndexRecord, VertexRecord, HEADER_BYTES,
    RECORD_BYTES,
};
use fx::Build;

/// The parser's build parameters.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Params {
    /// Bytes per beat of the read bus: 4, 8, 16 or 32 (a record is 32 / this beats).
    pub beat_bytes: u32,
    /// Entries of the vertex cache, a power of two from 1 to 1024.
    pub cache: u32,
}

impl Default for Params {
    /// A 128-bit bus and 512 cache entries. Each triangle costs an index record's burst
    /// and, on an index-ordered mesh, half a vertex record's: on a 64-bit bus (4 beats a
    /// record) the knot took 9.9 cycles a triangle, more than setup's 10-cycle pace leaves
    /// for the triangles culled in a cycle or two; on 128 bits (2 beats) 6.9. An
    /// index-ordered mesh reuses a vertex a row of the mesh later, so the cache must hold a
    /// row (the dense torus's rows are 255 vertices: 1.97 fetches per triangle at 32
    /// entries, 1.49 at 256, 0.50 at 512). 512 entries of a vertex (about 90 bits at class
    /// 10) and its tag fit three ECP5 block RAMs.
    fn default() -> Params {
        Params { beat_bytes: 16, cache: 512 }
    }
}

impl Params {
    /// Why these parameters build no parser, if they do not.
    pub fn check(&self) -> Result<(), String> {
        if !(self.beat_bytes.is_power_of_two() && (4..=32).contains(&self.beat_bytes)) {
            return Err(format!("a read bus of {} bytes a beat: 4, 8, 16 or 32", self.beat_bytes));
        }
        if !(self.cache.is_power_of_two() && self.cache <= 1024) {
            return Err(format!("a vertex cache of {} entries: a power of two from 1 to 1024", self.cache));
        }
        Ok(())
    }

    /// Beats of a burst of `bytes`.
    fn beats(&self, bytes: usize) -> u32 {
        bytes as u32 / self.beat_bytes
    }
}

/// Fig. 4's states, and where the parser stops.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum State {
    /// INIT: waiting for `start`.
    Init,
    /// Reading and checking the header.
    Header,
    /// Tri Index: reading and checking index record `t`.
    TriIndex,
    /// Looking up (and fetching) the vertices of triangle `t`.
    VertexFetch,
    /// CP Ready: triangle `t` assembled, waiting for the output register.
    CpReady,
    /// The buffer's last triangle is in the output register: waiting for it to be taken.
    End,
    /// Stopped on a broken rule until the next `start`.
    Error,
}

/// What the parser is given, one cycle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Inputs {
    /// Start reading the buffer at `address` (in INIT or Error).
    pub start: bool,
    pub address: u32,
    /// The largest screen the colour and depth buffers hold (width, height): a header
    /// asking for more stops the parser ([`Fault::Screen`]). Read when the header is checked.
    pub screen: [u32; 2],
    /// The memory's side of the read bus.
    pub bus: ReadResponse,
    /// The rasterizer takes the output triangle.
    pub out_ready: bool,
}

impl Default for Inputs {
    /// Nothing started, no screen refused ([`ANY_SCREEN`]).
    fn default() -> Inputs {
        Inputs { start: false, address: 0, screen: ANY_SCREEN, bus: ReadResponse::default(), out_ready: false }
    }
}

/// A `screen` input that refuses no header: the largest the RTL's 16-bit ports carry.
pub const ANY_SCREEN: [u32; 2] = [0xffff; 2];

/// A triangle as the parser hands it over.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Triangle {
    pub vertices: [Vtx; 3],
    /// TI's flags: the buffer's and the frame's last triangle.
    pub end_of_buffer: bool,
    pub end_of_frame: bool,
}

/// What the parser drives, one cycle (all from registers).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Outputs {
    pub state: State,
    /// The read address offered (ARVALID, ARADDR, ARLEN + 1).
    pub ar: Option<ReadRequest>,
    /// The triangle offered to the rasterizer (valid and its words).
    pub out: Option<Triangle>,
    /// The header's render state, from the cycle after the header is checked.
    pub render: Option<Header>,
    /// One cycle: the frame's last triangle was taken (or a buffer of none was read).
    pub frame_done: bool,
    /// One cycle: the buffer's last triangle was taken.
    pub buffer_done: bool,
    /// The error code while in [`State::Error`].
    pub fault: Option<Fault>,
}

/// Counts over a run.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Stats {
    pub triangles: u64,
    pub index_bursts: u64,
    pub vertex_bursts: u64,
    pub cache_hits: u64,
}

impl Stats {
    /// Vertex records fetched per triangle handed over.
    pub fn fetches_per_triangle(&self) -> f64 {
        self.vertex_bursts as f64 / self.triangles.max(1) as f64
    }
}

/// What a burst reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Burst {
    Header,
    Index,
    Vertex,
}

/// The parser's registers.
#[derive(Clone, Debug)]
pub struct CommandParser {
    params: Params,
    /// The build the hardware draws: a buffer for another is refused.
    build: Build,
    state: State,
    fault: Option<Fault>,
    base: u32,
    header: Option<Header>,
    /// The read offered, and the burst taken and being received (with its beats so far).
    ar: Option<ReadRequest>,
    burst: Option<(Burst, u32)>,
    /// A burst received whole, to be checked this cycle.
    complete: Option<Burst>,
    bus_error: bool,
    /// The words of the burst (a header at most).
    words: [u32; HEADER_BYTES / 4],
    /// Triangle `t`: its index record and the vertices assembled (`k` so far).
    t: u32,
    record: Option<IndexRecord>,
    k: usize,
    /// Record `t + 1`, read ahead while triangle `t` is assembled, and its verdict (the
    /// rule it breaks, kept until its turn).
    ahead: Option<Result<IndexRecord, Fault>>,
    assembled: [VertexRecord; 3],
    /// The vertex cache: the index each entry holds, and its record.
    tags: Vec<Option<u32>>,
    data: Vec<VertexRecord>,
    out: Option<Triangle>,
    frame_done: bool,
    buffer_done: bool,
    stats: Stats,
}

const NO_VERTEX: VertexRecord = VertexRecord { x: 0, y: 0, z: 0, c: [0; 3] };

impl CommandParser {
    /// A parser in INIT for hardware drawing `build`.
    pub fn new(params: Params, build: Build) -> Result<CommandParser, String> {
        params.check()?;
        Ok(CommandParser {
            params,
            build,
            state: State::Init,
            fault: None,
            base: 0,
            header: None,
            ar: None,
            burst: None,
            complete: None,
            bus_error: false,
            words: [0; HEADER_BYTES / 4],
            t: 0,
            record: None,
            k: 0,
            ahead: None,
            assembled: [NO_VERTEX; 3],
            tags: vec![None; params.cache as usize],
            data: vec![NO_VERTEX; params.cache as usize],
            out: None,
            frame_done: false,
            buffer_done: false,
            stats: Stats::default(),
        })
    }

    pub fn stats(&self) -> Stats {
        self.stats
    }

    /// What the parser drives this cycle.
    pub fn outputs(&self) -> Outputs {
        Outputs {
            state: self.state,
            ar: self.ar,
            out: self.out,
            render: self.header,
            frame_done: self.frame_done,
            buffer_done: self.buffer_done,
            fault: self.fault,
        }
    }

    fn read(&mut self, burst: Burst, offset: u32, bytes: usize) {
        self.ar = Some(ReadRequest { addr: self.base + offset, beats: self.params.beats(bytes) });
        self.burst = Some((burst, 0));
    }

    fn stop(&mut self, fault: Fault) {
        self.state = State::Error;
        self.fault = Some(fault);
    }

    /// The clock edge, given this cycle's inputs.
    pub fn clock(&mut self, i: &Inputs) {
        self.frame_done = false;
        self.buffer_done = false;
        let out_free = match self.out {
            Some(t) if i.out_ready => {
                self.out = None;
                self.stats.triangles += 1;
                self.frame_done = t.end_of_frame;
                self.buffer_done = t.end_of_buffer;
                true
            }
            Some(_) => false,
            None => true,
        };
        let complete = self.complete.take();
        self.receive(&i.bus);
        match self.state {
            State::Init | State::Error => {
                if i.start {
                    self.begin(i.address);
                }
            }
            State::Header | State::TriIndex => {
                if let Some(done) = complete {
                    self.checked(done, out_free, i.screen);
                }
            }
            State::VertexFetch => match complete {
                Some(done) => self.checked(done, out_free, i.screen),
                // A lookup waits for the burst of a miss to come in whole and be checked; record
                // t + 1's burst, read ahead, holds back only a miss.
                None if !matches!(self.burst, Some((Burst::Vertex, _))) && self.complete != Some(Burst::Vertex) => {
                    self.look_up(out_free)
                }
                None => {}
            },
            State::CpReady => match complete {
                // Record `t + 1` read ahead: checked this cycle, the hand-over waits a cycle.
                Some(done) => self.checked(done, out_free, i.screen),
                None if out_free => self.hand_over(),
                None => {}
            },
            State::End => {
                if out_free {
                    self.state = State::Init;
                }
            }
        }
    }

    /// The bus this cycle: the offered address taken, a beat stored.
    fn receive(&mut self, bus: &ReadResponse) {
        if self.ar.is_some() && bus.ar_ready {
            self.ar = None;
        }
        let Some((kind, beat)) = self.burst else { return };
        if !bus.r_valid || self.ar.is_some() {
            return;
        }
        let per = (self.params.beat_bytes / 4) as usize;
        for (j, &w) in bus.r_data.iter().take(per).enumerate() {
            if let Some(slot) = self.words.get_mut(beat as usize * per + j) {
                *slot = w;
            }
        }
        self.bus_error |= bus.r_error;
        let beats = self.params.beats(if kind == Burst::Header { HEADER_BYTES } else { RECORD_BYTES });
        if beat + 1 == beats {
            self.burst = None;
            self.complete = Some(kind);
        } else {
            self.burst = Some((kind, beat + 1));
        }
    }

    /// A new buffer: every register but the output's and the counts cleared, the cache
    /// emptied.
    fn begin(&mut self, address: u32) {
        let fresh = CommandParser::new(self.params, self.build).expect("checked");
        *self = CommandParser { stats: self.stats, out: self.out, ..fresh };
        if !address.is_multiple_of(RECORD_BYTES as u32) {
            self.stop(Fault::Address);
            return;
        }
        self.base = address;
        self.state = State::Header;
        self.read(Burst::Header, 0, HEADER_BYTES);
    }

    /// A burst received whole: its rules checked, then the next step.
    fn checked(&mut self, done: Burst, out_free: bool, screen: [u32; 2]) {
        let bus_error = std::mem::take(&mut self.bus_error);
        let record: [u32; RECORD_BYTES / 4] = self.words[..RECORD_BYTES / 4].try_into().expect("a record");
        if done == Burst::Index && self.state != State::TriIndex {
            // Record t + 1, read ahead: its verdict waits for its turn.
            let h = self.header.expect("the header was read");
            let verdict = match bus_error {
                true => Err(Fault::Bus),
                false => read_index_record(&record, self.t + 1, &h).map_err(|e| e.fault),
            };
            self.stats.index_bursts += verdict.is_ok() as u64;
            self.ahead = Some(verdict);
            return;
        }
        if bus_error {
            return self.stop(Fault::Bus);
        }
        let result: Result<(), Broken> = match done {
            Burst::Header => read_header(&self.words, Some(&self.build)).and_then(|h| self.accept_header(h, screen)),
            Burst::Index => {
                let h = self.header.expect("the header was read");
                read_index_record(&record, self.t, &h).map(|r| {
                    self.stats.index_bursts += 1;
                    self.record = Some(r);
                    self.k = 0;
                    self.state = State::VertexFetch;
                    self.read_ahead();
                })
            }
            Burst::Vertex => {
                let f = self.header.expect("the header was read").build.formats;
                let v = self.record.expect("an index record").v[self.k];
                read_vertex_record(&record, v, &f).map(|r| {
                    self.stats.vertex_bursts += 1;
                    let slot = (v & (self.params.cache - 1)) as usize;
                    (self.tags[slot], self.data[slot]) = (Some(v), r);
                    self.vertex_done(r, out_free);
                })
            }
        };
        if let Err(e) = result {
            self.stop(e.fault);
        }
    }

    /// The header passed `read_header` for this hardware: its reads must stay below 2^32,
    /// and its screen inside `screen`.
    fn accept_header(&mut self, h: Header, screen: [u32; 2]) -> Result<(), Broken> {
        if u64::from(self.base) + u64::from(h.length) > 1 << 32 {
            let rule = format!("{} bytes from {:#x} run past 32-bit addresses", h.length, self.base);
            return Err(Broken { at: 32, fault: Fault::Layout, rule });
        }
        if h.width > screen[0] || h.height > screen[1] {
            let rule = format!("a {}x{} screen on buffers of {}x{}", h.width, h.height, screen[0], screen[1]);
            return Err(Broken { at: 8, fault: Fault::Screen, rule });
        }
        self.header = Some(h);
        if h.triangles == 0 {
            // A buffer of no triangles: nothing to draw, and the frame ends.
            self.frame_done = true;
            self.buffer_done = true;
            self.state = State::Init;
        } else {
            self.state = State::TriIndex;
            self.read(Burst::Index, h.index_at, RECORD_BYTES);
        }
        Ok(())
    }

    /// One vertex looked up in the cache: a hit is copied (and, the last, hands the
    /// triangle over), a miss is fetched once the bus is free (else looked up again).
    fn look_up(&mut self, out_free: bool) {
        let v = self.record.expect("an index record").v[self.k];
        let slot = (v & (self.params.cache - 1)) as usize;
        if self.tags[slot] == Some(v) {
            self.stats.cache_hits += 1;
            self.vertex_done(self.data[slot], out_free);
        } else if self.burst.is_none() && self.complete.is_none() {
            let h = self.header.expect("the header was read");
            self.read(Burst::Vertex, h.vertex_at + v * RECORD_BYTES as u32, RECORD_BYTES);
        }
    }

    /// Vertex `k` assembled; after the third, the triangle handed over or waiting in CP Ready.
    fn vertex_done(&mut self, r: VertexRecord, out_free: bool) {
        self.assembled[self.k] = r;
        self.k += 1;
        if self.k == 3 {
            if out_free {
                self.hand_over();
            } else {
                self.state = State::CpReady;
            }
        }
    }

    /// Record `t + 1` asked for while triangle `t` is assembled, unless `t` ends the buffer
    /// (the bus is free: a record was just checked or taken from `ahead`).
    fn read_ahead(&mut self) {
        let r = self.record.expect("an index record");
        if !r.end_of_buffer {
            let h = self.header.expect("the header was read");
            self.read(Burst::Index, h.index_at + (self.t + 1) * RECORD_BYTES as u32, RECORD_BYTES);
        }
    }

    /// Triangle `t` into the output register; record `t + 1` becomes the current one if it
    /// was read ahead (stopping on the rule it breaks), else it is awaited in Tri Index.
    fn hand_over(&mut self) {
        let r = self.record.expect("an index record");
        let vertices = [0, 1, 2].map(|k| {
            let v = self.assembled[k];
            Vtx { x: v.x, y: v.y, z: v.z, c: v.c, iw: r.iw[k] }
        });
        self.out = Some(Triangle { vertices, end_of_buffer: r.end_of_buffer, end_of_frame: r.end_of_frame });
        if r.end_of_buffer {
            self.state = State::End;
            return;
        }
        self.t += 1;
        match self.ahead.take() {
            Some(Ok(next)) => {
                self.record = Some(next);
                self.k = 0;
                self.state = State::VertexFetch;
                self.read_ahead();
            }
            Some(Err(fault)) => self.stop(fault),
            // Its read is under way.
            None => self.state = State::TriIndex,
        }
    }
}

/// How a [`run`] ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Outcome {
    /// The frame's last triangle was taken (or the buffer held none).
    FrameDone,
    /// The buffer's last triangle was taken and it does not end the frame: the parser
    /// waits in INIT for the frame's next buffer.
    BufferDone,
    /// The parser stopped on a broken rule.
    Fault(Fault),
    /// Still going after the cycles allowed.
    Timeout,
}

/// One buffer through the parser.
#[derive(Clone, Debug, PartialEq)]
pub struct Run {
    pub outcome: Outcome,
    /// The triangles the rasterizer took, with the cycle it took each in (also one left in
    /// the output register when the parser stopped on an error, taken after).
    pub triangles: Vec<(u64, Triangle)>,
    /// The cycle the outcome showed in (`frame_done`, `buffer_done` or the Error state).
    pub cycles: u64,
    pub stats: Stats,
    /// Every read burst, in order, and the beats the memory answered with an error.
    pub reads: Vec<ReadRequest>,
    pub reads_outside: u64,
    /// The header, if it passed its checks.
    pub header: Option<Header>,
}

/// The memory and the rasterizer around a [`run`].
pub struct Bench<'a> {
    /// The buffer's bus address.
    pub base: u32,
    /// Cycles before a burst's first beat (`read_memory::ReadMemory`).
    pub latency: u32,
    /// Whether the memory holds back an address or a beat this cycle.
    pub stall: Box<dyn FnMut() -> bool + 'a>,
    /// Whether the rasterizer takes the output triangle in cycle `c`.
    pub take: Box<dyn FnMut(u64) -> bool + 'a>,
    /// The cycles allowed.
    pub max_cycles: u64,
    /// The parser's `screen` input.
    pub screen: [u32; 2],
}

impl Default for Bench<'_> {
    /// At address 0x1000, latency 0, nothing stalling, every triangle taken at once, a
    /// million cycles allowed, any screen.
    fn default() -> Self {
        Bench {
            base: 0x1000,
            latency: 0,
            stall: Box::new(|| false),
            take: Box::new(|_| true),
            max_cycles: 1_000_000,
            screen: ANY_SCREEN,
        }
    }
}

/// Buffer `bytes` through a parser of `params` drawing `build`, started in cycle 0.
pub fn run(params: Params, build: Build, bytes: &[u8], bench: Bench) -> Result<Run, String> {
    let Bench { base, latency, mut stall, mut take, max_cycles, screen } = bench;
    let mut parser = CommandParser::new(params, build)?;
    let mut memory = crate::read_memory::ReadMemory::new(bytes, base, params.beat_bytes, latency, &mut *stall);
    let (mut triangles, mut ended) = (Vec::new(), None);
    for cycle in 0..max_cycles {
        let o = parser.outputs();
        let outcome = match (o.frame_done, o.buffer_done, o.fault) {
            (true, _, _) => Some(Outcome::FrameDone),
            (_, true, _) => Some(Outcome::BufferDone),
            (_, _, Some(f)) => Some(Outcome::Fault(f)),
            _ => None,
        };
        ended = ended.or(outcome.map(|x| (x, cycle)));
        // A triangle handed over before an error is still taken.
        if let (Some((outcome, at)), None) = (ended, o.out) {
            let stats = parser.stats();
            return Ok(Run {
                outcome,
                triangles,
                cycles: at,
                stats,
                reads: memory.requests,
                reads_outside: memory.outside,
                header: o.render,
            });
        }
        let i = Inputs { start: cycle == 0, address: base, screen, bus: memory.response(), out_ready: take(cycle) };
        if let (Some(t), true) = (o.out, i.out_ready) {
            triangles.push((cycle, t));
        }
        memory.clock(o.ar, true);
        parser.clock(&i);
    }
    let (stats, header) = (parser.stats(), parser.outputs().render);
    Ok(Run {
        outcome: Outcome::Timeout,
        triangles,
        cycles: max_cycles,
        stats,
        reads: memory.requests,
        reads_outside: memory.outside,
        header,
    })
}
