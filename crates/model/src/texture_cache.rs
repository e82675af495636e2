//! The texture cache of paper 001's texture unit (Woo, Jang, Lee 2004, section II-5,
//! printed §II.2.마 "Texture Mapping": "to fetch the texture map's data efficiently we
//! implemented a texture cache"), cycle for cycle as `rtl::texture_cache` runs it.
//!
//! # Banking
//!
//! The paper says no more than that a cache exists. Ours serves the 2x2 footprint of a
//! bilinear sample in one clock: the texture unit stores each mip level as four parity
//! planes (`model::texture_memory`: texel (i, j) lives in plane (j & 1)·2 + (i & 1)), so the
//! four texels of a footprint lie in four different planes, and lane b of a request asks
//! for a word of plane b. The cache has one bank per lane: bank b is an independent
//! set-associative cache of 32-bit words over the whole texture memory (word addresses of
//! [`ADDR_BITS`] bits), looked up by lane b only. (Where two texels of a footprint coincide,
//! at a clamped edge or in a 1-wide level, the caller disables one of the two lanes.) The
//! four banks share one memory read port.
//!
//! A bank has `sets` sets of `ways` lines of `line` words, `sets · ways · line` words; an
//! address splits into (tag, set, word) from the top ([`Params::split`]). Each set replaces
//! round-robin: a victim pointer per set names the way the next fill of that set takes, and
//! advances by one (mod `ways`) with each fill of the set.
//!
//! # Cycle behaviour
//!
//! The request pipeline is stage 1 (S1: the request looked up) and the output register (O).
//! The block RAMs read synchronously: the read addresses go in at the clock edge that takes
//! a request, and their words (every way's tag and data word at the request's set and
//! word) are out in the next cycle, S1's, where the tags are compared and the way chosen.
//!
//! ```text
//!  cycle   hit                          miss of m lanes, memory latency L, mem$ack high
//!  t       inp_valid & inp_ready: taken  taken
//!  t+1     S1: all enabled lanes hit     S1: a lane misses; counted (hits, misses)
//!  t+2     out_valid (O)                 Fill: 1st word asked (MemAsk)
//!  ...                                   word k asked at t+2+k, k < m·line (lane order)
//!  t+1+m·line+L                          the last word in (mem$rvalid): line written
//!  t+2+m·line+L                          Wait: the RAMs read S1's addresses again
//!  t+3+m·line+L                          S1 again (Run): every lane hits, not counted
//!  t+4+m·line+L                          out_valid (O)
//! ```
//!
//! So the hit latency is [`HIT_LATENCY`] = 2 (a request taken in cycle t is at the output
//! in cycle t + 2) and one request a cycle goes through while every enabled lane hits. A
//! miss of m lanes costs `m · line + L + 2` cycles more than a hit ([`Params::miss_penalty`])
//! when the memory takes every word at once (`mem$ack` high) and answers each word asked
//! (taken) in cycle c in cycle c + L; in general the last word's arrival decides.
//!
//! Handshakes: a transfer happens when valid and ready are high in the same cycle.
//! `inp_ready` = Run & no flush asked (`inp_flush` this cycle or pending) & (S1 empty, or
//! S1 moves on this cycle); S1 moves on (to O) when every enabled lane hits and O is empty
//! or taken this cycle (`!out_valid | out_ready`). `out_valid`, `out_data*`, `out_side` are
//! O's registers: they hold until taken (and keep their last value after). A disabled
//! lane's `out_data` is 0.
//!
//! States (`st`): Clear (0), Run (1), Fill (2), Wait (3).
//!
//! * Clear: the tags of set `clr` of every way of every bank are invalidated and its
//!   victim pointer set to 0, one set a cycle, `sets` cycles; then Run. The unit powers up
//!   in Clear at set 0 (no reset pin: every register starts at 0, as everywhere in
//!   edgepaint), so after power-up `inp_ready` is low for exactly `sets` cycles.
//! * Run: lookups. If S1 holds a request and an enabled lane misses: Fill, with the missing
//!   lanes to fetch (hits and misses are counted in S1's first cycle only, so the lookup
//!   after the fill counts nothing). Else if a flush is asked and S1 is empty or moves on:
//!   Clear from set 0.
//! * Fill: the missing lanes' lines, in lane order, `line` words each from the line's first
//!   word: `MemAsk` with the next word's address, until `MemIn::ack`; the words come back
//!   in order (`mem$rvalid`, `mem$rdata`), each written to the victim way of its lane's
//!   bank; with a line's last word its tag is written valid and its set's victim pointer
//!   advances (`fills` counts it). Asking runs ahead of the answers: the next lane's words
//!   are asked while the previous lane's come in. With the last line in: Wait.
//! * Wait: one cycle, for the RAMs to read the lines just written (a RAM read in the cycle
//!   of a write to the same word gives the old word); then Run.
//!
//! `inp_flush` (a one-cycle pulse) asks for a flush: `inp_ready` is low from that cycle
//! until the flush's Clear has ended. A request in S1 completes first (its miss too); a
//! flush asked during a Clear makes another Clear after it.
//!
//! Counters (`hits`, `misses`, `fills`: 32 bits, wrapping) are registers: a request's
//! lookup shows in them from the cycle after S1's first cycle.
//!
//! RTL: `rtl::texture_cache`. Tests: `testbenches/tests/texture_cache.rs`.

/// Bits of a word address: texture memory's (`texture_memory::ADDR_BITS`).
pub const ADDR_BITS: u32 = crate::texture_memory::ADDR_BITS;
/// Bits of the side payload carried with a request.
pub const SIDE_BITS: u32 = 64;
/// Lanes of a request, one per bank.
pub const LANES: usize = 4;
/// Cycles from a request's taking to its result at the output when every lane hits.
pub const HIT_LATENCY: u64 = 2;

/// Largest `sets`, `ways` and `line` supported.
pub const MAX_SETS: u32 = 256;
pub const MAX_WAYS: u32 = 4;
pub const MAX_LINE: u32 = 16;
/// Smallest `sets`.
pub const MIN_SETS: u32 = 4;

/// The geometry of one bank (every bank has the same).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Params {
    /// Sets per bank: a power of two from 4 to 256.
    pub sets: u32,
    /// Ways per set: 1, 2 or 4.
    pub ways: u32,
    /// 32-bit words per line: a power of two from 1 to 16.
    pub line: u32,
}

impl Params {
    /// `Err` names the first parameter out of range or not a power of two.
    pub fn check(&self) -> Result<(), String> {
        let Params { sets, ways, line } = *self;
        if !sets.is_power_of_two() || !(MIN_SETS..=MAX_SETS).contains(&sets) {
            return Err(format!(
                "texture_cache: SETS = {sets} is not supported: sets per bank must be a power of two from \
                 {MIN_SETS} to {MAX_SETS}"
            ));
        }
        if ![1, 2, 4].contains(&ways) {
            return Err(format!("texture_cache: WAYS = {ways} is not supported: ways per set must be 1, 2 or 4"));
        }
        if !line.is_power_of_two() || line > MAX_LINE {
            return Err(format!(
                "texture_cache: LINE = {line} is not supported: words per line must be a power of two from 1 to \
                 {MAX_LINE}"
            ));
        }
        Ok(())
    }

    /// log2(sets): the set's bits.
    pub fn set_bits(&self) -> u32 {
        self.sets.trailing_zeros()
    }

    /// log2(line): the word's bits.
    pub fn line_bits(&self) -> u32 {
        self.line.trailing_zeros()
    }

    /// The tag's bits: the address's above the set's.
    pub fn tag_bits(&self) -> u32 {
        ADDR_BITS - self.set_bits() - self.line_bits()
    }

    /// Words of one bank.
    pub fn bank_words(&self) -> u32 {
        self.sets * self.ways * self.line
    }

    /// (tag, set, word) of a word address: word = the low `line_bits`, set = the next
    /// `set_bits`, tag = the rest.
    pub fn split(&self, addr: u32) -> (u32, u32, u32) {
        debug_assert!(addr >> ADDR_BITS == 0, "address {addr:#x} wider than {ADDR_BITS} bits");
        let (lb, sb) = (self.line_bits(), self.set_bits());
        (addr >> (lb + sb), (addr >> lb) & (self.sets - 1), addr & (self.line - 1))
    }

    /// Cycles a request missing in `missing` lanes takes beyond a hit's [`HIT_LATENCY`],
    /// when the memory takes every word asked at once and answers it `mem_latency` cycles
    /// later: `missing · line + mem_latency + 2` (see the module's cycle table; 0 for a hit).
    pub fn miss_penalty(&self, missing: u32, mem_latency: u32) -> u64 {
        if missing == 0 {
            return 0;
        }
        (missing * self.line + mem_latency + 2) as u64
    }
}

/// One bank's contents as the functional model keeps them: per set and way, the line's
/// tag if valid; per set, the victim pointer.
#[derive(Clone, Debug)]
struct Tags {
    ways: usize,
    tag: Vec<Option<u32>>,
    victim: Vec<u32>,
}

impl Tags {
    fn new(p: &Params) -> Self {
        Tags { ways: p.ways as usize, tag: vec![None; (p.sets * p.ways) as usize], victim: vec![0; p.sets as usize] }
    }

    /// The way of set `set` holding `tag`.
    fn way_of(&self, set: u32, tag: u32) -> Option<usize> {
        (0..self.ways).find(|&w| self.tag[set as usize * self.ways + w] == Some(tag))
    }

    /// Fills the victim way of `set` with `tag`: the way taken, the pointer advanced.
    fn fill(&mut self, set: u32, tag: u32) -> usize {
        let w = self.victim[set as usize] as usize;
        self.tag[set as usize * self.ways + w] = Some(tag);
        self.victim[set as usize] = (w as u32 + 1) % self.ways as u32;
        w
    }
}

/// Lookups counted: per enabled lane of each request, once.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Stats {
    pub hits: u64,
    pub misses: u64,
    /// Lines fetched: one per miss (each missing lane fetches its own line into its own bank).
    pub fills: u64,
}

/// The counts the cycle model (and the RTL) gives for `requests`, in order, with no flush
/// between them (after the power-up Clear): lane b's `Some(addr)` is a lookup of bank b.
pub fn hit_rate_of_trace(params: &Params, requests: &[[Option<u32>; LANES]]) -> Stats {
    let mut banks: Vec<Tags> = (0..LANES).map(|_| Tags::new(params)).collect();
    let mut s = Stats::default();
    for r in requests {
        for (bank, addr) in banks.iter_mut().zip(r) {
            let Some(addr) = *addr else { continue };
            let (tag, set, _) = params.split(addr);
            if bank.way_of(set, tag).is_some() {
                s.hits += 1;
            } else {
                s.misses += 1;
                s.fills += 1;
                bank.fill(set, tag);
            }
        }
    }
    s
}

/// The cache's inputs in one cycle (the RTL's ports of the same names).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CacheIn {
    pub inp_valid: bool,
    /// Bit b: lane b enabled.
    pub inp_en: u8,
    pub inp_addr: [u32; LANES],
    pub inp_side: u64,
    pub inp_flush: bool,
    pub out_ready: bool,
}

/// The cache's side of the read port in one cycle (the RTL's `mem$valid`, `mem$addr`): a
/// word asked, held until [`MemIn::ack`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct MemAsk {
    pub valid: bool,
    pub addr: u32,
}

/// The memory's side of the read port in one cycle (`mem$ack`, `mem$rvalid`, `mem$rdata`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct MemIn {
    /// The word asked ([`MemAsk`]) is taken this cycle.
    pub ack: bool,
    /// A word asked earlier is answered this cycle (in the order asked).
    pub rvalid: bool,
    pub rdata: u32,
}

/// The cache's outputs in one cycle, before the clock edge.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CacheOut {
    pub inp_ready: bool,
    pub out_valid: bool,
    pub out_data: [u32; LANES],
    pub out_side: u64,
    pub mem: MemAsk,
    pub counters: Counters,
}

/// The cache's counters (the RTL's `counters$*`), 32 bits, wrapping: lane lookups that hit
/// and that missed, counted in S1's first cycle, and lines fetched.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Counters {
    pub hits: u32,
    pub misses: u32,
    pub fills: u32,
}

/// The RTL's states (`st`), with its codes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum State {
    Clear = 0,
    Run = 1,
    Fill = 2,
    Wait = 3,
}

/// One bank with its block RAMs and their read registers.
#[derive(Clone, Debug)]
struct Bank {
    tags: Tags,
    /// `data[w][set · line + word]`.
    data: Vec<Vec<u32>>,
    /// What the RAMs read at the last clock edge: each way's tag (valid or not) and word,
    /// and the set's victim pointer.
    rd_tag: Vec<Option<u32>>,
    rd_word: Vec<u32>,
    rd_victim: u32,
}

impl Bank {
    fn new(p: &Params) -> Self {
        let ways = p.ways as usize;
        Bank {
            tags: Tags::new(p),
            data: vec![vec![0; (p.sets * p.line) as usize]; ways],
            rd_tag: vec![None; ways],
            rd_word: vec![0; ways],
            rd_victim: 0,
        }
    }

    /// The read registers' way holding `tag`.
    fn hit_way(&self, tag: u32) -> Option<usize> {
        self.rd_tag.iter().position(|t| *t == Some(tag))
    }

    /// The clock edge's read of the RAMs at `set`, word `i` (set · line + word).
    fn read(&mut self, set: u32, i: usize) {
        let ways = self.tags.ways;
        for w in 0..ways {
            self.rd_tag[w] = self.tags.tag[set as usize * ways + w];
            self.rd_word[w] = self.data[w][i];
        }
        self.rd_victim = self.tags.victim[set as usize];
    }
}

/// The texture cache, cycle for cycle: see the module documentation.
#[derive(Clone, Debug)]
pub struct TextureCache {
    p: Params,
    banks: Vec<Bank>,
    st: State,
    clr: u32,
    flush_pend: bool,
    s1_valid: bool,
    s1_fresh: bool,
    s1_en: u8,
    s1_addr: [u32; LANES],
    s1_side: u64,
    o_valid: bool,
    o_data: [u32; LANES],
    o_side: u64,
    /// Lanes whose words are still to ask, and to receive; the next word of each.
    iss_mask: u8,
    iss_word: u32,
    rcv_mask: u8,
    rcv_word: u32,
    counters: Counters,
}

/// The lowest lane of `mask` (3 when empty, as the RTL's priority encoder).
fn lowest(mask: u8) -> usize {
    (0..3).find(|&b| mask >> b & 1 == 1).unwrap_or(3)
}

impl TextureCache {
    /// The cache at power-up: Clear from set 0, every register 0. Panics on parameters
    /// [`Params::check`] refuses.
    pub fn new(p: Params) -> Self {
        p.check().unwrap_or_else(|e| panic!("{e}"));
        TextureCache {
            p,
            banks: (0..LANES).map(|_| Bank::new(&p)).collect(),
            st: State::Clear,
            clr: 0,
            flush_pend: false,
            s1_valid: false,
            s1_fresh: false,
            s1_en: 0,
            s1_addr: [0; LANES],
            s1_side: 0,
            o_valid: false,
            o_data: [0; LANES],
            o_side: 0,
            iss_mask: 0,
            iss_word: 0,
            rcv_mask: 0,
            rcv_word: 0,
            counters: Counters::default(),
        }
    }

    /// The parameters.
    pub fn params(&self) -> Params {
        self.p
    }

    /// The state this cycle.
    pub fn state(&self) -> State {
        self.st
    }

    /// One clock: the outputs of this cycle for inputs `i` and the memory's `m` (as the
    /// RTL's before the edge), then the edge.
    pub fn step(&mut self, i: &CacheIn, m: MemIn) -> CacheOut {
        let p = self.p;
        let run = self.st == State::Run;
        // S1's lookup, on what the RAMs read at the last edge.
        let mut hit_way = [None; LANES];
        let mut miss_mask = 0u8;
        for (b, bank) in self.banks.iter().enumerate() {
            hit_way[b] = bank.hit_way(p.split(self.s1_addr[b]).0);
            if self.s1_en >> b & 1 == 1 && hit_way[b].is_none() {
                miss_mask |= 1 << b;
            }
        }
        let all_hit = miss_mask == 0;
        let o_free = !self.o_valid || i.out_ready;
        let s1_go = run && self.s1_valid && all_hit && o_free;
        let pending = self.flush_pend || i.inp_flush;
        let inp_ready = run && !pending && (!self.s1_valid || s1_go);
        let take = i.inp_valid && inp_ready;
        let fill = self.st == State::Fill;
        let iss_lane = lowest(self.iss_mask);
        let mem = MemAsk {
            valid: fill && self.iss_mask != 0,
            addr: (self.s1_addr[iss_lane] & !(p.line - 1)) | self.iss_word,
        };
        let out = CacheOut {
            inp_ready,
            out_valid: self.o_valid,
            out_data: self.o_data,
            out_side: self.o_side,
            mem,
            counters: self.counters,
        };

        // The edge. The counters: S1's first cycle.
        if run && self.s1_valid && self.s1_fresh {
            let en = self.s1_en as u32 & 0xf;
            let c = &mut self.counters;
            c.hits = c.hits.wrapping_add((en & !miss_mask as u32).count_ones());
            c.misses = c.misses.wrapping_add(miss_mask.count_ones());
        }
        // The output register.
        if s1_go {
            self.o_valid = true;
            let en = self.s1_en;
            self.o_data = std::array::from_fn(|b| match hit_way[b] {
                Some(w) if en >> b & 1 == 1 => self.banks[b].rd_word[w],
                _ => 0,
            });
            self.o_side = self.s1_side;
        } else if i.out_ready {
            self.o_valid = false;
        }
        // The RAMs' writes this edge, decided on what they read at the last one.
        enum Write {
            Clear(u32),
            /// Bank, set, word index (set · line + word), data, and whether it is the line's
            /// last word (then the tag too).
            Word {
                bank: usize,
                way: usize,
                set: u32,
                i: usize,
                data: u32,
                tag: Option<u32>,
            },
        }
        let mut write = None;
        let mut st = self.st;
        let mut flush_pend = pending;
        match self.st {
            State::Clear => {
                write = Some(Write::Clear(self.clr));
                if self.clr == p.sets - 1 {
                    st = State::Run;
                }
                self.clr = (self.clr + 1) % p.sets;
            }
            State::Run => {
                if self.s1_valid && !all_hit {
                    st = State::Fill;
                    self.iss_mask = miss_mask;
                    self.rcv_mask = miss_mask;
                    self.iss_word = 0;
                    self.rcv_word = 0;
                } else if pending && (!self.s1_valid || s1_go) {
                    st = State::Clear;
                    self.clr = 0;
                    flush_pend = false;
                }
            }
            State::Fill => {
                if mem.valid && m.ack {
                    if self.iss_word == p.line - 1 {
                        self.iss_word = 0;
                        self.iss_mask &= self.iss_mask.wrapping_sub(1);
                    } else {
                        self.iss_word += 1;
                    }
                }
                if m.rvalid && self.rcv_mask != 0 {
                    let b = lowest(self.rcv_mask);
                    let (tag, set, _) = p.split(self.s1_addr[b]);
                    let last = self.rcv_word == p.line - 1;
                    let i = (set * p.line + self.rcv_word) as usize;
                    // The victim way, as the RAM read it (stable through the lane's fill: its
                    // set's pointer is written only with the line's last word).
                    let way = self.banks[b].rd_victim as usize;
                    write = Some(Write::Word { bank: b, way, set, i, data: m.rdata, tag: last.then_some(tag) });
                    if last {
                        self.rcv_word = 0;
                        self.rcv_mask &= self.rcv_mask.wrapping_sub(1);
                        self.counters.fills = self.counters.fills.wrapping_add(1);
                        if self.rcv_mask == 0 {
                            st = State::Wait;
                        }
                    } else {
                        self.rcv_word += 1;
                    }
                }
            }
            State::Wait => st = State::Run,
        }
        // The reads: the request taken, else S1's again; before the writes (a read of a
        // word written at the same edge gives the old word).
        for b in 0..LANES {
            let addr = if take { i.inp_addr[b] } else { self.s1_addr[b] };
            let (_, set, word) = p.split(addr);
            self.banks[b].read(set, (set * p.line + word) as usize);
        }
        match write {
            Some(Write::Clear(set)) => {
                for bank in &mut self.banks {
                    for w in 0..p.ways as usize {
                        bank.tags.tag[set as usize * p.ways as usize + w] = None;
                    }
                    bank.tags.victim[set as usize] = 0;
                }
            }
            Some(Write::Word { bank, way, set, i, data, tag }) => {
                let bk = &mut self.banks[bank];
                bk.data[way][i] = data;
                if let Some(tag) = tag {
                    let taken = bk.tags.fill(set, tag);
                    debug_assert_eq!(taken, way, "the victim pointer moved during the fill");
                }
            }
            None => {}
        }
        // Stage 1.
        self.s1_fresh = take;
        if take {
            self.s1_valid = true;
            self.s1_en = i.inp_en & 0xf;
            self.s1_addr = i.inp_addr;
            self.s1_side = i.inp_side;
        } else if s1_go {
            self.s1_valid = false;
        }
        self.st = st;
        self.flush_pend = flush_pend;
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn texture_cache_params_split_and_refuse() {
        let p = Params { sets: 16, ways: 2, line: 4 };
        assert_eq!(p.check(), Ok(()));
        assert_eq!(p.tag_bits(), ADDR_BITS - 6);
        // Word: 2 bits, set: 4 bits, tag: the other ADDR_BITS - 6.
        assert_eq!(p.split((1 << 6) | (0b0110 << 2) | 0b11), (1, 0b0110, 0b11));
        assert_eq!(p.split((1 << ADDR_BITS) - 1), ((1 << (ADDR_BITS - 6)) - 1, 15, 3));
        for bad in [
            Params { sets: 2, ways: 1, line: 1 },
            Params { sets: 12, ways: 1, line: 1 },
            Params { sets: 512, ways: 1, line: 1 },
            Params { sets: 4, ways: 3, line: 1 },
            Params { sets: 4, ways: 8, line: 1 },
            Params { sets: 4, ways: 1, line: 0 },
            Params { sets: 4, ways: 1, line: 32 },
        ] {
            assert!(bad.check().is_err(), "{bad:?} accepted");
        }
        assert!(Params { sets: 12, ways: 1, line: 1 }.check().unwrap_err().contains("SETS = 12"));
    }

    /// Round robin per set: a 2-way set keeps two conflicting lines, a third evicts the
    /// first filled, the fourth the second; another set's pointer is its own.
    #[test]
    fn texture_cache_round_robin_per_set() {
        let p = Params { sets: 4, ways: 2, line: 1 };
        let (a, b, c) = (0x000, 0x004, 0x008); // set 0, tags 0, 1, 2
        let lane0 = |addr: u32| [Some(addr), None, None, None];
        let s = hit_rate_of_trace(&p, &[lane0(a), lane0(b), lane0(a), lane0(b)]);
        assert_eq!((s.hits, s.misses), (2, 2));
        // c evicts a (way 0), then a evicts b (way 1): b misses, c hits.
        let s = hit_rate_of_trace(&p, &[lane0(a), lane0(b), lane0(c), lane0(a), lane0(c), lane0(b)]);
        assert_eq!((s.hits, s.misses, s.fills), (1, 5, 5));
        let s = hit_rate_of_trace(&p, &[lane0(a), lane0(0x001), lane0(b), lane0(0x001), lane0(a)]);
        assert_eq!((s.hits, s.misses), (2, 3), "set 1's fill does not move set 0's pointer");
    }
}
